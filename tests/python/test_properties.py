"""Properties over random input (Hypothesis, derandomized: the same examples on every run).

Valid input: random closed meshes (the procedural shapes, stretched, turned and moved), poses,
still waters of any up normal, level and density, and Airy seas, for the invariants that hold
whatever the body: the volume below plus the volume above is the total; the force is ρ·g·V
along the up normal in still water; Exact equals Exact Surface in still water; moving or turning
body and water together moves or turns the result; every result is finite.

Invalid input: random garbage in every argument of the public entry points, for "a typed
exception (``TypeError``, ``ValueError`` and their kind), never an abort, a hang or a NaN".
"""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np
import pytest

from conftest import quaternion_matrix, skip_unless_ci

try:
    from hypothesis import HealthCheck, given, settings
    from hypothesis import strategies as st
    from hypothesis.extra import numpy as hnp
except ImportError as error:  # not installed, or installed but not loadable here
    skip_unless_ci(f"hypothesis cannot be imported ({error}); the property suite needs it (pip install hypothesis)")

import buoyancy
from buoyancy import shapes

# Fixed examples (derandomize), no deadline (the first call of a shape builds its mesh).
VALID = settings(max_examples=1000, derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow])
INVALID = settings(max_examples=3000, derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow])

finite = st.floats(min_value=-1e3, max_value=1e3, allow_nan=False, allow_infinity=False)
positive = st.floats(min_value=0.05, max_value=20.0)


@st.composite
def unit_vectors(draw: st.DrawFn) -> np.ndarray:
    v = np.array(draw(st.tuples(finite, finite, finite)))
    norm = float(np.linalg.norm(v))
    if norm < 1e-3:
        return np.array([0.0, 1.0, 0.0])
    return v / norm


@st.composite
def quaternions(draw: st.DrawFn) -> np.ndarray:
    q = np.array(draw(st.tuples(finite, finite, finite, finite)))
    norm = float(np.linalg.norm(q))
    if norm < 1e-3:
        return np.array([0.0, 0.0, 0.0, 1.0])
    return q / norm


SHAPES = [
    lambda a, b, c: shapes.cuboid((a, b, c)),
    lambda a, b, c: shapes.ellipsoid((a, b, c), 12, 8),
    lambda a, b, c: shapes.cylinder(a, b, 12),
    lambda a, b, c: shapes.capsule(a, b, 10, 6),
    lambda a, b, c: shapes.torus(a + b, min(a, b) * 0.5, 12, 8),
    lambda a, b, c: shapes.cube(2).scaled((a, b, c)),
]


@st.composite
def meshes(draw: st.DrawFn) -> buoyancy.Mesh:
    make = draw(st.sampled_from(SHAPES))
    a, b, c = draw(positive), draw(positive), draw(positive)
    mesh = make(a, b, c)
    # Turned and moved in its own frame, so that the centroid is not the origin.
    rotation = quaternion_matrix(draw(quaternions()))
    offset = np.array(draw(st.tuples(finite, finite, finite))) / 10
    matrix = np.eye(4)
    matrix[:3, :3] = rotation
    matrix[:3, 3] = offset
    return mesh.transformed(matrix)


@st.composite
def still_waters(draw: st.DrawFn) -> buoyancy.Water:
    return buoyancy.Water(
        density=draw(st.floats(min_value=500.0, max_value=1500.0)),
        gravity=draw(st.floats(min_value=1.0, max_value=20.0)),
        level=draw(finite) / 10,
        normal=tuple(draw(unit_vectors())),
    )


@st.composite
def placements(draw: st.DrawFn, mesh: buoyancy.Mesh, water: buoyancy.Water) -> tuple[np.ndarray, np.ndarray]:
    """A pose whose centroid is within two bounding radii of the water's still plane."""
    q = draw(quaternions())
    n = np.asarray(water.normal)
    height = draw(st.floats(min_value=-2.0, max_value=2.0)) * mesh.bounding_radius
    sideways = np.array(draw(st.tuples(finite, finite, finite)))
    sideways -= n * float(sideways @ n)
    centroid_world = quaternion_matrix(q) @ np.asarray(mesh.centroid)
    position = n * (water.level + height) + sideways - centroid_world
    return position, q


def scale_of(mesh: buoyancy.Mesh, water: buoyancy.Water) -> tuple[float, float, float]:
    """Tolerances: on volumes, forces and lengths."""
    volume = 1e-9 * mesh.volume + 1e-12 * mesh.bounding_radius**3
    return volume, volume * water.density * water.gravity, 1e-9 * mesh.bounding_radius


def water_like(water: buoyancy.Water, level: float, normal: np.ndarray) -> buoyancy.Water:
    """``water`` with another still plane."""
    return buoyancy.Water(density=water.density, gravity=water.gravity, level=level, normal=tuple(normal))


def assert_same(
    got: buoyancy.Buoyancy, base: buoyancy.Buoyancy, rotation: np.ndarray, tol_v: float, tol_f: float
) -> None:
    """``got`` is ``base`` turned by ``rotation``: the same volume, the force and torque turned
    (forces to ``tol_f``; torques to ``tol_f`` times the body's size plus one)."""
    assert got.volume == pytest.approx(base.volume, abs=tol_v)
    np.testing.assert_allclose(got.force, rotation @ base.force, atol=tol_f)
    np.testing.assert_allclose(got.torque, rotation @ base.torque, atol=tol_f)


@VALID
@given(st.data())
def test_still_water_invariants(data: st.DataObject) -> None:
    mesh = data.draw(meshes())
    water = data.draw(still_waters())
    position, q = data.draw(placements(mesh, water))
    tol_v, tol_f, tol_l = scale_of(mesh, water)
    exact = mesh.buoyancy(position, q, water=water)
    for array in (exact.force, exact.torque, exact.center):
        assert np.all(np.isfinite(array))
    # Below + above = total: the same body under the water turned upside down.
    n = np.asarray(water.normal)
    flipped = water_like(water, -water.level, -n)
    above = mesh.buoyancy(position, q, water=flipped)
    assert exact.volume + above.volume == pytest.approx(mesh.volume, abs=tol_v)
    assert -tol_v <= exact.volume <= mesh.volume + tol_v
    # The force: ρ·g·V along the up normal.
    expected = water.density * water.gravity * exact.volume * n
    np.testing.assert_allclose(exact.force, expected, atol=tol_f)
    # Exact Surface integrates the pressure: the same force, torque and line of action.
    surface = mesh.buoyancy(position, q, water=water, method="exact_surface")
    np.testing.assert_allclose(surface.force, exact.force, atol=tol_f * 10)
    np.testing.assert_allclose(surface.torque, exact.torque, atol=tol_f * 10 * (1 + mesh.bounding_radius))
    assert surface.volume == pytest.approx(exact.volume, abs=tol_v * 10)
    if exact.volume > 1e-6 * mesh.volume:
        # The torque about the center of mass is the force's, applied at the center of buoyancy.
        arm = exact.center - np.asarray(exact.about)
        if exact.volume > 1e-3 * mesh.volume:
            np.testing.assert_allclose(surface.center, exact.center, atol=1e3 * tol_l)
        np.testing.assert_allclose(
            np.cross(arm, exact.force), exact.torque, atol=tol_f * 10 * (1 + mesh.bounding_radius)
        )


@VALID
@given(st.data())
def test_moving_and_turning_body_and_water_together(data: st.DataObject) -> None:
    mesh = data.draw(meshes())
    water = data.draw(still_waters())
    position, q = data.draw(placements(mesh, water))
    tol_v, tol_f, _ = scale_of(mesh, water)
    base = mesh.buoyancy(position, q, water=water)
    # Translation: body and plane moved by d.
    d = np.array(data.draw(st.tuples(finite, finite, finite)))
    n = np.asarray(water.normal)
    moved = mesh.buoyancy(position + d, q, water=water_like(water, water.level + float(d @ n), n))
    assert_same(moved, base, np.eye(3), tol_v, tol_f * (1 + mesh.bounding_radius))
    # Rotation about the origin: body pose and normal turned by R.
    r = data.draw(quaternions())
    rot = quaternion_matrix(r)
    x, y, z, w = r
    a, b, c, e = q
    composed = np.array(
        [
            w * a + x * e + y * c - z * b,
            w * b - x * c + y * e + z * a,
            w * c + x * b - y * a + z * e,
            w * e - x * a - y * b - z * c,
        ]
    )
    turned_water = water_like(water, water.level, rot @ n)
    turned = mesh.buoyancy(rot @ position, composed / np.linalg.norm(composed), water=turned_water)
    assert_same(turned, base, rot, tol_v, tol_f * (1 + mesh.bounding_radius))


@st.composite
def seas(draw: st.DrawFn) -> buoyancy.Water:
    components = [
        buoyancy.AiryWave(
            amplitude=draw(st.floats(min_value=0.0, max_value=0.5)) * wavelength / 14,
            wavelength=wavelength,
            direction=(math.cos(angle), 0.0, math.sin(angle)),
            phase=draw(st.floats(min_value=-10.0, max_value=10.0)),
        )
        for wavelength, angle in draw(
            st.lists(
                st.tuples(st.floats(min_value=5.0, max_value=200.0), st.floats(min_value=-4.0, max_value=4.0)),
                min_size=1,
                max_size=4,
            )
        )
    ]
    pressure: Literal["hydrostatic", "froude_krylov"] = draw(st.sampled_from(["hydrostatic", "froude_krylov"]))
    return buoyancy.Water(density=1025.0, waves=buoyancy.Waves(components, pressure=pressure))


@VALID
@given(st.data())
def test_under_waves_results_are_finite_and_bounded(data: st.DataObject) -> None:
    import warnings

    mesh = data.draw(meshes())
    water = data.draw(seas())
    position, q = data.draw(placements(mesh, buoyancy.Water()))
    time = data.draw(st.floats(min_value=-100.0, max_value=100.0))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # coarse meshes on short waves: warned of, still finite
        b = mesh.buoyancy(position, q, water=water, time=time)
    for array in (b.force, b.torque, b.center):
        assert np.all(np.isfinite(array))
    v, f = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    area = 0.5 * np.linalg.norm(np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]), axis=1).sum()
    assert np.isfinite(b.volume) and 0.0 <= b.wetted_area <= area * (1 + 1e-9)


# -- invalid input -------------------------------------------------------------------------------

garbage = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(min_value=-(2**70), max_value=2**70),
    st.floats(allow_nan=True, allow_infinity=True),
    st.complex_numbers(),
    st.text(max_size=5),
    st.binary(max_size=5),
    st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=5),
    st.lists(st.integers(min_value=-(2**40), max_value=2**40), max_size=5),
    st.tuples(st.floats(allow_nan=True), st.floats(allow_nan=True), st.floats(allow_nan=True)),
    hnp.arrays(
        st.sampled_from([np.float64, np.float32, np.int64, np.bool_, np.complex128, np.uint8]),
        hnp.array_shapes(min_dims=0, max_dims=3, max_side=4),
    ),
    st.builds(object),
    st.dictionaries(st.text(max_size=2), st.integers(), max_size=2),
)

TYPED = (TypeError, ValueError, IndexError, OverflowError, MemoryError, RuntimeError)

MESH = shapes.cube()


def _assert_finite(result: Any) -> None:
    for name in ("volume", "force", "torque", "center", "about"):
        value = getattr(result, name, None)
        if value is not None:
            assert np.all(np.isfinite(np.asarray(value, dtype=float))), name


def _call(function: Any, *args: Any, **kwargs: Any) -> None:
    try:
        result = function(*args, **kwargs)
    except TYPED:
        return
    _assert_finite(result)


@INVALID
@given(garbage, garbage, garbage)
def test_garbage_to_buoyancy_is_a_typed_error_or_a_finite_result(position: Any, rotation: Any, about: Any) -> None:
    _call(MESH.buoyancy, position, rotation, about=about)
    _call(MESH.buoyancy, (0, 0, 0), None, method=position)
    _call(MESH.buoyancy, (0, 0, 0), None, water=rotation)
    _call(MESH.buoyancy, (0, 0, 0), None, time=about)


@INVALID
@given(garbage, garbage)
def test_garbage_to_constructors_is_a_typed_error(first: Any, second: Any) -> None:
    _call(buoyancy.Mesh, first, second)
    _call(buoyancy.Water, density=first, normal=second)
    _call(buoyancy.Water, level=first, gravity=second)
    _call(buoyancy.Water, waves=first)
    _call(buoyancy.AiryWave, first, second)
    _call(buoyancy.Waves, first, depth=second)
    _call(buoyancy.Waves.jonswap, first, second, n=8)
    _call(buoyancy.HeightGrid, first, spacing=second)
    _call(buoyancy.DampingCoefficients, linear_drag=first, current=second)
    _call(shapes.cuboid, first)
    _call(shapes.uv_sphere, first, 8, 4)


@INVALID
@given(garbage, garbage, garbage)
def test_garbage_to_hydrostatics_and_batches_is_a_typed_error(first: Any, second: Any, third: Any) -> None:
    _call(MESH.buoyancy_batch, first, second)
    _call(MESH.buoyancy_batch, np.zeros((2, 3)), None, times=third)
    _call(MESH.waterplane, first, second)
    _call(MESH.hydrostatics, center_of_mass=first, position=second)
    _call(MESH.hydrostatic_table, first)
    _call(MESH.damping, first, second, third)
    controller = buoyancy.Controller()
    _call(controller.add, first)
    _call(controller.report, second)
    _call(setattr, controller, "time", third)


@settings(max_examples=300, derandomize=True, deadline=None)
@given(garbage, garbage)
def test_garbage_to_the_solvers_is_a_typed_error(mass: Any, center: Any) -> None:
    _call(MESH.equilibrium, mass, center)
    _call(MESH.gz_curve, mass, center, heel_deg=[0.0, 10.0])
    _call(MESH.gz_curve, 300.0, (0, 0, -0.1), heel_deg=center)


def test_the_property_suite_saw_what_it_claims() -> None:
    # The strategies make what they say: a mesh of each shape, and garbage of each kind.
    assert len(SHAPES) == 6 and math.isclose(shapes.cuboid((1, 1, 1)).volume, 8.0)
