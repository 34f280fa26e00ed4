"""Buoyancy on waves through the Python API: surfaces (Airy, sea states, Gerstner, height grids,
callables), ``Water.elevation``, ``Mesh.buoyancy(time=…)`` and ``buoyancy_batch(times=…)``, under
the hydrostatic and the Froude–Krylov pressure, against still water and analytic results;
pickling, comparison and errors."""

from __future__ import annotations

import math
import pickle
import threading
import warnings

import numpy as np
import pytest

import buoyancy
from buoyancy import shapes

from conftest import random_quaternions

MESHES = {
    "cube": shapes.cube(4),
    "sphere": shapes.uv_sphere(0.5, 24, 12),
    "torus": shapes.torus(1.0, 0.3, 24, 12),
    "knot": shapes.torus_knot(),
}


def flat(points: np.ndarray, t: float) -> np.ndarray:
    """A module-level surface function (it pickles by reference): calm water."""
    return np.zeros(len(points))


def assert_same(a: buoyancy.Buoyancy, b: buoyancy.Buoyancy, scale: float, rtol: float = 1e-12) -> None:
    """Force, torque and volume equal to ``rtol`` of ``scale`` (N), the torque of ``scale`` × 1 m."""
    assert abs(a.volume - b.volume) <= rtol * scale
    np.testing.assert_allclose(a.force, b.force, rtol=0, atol=rtol * scale)
    np.testing.assert_allclose(a.torque, b.torque, rtol=0, atol=rtol * scale)


def poses(rng: np.random.Generator, mesh: buoyancy.Mesh, k: int) -> tuple[np.ndarray, np.ndarray]:
    """K random poses from dry to submerged (y up)."""
    r = mesh.bounding_radius
    positions = np.c_[rng.uniform(-2, 2, k), np.linspace(-1.2 * r, 1.2 * r, k), rng.uniform(-2, 2, k)]
    return positions, random_quaternions(rng, k)


# --- still water through the wave API --------------------------------------------------------


@pytest.mark.parametrize(
    "waves",
    [
        buoyancy.Waves([]),
        buoyancy.AiryWave(amplitude=0.0, wavelength=3.0),
        buoyancy.HeightGrid(np.zeros((3, 4)), spacing=0.5),
        flat,
    ],
    ids=["no components", "zero amplitude", "zero grid", "callable"],
)
def test_calm_waves_equal_still_water(waves: object, rng: np.random.Generator) -> None:
    for normal in [(0, 1, 0), (0.2, 0.3, 1.0)]:
        still = buoyancy.Water(density=1025.0, normal=normal, level=0.1)
        calm = buoyancy.Water(density=1025.0, normal=normal, level=0.1, waves=waves)
        for mesh in MESHES.values():
            positions, rotations = poses(rng, mesh, 9)
            weight = still.specific_weight * mesh.volume
            for k, (p, q) in enumerate(zip(positions, rotations, strict=True)):
                expected = mesh.buoyancy(p, q, water=still, method="exact_surface", traversal="scan")
                got = mesh.buoyancy(p, q, water=calm, time=1.5 * k)
                assert got.method == "exact"
                assert_same(got, expected, weight)


# --- a plane surface: the divergence theorem -------------------------------------------------


@pytest.mark.parametrize("up", ["y", "z"])
def test_a_plane_surface_from_a_callable_gives_the_divergence_theorem(up: str, rng: np.random.Generator) -> None:
    """η = s·u + b (u the first horizontal axis): the pressure ρg(η − h) over the closed surface
    is ρg·V·(−∇η + n) with V the volume under that plane, through its centroid, exactly."""
    s, b = 0.3, 0.1
    normal = np.array([0.0, 1.0, 0.0] if up == "y" else [0.0, 0.0, 1.0])
    slope_axis = np.array([1.0, 0.0, 0.0]) if up == "y" else np.array([0.0, 1.0, 0.0])
    calls = []

    def ramp(points: np.ndarray, t: float) -> np.ndarray:
        calls.append(len(points))
        return s * (points @ slope_axis) + b

    waves = buoyancy.Water(normal=tuple(normal), waves=ramp)
    # The same plane as still water: n·p − s·u·p = b.
    tilted_normal = normal - s * slope_axis
    tilted = buoyancy.Water(normal=tuple(tilted_normal), level=b / np.linalg.norm(tilted_normal))
    for name, mesh in MESHES.items():
        positions, rotations = poses(rng, mesh, 7)
        if up == "z":
            positions = positions[:, [0, 2, 1]]
        weight = waves.specific_weight * mesh.volume
        for p, q in zip(positions, rotations, strict=True):
            calls.clear()
            got = mesh.buoyancy(p, q, water=waves)
            assert len(calls) == 1  # one call per evaluation
            exact = mesh.buoyancy(p, q, water=tilted, method="exact")
            expected = waves.specific_weight * exact.volume * tilted_normal
            torque = np.cross(exact.center - got.about, expected)
            np.testing.assert_allclose(got.force, expected, rtol=0, atol=1e-12 * weight, err_msg=name)
            np.testing.assert_allclose(got.torque, torque, rtol=0, atol=1e-12 * weight * (1 + mesh.bounding_radius))
            if exact.volume > 1e-6 * mesh.volume:
                # The horizontal force of the slope is there, not zeroed.
                assert got.force @ slope_axis == pytest.approx(-s * (got.force @ normal), rel=1e-9)


def test_a_wall_sided_box_in_a_regular_airy_wave() -> None:
    """Heave force ρgBLT + ρgBa·(2/k)·sin(kL/2)·cos(φ − ωt) on a box L × B of draft T."""
    length, beam, draft, a, wavelength, phase = 4.0, 1.0, 0.5, 0.1, 10.0, 0.3
    water = buoyancy.Water(waves=buoyancy.Waves([buoyancy.AiryWave(a, wavelength, phase=phase)]))
    k = 2 * math.pi / wavelength
    omega = math.sqrt(water.gravity * k)
    box = shapes.cube(32).scaled((length, 1.0, beam))
    times = np.arange(8) * 0.37
    batch = box.buoyancy_batch(np.tile((0.0, 0.5 - draft, 0.0), (8, 1)), None, water=water, times=times)
    weight = water.specific_weight
    expected = weight * beam * (length * draft + a * (2 / k) * math.sin(k * length / 2) * np.cos(phase - omega * times))
    assert np.max(np.abs(batch.force[:, 1] - expected)) < 1e-4 * weight * beam * length * draft


# --- batches ---------------------------------------------------------------------------------


def surfaces() -> dict[str, object]:
    x = np.arange(40) * 0.25
    heights = 0.2 * np.sin(2 * np.pi * x / 10.0)[None, :] * np.cos(np.arange(24) * 0.3)[:, None]
    return {
        "airy": buoyancy.Waves([buoyancy.AiryWave(0.3, 7.0), buoyancy.AiryWave(0.1, 3.0, (1, 0, 1), 0.5)], depth=8.0),
        "jonswap": buoyancy.Waves.jonswap(hs=1.0, tp=5.0, spreading=5.0, n=16, seed=3),
        "airy froude_krylov": buoyancy.Waves(
            [buoyancy.AiryWave(0.3, 7.0), buoyancy.AiryWave(0.1, 3.0, (1, 0, 1), 0.5)], 8.0, "froude_krylov"
        ),
        "jonswap froude_krylov": buoyancy.Waves.pierson_moskowitz(1.0, 5.0, n=16, seed=3, pressure="froude_krylov"),
        "gerstner": buoyancy.GerstnerWaves([buoyancy.AiryWave(0.3, 9.0), buoyancy.AiryWave(0.1, 4.0, (0.3, 0, 1))]),
        "grid": buoyancy.HeightGrid(heights, spacing=(0.25, 0.4), origin=(-5.0, -4.0)),
        "callable": lambda p, t: 0.2 * np.sin(p[:, 0] - t) * np.cos(p[:, 2]),
    }


@pytest.mark.parametrize("surface", list(surfaces()))
def test_a_batch_with_times_equals_single_calls(surface: str, rng: np.random.Generator) -> None:
    water = buoyancy.Water(density=1025.0, waves=surfaces()[surface])
    mesh = MESHES["knot"]
    positions, rotations = poses(rng, mesh, 24)
    times = rng.uniform(0, 20, 24)
    about = rng.normal(size=(24, 3))
    for threads in (None, 1, 2):
        batch = mesh.buoyancy_batch(positions, rotations, water=water, times=times, about=about, threads=threads)
        assert batch.method == "exact"
        for k in range(24):
            single = mesh.buoyancy(positions[k], rotations[k], water=water, time=times[k], about=about[k])
            assert batch[k] == single, (surface, threads, k)
    # One time for every pose.
    one = mesh.buoyancy_batch(positions, rotations, water=water, times=2.5)
    np.testing.assert_array_equal(one.force, mesh.buoyancy_batch(positions, rotations, water, times=[2.5] * 24).force)
    # Without times: t = 0.
    zero = mesh.buoyancy_batch(positions[:3], rotations[:3], water=water)
    assert zero[1] == mesh.buoyancy(positions[1], rotations[1], water=water)


def test_a_callable_is_called_once_per_evaluation_with_the_still_plane_points() -> None:
    seen: list[tuple[np.ndarray, float]] = []

    def surface(points: np.ndarray, t: float) -> np.ndarray:
        seen.append((np.array(points), t))
        return np.zeros(len(points))

    water = buoyancy.Water(normal=(0, 0, 2), level=0.5, waves=surface)
    cube = shapes.cube()
    cube.buoyancy(position=(0, 0, 0.5), water=water, time=3.0)
    [(points, t)] = seen
    assert t == 3.0 and isinstance(t, float)
    assert points.shape[1] == 3 and 1 <= len(points) <= 8
    np.testing.assert_allclose(points[:, 2], 0.5)  # on the still plane z = 0.5
    seen.clear()
    cube.buoyancy_batch(np.zeros((5, 3)), None, water=water, times=np.arange(5.0), threads=2)
    assert sorted(t for _, t in seen) == [0.0, 1.0, 2.0, 3.0, 4.0]


def test_a_callable_on_a_large_mesh_takes_the_interpreter_lock_back() -> None:
    """From 4096 triangles the evaluation runs without the lock; the callable still runs, and
    another Python thread can call into the module meanwhile."""
    mesh = shapes.uv_sphere(1.0, 96, 48)
    assert mesh.n_triangles >= 4096
    water = buoyancy.Water(waves=lambda p, t: 0.1 * np.cos(p[:, 0] - t))
    results: list[buoyancy.BuoyancyBatch] = []
    worker = threading.Thread(
        target=lambda: results.append(mesh.buoyancy_batch(np.zeros((8, 3)), None, water=water, times=np.arange(8.0)))
    )
    worker.start()
    single = mesh.buoyancy(water=water, time=5.0)
    worker.join()
    assert results[0][5] == single


# --- surfaces --------------------------------------------------------------------------------


def test_airy_elevation_follows_the_dispersion_relation() -> None:
    a, wavelength, phase, depth = 0.4, 12.0, 0.7, 3.0
    direction = np.array([1.0, 0.0, 1.0]) / math.sqrt(2)
    sea = buoyancy.Waves([buoyancy.AiryWave(a, wavelength, direction=(2, 0, 2), phase=phase)], depth=depth)
    water = buoyancy.Water(gravity=9.7, level=1.0, waves=sea)
    k = 2 * math.pi / wavelength
    omega = math.sqrt(9.7 * k * math.tanh(k * depth))
    assert sea.angular_frequencies(9.7)[0] == pytest.approx(omega, rel=1e-14)
    points = np.random.default_rng(1).uniform(-20, 20, size=(50, 3))
    for t in (0.0, 1.3):
        expected = a * np.cos(k * (points @ direction) - omega * t + phase)  # y is dropped: y up
        np.testing.assert_allclose(water.elevation(points, time=t), expected, rtol=0, atol=1e-12)
    assert isinstance(water.elevation((1.0, 5.0, 2.0)), float)
    assert water.elevation(points[:1]).shape == (1,)


def test_sea_states_are_deterministic_and_have_the_requested_height() -> None:
    sea = buoyancy.Waves.jonswap(hs=3.0, tp=9.0, gamma=2.0, direction=(1, 0, 1), spreading=4.0, n=128, seed=11)
    a = np.array([c.amplitude for c in sea.components])
    assert len(sea) == 128 and 4 * math.sqrt(np.sum(a**2) / 2) == pytest.approx(3.0, rel=1e-12)
    assert sea == buoyancy.Waves.jonswap(3.0, 9.0, 2.0, (1, 0, 1), 4.0, 128, 11)
    assert sea != buoyancy.Waves.jonswap(3.0, 9.0, 2.0, (1, 0, 1), 4.0, 128, 12)
    directions = np.array([c.direction for c in sea.components])
    assert np.ptp(directions[:, 0]) > 0.1 and np.allclose(directions[:, 1], 0)  # spread in the still plane
    pm = buoyancy.Waves.pierson_moskowitz(hs=1.5, tp=7.0, n=32, depth=20.0)
    assert pm.depth == 20.0
    peak_wavelength = 9.81 * 7.0**2 / (2 * math.pi)  # deep water
    wavelengths = np.array([c.wavelength for c in pm.components])
    assert wavelengths.min() < peak_wavelength < wavelengths.max()
    # Drawn for a z-up water, given to one.
    z_up = buoyancy.Water(normal=(0, 0, 1))
    ocean = buoyancy.Water(normal=(0, 0, 1), waves=buoyancy.Waves.jonswap(2.0, 8.0, spreading=3.0, water=z_up))
    assert np.allclose([c.direction[2] for c in ocean.waves.components], 0)


def test_a_sea_state_drawn_without_a_water_is_drawn_for_the_water_it_is_given_to() -> None:
    """``Waves.jonswap`` without ``water=`` given to a z-up water of another gravity: the same
    components as drawn with that water, its wavelengths following the gravity and its
    directions spread about z; they pickle as drawn for the water they were given to."""
    import pickle

    sea = buoyancy.Waves.jonswap(2.0, 8.0, spreading=3.0, n=16, seed=5)
    assert np.ptp([c.direction[2] for c in sea.components]) > 0.1  # standalone: y up, spread in x-z
    moon = buoyancy.Water(gravity=1.62, normal=(0, 0, 1))
    given = buoyancy.Water(gravity=1.62, normal=(0, 0, 1), waves=sea)
    drawn = buoyancy.Waves.jonswap(2.0, 8.0, spreading=3.0, n=16, seed=5, water=moon)
    assert given.waves == drawn and given.waves is not sea
    assert [c.direction[2] for c in given.waves.components] == [0.0] * 16
    assert [c.amplitude for c in given.waves.components] == [c.amplitude for c in drawn.components]
    # The wavelengths follow the gravity: the periods are the standalone draw's.
    periods = 2 * np.pi / given.waves.angular_frequencies(gravity=1.62)
    np.testing.assert_allclose(periods, 2 * np.pi / sea.angular_frequencies(gravity=9.81), rtol=1e-12)
    again = pickle.loads(pickle.dumps(given))
    assert again == given and again.waves == drawn
    assert pickle.loads(pickle.dumps(given.waves)) == drawn  # alone, still drawn for that water
    # Drawn for the default water and given to it: the same object, nothing drawn again.
    assert buoyancy.Water(waves=sea).waves is sea


# --- the Froude–Krylov pressure --------------------------------------------------------------


@pytest.mark.parametrize("normal, direction", [((0, 1, 0), (1, 0, 0)), ((0, 0, 1), (1, 2, 0))])
def test_froude_krylov_on_a_submerged_ball_is_its_weight_of_water_and_the_water_acceleration(
    normal: tuple[float, float, float], direction: tuple[float, float, float]
) -> None:
    """A ball wholly under a deep-water Airy wave: ``ρ g V`` up plus ``ρ V a``, ``a`` the water's
    acceleration at the center (harmonic, so its mean over the ball): ``A ω² e^{kz} sin θ`` along
    the direction of travel, ``−A ω² e^{kz} cos θ`` along the normal, ``θ = k x − ω t + φ``."""
    amplitude, wavelength, phase, radius = 0.5, 8.0, 0.4, 0.5
    up = np.array(normal, float) / np.linalg.norm(normal)
    along = np.array(direction, float) / np.linalg.norm(direction)
    sea = buoyancy.Waves([buoyancy.AiryWave(amplitude, wavelength, direction, phase)], pressure="froude_krylov")
    water = buoyancy.Water(density=1025.0, normal=normal, waves=sea)
    ball = shapes.uv_sphere(radius, 96, 48)
    rho, g, volume = water.density, water.gravity, ball.volume
    k = 2 * math.pi / wavelength
    omega = math.sqrt(g * k)
    times = np.array([0.0, 0.7, 1.9, 3.1])
    height = -1.5  # the top 1 m under the still plane, 0.5 m under the trough
    centers = np.array([along * 1.3 + up * height + np.cross(up, along) * 2.0] * len(times))
    batch = ball.buoyancy_batch(centers, None, water=water, times=times)
    for i, t in enumerate(times):
        theta = k * (centers[i] @ along) - omega * t + phase
        decay = amplitude * omega**2 * math.exp(k * height)
        acceleration = decay * math.sin(theta) * along - decay * math.cos(theta) * up
        expected = rho * g * volume * up + rho * volume * acceleration
        got = ball.buoyancy(centers[i], water=water, time=t)
        assert got == batch[i]
        assert np.linalg.norm(got.force - expected) <= 1e-3 * np.linalg.norm(expected), (t, got.force, expected)
        # The wave part alone, to 1e-3 of itself.
        wave_part = got.force - rho * g * volume * up
        assert np.linalg.norm(wave_part - rho * volume * acceleration) <= 1e-3 * rho * volume * decay
        # On the ball the pressure acts along the normals, all through the center: no torque
        # about it; on the faceted ball, one of the order of the facets' size squared.
        assert np.linalg.norm(got.torque) <= 1e-4 * np.linalg.norm(expected) * radius


def test_froude_krylov_heave_on_a_box_decays_with_the_draft() -> None:
    """The Smith effect: the heave force on a wall-sided box L × B of draft T under the
    Froude–Krylov pressure is ``ρgB[LT + A e^{−kT}(2/k) sin(kL/2) cos(ωt − φ)]``; under the
    hydrostatic pressure it has no ``e^{−kT}``."""
    length, beam, draft, a, wavelength, phase = 4.0, 1.0, 0.8, 0.05, 10.0, 0.3
    component = buoyancy.AiryWave(a, wavelength, phase=phase)
    water = buoyancy.Water(waves=buoyancy.Waves([component], pressure="froude_krylov"))
    k = 2 * math.pi / wavelength
    omega = math.sqrt(water.gravity * k)
    box = shapes.cube(16).scaled((length, 1.0, beam))
    times = np.arange(8) * 0.29
    batch = box.buoyancy_batch(np.tile((0.0, 0.5 - draft, 0.0), (8, 1)), None, water=water, times=times)
    weight = water.specific_weight
    heave = a * (2 / k) * math.sin(k * length / 2) * np.cos(omega * times - phase)
    expected = weight * beam * (length * draft + math.exp(-k * draft) * heave)
    scale = weight * beam * a * length
    assert np.max(np.abs(batch.force[:, 1] - expected)) < 1e-6 * scale
    # The decay is there: the hydrostatic pressure gives the undecayed heave force.
    hydrostatic = buoyancy.Water(waves=buoyancy.Waves([component]))
    still = box.buoyancy_batch(np.tile((0.0, 0.5 - draft, 0.0), (8, 1)), None, water=hydrostatic, times=times)
    undecayed = weight * beam * (length * draft + heave)
    assert np.max(np.abs(still.force[:, 1] - undecayed)) < 1e-4 * weight * beam * length * draft
    assert np.max(np.abs(still.force[:, 1] - batch.force[:, 1])) > 0.3 * scale * (1 - math.exp(-k * draft))


def test_hydrostatic_is_the_default_pressure_and_unchanged() -> None:
    components = [buoyancy.AiryWave(0.3, 7.0), buoyancy.AiryWave(0.1, 3.0, (1, 0, 1), 0.5)]
    default = buoyancy.Waves(components, depth=8.0)
    explicit = buoyancy.Waves(components, depth=8.0, pressure="hydrostatic")
    fk = buoyancy.Waves(components, depth=8.0, pressure="froude_krylov")
    assert default.pressure == explicit.pressure == "hydrostatic" and fk.pressure == "froude_krylov"
    assert default == explicit and default != fk and buoyancy.Water(waves=default) != buoyancy.Water(waves=fk)
    assert buoyancy.Waves.jonswap(1.0, 5.0, n=8) == buoyancy.Waves.jonswap(1.0, 5.0, n=8, pressure=None)
    assert buoyancy.Waves.jonswap(1.0, 5.0, n=8) != buoyancy.Waves.jonswap(1.0, 5.0, n=8, pressure="froude_krylov")
    knot = MESHES["knot"]
    for position in [(0.0, 0.0, 0.0), (0.3, -0.4, 0.2)]:
        single = buoyancy.Waves([components[0]])
        # Hydrostatic Waves equal one AiryWave given alone, as before the pressure model.
        assert knot.buoyancy(position, water=buoyancy.Water(waves=single), time=1.1) == knot.buoyancy(
            position, water=buoyancy.Water(waves=components[0]), time=1.1
        )
        a = knot.buoyancy(position, water=buoyancy.Water(waves=default), time=2.0)
        b = knot.buoyancy(position, water=buoyancy.Water(waves=explicit), time=2.0)
        c = knot.buoyancy(position, water=buoyancy.Water(waves=fk), time=2.0)
        assert a == b and a.method == c.method == "exact"
        assert not np.allclose(a.force, c.force, rtol=1e-6)
    # Calm water is calm under either pressure.
    for mesh in MESHES.values():
        calm = mesh.buoyancy((0.1, -0.2, 0.0), water=buoyancy.Water(waves=buoyancy.Waves([], pressure="froude_krylov")))
        exact = mesh.buoyancy((0.1, -0.2, 0.0), method="exact_surface")
        assert_same(calm, exact, buoyancy.Water().specific_weight * mesh.volume, rtol=1e-9)


def test_the_pressure_pickles_and_shows_in_the_repr() -> None:
    fk = buoyancy.Waves([buoyancy.AiryWave(0.1, 2.0)], pressure="froude_krylov")
    assert repr(fk) == (
        "Waves([AiryWave(amplitude=0.1, wavelength=2, direction=(1, 0, 0), phase=0)], depth=None, "
        "pressure='froude_krylov')"
    )
    many = buoyancy.Waves([buoyancy.AiryWave(0.1, 2.0 + i) for i in range(5)], 10.0, "froude_krylov")
    assert repr(many) == "Waves(5 components, depth=10, pressure='froude_krylov')"
    pm = buoyancy.Waves.pierson_moskowitz(1.0, 6.0, n=8, pressure="froude_krylov")
    assert repr(pm) == (
        "Waves.pierson_moskowitz(hs=1, tp=6, direction=(1, 0, 0), spreading=None, n=8, seed=0, depth=None, "
        "pressure='froude_krylov')"
    )
    z_up = buoyancy.Water(normal=(0, 0, 1))
    js = buoyancy.Waves.jonswap(1.0, 6.0, n=8, water=z_up, pressure="froude_krylov")
    for waves in (fk, many, pm, js):
        again = pickle.loads(pickle.dumps(waves))
        assert again == waves and again.pressure == "froude_krylov" and repr(again) == repr(waves)
    water = buoyancy.Water(normal=(0, 0, 1), waves=js)
    copy = pickle.loads(pickle.dumps(water))
    assert copy == water and copy.waves.pressure == "froude_krylov"
    assert "pressure='froude_krylov'" in repr(water)
    ball = shapes.uv_sphere(0.5, 24, 12)
    assert ball.buoyancy((0, 0, -0.2), water=copy, time=1.0) == ball.buoyancy((0, 0, -0.2), water=water, time=1.0)


@pytest.mark.parametrize(
    "build, error, match",
    [
        (
            lambda: buoyancy.Waves([], pressure="FroudeKrylov"),
            ValueError,
            "^pressure: unknown pressure model 'FroudeKrylov': pass 'hydrostatic' or 'froude_krylov'$",
        ),
        (
            lambda: buoyancy.Waves([], None, "linear"),
            ValueError,
            "^pressure: unknown pressure model 'linear': pass 'hydrostatic' or 'froude_krylov'$",
        ),
        (
            lambda: buoyancy.Waves([], pressure=1),
            TypeError,
            "^pressure: expected 'hydrostatic' or 'froude_krylov', got int$",
        ),
        (lambda: buoyancy.Waves.jonswap(1.0, 8.0, pressure="fk"), ValueError, "^pressure: unknown pressure model 'fk'"),
        (
            lambda: buoyancy.Waves.pierson_moskowitz(1.0, 8.0, pressure=b"hydrostatic"),
            TypeError,
            "^pressure: expected 'hydrostatic' or 'froude_krylov', got bytes$",
        ),
        (
            lambda: buoyancy.Water(
                waves=buoyancy.Waves([buoyancy.AiryWave(0.1, 2.0, (0, 1, 0))], pressure="froude_krylov")
            ),
            ValueError,
            "^waves: invalid water surface: a wave direction",
        ),
    ],
)
def test_pressure_errors_name_the_argument(build, error: type[Exception], match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(error, match=match):
        build()


FK_SEA = buoyancy.Water(waves=buoyancy.Waves([buoyancy.AiryWave(0.2, 5.0)], pressure="froude_krylov"))


@pytest.mark.parametrize(
    "call, error, match",
    [
        (
            lambda m: m.buoyancy(water=FK_SEA, method="improved"),
            ValueError,
            "^method: improved cuts the triangles at a flat",
        ),
        (lambda m: m.buoyancy(water=FK_SEA, time=NAN), ValueError, r"^time: must be finite \(s\)$"),
        (lambda m: m.buoyancy_batch(np.zeros((2, 3)), None, FK_SEA, times=[0, NAN]), ValueError, r"^times\[1\]: must"),
        (lambda m: m.buoyancy(position=(0, NAN, 0), water=FK_SEA), ValueError, "^position: "),
    ],
)
def test_froude_krylov_query_errors_name_the_argument(call, error: type[Exception], match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(error, match=match):
        call(shapes.cube())


def test_gerstner_crests_are_sharper_than_troughs() -> None:
    trochoid = buoyancy.GerstnerWaves([buoyancy.AiryWave(1.0, 12.0)])
    assert trochoid.steepness == pytest.approx(2 * math.pi / 12.0)
    with pytest.warns(UserWarning, match=r"component 0 is steeper than a wave can be \(H/λ = 0.166667 > 1/7"):
        water = buoyancy.Water(waves=trochoid)
    x = np.linspace(0, 12, 1200, endpoint=False)
    eta = water.elevation(np.c_[x, np.zeros_like(x), np.zeros_like(x)])
    assert eta.max() == pytest.approx(1.0, abs=1e-9) and eta.min() == pytest.approx(-1.0, abs=1e-9)
    assert np.count_nonzero(eta > 0) < 600  # narrow crests, wide troughs
    assert eta.mean() == pytest.approx(-math.pi / 12.0, abs=1e-3)  # the trochoid's −k·a²/2


@pytest.mark.parametrize(
    "normal, axes",
    [
        ((0, 1, 0), (0, 2)),
        ((0, 0, 1), (0, 1)),
        ((1, 0, 0), (1, 2)),
        ((0.3, -1.0, 0.5), (0, 2)),
        ((0.1, 0.3, 2), (0, 1)),
    ],
)
def test_grid_axes_follow_the_normal(normal: tuple[float, ...], axes: tuple[int, int]) -> None:
    """Columns and rows run along the two world axes other than the one most aligned with the
    normal; η is linear on the grid, so bilinear interpolation is exact."""
    columns, rows, spacing, origin = 6, 5, (0.5, 2.0), (-1.0, 3.0)
    u = origin[0] + np.arange(columns) * spacing[0]
    v = origin[1] + np.arange(rows) * spacing[1]
    heights = 0.1 * u[None, :] - 0.05 * v[:, None] + 0.3
    grid = buoyancy.HeightGrid(heights, spacing, origin, periodic=False)
    water = buoyancy.Water(normal=normal, waves=grid)
    n = np.array(normal, float) / np.linalg.norm(normal)
    points = np.random.default_rng(2).uniform(-1, 8, size=(40, 3))
    projected = points - np.outer(points @ n, n)
    inside = projected[:, axes[0]].clip(u[0], u[-1]), projected[:, axes[1]].clip(v[0], v[-1])
    np.testing.assert_allclose(water.elevation(points), 0.1 * inside[0] - 0.05 * inside[1] + 0.3, atol=1e-12)


def test_a_grid_from_numpy_arrays_matches_the_same_field_as_a_callable(rng: np.random.Generator) -> None:
    """A linear field on a grid large enough to hold the body (bilinear interpolation is exact
    on it): the same forces as the field given as a function, whatever the array's layout."""
    u = np.arange(-5.0, 5.01, 0.5)
    v = np.arange(-4.0, 4.01, 0.25)
    field = 0.08 * u[None, :] + 0.05 * v[:, None] - 0.1  # heights[row (z), column (x)]
    wide = np.zeros((2 * len(v), 3 * len(u)))
    wide[::2, ::3] = field
    as_function = buoyancy.Water(waves=lambda p, t: 0.08 * p[:, 0] + 0.05 * p[:, 2] - 0.1)
    mesh = MESHES["torus"]
    positions, rotations = poses(rng, mesh, 5)
    positions[:, [0, 2]] *= 0.5
    for heights in (field, np.asfortranarray(field), field.tolist(), wide[::2, ::3]):
        water = buoyancy.Water(waves=buoyancy.HeightGrid(heights, spacing=(0.5, 0.25), origin=(-5.0, -4.0)))
        for p, q in zip(positions, rotations, strict=True):
            expected = mesh.buoyancy(p, q, water=as_function)
            assert_same(mesh.buoyancy(p, q, water=water), expected, water.specific_weight * mesh.volume, rtol=1e-11)
    assert buoyancy.HeightGrid(np.ones((2, 3), dtype=np.int32), 1.0).heights.dtype == np.float64
    assert buoyancy.HeightGrid(np.ones((2, 3), dtype=np.float32), 1.0).heights.tolist() == np.ones((2, 3)).tolist()


def test_a_grid_on_z_up_water_matches_the_same_field_as_a_callable(rng: np.random.Generator) -> None:
    """z up: the grid read along x and y, its bound over each body taken on those axes: the
    same forces as the (linear) field given as a function, at poses from dry to submerged."""
    u = np.arange(-5.0, 5.01, 0.5)
    v = np.arange(-4.0, 4.01, 0.25)
    field = 0.08 * u[None, :] + 0.05 * v[:, None] - 0.1  # heights[row (y), column (x)]
    grid = buoyancy.Water(normal=(0, 0, 1), waves=buoyancy.HeightGrid(field, spacing=(0.5, 0.25), origin=(-5.0, -4.0)))
    as_function = buoyancy.Water(normal=(0, 0, 1), waves=lambda p, t: 0.08 * p[:, 0] + 0.05 * p[:, 1] - 0.1)
    mesh = MESHES["torus"]
    positions, rotations = poses(rng, mesh, 9)
    positions = positions[:, [0, 2, 1]] * (0.5, 0.5, 1.0)  # the sweep along z, within the grid
    for p, q in zip(positions, rotations, strict=True):
        expected = mesh.buoyancy(p, q, water=as_function)
        assert_same(mesh.buoyancy(p, q, water=grid), expected, grid.specific_weight * mesh.volume, rtol=1e-11)


def test_a_periodic_grid_repeats() -> None:
    heights = np.random.default_rng(3).normal(size=(8, 16))
    grid = buoyancy.HeightGrid(heights, spacing=0.5)
    water = buoyancy.Water(normal=(0, 0, 1), waves=grid)
    points = np.random.default_rng(4).uniform(0, 8, size=(30, 3))
    shifted = points + np.array([8.0 * 3, -4.0 * 2, 0.0])  # whole periods: 16 × 0.5 and 8 × 0.5
    np.testing.assert_allclose(water.elevation(points), water.elevation(shifted), atol=1e-12)
    assert water.elevation((0.5, 1.0, 0.0)) == heights[2, 1]


def test_set_heights_changes_every_water_holding_the_grid_in_place() -> None:
    grid = buoyancy.HeightGrid(np.zeros((4, 4)), spacing=1.0)
    a, b = buoyancy.Water(waves=grid), buoyancy.Water(density=1025.0, waves=grid)
    cube = shapes.cube()
    before = cube.buoyancy(water=a)
    grid.set_heights(np.full((4, 4), 0.25))
    assert a.elevation((1.5, 0, 1.5)) == b.elevation((1.5, 0, 1.5)) == 0.25
    assert cube.buoyancy(water=a).volume == pytest.approx(before.volume + 0.25, rel=1e-12)
    with pytest.raises(ValueError, match="heights: invalid water surface: a height grid's heights must be finite"):
        grid.set_heights(np.full((4, 4), np.nan))
    assert grid.heights.tolist() == np.full((4, 4), 0.25).tolist()  # unchanged by the error


# --- comparing and pickling ------------------------------------------------------------------


def test_surfaces_and_waters_pickle_and_compare() -> None:
    for name, surface in surfaces().items():
        if name == "callable":
            continue
        again = pickle.loads(pickle.dumps(surface))
        assert again == surface and repr(again) == repr(surface), name
        water = buoyancy.Water(density=1025.0, normal=(0, 1, 0), waves=surface)
        copy = pickle.loads(pickle.dumps(water))
        assert copy == water and repr(copy) == repr(water), name
        np.testing.assert_array_equal(copy.elevation(np.eye(3) * 2), water.elevation(np.eye(3) * 2))
        assert water != buoyancy.Water(density=1025.0)
    wave = buoyancy.AiryWave(0.5, 20.0, (1, 0, 1), 0.3)
    assert pickle.loads(pickle.dumps(wave)) == wave
    assert buoyancy.Water(waves=wave) == buoyancy.Water(waves=buoyancy.AiryWave(0.5, 20.0, (1, 0, 1), 0.3))
    assert buoyancy.Water(waves=wave) != buoyancy.Water(waves=buoyancy.AiryWave(0.5, 20.0, (1, 0, 1), 0.4))
    # A module-level function pickles by reference, a lambda does not.
    water = buoyancy.Water(waves=flat)
    assert pickle.loads(pickle.dumps(water)) == water
    lam = buoyancy.Water(waves=lambda p, t: 0 * p[:, 0])
    with pytest.raises(
        TypeError, match="waves: a Water whose waves are a Python callable pickles only if the callable"
    ):
        pickle.dumps(lam)
    assert lam == lam and lam != buoyancy.Water(waves=lambda p, t: 0 * p[:, 0])  # callables by identity
    # A grid compares by value and is not hashable (it changes).
    g1, g2 = buoyancy.HeightGrid(np.zeros((2, 2)), 1.0), buoyancy.HeightGrid(np.zeros((2, 2)), 1.0)
    assert g1 == g2
    g2.set_heights(np.ones((2, 2)))
    assert g1 != g2
    with pytest.raises(TypeError):
        hash(g1)


def test_reprs() -> None:
    assert repr(buoyancy.Waves.pierson_moskowitz(1.0, 6.0, n=8)) == (
        "Waves.pierson_moskowitz(hs=1, tp=6, direction=(1, 0, 0), spreading=None, n=8, seed=0, depth=None)"
    )
    many = buoyancy.Waves([buoyancy.AiryWave(0.1, 2.0 + i) for i in range(5)], depth=10.0)
    assert repr(many) == "Waves(5 components, depth=10)"
    assert repr(buoyancy.GerstnerWaves([buoyancy.AiryWave(0.1, 2.0)])) == (
        "GerstnerWaves([AiryWave(amplitude=0.1, wavelength=2, direction=(1, 0, 0), phase=0)])"
    )
    assert repr(buoyancy.HeightGrid(np.zeros((2, 3)), (1, 2), (0.5, 0), periodic=False)) == (
        "HeightGrid(shape=(2, 3), spacing=(1, 2), origin=(0.5, 0), periodic=False)"
    )


# --- errors ----------------------------------------------------------------------------------

NAN = float("nan")


@pytest.mark.parametrize(
    "build, error, match",
    [
        (
            lambda: buoyancy.AiryWave(-1.0, 2.0),
            ValueError,
            "^amplitude: invalid water surface: a wave amplitude must be",
        ),
        (lambda: buoyancy.AiryWave(1.0, 0.0), ValueError, "^wavelength: invalid water surface: a wavelength must be"),
        (lambda: buoyancy.AiryWave(1.0, NAN), ValueError, "^wavelength: "),
        (lambda: buoyancy.AiryWave(1.0, 2.0, (0, 0, 0)), ValueError, "^direction: is the zero vector"),
        (lambda: buoyancy.AiryWave(1.0, 2.0, (1, 0)), ValueError, r"^direction: expected 3 numbers"),
        (lambda: buoyancy.AiryWave(1.0, 2.0, phase=math.inf), ValueError, r"^phase: must be finite \(rad\)$"),
        (lambda: buoyancy.AiryWave("1", 2.0), TypeError, "^amplitude: expected a number, got str$"),
        (lambda: buoyancy.Waves([buoyancy.AiryWave(1, 2), 3.0]), TypeError, r"^components\[1\]: expected a buoyancy"),
        (lambda: buoyancy.Waves(5), TypeError, "^components: expected an iterable of buoyancy.AiryWave, got int$"),
        (lambda: buoyancy.Waves([], depth=-1.0), ValueError, "^depth: invalid water surface: the depth must be"),
        (lambda: buoyancy.Waves([]).angular_frequencies(-1.0), ValueError, "^gravity: must be finite and non-negative"),
        (lambda: buoyancy.Waves.jonswap(-1.0, 8.0), ValueError, "^hs: invalid water surface: the significant height"),
        (lambda: buoyancy.Waves.jonswap(1.0, 0.0), ValueError, "^tp: invalid water surface: the peak period"),
        (lambda: buoyancy.Waves.jonswap(1.0, 8.0, gamma=0.5), ValueError, "^gamma: invalid water surface: JONSWAP"),
        (lambda: buoyancy.Waves.jonswap(1.0, 8.0, spreading=0.0), ValueError, "^spreading: invalid water surface"),
        (lambda: buoyancy.Waves.jonswap(1.0, 8.0, n=0), ValueError, "^n: invalid water surface: a sea state needs"),
        (lambda: buoyancy.Waves.jonswap(1.0, 8.0, n=-3), ValueError, "^n: must be a non-negative integer"),
        (lambda: buoyancy.Waves.jonswap(1.0, 8.0, seed=-1), ValueError, "^seed: must be an integer from 0 to 2"),
        (lambda: buoyancy.Waves.jonswap(1.0, 8.0, seed=1.5), TypeError, "^seed: expected an integer from 0 to 2"),
        (lambda: buoyancy.Waves.jonswap(1.0, 8.0, depth=0.0), ValueError, "^depth: invalid water surface"),
        (
            lambda: buoyancy.Waves.jonswap(1.0, 8.0, direction=(0, 1, 0)),
            ValueError,
            "^direction: invalid water surface",
        ),
        (lambda: buoyancy.Waves.pierson_moskowitz(1.0, 8.0, water=1), TypeError, "^water: expected a buoyancy.Water"),
        (
            lambda: buoyancy.GerstnerWaves([buoyancy.AiryWave(2.0, 12.0)]),
            ValueError,
            "^components: invalid water surface: a Gerstner sea with steepness",
        ),
        (lambda: buoyancy.HeightGrid(np.zeros(4), 1.0), ValueError, r"^heights: expected shape \(rows, columns\)"),
        (lambda: buoyancy.HeightGrid(np.zeros((1, 4)), 1.0), ValueError, r"^heights: .*at least 2 rows.*\(1, 4\)$"),
        (lambda: buoyancy.HeightGrid([[0, NAN], [0, 0]], 1.0), ValueError, "^heights: invalid water surface: .*finite"),
        (
            lambda: buoyancy.HeightGrid(np.zeros((2, 2)), 0.0),
            ValueError,
            r"^spacing: must be finite and positive \(m\)$",
        ),
        (lambda: buoyancy.HeightGrid(np.zeros((2, 2)), (1, 2, 3)), ValueError, r"^spacing: expected one number or 2"),
        (lambda: buoyancy.HeightGrid(np.zeros((2, 2)), 1, (0, NAN)), ValueError, "^origin: has a NaN or infinite"),
        (lambda: buoyancy.HeightGrid(np.zeros((2, 2)), 1, (0, 0, 0)), ValueError, r"^origin: expected 2 numbers"),
        (lambda: buoyancy.HeightGrid(np.zeros((2, 2)), 1, periodic="yes"), TypeError, "^periodic: expected True or"),
        (
            lambda: buoyancy.Water(waves=3.0),
            TypeError,
            "^waves: expected a buoyancy.AiryWave, buoyancy.Waves, .*float$",
        ),
        (lambda: buoyancy.Water(waves=buoyancy.Waves), TypeError, "^waves: expected .*, got type$"),
        (
            lambda: buoyancy.Water(waves=buoyancy.AiryWave(1.0, 2.0, (0, 1, 0))),
            ValueError,
            "^waves: invalid water surface: a wave direction must be finite and not along the water's up normal$",
        ),
        (
            lambda: buoyancy.Water(
                normal=(0, 0, 1), waves=buoyancy.GerstnerWaves([buoyancy.AiryWave(0.1, 2.0, (0, 0, 1))])
            ),
            ValueError,
            "^waves: invalid water surface: a wave direction",
        ),
        (
            lambda: buoyancy.Water(normal=(0, 0, 1), waves=buoyancy.Waves.jonswap(1.0, 8.0, water=buoyancy.Water())),
            ValueError,
            r"^waves: the sea state's components were drawn for the water given as water=, of gravity 9.81 m/s² and "
            r"up normal \(0, 1, 0\), and this water has gravity 9.81 and normal \(0, 0, 1\): pass this water as "
            r"water= to Waves.jonswap, or no water \(the waves are then drawn for the water they are given to\)$",
        ),
        (
            lambda: buoyancy.Water(
                gravity=9.8, waves=buoyancy.Waves.pierson_moskowitz(1.0, 8.0, water=buoyancy.Water())
            ),
            ValueError,
            r"^waves: the sea state's .* to Waves.pierson_moskowitz, or no water",
        ),
        (
            lambda: buoyancy.Waves.jonswap(1.0, 8.0, direction=(0, 1, 0)),  # drawn for Water(): y up
            ValueError,
            "^direction: invalid water surface: a wave direction must be finite and not along",
        ),
        (
            lambda: buoyancy.Water(normal=(1, 0, 0), waves=buoyancy.Waves.jonswap(1.0, 8.0)),
            ValueError,
            "^waves: invalid water surface: a wave direction must be finite and not along",
        ),
    ],
)
def test_surface_errors_name_the_argument(build, error: type[Exception], match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(error, match=match):
        build()


SEA = buoyancy.Water(waves=buoyancy.AiryWave(0.2, 5.0))


@pytest.mark.parametrize(
    "call, error, match",
    [
        (
            lambda m: m.buoyancy(water=SEA, method="fast_surface"),
            ValueError,
            "^method: fast_surface integrates below a flat",
        ),
        (
            lambda m: m.buoyancy_batch(np.zeros((2, 3)), None, SEA, "fast"),
            ValueError,
            "^method: fast counts the triangles below a flat",
        ),
        (lambda m: m.buoyancy(water=SEA, time=NAN), ValueError, r"^time: must be finite \(s\)$"),
        (lambda m: m.buoyancy(water=SEA, time="now"), TypeError, "^time: expected a number, got str$"),
        (lambda m: m.buoyancy(time=math.inf), ValueError, r"^time: must be finite \(s\)$"),
        (
            lambda m: m.buoyancy_batch(np.zeros((2, 3)), None, SEA, times=[0, 1, 2]),
            ValueError,
            r"^times: expected one time \(\) or one per pose \(2,\), got shape \(3,\)$",
        ),
        (lambda m: m.buoyancy_batch(np.zeros((2, 3)), None, SEA, times=[0, NAN]), ValueError, r"^times\[1\]: must be"),
        (lambda m: m.damping(water=SEA), ValueError, "^water: the damping model assumes a flat water surface"),
        (
            lambda m: SEA.elevation([(0, 0)]),
            ValueError,
            r"^points: expected shape \(N, 3\) or \(3,\), got shape \(1, 2\)$",
        ),
        (lambda m: SEA.elevation([(0, 0, 0), (0, NAN, 0)]), ValueError, r"^points\[1\]: has a NaN or infinite"),
        (lambda m: SEA.elevation((0, 0, 0), time=NAN), ValueError, r"^time: must be finite \(s\)$"),
    ],
)
def test_query_errors_name_the_argument(call, error: type[Exception], match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(error, match=match):
        call(shapes.cube())


@pytest.mark.parametrize(
    "function, error, match",
    [
        (
            lambda p, t: np.zeros((len(p), 2)),
            ValueError,
            r"waves: the surface function returned shape \(\d+, 2\); expected",
        ),
        (lambda p, t: 0.0, ValueError, r"waves: the surface function returned shape \(\); expected \(\d+,\)"),
        (lambda p, t: np.full(len(p), np.nan), ValueError, "waves: the surface function returned NaN at point 0 "),
        (lambda p, t: np.where(p[:, 0] > 0, np.inf, 0.0), ValueError, "waves: the surface function returned inf at"),
        (lambda p, t: ["a"] * len(p), ValueError, r"waves: the surface function must return \d+ numbers .* got list$"),
        (lambda p, t: 1 / 0, ZeroDivisionError, "division by zero"),
    ],
)
def test_a_wrong_surface_function_is_a_clear_error(function, error: type[Exception], match: str) -> None:  # type: ignore[no-untyped-def]
    water = buoyancy.Water(waves=function)
    cube = shapes.cube()
    with pytest.raises(error, match=f"^{match}" if error is ValueError else match):
        cube.buoyancy(water=water)
    with pytest.raises(error, match=f"^pose 0: {match}" if error is ValueError else match):
        cube.buoyancy_batch(np.zeros((1, 3)), None, water=water)
    with pytest.raises(error, match=f"^{match}" if error is ValueError else match):
        water.elevation(np.eye(3))


def test_waves_beyond_the_breaking_limit_are_warned_of() -> None:
    # Once accepted without a word: H/λ = 0.4, where the sea breaks at 1/7.
    with pytest.warns(UserWarning, match=r"^waves: component 1 is steeper than a wave can be \(H/λ = 0.4 > 1/7"):
        buoyancy.Water(waves=buoyancy.Waves([buoyancy.AiryWave(0.1, 20.0), buoyancy.AiryWave(1.0, 5.0)]))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        buoyancy.Water(waves=buoyancy.AiryWave(0.5, 7.1))  # H/λ = 0.141: no warning


def test_a_seabed_in_the_trough_is_an_error() -> None:
    components = [buoyancy.AiryWave(1.0, 20.0), buoyancy.AiryWave(0.5, 30.0)]
    with pytest.raises(ValueError, match="^depth: .*greater than the deepest trough the waves reach"):
        buoyancy.Waves(components, depth=1.5)
    assert buoyancy.Waves(components, depth=1.51).depth == 1.51


def test_a_mesh_too_coarse_for_the_waves_is_warned_of() -> None:
    # Edges of 14 m against a 5 m wave: sampled at the vertices, the wave is not seen.
    coarse = shapes.cube().scaled(10.0)
    assert coarse.longest_edge == pytest.approx(10 * 2**0.5)
    water = buoyancy.Water(waves=buoyancy.AiryWave(0.1, 5.0))
    with pytest.warns(UserWarning, match=r"longest edge, 14.1421 m, is more than half the shortest wavelength, 5 m"):
        coarse.buoyancy(water=water)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        shapes.cube(40).scaled(10.0).buoyancy(water=water)  # edges of 0.35 m
        with pytest.raises(UserWarning):
            coarse.buoyancy(water=water)


def test_a_body_deep_under_the_hydrostatic_wave_pressure_is_warned_of() -> None:
    # The default pressure carries ρg(η − z) to any depth (a cube 600 m down once felt the
    # surface's wave force without a word); Froude–Krylov's decays, and is the one to use.
    swell = [buoyancy.AiryWave(0.5, 20.0, (1, 0, 0), 1.0)]
    hydrostatic = buoyancy.Water(waves=buoyancy.Waves(swell))
    cube = shapes.cube()
    with pytest.warns(
        UserWarning,
        match=r"the body lies deeper under the still level than .* \(3.1831 m\).*pressure=\"froude_krylov\"",
    ):
        deep = cube.buoyancy(position=(0, -600, 0), water=hydrostatic)
    assert abs(deep.force[0]) > 100.0  # the surface's wave force, 600 m down
    fk = buoyancy.Water(waves=buoyancy.Waves(swell, pressure="froude_krylov"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert abs(cube.buoyancy(position=(0, -600, 0), water=fk).force[0]) < 1e-9
        cube.buoyancy(position=(0, -3, 0), water=hydrostatic)  # 2.1 m under: within 1/k
