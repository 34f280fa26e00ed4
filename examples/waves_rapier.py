"""The demo on waves, in Python: a ship-like hull, the Stanford bunny and a small buoy float in a
rapier3d world (rapier's Python binding) with buoyancy.rapier, on a regular wave and on an
irregular JONSWAP sea. Prints, per body and sea, the heave and pitch against the wave's elevation
and slope at the body, the mean draft, the drift and the checks' verdicts, and writes
``out/waves_rapier.png``: heave and pitch over time against the surface at each body. The Python
counterpart of ``cargo run --release --example waves`` (examples/waves.rs), with the same bodies,
seas and checks.

    pip install 'buoyancy[rapier,plot]'
    python examples/waves_rapier.py [--seconds 60] [--out out/waves_rapier.png]

* **Hull**: a closed Wigley hull (:func:`buoyancy.shapes.wigley_hull`), 4 m long, 0.6 m wide,
  0.25 m design draft, 0.15 m of freeboard, of the uniform density that floats it at its design
  draft; heading into the waves (its length along x, the waves travelling along +x).
* **Bunny**: the Stanford bunny of the sample meshes (``$BUOYANCY_MESHES/bunny.obj``, else
  ``../shared/meshes/bunny.obj`` beside the repository), 1.2 m across, half as dense as water;
  skipped, with a note, when absent.
* **Buoy**: a foam cylinder 0.6 m across and 0.5 m tall with a lead ball 0.2 m across at its
  bottom (only the cylinder floats; the ball is ballast inside it).

The bodies first settle in still water; then the waves grow from nothing over 5 s (the elevation
times a smooth step, given to the water as a Python function; the Airy waves themselves, with
their orbital velocity, from then on) and run for 60 s. The statistics are taken over the last
40 s. **heave**: the rise of the center of mass above its rest height; **pitch**: the tilt of the
body's line along the waves, bow (+x) up positive, against the wave's **slope** angle
``atan(∂η/∂x)``; **η at the body**: the elevation of the surface at the center of mass's
horizontal position; **draft**: the depth below the still level of the body's point that was
lowest at rest.

Checks (as in the Rust demo; tests/python/test_rapier.py holds them as tests): the hull placed at
its design draft in still water stays at rest for 30 s; on the waves every pose stays finite, the
heave within two wave heights, the speed within 3 m/s and the spin within 5 rad/s.
"""

from __future__ import annotations

import argparse
import math
import pathlib
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import rapier3d

import buoyancy
from buoyancy._sample_meshes import find_sample_mesh, not_found_message
from buoyancy.rapier import FloatingBodies

REPO = pathlib.Path(__file__).resolve().parents[1]
WATER_DENSITY = 1000.0
GRAVITY = 9.81
#: Still water before the waves, s; the waves' ramp, and their run (the ramp included), s.
SETTLE, RAMP, SECONDS = 20.0, 5.0, 60.0
#: The statistics are taken from this time on (s), sampled this often (Hz).
STATS_FROM, SAMPLE_RATE = 20.0, 20.0
#: The hull: Wigley, L × B × T with a freeboard (m), 41 stations, 17 waterlines (2,798 triangles).
HULL = (4.0, 0.6, 0.25, 0.15)
#: The regular wave: amplitude (m), wavelength (m), deep water, along +x.
REGULAR = (0.1, 8.0)
#: The JONSWAP sea (γ = 3.3, long-crested along +x): Hs (m), Tp (s), components, seed.
JONSWAP = (0.3, 2.5, 64, 7)
#: The buoy's cylinder: radius, half height (m), density (kg/m³); its lead ball: radius (m),
#: density (kg/m³), depth of its center below the cylinder's (m).
BUOY = (0.3, 0.25, 160.0)
BALLAST = (0.1, 11340.0, 0.15)
#: The rest check: the hull at its design draft in still water for this long (s) moves slower than
#: these (m/s, rad/s) and ends nearer than these to where it was placed (m, degrees).
REST_SECONDS, REST_SPEED, REST_SPIN, REST_DRIFT, REST_TURN = 30.0, 1e-4, 1e-4, 1e-4, 1e-3
#: The bounds on waves: heave within this many wave heights (H = 2a, or Hs), speed (m/s), spin (rad/s).
HEAVE_BOUND_HEIGHTS, SPEED_BOUND, SPIN_BOUND = 2.0, 3.0, 5.0


@dataclass
class Sea:
    """One sea: its name, its waves, the wave height the bounds are stated in (m), and the regular
    wave's angular frequency (rad/s; ``None`` for an irregular sea)."""

    name: str
    title: str
    waves: buoyancy.Waves
    height: float
    omega: float | None

    def water(self) -> buoyancy.Water:
        """The water with these waves at full height."""
        return buoyancy.Water(waves=self.waves)

    def ramped(self) -> buoyancy.Water:
        """The water whose elevation grows from 0 at t = 0 to the waves' at t = RAMP (a smooth
        step), as a Python function of the points and the time."""
        full = self.water()

        def elevation(points: np.ndarray, t: float) -> np.ndarray:
            return ramp(t) * full.elevation(points, t)

        return buoyancy.Water(waves=elevation)

    def elevation_and_slope(self, point: np.ndarray, t: float) -> tuple[float, float]:
        """The elevation (m) and the slope angle along x (degrees) at the horizontal position of
        ``point``, at full height."""
        dx = 0.02
        p = np.array([[point[0], 0.0, point[2]], [point[0] - dx, 0.0, point[2]], [point[0] + dx, 0.0, point[2]]])
        eta = self.water().elevation(p, t)
        factor = ramp(t)
        return factor * float(eta[0]), math.degrees(math.atan(factor * (eta[2] - eta[1]) / (2 * dx)))


def ramp(t: float) -> float:
    """The waves' height factor at time ``t``: a smooth step from 0 at t = 0 to 1 at t = RAMP."""
    x = min(max(t / RAMP, 0.0), 1.0)
    return x * x * (3.0 - 2.0 * x)


def seas() -> list[Sea]:
    amplitude, wavelength = REGULAR
    regular = buoyancy.Waves([buoyancy.AiryWave(amplitude, wavelength)])
    omega = float(regular.angular_frequencies(GRAVITY)[0])
    hs, tp, n, seed = JONSWAP
    return [
        Sea(
            "regular",
            f"regular Airy wave: height {2 * amplitude:.2f} m, length {wavelength:g} m, period {2 * math.pi / omega:.2f} s",
            regular,
            2 * amplitude,
            omega,
        ),
        Sea(
            "JONSWAP",
            f"JONSWAP sea (γ = 3.3, long-crested): Hs {hs} m, Tp {tp} s, {n} components",
            buoyancy.Waves.jonswap(hs, tp, gamma=3.3, n=n, seed=seed),
            hs,
            None,
        ),
    ]


# --- bodies -------------------------------------------------------------------------------------


def hull_mesh(stations: int = 41, waterlines: int = 17) -> tuple[buoyancy.Mesh, float]:
    """The Wigley hull and its uniform density that floats it at its design draft, kg/m³ (its
    mass is ρ times the mesh's volume below y = 0)."""
    hull = buoyancy.shapes.wigley_hull(*HULL, stations, waterlines)
    below = hull.buoyancy().volume
    return hull, WATER_DENSITY * below / hull.volume


def bunny_mesh() -> tuple[buoyancy.Mesh | None, str | None]:
    """The bunny 1.2 m across about its centroid, or ``None`` and a note."""
    path = find_sample_mesh("bunny.obj", REPO)
    if path is None:
        return None, f"note: {not_found_message(REPO, 'bunny.obj')}: the bunny is skipped"
    raw = buoyancy.load(path)
    scale = 0.6 / raw.bounding_radius
    return buoyancy.Mesh((raw.vertices - raw.centroid) * scale, raw.faces), None


def trimesh(mesh: buoyancy.Mesh) -> Any:
    return rapier3d.Collider.trimesh(mesh.vertices.astype(np.float32), mesh.faces.astype(np.uint32))


def add_hull(world: Any, water: FloatingBodies, z: float, mesh: buoyancy.Mesh, density: float) -> Any:
    """The hull at its design draft (the identity pose, its waterline at y = 0) at ``z``."""
    handle = world.add_body(
        rapier3d.RigidBody.dynamic().translation((0.0, 0.0, z)).can_sleep(False), [trimesh(mesh).density(density)]
    )
    water.register(handle, mesh)
    return handle


def add_half_density(world: Any, water: FloatingBodies, z: float, mesh: buoyancy.Mesh) -> Any:
    """``mesh`` half as dense as water at ``z``, placed at rest (its equilibrium in still water)."""
    handle = world.add_body(
        rapier3d.RigidBody.dynamic().translation((0.0, 0.0, z)).can_sleep(False),
        [trimesh(mesh).density(0.5 * WATER_DENSITY)],
    )
    water.register(handle, mesh)
    water.place_at_rest(handle, world.rigid_bodies, world.colliders)
    return handle


def add_buoy(world: Any, water: FloatingBodies, z: float, segments: int = 48) -> Any:
    """The buoy at ``z``, at the height where it displaces its weight: only the cylinder floats
    (meshed with ``segments`` around)."""
    radius, half_height, density = BUOY
    ball, ball_density, ball_depth = BALLAST
    mass = density * math.pi * radius**2 * 2 * half_height + ball_density * 4 / 3 * math.pi * ball**3
    draft = mass / (WATER_DENSITY * math.pi * radius**2)
    handle = world.add_body(
        rapier3d.RigidBody.dynamic().translation((0.0, half_height - draft, z)).can_sleep(False),
        [
            rapier3d.Collider.cylinder(half_height, radius).density(density),
            rapier3d.Collider.ball(ball).translation((0.0, -ball_depth, 0.0)).density(ball_density),
        ],
    )
    vertices, faces = rapier3d.Cylinder(half_height, radius).to_trimesh(segments)
    water.register(handle, buoyancy.Mesh(vertices, faces))
    return handle


# --- runs ---------------------------------------------------------------------------------------


def rotation_matrix(rb: Any) -> np.ndarray:
    return np.asarray(rb.rotation.to_matrix(), dtype=np.float64).reshape(3, 3)


def center_of_mass(rb: Any) -> np.ndarray:
    return np.array(tuple(rb.center_of_mass), dtype=np.float64)


@dataclass
class Run:
    """One body's run on one sea: its samples, one row per sample (see COLUMNS)."""

    body: str
    sea: Sea
    rest_draft: float
    samples: list[tuple[float, ...]] = field(default_factory=list)

    COLUMNS = ("t", "heave", "pitch", "eta", "slope", "draft", "speed", "spin", "drift", "force_x", "finite")

    def column(self, name: str, since: float | None = None) -> np.ndarray:
        """One column of the samples, from the time ``since`` on (s; all of them for ``None``)."""
        table = np.array(self.samples, dtype=np.float64).reshape(-1, len(self.COLUMNS))
        if since is not None:
            table = table[table[:, 0] >= since]
        return table[:, self.COLUMNS.index(name)]


def run_sea(
    sea: Sea, bodies: list[tuple[str, Callable[[Any, FloatingBodies, float], Any]]], seconds: float, settle: float
) -> list[Run]:
    """The bodies, 15 m apart across the waves, settled in still water for ``settle`` s, then on
    the ramped waves for ``seconds``."""
    world = rapier3d.PhysicsWorld(gravity=(0.0, -GRAVITY, 0.0))
    water = FloatingBodies.for_world(world)
    handles = [(name, add(world, water, 15.0 * i)) for i, (name, add) in enumerate(bodies)]
    for _ in range(round(settle * 60)):
        water.step(world)
    rests = []
    runs = []
    for name, h in handles:
        rb = world.rigid_bodies[h]
        mesh = water.mesh(h)
        assert mesh is not None
        translation = np.array(tuple(rb.translation))
        heights = (mesh.vertices @ rotation_matrix(rb).T + translation)[:, 1]
        keel = mesh.vertices[int(np.argmin(heights))]  # body frame
        rests.append((center_of_mass(rb), rotation_matrix(rb), keel))
        runs.append(Run(name, sea, -float(heights.min())))
    water.water = sea.ramped()
    water.time = 0.0
    dt = world.integration_parameters.dt
    every = round(1.0 / (SAMPLE_RATE * dt))
    for i in range(round(seconds / dt) + 1):
        if water.time >= RAMP and water.water.waves is not sea.waves:
            water.water = sea.water()  # full height: the Airy waves and their orbital velocity
        if i % every == 0:
            t = water.time
            for (_, h), (rest_center, rest_rotation, keel), run in zip(handles, rests, runs, strict=True):
                rb = world.rigid_bodies[h]
                run.samples.append(sample(rb, water.report(h), sea, t, rest_center, rest_rotation, keel))
        water.step(world)
    return runs


def sample(
    rb: Any, report: Any, sea: Sea, t: float, rest_center: np.ndarray, rest_rotation: np.ndarray, keel: np.ndarray
) -> tuple[float, ...]:
    com = center_of_mass(rb)
    rotation = rotation_matrix(rb)
    eta, slope = sea.elevation_and_slope(com, t)
    turned = (rotation @ rest_rotation.T) @ np.array([1.0, 0.0, 0.0])
    horizontal = (com - rest_center) * (1.0, 0.0, 1.0)
    draft = -float((rotation @ keel + np.array(tuple(rb.translation)))[1])
    velocity = np.array(tuple(rb.linvel))
    spin = np.array(tuple(rb.angvel))
    pose = np.concatenate([tuple(rb.translation), tuple(rb.rotation.quaternion), velocity, spin])
    return (
        t,
        float(com[1] - rest_center[1]),
        math.degrees(math.asin(float(np.clip(turned[1], -1.0, 1.0)))),
        eta,
        slope,
        draft,
        float(np.linalg.norm(velocity)),
        float(np.linalg.norm(spin)),
        float(np.linalg.norm(horizontal)),
        float(report.buoyancy_force[0]) if report is not None else math.nan,
        float(np.isfinite(pose).all()),
    )


# --- statistics, table, plot --------------------------------------------------------------------


def harmonic(t: np.ndarray, y: np.ndarray, omega: float) -> tuple[float, float]:
    """The amplitude and phase (degrees) of ``y ≈ A cos(ωt − φ) + C`` by least squares."""
    basis = np.column_stack([np.cos(omega * t), np.sin(omega * t), np.ones_like(t)])
    (a, b, _), *_ = np.linalg.lstsq(basis, y, rcond=None)
    return float(math.hypot(a, b)), math.degrees(math.atan2(b, a))


def wrap_degrees(a: float) -> float:
    """An angle difference (degrees) in (−180, 180]."""
    a = a % 360.0
    return a - 360.0 if a > 180.0 else a


@dataclass
class Stats:
    """What the table and the plot say of a run: over the statistics' window, and the bounds over
    the whole run."""

    eta_std: float
    heave_std: float
    #: Heave over η: amplitudes at the regular wave's frequency, else standard deviations.
    heave_ratio: float
    #: The heave's lag behind η at the body (degrees), on the regular wave.
    heave_lag: float | None
    pitch: tuple[float, float]
    slope: tuple[float, float]
    draft: float
    heave: float
    eta: float
    force_x: float
    max_speed: float
    drift: float
    verdict: str


def stats(run: Run, stats_from: float = STATS_FROM) -> Stats:
    """The figures of ``run`` over the samples from ``stats_from`` (s) on."""

    def col(name: str, window: bool = False) -> np.ndarray:
        return run.column(name, stats_from if window else None)

    t, heave, eta = col("t", True), col("heave", True), col("eta", True)
    if run.sea.omega is not None:
        (h, h_phase), (e, e_phase) = harmonic(t, heave, run.sea.omega), harmonic(t, eta, run.sea.omega)
        ratio, lag = h / e, wrap_degrees(h_phase - e_phase)
    else:
        ratio, lag = float(np.std(heave) / np.std(eta)), None
    max_heave = float(np.abs(col("heave")).max())
    max_speed, max_spin = float(col("speed").max()), float(col("spin").max())
    if not col("finite").all():
        verdict = "FAIL: not finite"
    elif max_heave > HEAVE_BOUND_HEIGHTS * run.sea.height:
        verdict = f"FAIL: heave {max_heave:.2f} m"
    elif max_speed > SPEED_BOUND:
        verdict = f"FAIL: speed {max_speed:.2f} m/s"
    elif max_spin > SPIN_BOUND:
        verdict = f"FAIL: spin {max_spin:.2f} rad/s"
    else:
        verdict = "ok"
    pitch, slope = col("pitch", True), col("slope", True)
    return Stats(
        eta_std=float(np.std(eta)),
        heave_std=float(np.std(heave)),
        heave_ratio=ratio,
        heave_lag=lag,
        pitch=(float(pitch.min()), float(pitch.max())),
        slope=(float(slope.min()), float(slope.max())),
        draft=float(np.mean(col("draft", True))),
        heave=float(np.mean(heave)),
        eta=float(np.mean(eta)),
        force_x=float(np.mean(col("force_x", True))),
        max_speed=max_speed,
        drift=float(col("drift")[-1]),
        verdict=verdict,
    )


def signed(value: float, decimals: int) -> str:
    """A signed number with a true minus sign."""
    return f"{value:+.{decimals}f}".replace("-", "−")


def table(runs: list[Run], stats_from: float = STATS_FROM) -> str:
    """The table of the runs, Markdown, the figures from ``stats_from`` (s) on."""
    lines = [
        "| sea | body | η at the body, std (m) | heave, std (m) | heave / η | heave lag (°) | pitch range (°) "
        "| slope range (°) | mean draft (rest) (m) | mean heave, η (mm) | largest speed (m/s) | drift (m) "
        "| mean wave force along x (N) | bounded |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for run in runs:
        s = stats(run, stats_from)
        lag = "—" if s.heave_lag is None else signed(s.heave_lag, 1)
        lines.append(
            f"| {run.sea.name} | {run.body} | {s.eta_std:.4f} | {s.heave_std:.4f} | {s.heave_ratio:.3f} | {lag} "
            f"| {signed(s.pitch[0], 1)} to {signed(s.pitch[1], 1)} | {signed(s.slope[0], 1)} to {signed(s.slope[1], 1)} "
            f"| {s.draft:.4f} ({run.rest_draft:.4f}) | {signed(s.heave * 1e3, 1)}, {signed(s.eta * 1e3, 1)} "
            f"| {s.max_speed:.2f} | {s.drift:.2f} | {signed(s.force_x, 2)} | {s.verdict} |"
        )
    return "\n".join(lines)


TITLES = {"hull": "Wigley hull 4 × 0.6 m", "bunny": "Stanford bunny 1.2 m", "buoy": "buoy 0.6 m across"}


def plot(
    runs: list[Run], sea_list: list[Sea], path: pathlib.Path, seconds: float, stats_from: float = STATS_FROM
) -> None:
    """Writes the PNG ``path``: a column per sea, two rows per body, the heave over η at the body
    and the pitch over the slope against time; the figures from ``stats_from`` (s) on."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = list(dict.fromkeys(r.body for r in runs))
    fig, axes = plt.subplots(
        2 * len(names), len(sea_list), figsize=(9 * len(sea_list), 3.2 * 2 * len(names)), sharex=True, squeeze=False
    )
    fig.suptitle(
        "Floating on waves in rapier3d (buoyancy.rapier): heave and pitch against the surface at each body\n"
        + "    ".join(s.title for s in sea_list)
        + f"\nthe bodies settle in still water; the waves, travelling along +x, grow over the first {RAMP:g} s; "
        f"figures over {stats_from:.3g}–{seconds:g} s",
        fontsize=11,
    )
    for column, sea in enumerate(sea_list):
        column_runs = [r for r in runs if r.sea is sea]
        heave_max = 1.1 * max(float(np.abs(np.r_[r.column("heave"), r.column("eta")]).max()) for r in column_runs)
        pitch_max = 1.1 * max(float(np.abs(np.r_[r.column("pitch"), r.column("slope")]).max()) for r in column_runs)
        for row, run in enumerate(column_runs):
            s = stats(run, stats_from)
            t = run.column("t")
            top, bottom = axes[2 * row, column], axes[2 * row + 1, column]
            heave = (
                f"heave {s.heave_ratio:.2f} × η, lag {signed(s.heave_lag, 0)}°"
                if s.heave_lag is not None
                else f"heave std {s.heave_ratio:.2f} × η std"
            )
            top.plot(t, run.column("eta"), color="black", lw=0.8, label="η: surface elevation at the body")
            top.plot(t, run.column("heave"), color="#006ec8", lw=1.6, label="heave of the center of mass")
            top.set_title(f"{TITLES[run.body]}, {sea.name}: {heave}", fontsize=10)
            top.set_ylabel("heave, η (m)")
            top.set_ylim(-max(heave_max, 1e-6), max(heave_max, 1e-6))
            bottom.plot(t, run.column("slope"), color="black", lw=0.8, label="the wave's slope angle at the body")
            bottom.plot(t, run.column("pitch"), color="#dc5014", lw=1.6, label="pitch (bow up +)")
            bottom.set_title(
                f"{TITLES[run.body]}, {sea.name}: pitch {signed(s.pitch[0], 1)}° to {signed(s.pitch[1], 1)}° "
                f"(slope {signed(s.slope[0], 1)}° to {signed(s.slope[1], 1)}°)",
                fontsize=10,
            )
            bottom.set_ylabel("pitch, slope (°)")
            bottom.set_ylim(-max(pitch_max, 1e-6), max(pitch_max, 1e-6))
            for ax in (top, bottom):
                ax.grid(color="#e1e1e1")
            if row == 0 and column == 0:
                top.legend(loc="upper right", fontsize=8)
                bottom.legend(loc="upper right", fontsize=8)
        axes[-1, column].set_xlabel("time since the waves started (s)")
    fig.tight_layout(rect=(0.0, 0.0, 1.0, 1.0 - 0.8 / fig.get_figheight()))  # room for the title
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=80)
    plt.close(fig)


def rest_check(
    seconds: float = REST_SECONDS, water: buoyancy.Water | None = None, stations: int = 41, waterlines: int = 17
) -> tuple[float, float, float, float]:
    """The hull placed at its design draft in ``water`` (default: still fresh water) for
    ``seconds``: its largest speed (m/s) and spin (rad/s), and how far it moved (m) and turned
    (degrees) from where it was placed."""
    mesh, density = hull_mesh(stations, waterlines)
    world = rapier3d.PhysicsWorld(gravity=(0.0, -GRAVITY, 0.0))
    water = FloatingBodies.for_world(world, water=water)
    h = add_hull(world, water, 0.0, mesh, density)
    rb = world.rigid_bodies[h]
    start, rotation = np.array(tuple(rb.translation)), rotation_matrix(rb)
    speed = spin = 0.0
    for _ in range(round(seconds * 60)):
        water.step(world)
        rb = world.rigid_bodies[h]
        speed = max(speed, float(np.linalg.norm(tuple(rb.linvel))))
        spin = max(spin, float(np.linalg.norm(tuple(rb.angvel))))
    drift = float(np.linalg.norm(np.array(tuple(rb.translation)) - start))
    cos = (np.trace(rotation_matrix(rb) @ rotation.T) - 1.0) / 2.0
    turn = math.degrees(math.acos(min(1.0, max(-1.0, float(cos)))))
    return speed, spin, drift, turn


def run(
    seconds: float = SECONDS, settle: float = SETTLE, sea_names: tuple[str, ...] = ("regular", "JONSWAP")
) -> tuple[list[Run], list[Sea], str | None]:
    """The three bodies on each sea (``sea_names``, of "regular" and "JONSWAP"), settled in still
    water for ``settle`` s, then on the waves for ``seconds``; the runs, the seas, and the note
    about the bunny (``None`` when it floats)."""
    hull, hull_density = hull_mesh()
    bunny, note = bunny_mesh()
    bodies: list[tuple[str, Callable[[Any, FloatingBodies, float], Any]]] = [
        ("hull", lambda world, water, z: add_hull(world, water, z, hull, hull_density))
    ]
    if bunny is not None:
        bodies.append(("bunny", lambda world, water, z: add_half_density(world, water, z, bunny)))
    bodies.append(("buoy", add_buoy))
    chosen = [sea for sea in seas() if sea.name in sea_names]
    runs = [r for sea in chosen for r in run_sea(sea, bodies, seconds, settle)]
    return runs, chosen, note


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=SECONDS, help=f"seconds of waves (default {SECONDS:g})")
    parser.add_argument("--out", type=pathlib.Path, default=REPO / "out" / "waves_rapier.png", help="the PNG to write")
    args = parser.parse_args()
    if not (math.isfinite(args.seconds) and args.seconds > RAMP):
        parser.error(f"--seconds: must be more than the waves' ramp, {RAMP:g} s; got {args.seconds:g}")
    # The statistics over the last two thirds of the waves at most (from 20 s of 60 on).
    stats_from = min(STATS_FROM, args.seconds / 3)
    started = time.perf_counter()
    speed, spin, drift, turn = rest_check()
    at_rest = speed < REST_SPEED and spin < REST_SPIN and drift < REST_DRIFT and turn < REST_TURN
    print(
        f"still water: the hull placed at its design draft, after {REST_SECONDS:g} s: largest speed {speed:.1e} m/s "
        f"(bound {REST_SPEED:.0e}), spin {spin:.1e} rad/s (bound {REST_SPIN:.0e}), drift {drift:.1e} m "
        f"(bound {REST_DRIFT:.0e}), turn {turn:.1e}° (bound {REST_TURN:g}°): {'at rest' if at_rest else 'FAIL'}\n"
    )
    runs, sea_list, note = run(args.seconds)
    if note:
        print(note)
    for sea in sea_list:
        print(f"{sea.name}: {sea.title}")
    print(
        f"{len(runs) // len(sea_list)} bodies, {SETTLE:g} s of still water then {args.seconds:g} s of waves "
        f"(ramped in over {RAMP:g} s), rapier at 60 Hz; statistics from {stats_from:.3g} s on\n"
    )
    print(table(runs, stats_from))
    print(
        "\nheave / η: on the regular wave, the amplitudes of the heave and of the elevation at the body at the wave's\n"
        "   frequency (least squares), and the heave's lag; on the JONSWAP sea, their standard deviations.\n"
        "pitch: the tilt of the body's line along the waves (bow up +); slope: the wave's slope angle at the body.\n"
        "draft: the depth below the still level of the body's lowest point at rest; in brackets, at rest.\n"
        f"bounded: every pose finite, |heave| ≤ {HEAVE_BOUND_HEIGHTS:g} wave heights (H = 2a, or Hs), "
        f"speed ≤ {SPEED_BOUND:g} m/s, spin ≤ {SPIN_BOUND:g} rad/s.\n"
    )
    plot(runs, sea_list, args.out, args.seconds, stats_from)
    print(f"wrote {args.out}")
    print(f"finished in {time.perf_counter() - started:.1f} s")


if __name__ == "__main__":
    main()
