"""buoyancy.rapier with rapier's Python binding (the rapier3d package).

The behaviours of the Rust adapter, specified by crates/buoyancy-rapier/tests/*.rs, hold here too:
each test below names the Rust test it ports. Both adapters are glue over the same controller
(buoyancy.Controller), so the numbers are the same physics; the Python adapter takes meshes where
the Rust one meshes rapier's colliders, so the shapes come from buoyancy.shapes or rapier's own
``to_trimesh``.

Registered without a mesh, a body floats with its colliders meshed as the Rust adapter meshes
them (rapier's own ``to_trimesh``, welded): ``test_every_supported_shape_floats`` runs both ways,
and ``test_colliders_become_parts`` holds the placement of translated, rotated and compound
colliders, a repeated collider floating once (several_parts.rs ``repeated_collider_floats_once``)
and the errors ``UnsupportedShape`` and ``NothingToFloat`` (floating.rs
``per_body_water_and_errors``).

Plus what is the Python adapter's own: the example settles within 1% of theory, the report
against the core at the body's pose, removed bodies, bad gravity, the module docstring, forces
beyond float32, and reading rapier's state without its ``to_bytes`` format.
"""

from __future__ import annotations

import importlib.util
import itertools
import math
import sys
import textwrap
import warnings
from typing import Any

import numpy as np
import pytest

import buoyancy

from conftest import REPO, quaternion_matrix, sample_mesh_or_fallback, skip_unless_ci

try:
    import rapier3d
except ImportError as error:  # not installed, or installed but not loadable here
    skip_unless_ci(
        f"rapier3d (rapier's Python binding, pip install rapier3d) cannot be imported ({error}); "
        "scripts/test.sh installs it when the package index allows"
    )
import buoyancy.rapier
from buoyancy.rapier import FloatingBodies, FloatReport

DT = 1.0 / 60.0
WATER_DENSITY = 1000.0
DYNAMIC = rapier3d.RigidBodyType.DYNAMIC
IDENTITY = (0.0, 0.0, 0.0, 1.0)


def vec(v: Any) -> np.ndarray:
    return np.array(tuple(v), dtype=np.float64)


def f32(v: Any) -> np.ndarray:
    return np.asarray(v, dtype=np.float64).astype(np.float32)


class Pool:
    """A rapier world (gravity −9.81 y, 60 Hz) with water at y = 0 (tests/common/mod.rs)."""

    def __init__(self, **settings: Any) -> None:
        self.world = rapier3d.PhysicsWorld(gravity=(0.0, -9.81, 0.0))
        self.water = FloatingBodies.for_world(self.world, **settings)

    def add(self, body: Any, colliders: Any, mesh: Any, **options: Any) -> Any:
        """Adds a dynamic body that never sleeps, and makes it float with ``mesh``."""
        colliders = colliders if isinstance(colliders, list) else [colliders]
        handle = self.world.add_body(body.can_sleep(False), colliders)
        self.water.register(handle, mesh, **options)
        return handle

    def apply(self) -> None:
        self.water.apply(self.world.rigid_bodies, self.world.integration_parameters.dt)

    def step(self) -> None:
        self.water.step(self.world)

    def run(self, seconds: float) -> None:
        for _ in range(round(seconds / self.world.integration_parameters.dt)):
            self.step()

    def body(self, handle: Any) -> Any:
        return self.world.rigid_bodies[handle]

    def half_density_cube(self, y: float = 0.0) -> Any:
        """A 1 m cube of density 500 kg/m³ centered at height ``y``: it floats half submerged."""
        return self.add(
            rapier3d.RigidBody.dynamic().translation((0.0, y, 0.0)),
            rapier3d.Collider.cuboid(0.5, 0.5, 0.5).density(500.0),
            buoyancy.shapes.cube(),
        )

    def own_wrench(self, handle: Any) -> tuple[np.ndarray, np.ndarray]:
        """The application's own force and torque: rapier's stored ones minus the report's."""
        r = self.water.report(handle)
        assert r is not None
        rb = self.body(handle)
        return vec(rb.user_force) - f32(r.force), vec(rb.user_torque) - f32(r.torque)

    def assert_equilibrium(self, handle: Any, size: float, what: str) -> None:
        """Submerged volume = m/ρ within 0.5 %, the center of buoyancy on the vertical through the
        center of mass within 1 % of ``size``, at rest."""
        self.apply()
        rb = self.body(handle)
        report = self.water.report(handle)
        expected = rb.mass / self.water.water.density
        error = abs(report.submerged_volume - expected) / expected
        assert error < 0.005, f"{what}: submerged {report.submerged_volume} m³ vs m/ρ = {expected} m³"
        up = self.water.water.normal
        offset = report.center_of_buoyancy - report.center_of_mass
        horizontal = np.linalg.norm(offset - up * (up @ offset))
        assert horizontal <= 0.01 * size, f"{what}: center of buoyancy {horizontal} m off the vertical"
        speed, spin = np.linalg.norm(vec(rb.linvel)), np.linalg.norm(vec(rb.angvel))
        assert speed < 0.02 and spin < 0.02, f"{what}: not at rest: v {speed}, ω {spin}"


def tilt_degrees(rb: Any) -> float:
    """The angle between the vertical and the body axis closest to it, degrees."""
    r = np.asarray(rb.rotation.to_matrix(), dtype=np.float64).reshape(3, 3)
    return math.degrees(math.acos(min(1.0, float(np.abs(r[1]).max()))))


def model(name: str, radius: float) -> tuple[str, buoyancy.Mesh]:
    """A sample mesh scaled to the bounding radius ``radius`` about its centroid, or the
    procedural torus knot when the file is absent (with a warning; under ``CI=true`` the test
    fails instead)."""
    path = sample_mesh_or_fallback(name, "the procedural torus knot")
    if path is None:
        label, mesh = "procedural torus knot", buoyancy.shapes.torus_knot(2, 3, 1.0, 0.3, 128, 12)
    else:
        label, mesh = name, buoyancy.load(path)
    k = radius / mesh.bounding_radius
    return label, buoyancy.Mesh((mesh.vertices - mesh.centroid) * k, mesh.faces)


def trimesh(mesh: buoyancy.Mesh) -> Any:
    return rapier3d.Collider.trimesh(mesh.vertices.astype(np.float32), mesh.faces.astype(np.uint32))


def rapier_mesh(shape: Any, *subdivisions: int) -> buoyancy.Mesh:
    """The mesh rapier makes of one of its shapes."""
    vertices, faces = shape.to_trimesh(*subdivisions)
    return buoyancy.Mesh(vertices, faces)


def unit_cube(s: float) -> Any:
    return rapier3d.Collider.cuboid(0.5, 0.5, 0.5).density(s * WATER_DENSITY)


def pose(translation: tuple[float, float, float], *rotations: Any) -> Any:
    rotation = rapier3d.Rotation3.identity()
    for r in rotations:
        rotation = rotation * r
    return rapier3d.RigidBody.dynamic().position((translation, rotation))


def axis_angle(axis: Any, angle: float) -> Any:
    axis = np.asarray(axis, dtype=np.float64)
    return rapier3d.Rotation3.from_axis_angle(tuple(axis / np.linalg.norm(axis)), angle)


# --- floating.rs ------------------------------------------------------------------------------


@pytest.mark.parametrize("s", [0.1, 0.9])
def test_cube_upright_when_stable(s: float) -> None:
    # floating.rs cube_upright_when_stable: GM = s/2 + 1/(12 s) − 1/2 > 0.
    pool = Pool()
    h = pool.add(pose((0.0, 0.8, 0.0), axis_angle((1, 0, 1), 0.1)), unit_cube(s), buoyancy.shapes.cube())
    pool.run(40.0)
    rb = pool.body(h)
    assert s / 2 + 1 / (12 * s) - 0.5 > 0
    assert tilt_degrees(rb) < 0.5, f"s = {s}: tilt {tilt_degrees(rb)}°"
    draft = 0.5 - rb.translation.y
    assert abs(draft - s) < 0.005 * max(s, 0.1) + 1e-4, f"s = {s}: draft {draft}"
    pool.assert_equilibrium(h, 1.0, f"cube s = {s}")


@pytest.mark.parametrize("s", [0.25, 0.5, 0.75])
def test_cube_tips_when_upright_is_unstable(s: float) -> None:
    # floating.rs cube_tips_when_upright_is_unstable.
    assert s / 2 + 1 / (12 * s) - 0.5 < 0
    pool = Pool()
    h = pool.add(
        pose((0.0, 0.5 - s, 0.0), axis_angle((1, 0, 0.3), math.radians(3))), unit_cube(s), buoyancy.shapes.cube()
    )
    pool.run(60.0)
    assert tilt_degrees(pool.body(h)) > 10.0, f"s = {s}: still upright"
    pool.assert_equilibrium(h, 1.0, f"tipped cube s = {s}")


@pytest.mark.parametrize("s", [0.25, 0.5, 0.8])
def test_sphere_at_the_analytic_cap_height(s: float) -> None:
    # floating.rs sphere_at_the_analytic_cap_height: π d² (3R − d)/3 = s·4πR³/3.
    radius = 0.5
    pool = Pool()
    h = pool.add(
        rapier3d.RigidBody.dynamic().translation((0.0, 1.0, 0.0)),
        rapier3d.Collider.ball(radius).density(s * WATER_DENSITY),
        buoyancy.shapes.uv_sphere(radius, 96, 48),
    )
    pool.run(60.0)
    target = 4.0 * s * radius**3
    lo, hi = 0.0, 2.0 * radius
    for _ in range(100):
        d = (lo + hi) / 2
        lo, hi = (d, hi) if d * d * (3 * radius - d) < target else (lo, d)
    y = pool.body(h).translation.y
    assert abs(y - (radius - lo)) < 0.01 * radius, f"s = {s}: center at {y} m, analytic {radius - lo} m"
    pool.assert_equilibrium(h, 2 * radius, f"sphere s = {s}")


def test_long_flat_box_floats_flat() -> None:
    # floating.rs long_flat_box_floats_flat: 2 × 0.2 × 0.5 m, 500 kg/m³.
    pool = Pool()
    h = pool.add(
        pose((0.0, 0.5, 0.0), axis_angle((1, 0, 0), 0.2), axis_angle((0, 0, 1), 0.1)),
        rapier3d.Collider.cuboid(1.0, 0.1, 0.25).density(500.0),
        buoyancy.shapes.cube().scaled((2.0, 0.2, 0.5)),
    )
    pool.run(60.0)
    rb = pool.body(h)
    up = np.asarray(rb.rotation.to_matrix(), dtype=np.float64).reshape(3, 3)[:, 1]
    assert up[1] > min(0.9999, math.cos(math.radians(1))) or up[1] < -0.9998, f"thin axis not vertical: {up}"
    assert abs(rb.translation.y) < 0.002
    pool.assert_equilibrium(h, 2.0, "flat box")


@pytest.mark.parametrize(("name", "s"), [("bunny.obj", 0.6), ("torusknot.obj", 0.4)])
def test_bunny_and_torus_knot_equilibrium(name: str, s: float) -> None:
    # floating.rs bunny_and_torus_knot_equilibrium.
    label, mesh = model(name, 0.4)
    pool = Pool()
    h = pool.add(
        rapier3d.RigidBody.dynamic().translation((0.0, 0.5, 0.0)), trimesh(mesh).density(s * WATER_DENSITY), mesh
    )
    pool.run(60.0)
    pool.assert_equilibrium(h, 0.8, label)


def test_denser_body_sinks() -> None:
    # floating.rs denser_body_sinks, at the terminal velocity (s − 1)ρgV = c₁u + ½ρC_D u².
    pool = Pool()
    h = pool.add(rapier3d.RigidBody.dynamic().translation((0.0, 1.0, 0.0)), unit_cube(1.5), buoyancy.shapes.cube())
    pool.run(10.0)
    rb = pool.body(h)
    assert rb.translation.y < -5.0
    v = rb.linvel.y
    assert v < 0 and math.isfinite(v)
    net, c1, c2 = 0.5 * 1000.0 * 9.81, 1000.0, 500.0
    u = (-c1 + math.sqrt(c1 * c1 + 4 * c2 * net)) / (2 * c2)
    assert abs(v + u) < 0.05 * u, f"sinks at {-v} m/s, terminal {u} m/s"


def test_spawned_deep_rises_and_settles() -> None:
    # floating.rs spawned_deep_rises_and_settles.
    pool = Pool()
    h = pool.add(rapier3d.RigidBody.dynamic().translation((0.0, -10.0, 0.0)), unit_cube(0.9), buoyancy.shapes.cube())
    highest = -math.inf
    for _ in range(60 * 60):
        pool.step()
        y = pool.body(h).translation.y
        highest = max(highest, y)
        assert math.isfinite(y)
    assert highest > -0.5 + 0.1, f"never reached the surface: highest {highest}"
    y = pool.body(h).translation.y
    assert abs(y - (0.5 - 0.9)) < 0.005, f"settled at {y}, tilt {tilt_degrees(pool.body(h))}°"
    pool.assert_equilibrium(h, 1.0, "cube spawned deep")


def test_extreme_spawns_stay_finite() -> None:
    # floating.rs extreme_spawns_stay_finite: dropped fast, far above, very deep.
    pool = Pool()
    fast = pool.add(
        rapier3d.RigidBody.dynamic().translation((0.0, 2.0, 0.0)).linvel((3.0, -80.0, 0.0)),
        unit_cube(0.1),
        buoyancy.shapes.cube(),
    )
    light_deep = pool.add(
        rapier3d.RigidBody.dynamic().translation((5.0, -200.0, 0.0)).angvel((20.0, 0.0, 5.0)),
        rapier3d.Collider.ball(0.05).density(10.0),
        buoyancy.shapes.uv_sphere(0.05, 32, 16),
    )
    above = pool.add(
        rapier3d.RigidBody.dynamic().translation((-5.0, 1000.0, 0.0)), unit_cube(0.5), buoyancy.shapes.cube()
    )
    for step in range(60 * 20):
        pool.step()
        if step == 60:
            r = pool.water.report(above)
            assert r.buoyancy_force.tolist() == [0, 0, 0] and r.damping_force.tolist() == [0, 0, 0]
        for h in (fast, light_deep, above):
            rb = pool.body(h)
            state = np.concatenate([vec(rb.translation), vec(rb.linvel), vec(rb.angvel)])
            assert np.isfinite(state).all()
            assert np.linalg.norm(vec(rb.linvel)) < 200.0
    assert abs(pool.body(fast).translation.y) < 1.0


def test_user_thrust_survives_steps() -> None:
    # floating.rs user_thrust_survives_steps, then unregister leaves exactly the user's forces.
    pool = Pool()
    h = pool.add(rapier3d.RigidBody.dynamic(), unit_cube(0.5), buoyancy.shapes.cube())
    pool.run(5.0)
    thrust, torque = np.array([200.0, 0.0, 0.0]), np.array([0.0, 5.0, 0.0])
    pool.body(h).add_force(tuple(thrust), True)
    pool.body(h).add_torque(tuple(torque), True)
    x0 = pool.body(h).translation.x
    for _ in range(600):
        pool.step()
        own_force, own_torque = pool.own_wrench(h)
        assert np.linalg.norm(own_force - thrust) < 1e-3 * 200.0 + 1e-2, own_force
        assert np.linalg.norm(own_torque - torque) < 1e-3 * 5.0 + 1e-2, own_torque
    rb = pool.body(h)
    assert rb.translation.x - x0 > 2.0 and rb.angvel.y > 0.0
    assert pool.water.unregister(h, pool.world.rigid_bodies)
    assert np.linalg.norm(vec(pool.body(h).user_force) - thrust) < 1e-2
    assert np.linalg.norm(vec(pool.body(h).user_torque) - torque) < 1e-3


def test_per_body_water_and_method() -> None:
    # floating.rs per_body_water_and_errors (its errors: see the module docstring).
    pool = Pool()
    raised = buoyancy.Water(gravity=pool.water.water.gravity, level=2.0)
    high = pool.add(
        rapier3d.RigidBody.dynamic().translation((0.0, 3.0, 0.0)),
        unit_cube(0.5),
        buoyancy.shapes.cube(),
        water=raised,
        method="exact_surface",
    )
    low = pool.add(rapier3d.RigidBody.dynamic().translation((3.0, 1.0, 0.0)), unit_cube(0.5), buoyancy.shapes.cube())
    pool.run(20.0)
    assert abs(pool.body(high).translation.y - 2.0) < 0.005
    assert abs(pool.body(low).translation.y) < 0.005


@pytest.mark.parametrize("source", ["given meshes", "colliders"])
def test_every_supported_shape_floats(source: str) -> None:
    # floating.rs every_supported_shape_floats, with the meshes rapier makes of its shapes (given,
    # or made by register from the colliders): they float with the volume rapier gives them
    # (rapier's mass uses the exact round volumes).
    hull_points = [(-0.4, -0.3, -0.3), (0.4, -0.3, -0.3), (0.0, 0.4, -0.3), (0.0, 0.0, 0.4)]
    hull = rapier3d.SharedShape.convex_hull(hull_points)
    compound = [
        (((-0.4, 0.0, 0.0), IDENTITY), rapier3d.SharedShape.cuboid(0.2, 0.2, 0.2)),
        (((0.4, 0.0, 0.0), IDENTITY), rapier3d.SharedShape.ball(0.25)),
    ]
    compound_parts = [
        (buoyancy.shapes.cube().scaled(0.4), (-0.4, 0.0, 0.0), IDENTITY),
        (rapier_mesh(rapier3d.Ball(0.25), 64, 32), (0.4, 0.0, 0.0), IDENTITY),
    ]
    shapes = [
        ("cylinder", rapier3d.Collider.cylinder(0.3, 0.2), rapier_mesh(rapier3d.Cylinder(0.3, 0.2), 64)),
        (
            "capsule",
            rapier3d.Collider.capsule_y(0.3, 0.2),
            rapier_mesh(rapier3d.Capsule((0, -0.3, 0), (0, 0.3, 0), 0.2), 64, 32),
        ),
        ("cone", rapier3d.Collider.cone(0.3, 0.3), rapier_mesh(rapier3d.Cone(0.3, 0.3), 64)),
        ("convex hull", rapier3d.Collider.convex_hull(hull_points), rapier_mesh(hull.as_convex_polyhedron())),
        ("compound", rapier3d.Collider.compound(compound), compound_parts),
    ]
    for name, collider, mesh in shapes:
        pool = Pool()
        if source == "given meshes":
            h = pool.add(rapier3d.RigidBody.dynamic().translation((0.0, 0.5, 0.0)), collider.density(600.0), mesh)
        else:
            h = pool.add(
                rapier3d.RigidBody.dynamic().translation((0.0, 0.5, 0.0)),
                collider.density(600.0),
                None,
                subdivisions=64,
            )
            given = mesh if isinstance(mesh, list) else [mesh]
            made = pool.water.parts(h)
            assert made is not None
            for (made_mesh, position, _), part in zip(made, given, strict=True):
                given_mesh, given_position = (part, (0.0, 0.0, 0.0)) if isinstance(part, buoyancy.Mesh) else part[:2]
                assert made_mesh.volume == pytest.approx(given_mesh.volume, rel=1e-6), name
                np.testing.assert_allclose(position, given_position, atol=1e-7)
        pool.run(40.0)
        pool.apply()
        rb = pool.body(h)
        expected = rb.mass / 1000.0
        submerged = pool.water.report(h).submerged_volume
        assert abs(submerged - expected) < 0.01 * expected, f"{name}: {submerged} vs {expected}"
        assert np.linalg.norm(vec(rb.linvel)) < 0.01, f"{name} still moves"


def test_colliders_become_parts() -> None:
    pool = Pool()
    turn = axis_angle((1.0, 2.0, 3.0), 0.7)
    nested = rapier3d.SharedShape.compound(
        [(((0.0, 1.0, 0.0), tuple(turn.to_tuple())), rapier3d.SharedShape.cuboid(0.1, 0.2, 0.3))]
    )
    colliders = [
        rapier3d.Collider.cuboid(0.5, 0.25, 0.125).translation((1.0, 2.0, 3.0)).rotation(tuple(turn.scaled_axis)),
        rapier3d.Collider.new(nested).translation((-1.0, 0.0, 0.0)).rotation(tuple(turn.scaled_axis)),
        rapier3d.Collider.ball(0.3),
    ]
    handle = pool.world.add_body(rapier3d.RigidBody.dynamic(), colliders)
    pool.water.register(handle)
    parts = pool.water.parts(handle)
    assert parts is not None and len(parts) == 3
    # Each box placed on the body has its corners where rapier's own poses put them: the
    # collider's pose on the body, then (in the compound) the shape's pose in the collider.
    rb = pool.body(handle)
    first, second = (pool.world.colliders[c].position_wrt_parent for c in rb.colliders[:2])
    ((sub_pose, _),) = pool.world.colliders[rb.colliders[1]].shape.as_compound().shapes()
    signs = np.array(list(itertools.product((-1.0, 1.0), repeat=3)))
    for (mesh, position, quaternion), iso, half in zip(
        parts[:2], [first, second * sub_pose], [(0.5, 0.25, 0.125), (0.1, 0.2, 0.3)], strict=True
    ):
        placed = mesh.vertices @ quaternion_matrix(quaternion).T + position
        corners = np.array([vec(iso.transform_point(tuple(c))) for c in signs * half])
        assert len(placed) == 8
        distances = np.linalg.norm(placed[:, None, :] - corners[None, :, :], axis=2)
        assert distances.min(axis=0).max() < 2e-6 and distances.min(axis=1).max() < 2e-6
    assert parts[0][0].volume == pytest.approx(0.125, rel=1e-6)
    # The ball: rapier's inscribed tessellation, a little less than the ball.
    assert 0.98 < parts[2][0].volume / (4 / 3 * math.pi * 0.027) < 1.0
    # Equal shapes share one mesh.
    other = pool.world.add_body(rapier3d.RigidBody.dynamic(), [rapier3d.Collider.ball(0.3)])
    pool.water.register(other)
    assert pool.water.parts(other)[0][0] is parts[2][0]  # type: ignore[index]
    # several_parts.rs repeated_collider_floats_once: a collider listed twice floats once.
    cube = pool.world.add_body(rapier3d.RigidBody.dynamic(), [rapier3d.Collider.cuboid(0.5, 0.5, 0.5)])
    (c,) = pool.body(cube).colliders
    pool.water.register(cube, colliders=[c, c])
    pool.apply()
    assert len(pool.water.parts(cube)) == 1  # type: ignore[arg-type]
    assert pool.water.report(cube).submerged_volume == pytest.approx(0.5, abs=1e-6)  # type: ignore[union-attr]
    # floating.rs per_body_water_and_errors: UnsupportedShape and NothingToFloat.
    ground = pool.world.add_body(rapier3d.RigidBody.fixed(), [rapier3d.Collider.halfspace((0.0, 1.0, 0.0))])
    with pytest.raises(ValueError, match=r"halfspace shape, which cannot float.*mesh="):
        pool.water.register(ground)
    empty = pool.world.add_body(rapier3d.RigidBody.dynamic(), [])
    with pytest.raises(ValueError, match="has no collider to float with"):
        pool.water.register(empty)
    with pytest.raises(ValueError, match="is attached to"):
        pool.water.register(cube, colliders=[pool.body(handle).colliders[0]])
    with pytest.raises(ValueError, match="subdivisions"):
        pool.water.register(cube, subdivisions=-1)
    assert ground not in pool.water and empty not in pool.water
    # Without a world to read the colliders from, register says what to pass.
    alone = FloatingBodies()
    with pytest.raises(TypeError, match="world: register.body. without a mesh"):
        alone.register(cube)
    alone.register(cube, world=pool.world)
    assert cube in alone


def mechanical_energy(pool: Pool, handles: list[Any]) -> float:
    """Kinetic + gravitational + hydrostatic (−ρ g V_sub h_B) energy of the bodies."""
    pool.apply()
    water = pool.water.water
    up, level, g = water.normal, water.level, water.gravity
    total = 0.0
    for h in handles:
        rb, r = pool.body(h), pool.water.report(h)
        total += rb.kinetic_energy() + rb.mass * g * (up @ r.center_of_mass - level)
        total -= water.density * g * r.submerged_volume * (up @ r.center_of_buoyancy - level)
    return total


def test_hundred_mixed_bodies_settle() -> None:
    # floating.rs hundred_mixed_bodies_settle: 20 s without a NaN, the energy decays.
    pool = Pool()
    _, bunny = model("bunny.obj", 0.3)
    seed = 12345

    def random() -> float:
        nonlocal seed
        seed = (seed * 6364136223846793005 + 1442695040888963407) % 2**64
        return (seed >> 11) / 2**53

    cube, ball = buoyancy.shapes.cube(), rapier_mesh(rapier3d.Ball(0.25), 16, 8)
    kinds = [
        (rapier3d.Collider.cuboid(0.3, 0.2, 0.25), cube.scaled((0.6, 0.4, 0.5))),
        (rapier3d.Collider.ball(0.25), ball),
        (rapier3d.Collider.cylinder(0.2, 0.2), rapier_mesh(rapier3d.Cylinder(0.2, 0.2), 16)),
        (
            rapier3d.Collider.capsule_y(0.15, 0.15),
            rapier_mesh(rapier3d.Capsule((0, -0.15, 0), (0, 0.15, 0), 0.15), 16, 8),
        ),
        (rapier3d.Collider.cone(0.25, 0.25), rapier_mesh(rapier3d.Cone(0.25, 0.25), 16)),
        (
            rapier3d.Collider.compound(
                [
                    (((-0.2, 0.0, 0.0), IDENTITY), rapier3d.SharedShape.cuboid(0.15, 0.15, 0.15)),
                    (((0.2, 0.0, 0.0), IDENTITY), rapier3d.SharedShape.ball(0.15)),
                ]
            ),
            [(cube.scaled(0.3), (-0.2, 0.0, 0.0), IDENTITY), (ball.scaled(0.6), (0.2, 0.0, 0.0), IDENTITY)],
        ),
        (trimesh(bunny), bunny),
    ]
    handles = []
    for i in range(100):
        s = 0.2 + 0.7 * random()
        collider, mesh = kinds[i % 7]
        position = ((i % 10) * 1.5 - 7.0, 1.0 + 4.0 * random(), (i // 10) * 1.5 - 7.0)
        rotation = tuple(2.0 * random() for _ in range(3))
        body = rapier3d.RigidBody.dynamic().translation(position).rotation(rotation).linvel((0.0, -3.0 * random(), 0.0))
        handles.append(pool.add(body, collider.density(s * WATER_DENSITY), mesh))
    energies = []
    for second in range(1, 21):
        pool.run(1.0)
        for h in handles:
            rb = pool.body(h)
            assert np.isfinite(np.concatenate([vec(rb.translation), vec(rb.linvel), vec(rb.angvel)])).all(), second
        if second >= 5:
            energies.append(mechanical_energy(pool, handles))
            for h in handles:
                assert pool.water.report(h).submerged_volume > 0, f"a body is out of the water at {second} s"
    assert all(b < a for a, b in itertools.pairwise(energies)), f"energy rose: {energies}"


# --- applied_share.rs -------------------------------------------------------------------------


@pytest.mark.parametrize(
    "other",
    [
        rapier3d.RigidBodyType.KINEMATIC_POSITION_BASED,
        rapier3d.RigidBodyType.KINEMATIC_VELOCITY_BASED,
        rapier3d.RigidBodyType.FIXED,
    ],
)
def test_body_type_round_trip_keeps_one_buoyancy(other: Any) -> None:
    # applied_share.rs body_type_round_trip_keeps_one_buoyancy.
    pool = Pool()
    h = pool.half_density_cube(0.0)
    pool.run(3.0)
    pool.body(h).body_type = other
    pool.run(0.5)
    pool.body(h).body_type = DYNAMIC
    pool.apply()
    own_force, own_torque = pool.own_wrench(h)
    assert np.linalg.norm(own_force) < 1.0 and np.linalg.norm(own_torque) < 1.0, (own_force, own_torque)
    assert abs(pool.body(h).user_force.y - 4905.0) < 50.0
    pool.run(3.0)
    assert abs(pool.body(h).translation.y) < 0.05


def test_unregister_while_kinematic_takes_the_share_off() -> None:
    # applied_share.rs unregister_while_kinematic_takes_the_share_off.
    pool = Pool()
    h = pool.half_density_cube(0.0)
    pool.run(1.0)
    kinematic = rapier3d.RigidBodyType.KINEMATIC_POSITION_BASED
    pool.body(h).body_type = kinematic
    pool.step()
    pool.body(h).sleep()
    assert pool.water.unregister(h, pool.world.rigid_bodies)
    assert pool.body(h).body_type == kinematic and pool.body(h).is_sleeping
    pool.body(h).body_type = DYNAMIC
    assert np.linalg.norm(vec(pool.body(h).user_force)) < 1e-2, pool.body(h).user_force
    assert np.linalg.norm(vec(pool.body(h).user_torque)) < 1e-2


def test_quarantined_body_gets_no_phantom_force() -> None:
    # applied_share.rs quarantined_body_gets_no_phantom_force.
    pool = Pool()
    h = pool.half_density_cube(0.0)
    pool.run(3.0)
    pool.body(h).add_force((math.nan, 0.0, 0.0), True)
    pool.step()
    assert list(pool.world.quarantine.bodies) == [h]
    pool.step()
    assert not pool.body(h).is_enabled
    assert np.linalg.norm(vec(pool.body(h).user_force)) < 1e-3
    pool.body(h).is_enabled = True
    pool.run(3.0)
    own_force, _ = pool.own_wrench(h)
    assert np.linalg.norm(own_force) < 1.0, own_force
    assert abs(pool.body(h).translation.y) < 0.02


# --- damping_stability.rs ---------------------------------------------------------------------


def test_damping_keeps_the_drag_moment_and_its_line_of_action() -> None:
    # damping_stability.rs damping_keeps_the_drag_moment_and_its_line_of_action.
    pool = Pool()
    h = pool.half_density_cube(0.0)
    pool.body(h).linvel = (2.0, 0.0, 0.0)
    pool.apply()
    r = pool.water.report(h)
    mesh = pool.water.mesh(h)
    core = mesh.damping(
        (0.0, pool.body(h).translation.y, 0.0), None, (2.0, 0.0, 0.0), None, pool.water.water, pool.water.damping
    )
    # Sideways drag on the wetted lower half of the front face: −2000 N, moment −500 N·m.
    assert abs(core.force[0] + 2000.0) < 1.0 and abs(core.torque[2] + 500.0) < 1.0
    assert r.damping_torque[2] < -0.8 * 500.0
    s = r.damping_force[0] / core.force[0]
    assert 0.8 < s <= 1 + 1e-9
    assert np.linalg.norm(r.damping_torque - core.torque * s) < 1e-6 * 500.0

    # Spinning in place at the floating height: the drag force of the paddling faces is kept.
    pool = Pool()
    h = pool.half_density_cube(0.0)
    pool.body(h).angvel = (0.0, 0.0, 3.0)
    pool.apply()
    r = pool.water.report(h)
    core = pool.water.mesh(h).damping(None, None, None, (0.0, 0.0, 3.0), pool.water.water, pool.water.damping)
    assert np.linalg.norm(core.force) > 100.0
    s = r.damping_torque[2] / core.torque[2]
    assert 0.3 < s <= 1 + 1e-9
    assert np.linalg.norm(r.damping_force - core.force * s) < 1e-6 * np.linalg.norm(core.force)


def test_light_ball_rises_at_the_model_terminal_velocity() -> None:
    # damping_stability.rs light_ball_rises_at_the_model_terminal_velocity.
    pool = Pool()
    mesh = buoyancy.shapes.uv_sphere(0.05, 32, 16)
    h = pool.add(
        rapier3d.RigidBody.dynamic().translation((0.0, -200.0, 0.0)), rapier3d.Collider.ball(0.05).density(10.0), mesh
    )
    pool.run(2.0)
    y0 = pool.body(h).translation.y
    pool.run(2.0)
    speed = (pool.body(h).translation.y - y0) / 2.0
    water = pool.water.water

    def drag(v: float) -> float:
        d = mesh.damping((0.0, -100.0, 0.0), None, (0.0, v, 0.0), None, water, pool.water.damping)
        return float(d.force[1])

    net = water.specific_weight * mesh.volume - pool.body(h).mass * water.gravity
    assert net > 0
    lo, hi = 0.0, 100.0
    for _ in range(100):
        v = (lo + hi) / 2
        lo, hi = (v, hi) if -drag(v) < net else (lo, v)
    assert abs(lo - 0.76) < 0.05, f"model terminal velocity {lo}"
    assert abs(speed - lo) < 0.03 * lo, f"rises at {speed} m/s, the model's terminal velocity is {lo} m/s"


# --- outcomes.rs ------------------------------------------------------------------------------


def test_report_outcome_follows_the_body() -> None:
    # outcomes.rs report_outcome_follows_the_body.
    pool = Pool()
    h = pool.half_density_cube(0.0)
    assert pool.water.report(h).outcome == "not_evaluated"
    pool.run(1.0)
    report = pool.water.report(h)
    assert report.outcome == "applied" and report.buoyancy_force[1] > 4000.0
    held = vec(pool.body(h).user_force)

    # Kinematic: nothing computed, the share left as it is.
    pool.body(h).body_type = rapier3d.RigidBodyType.KINEMATIC_POSITION_BASED
    pool.apply()
    report = pool.water.report(h)
    assert report.outcome == "inactive" and report.buoyancy_force[1] == 0.0
    assert report.center_of_buoyancy.tolist() == report.center_of_mass.tolist()
    pool.body(h).body_type = DYNAMIC
    assert vec(pool.body(h).user_force).tolist() == held.tolist()

    # A NaN velocity: no force, the share taken back.
    pool.body(h).linvel = (math.nan, 0.0, 0.0)
    pool.apply()
    report = pool.water.report(h)
    assert report.outcome == "not_finite" and report.buoyancy_force[1] == 0.0
    assert np.linalg.norm(vec(pool.body(h).user_force)) < 1e-3

    # Finite again: the whole share comes back.
    pool.body(h).linvel = (0.0, 0.0, 0.0)
    pool.apply()
    assert pool.water.report(h).outcome == "applied"
    assert abs(pool.body(h).user_force.y - held[1]) < 0.01 * held[1]

    # A rotation that is not finite: the same.
    rotation = pool.body(h).rotation
    pool.body(h).rotation = rapier3d.Rotation3(math.nan, 0.0, 0.0, 0.0)
    pool.apply()
    assert pool.water.report(h).outcome == "not_finite"
    assert np.linalg.norm(vec(pool.body(h).user_force)) < 1e-3
    pool.body(h).rotation = rotation
    pool.apply()
    assert pool.water.report(h).outcome == "applied"


# --- several_parts.rs -------------------------------------------------------------------------


def test_registering_again_replaces_the_meshes() -> None:
    # The Python counterpart of several_parts.rs repeated_collider_floats_once: a body
    # registered twice floats once, with its last meshes.
    pool = Pool()
    h = pool.half_density_cube(0.0)
    pool.water.register(h, buoyancy.shapes.cube())
    pool.apply()
    assert len(pool.water) == 1 and len(pool.water.parts(h)) == 1
    assert pool.water.report(h).submerged_volume == pytest.approx(0.5, abs=1e-9)
    assert pool.body(h).user_force.y == pytest.approx(4905.0, rel=1e-6)


def test_angular_damping_of_a_body_split_into_parts() -> None:
    # several_parts.rs angular_damping_of_a_body_split_into_parts: a cube split into 8 parts is
    # damped like the cube.
    pool = Pool(damping=buoyancy.DampingCoefficients(0.0, 0.0, 0.1, 0.1))
    omega = (0.3, 1.0, -0.5)
    whole = pool.add(
        rapier3d.RigidBody.dynamic().translation((0.0, -5.0, 0.0)).angvel(omega), unit_cube(1.0), buoyancy.shapes.cube()
    )
    corners = [tuple(0.25 if i & bit else -0.25 for bit in (1, 2, 4)) for i in range(8)]
    split = pool.add(
        rapier3d.RigidBody.dynamic().translation((5.0, -5.0, 0.0)).angvel(omega),
        rapier3d.Collider.compound(
            [((c, IDENTITY), rapier3d.SharedShape.cuboid(0.25, 0.25, 0.25)) for c in corners]
        ).density(1000.0),
        [(buoyancy.shapes.cube().scaled(0.5), c, IDENTITY) for c in corners],
    )
    pool.apply()
    a, b = pool.water.report(whole).damping_torque, pool.water.report(split).damping_torque
    assert np.linalg.norm(a) > 10.0, a
    assert np.linalg.norm(a - b) < 1e-4 * np.linalg.norm(a), (a, b)


# --- sleeping.rs ------------------------------------------------------------------------------


def test_sleeping_body_wakes_for_a_slowly_rising_tide() -> None:
    # sleeping.rs sleeping_body_wakes_for_a_slowly_rising_tide: 0.5 mm per step, each step's
    # change far below the waking threshold.
    pool = Pool()
    h = pool.world.add_body(rapier3d.RigidBody.dynamic(), [rapier3d.Collider.cuboid(0.5, 0.5, 0.5).density(500.0)])
    pool.water.register(h, buoyancy.shapes.cube())
    pool.run(10.0)
    assert pool.body(h).is_sleeping, "the cube should have fallen asleep"
    gravity, level = pool.water.water.gravity, 0.0
    for _ in range(600):
        level += 0.0005
        pool.water.water = buoyancy.Water(gravity=gravity, level=level)
        pool.step()
    pool.run(5.0)
    y = pool.body(h).translation.y
    assert abs(y - level) < 0.02, f"the cube is at {y} m, the water at {level} m"


# --- world_water.rs ---------------------------------------------------------------------------


def test_water_is_up_against_gravity() -> None:
    water = FloatingBodies((0.0, 0.0, -3.0)).water
    assert water.normal.tolist() == [0.0, 0.0, 1.0] and water.gravity == 3.0
    water = FloatingBodies((0.0, -9.81, 0.0)).water
    assert water.normal[1] == 1.0 and abs(water.gravity - 9.81) < 1e-6


def test_zero_gravity_keeps_y_up() -> None:
    water = FloatingBodies((0.0, 0.0, 0.0)).water
    assert water.normal[1] == 1.0 and water.gravity == 0.0


@pytest.mark.parametrize(
    "gravity, match",
    [
        ((0.0, float("nan"), 0.0), r"^gravity: has a NaN or infinite component: \(0.0, nan, 0.0\)$"),
        ((0.0, -float("inf"), 0.0), "^gravity: has a NaN or infinite component"),
        ((float("inf"), -9.81, 0.0), "^gravity: has a NaN or infinite component"),
        ((1.5e308, 1.5e308, 0.0), "^gravity: too large, its magnitude overflows"),
        ((0.0, -9.81), r"^gravity: expected 3 numbers, the gravity vector in m/s², got shape \(2,\)$"),
        (-9.81, r"^gravity: expected 3 numbers, the gravity vector in m/s², got shape \(\)$"),
        ("down", "^gravity: expected 3 numbers, the gravity vector in m/s²"),
    ],
)
def test_invalid_gravity_is_a_value_error_naming_it(gravity: Any, match: str) -> None:
    # world_water.rs non_finite_gravity_is_an_error, and shapes that are not a vector.
    with pytest.raises(ValueError, match=match):
        FloatingBodies(gravity)
    # Even when the water is given, so that gravity is not used to build it.
    with pytest.raises(ValueError, match=match):
        FloatingBodies(gravity, water=buoyancy.Water())
    world = rapier3d.PhysicsWorld(gravity=(0.0, -9.81, 0.0))
    if np.shape(gravity) == (3,):  # a world's gravity is always a vector (of float32)
        world.gravity = tuple(gravity)
        with pytest.raises(ValueError, match="^gravity: "):
            FloatingBodies.for_world(world)


# --- the Python adapter's own -----------------------------------------------------------------


def load_example(name: str = "float_rapier") -> Any:
    path = REPO / "examples" / f"{name}.py"
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def test_example_settles_within_one_percent_of_theory() -> None:
    example = load_example()
    results, note = example.run(seconds=30.0)
    assert [r.name for r in results][1] == "cube"
    if sample_mesh_or_fallback("bunny.obj", "the example's procedural torus knot") is not None:
        assert note is None and results[0].name == "bunny"
    else:
        assert note is not None and "torus knot" in note
    for r in results:
        # Theory from the body's actual (rapier) mass: submerged volume = m / ρ.
        assert r.theory == pytest.approx(r.density / 1000.0, rel=1e-5), r
        assert abs(r.error) < 0.01, f"{r.name}: submerged {r.simulated:.4f} vs {r.theory:.4f}"
        assert r.residual_speed < 0.01, f"{r.name} still moves at {r.residual_speed} m/s"


def test_the_users_own_forces_are_preserved_and_reset() -> None:
    pool = Pool()
    h = pool.half_density_cube(0.3)
    thrust, twist = np.array([30.0, 0.0, -20.0]), np.array([0.0, 5.0, 0.0])
    pool.body(h).add_force(tuple(thrust))
    pool.body(h).add_torque(tuple(twist))
    for _ in range(120):
        pool.apply()
        report = pool.water.report(h)
        assert isinstance(report, FloatReport) and report.outcome == "applied"
        rb = pool.body(h)
        scale = 1e-5 * (np.linalg.norm(report.force) + 1)
        np.testing.assert_allclose(vec(rb.user_force), thrust + report.force, atol=scale)
        np.testing.assert_allclose(vec(rb.user_torque), twist + report.torque, atol=scale)
        pool.world.step()
    position = vec(pool.body(h).translation)
    assert position[0] > 0.05 and position[2] < -0.03
    # Resetting: the adapter is told, and adds its whole share again.
    pool.body(h).reset_forces()
    pool.body(h).reset_torques()
    pool.water.forget_applied(h)
    pool.apply()
    np.testing.assert_allclose(vec(pool.body(h).user_force), pool.water.report(h).force, rtol=1e-5, atol=1e-3)
    # Unregistering takes the adapter's share back off, leaving the user's.
    pool.body(h).add_force(tuple(thrust))
    assert pool.water.unregister(h, pool.world.rigid_bodies) and h not in pool.water and len(pool.water) == 0
    np.testing.assert_allclose(vec(pool.body(h).user_force), thrust, atol=1e-2)
    assert not pool.water.unregister(h, pool.world.rigid_bodies)


def test_report_matches_the_core_at_the_body_pose() -> None:
    # A rotated, moving cube whose center of mass is off the mesh centroid (an extra mass).
    world = rapier3d.PhysicsWorld(gravity=(0.0, -9.81, 0.0))
    builder = rapier3d.RigidBody.dynamic().translation((0.0, -0.2, 0.0)).rotation((0.3, 0.2, 0.1))
    builder = builder.linvel((0.5, -1.0, 0.2)).angvel((0.4, 0.0, -0.6)).can_sleep(False)
    h = world.add_body(builder, [rapier3d.Collider.cuboid(0.5, 0.5, 0.5).density(500.0)])
    rb = world.rigid_bodies[h]
    rb.set_additional_mass_properties(rapier3d.MassProperties((0.2, -0.1, 0.0), 300.0, (10.0, 10.0, 10.0)))
    rb.recompute_mass_properties_from_colliders(world.colliders)
    cube = buoyancy.shapes.cube(3)
    fb = FloatingBodies.for_world(world, damping=buoyancy.DampingCoefficients(linear_drag=10.0, drag_coefficient=0.1))
    fb.register(h, cube)
    fb.apply(world.rigid_bodies, 1 / 60)
    rb = world.rigid_bodies[h]
    com = vec(rb.center_of_mass)
    assert np.linalg.norm(com - vec(rb.translation)) > 0.05
    q = np.array(rb.rotation.quaternion)
    b = cube.buoyancy(vec(rb.translation), q / np.linalg.norm(q), fb.water, about=com)
    report = fb.report(h)
    np.testing.assert_allclose(report.buoyancy_force, b.force, rtol=1e-9)
    np.testing.assert_allclose(report.buoyancy_torque, b.torque, rtol=1e-9, atol=1e-6)
    np.testing.assert_allclose(report.center_of_mass, com)
    assert report.submerged_volume == pytest.approx(b.volume, rel=1e-12)
    # The damping opposes the motion (semi-implicit: not the model's explicit value).
    assert report.damping_force @ vec(rb.linvel) < 0


@pytest.mark.parametrize(
    ("damping", "linvel", "angvel"),
    [((1e7, 0.0), -5.0, 0.0), ((0.0, 1e5), 0.0, 4.0), ((1e7, 1e5), -5.0, 4.0)],
    ids=["moving", "spinning", "both"],
)
def test_stiff_damping_does_not_overshoot(damping: tuple[float, float], linvel: float, angvel: float) -> None:
    # A neutrally buoyant cube under water moving down fast, or spinning fast, or both, with a
    # huge drag: explicit, one step of drag would throw it back; semi-implicit, it can at most
    # stop. With both, the spin is far stiffer than the sinking: each direction at its own rate.
    linear_drag, angular_drag = damping
    coefficients = buoyancy.DampingCoefficients(linear_drag=linear_drag, angular_drag_linear=angular_drag)
    pool = Pool(damping=coefficients)
    body = rapier3d.RigidBody.dynamic().translation((0.0, -3.0, 0.0))
    h = pool.add(body.linvel((0.0, linvel, 0.0)).angvel((0.0, angvel, 0.0)), unit_cube(1.0), buoyancy.shapes.cube())
    for _ in range(3):
        pool.step()
        rb = pool.body(h)
        assert linvel <= rb.linvel.y <= 1e-6 and -1e-6 <= rb.angvel.y <= angvel * 1.001, (rb.linvel, rb.angvel)
    report = pool.water.report(h)
    assert np.isfinite(report.force).all() and np.isfinite(report.torque).all()


@pytest.mark.parametrize("y", [1e6, 50.0, -50.0, -1e5])
def test_no_nan_far_above_or_deep_below(y: float) -> None:
    pool = Pool()
    h = pool.add(
        rapier3d.RigidBody.dynamic().translation((0.0, y, 0.0)).linvel((0.0, -2.0, 0.0)).angvel((0.1, 0.2, 0.3)),
        unit_cube(0.5),
        buoyancy.shapes.cube(),
    )
    for _ in range(5):
        pool.step()
    report, rb = pool.water.report(h), pool.body(h)
    assert report.outcome == "applied"
    for value in (report.force, report.torque, report.center_of_buoyancy, vec(rb.user_force), vec(rb.translation)):
        assert np.isfinite(value).all()
    if y > 0:
        assert report.submerged_volume == 0 and np.linalg.norm(report.force) == 0
        assert np.linalg.norm(vec(rb.user_force)) == 0
    else:
        assert report.submerged_volume == pytest.approx(1.0, rel=1e-9)
        assert report.buoyancy_force[1] == pytest.approx(1000.0 * pool.water.water.gravity, rel=1e-9)
        assert pool.water.water.gravity == pytest.approx(9.81, rel=1e-6)  # rapier's float32 gravity


def test_damping_resolution_of_the_world_and_per_body() -> None:
    # Two spheres of 2,352 triangles in the same state: the one floated with the full mesh's
    # drag feels another damping than the one over the reduced copy, unless the world's is full.
    sphere = buoyancy.shapes.uv_sphere(0.62, 49, 25)

    def damping_forces(pool: Pool, full_override: bool) -> list[list[float]]:
        handles = []
        for x in (-2.0, 2.0):
            body = rapier3d.RigidBody.dynamic().translation((x, 0.0, 0.0)).linvel((0.3, -1.0, 0.0))
            handles.append(pool.add(body.angvel((0.0, 0.5, 2.0)), rapier3d.Collider.ball(0.62).density(500.0), sphere))
        if full_override:
            pool.water.register(handles[1], sphere, damping_resolution="full")
        pool.apply()
        return [pool.water.report(h).damping_force.tolist() for h in handles]

    pool = Pool()
    assert pool.water.damping_resolution == 384
    reduced, full = damping_forces(pool, True)
    assert reduced != full and np.linalg.norm(np.subtract(reduced, full)) < 0.05 * np.linalg.norm(full)
    everywhere = Pool(damping_resolution="full")
    assert everywhere.water.damping_resolution == "full"
    assert damping_forces(everywhere, False) == [full, full]
    # Back to the reduced copies for the bodies without their own.
    everywhere.water.damping_resolution = 384
    assert damping_forces(everywhere, True) == [reduced, full]
    with pytest.raises(ValueError, match=r"^damping_resolution: expected 'full' or"):
        Pool(damping_resolution=-3)


def test_z_up_world_and_per_body_overrides() -> None:
    world = rapier3d.PhysicsWorld(gravity=(0.0, 0.0, -9.81))
    fb = FloatingBodies.for_world(world)
    np.testing.assert_allclose(fb.water.normal, [0, 0, 1])
    cube = buoyancy.shapes.cube()
    handles = []
    for x, water in ((-2.0, None), (2.0, buoyancy.Water(density=1250.0, gravity=9.81, normal=(0, 0, 1)))):
        builder = rapier3d.RigidBody.dynamic().translation((x, 0.0, 1.0)).can_sleep(False)
        h = world.add_body(builder, [rapier3d.Collider.cuboid(0.5, 0.5, 0.5).density(500.0)])
        fb.register(h, cube, water=water, method="exact_surface")
        handles.append(h)
    for _ in range(1200):
        fb.step(world)
    # Half under fresh water, 0.4 under the denser water: the center at z = 0 and z = 0.1.
    assert world.rigid_bodies[handles[0]].translation.z == pytest.approx(0.0, abs=0.01)
    assert world.rigid_bodies[handles[1]].translation.z == pytest.approx(0.1, abs=0.01)


def test_bookkeeping_and_errors() -> None:
    pool = Pool()
    h = pool.half_density_cube(-0.2)
    fixed = pool.world.add_body(
        rapier3d.RigidBody.fixed().translation((3.0, -0.2, 0.0)), [rapier3d.Collider.cuboid(0.5, 0.5, 0.5)]
    )
    fb = FloatingBodies()
    cube = buoyancy.shapes.cube()
    fb.register(h, cube)
    fb.register(fixed, cube)
    assert len(fb) == 2 and h in fb and fb.mesh(h) is cube
    assert fb.report(h).submerged_volume == 0 and fb.report(h).outcome == "not_evaluated"
    assert "2 bodies" in repr(fb)
    fb.step(pool.world)
    assert fb.report(fixed).force.tolist() == [0, 0, 0] and fb.report(fixed).outcome == "inactive"
    assert fb.report(h).submerged_volume == pytest.approx(0.7)
    # Removed bodies are forgotten.
    pool.world.remove_body(h)
    fb.step(pool.world)
    assert h not in fb and len(fb) == 1 and fb.report(h) is None and fb.mesh(h) is None
    assert fb.report(fixed).outcome == "inactive"
    with pytest.raises(TypeError, match="^mesh: expected a buoyancy.Mesh"):
        fb.register(fixed, "cube")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="^parts: a floating body needs at least one mesh"):
        fb.register(fixed, [])
    with pytest.raises(TypeError, match=r"^parts\[1\]: expected a Mesh or a \(mesh, position, quaternion\)"):
        fb.register(fixed, [cube, "cube"])  # type: ignore[list-item]
    with pytest.raises(ValueError, match="^method: .*exact"):
        fb.register(fixed, cube, method="bogus")
    with pytest.raises(ValueError, match="^method:"):
        FloatingBodies(method="bogus")
    with pytest.raises(ValueError, match="^method:"):
        fb.method = "bogus"
    with pytest.raises(TypeError, match="^damping:"):
        FloatingBodies(damping=buoyancy.Water())  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="^water: expected a buoyancy.Water, got str"):
        fb.water = "sea"  # type: ignore[assignment]
    with pytest.raises(ValueError, match="^water: .*waves"):
        fb.register(fixed, cube, water=buoyancy.Water(waves=buoyancy.AiryWave(0.1, 5.0)))
    with pytest.raises(ValueError, match="^gravity:"):
        FloatingBodies((0.0, float("nan"), 0.0))
    # Settings read back.
    fb.method = "ExactSurface"
    assert fb.method == "exact_surface"
    fb.damping = buoyancy.DampingCoefficients.off()
    assert fb.damping.is_off
    # A body of several parts.
    parts = [(cube, (0.0, 0.5, 0.0), IDENTITY), cube.scaled(0.5)]
    fb.register(fixed, parts)
    assert [p[0] for p in fb.parts(fixed)] == [cube, cube.scaled(0.5)]
    assert fb.parts(fixed)[0][1].tolist() == [0.0, 0.5, 0.0] and fb.parts(fixed)[0][2].tolist() == list(IDENTITY)
    with pytest.raises(ValueError, match="^body: floats with 2 parts"):
        fb.mesh(fixed)


def test_bodies_keep_their_own_state_through_removals() -> None:
    # Unregistered and removed bodies leave the others' numbers right (the last body takes the
    # freed number in the controller and in the adapter alike).
    pool = Pool()
    heights = [0.4, 0.2, 0.0, -0.2, -0.4, -0.1]
    handles = [pool.half_density_cube(y) for y in heights]
    pool.apply()
    assert pool.water.unregister(handles[1], pool.world.rigid_bodies)
    pool.world.remove_body(handles[3])
    pool.apply()
    assert len(pool.water) == 4
    for h, y in zip(handles, heights, strict=True):
        if h in (handles[1], handles[3]):
            assert h not in pool.water and pool.water.report(h) is None
            continue
        report = pool.water.report(h)
        assert report.submerged_volume == pytest.approx(0.5 - y, abs=1e-6), (h, y)
        assert report.center_of_mass[1] == pytest.approx(y, abs=1e-6)
        own, _ = pool.own_wrench(h)
        assert np.linalg.norm(own) < 1e-2


def test_module_docstring_example_runs() -> None:
    after = (buoyancy.rapier.__doc__ or "").split("floats half submerged)::\n", 1)[1]
    lines = []
    for line in after.splitlines():
        if line and not line.startswith("    "):
            break  # the end of the indented block
        lines.append(line)
    code = textwrap.dedent("\n".join(lines))
    assert "water.step(world)" in code
    namespace: dict[str, Any] = {}
    exec(compile(code, "buoyancy/rapier.py", "exec"), namespace)
    world, crate = namespace["world"], namespace["crate"]
    assert abs(world.rigid_bodies[crate].translation.y) < 0.01


def test_beyond_float32_is_not_finite() -> None:
    # Finite in float64, but water of 1e38 kg/m³ makes forces beyond rapier's float32.
    pool = Pool(water=buoyancy.Water(density=1e38))
    h = pool.half_density_cube(-0.2)
    pool.apply()
    assert pool.water.report(h).outcome == "not_finite"
    assert vec(pool.body(h).user_force).tolist() == [0, 0, 0]
    # Back to normal water: the body floats again.
    pool.water.water = buoyancy.Water(gravity=9.81)
    pool.apply()
    assert pool.water.report(h).outcome == "applied" and pool.body(h).user_force.y > 0


def test_skipped_is_deprecated() -> None:
    pool = Pool()
    h = pool.half_density_cube(0.0)
    pool.apply()
    with pytest.warns(DeprecationWarning, match="outcome"):
        assert pool.water.report(h).skipped is False


def test_state_read_without_the_bytes_format(monkeypatch: pytest.MonkeyPatch) -> None:
    # rapier3d's to_bytes format is checked at import; were it to differ, the state is read with
    # to_tuple instead, to the same forces.
    assert buoyancy.rapier._BYTES_LAYOUT_OK

    def forces() -> list[list[float]]:
        pool = Pool()
        handles = [pool.half_density_cube(0.1 * k) for k in range(3)]
        pool.body(handles[1]).angvel = (0.3, -0.2, 0.5)
        pool.body(handles[2]).linvel = (1.0, 0.5, 0.0)
        pool.body(handles[2]).locked_axes = rapier3d.LockedAxes.ROTATION_LOCKED_X
        pool.run(0.5)
        return [vec(pool.body(h).user_force).tolist() + vec(pool.body(h).user_torque).tolist() for h in handles]

    with_bytes = forces()
    monkeypatch.setattr(buoyancy.rapier, "_BYTES_LAYOUT_OK", False)
    assert forces() == with_bytes


@pytest.mark.parametrize("read", ["vectors", "tuples"])
def test_whole_body_read_gives_the_getters_forces(monkeypatch: pytest.MonkeyPatch, read: str) -> None:
    # The state is read from each body's whole serialisation (RigidBody.to_bytes), checked at
    # import against the getters; the forces are those of the getters' reads, bit for bit, over
    # bodies of every kind: tilted and spinning, of several colliders, with an additional mass
    # (serialisations of other lengths), locked axes, kinematic for a while with a force of the
    # application's own, disabled, asleep, and with the application's forces reset.
    assert buoyancy.rapier._BODY_LAYOUT_OK

    def run() -> list[list[float]]:
        pool = Pool()
        handles = [pool.half_density_cube(0.2 * k - 0.3) for k in range(4)]
        handles.append(
            pool.add(
                rapier3d.RigidBody.dynamic().translation((3.0, 0.1, 0.0)).rotation((0.2, 0.5, -0.1)),
                [
                    rapier3d.Collider.cuboid(0.5, 0.25, 0.25).translation((0.0, 0.0, z)).density(400.0)
                    for z in (-0.25, 0.25)
                ],
                [(buoyancy.shapes.cube(), (0.0, 0.0, z), (0.0, 0.0, 0.0, 1.0)) for z in (-0.25, 0.25)],
            )
        )
        for handle in handles:
            pool.body(handle).angvel = (0.3, -0.2, 0.5)
        pool.body(handles[1]).set_additional_mass(120.0)
        pool.body(handles[2]).locked_axes = rapier3d.LockedAxes.ROTATION_LOCKED_X
        pool.body(handles[3]).add_force((5.0, 30.0, -2.0), True)
        pool.body(handles[3]).body_type = rapier3d.RigidBodyType.KINEMATIC_VELOCITY_BASED
        rows = []
        for step in range(40):
            if step == 10:
                pool.body(handles[3]).body_type = rapier3d.RigidBodyType.DYNAMIC
                pool.body(handles[0]).is_enabled = False
            if step == 20:
                pool.body(handles[0]).is_enabled = True
                pool.body(handles[2]).sleep()
                pool.body(handles[4]).reset_forces()
                pool.water.forget_applied(handles[4])
            pool.step()
            for h in handles:
                rb = pool.body(h)
                rows.append([*vec(rb.user_force), *vec(rb.user_torque), *vec(rb.translation), *vec(rb.angvel)])
        return rows

    whole = run()
    monkeypatch.setattr(buoyancy.rapier, "_BODY_LAYOUT_OK", False)
    if read == "tuples":
        monkeypatch.setattr(buoyancy.rapier, "_BYTES_LAYOUT_OK", False)
    assert np.array_equal(np.array(run()), np.array(whole))


def test_locked_axes_and_mass_changes_are_read() -> None:
    # The effective inverse mass and inertia are rapier's (zero on locked axes), read again when
    # the locked axes or the mass properties change: they set the semi-implicit damping's rate.
    pool = Pool()
    h = pool.half_density_cube(0.0)

    def damping_torque(**change: Any) -> float:
        rb = pool.body(h)
        rb.reset_forces()
        rb.reset_torques()
        pool.water.forget_applied(h)
        for name, value in change.items():
            setattr(rb, name, value)
        rb.angvel = (0.0, 0.0, 3.0)
        pool.apply()
        return float(pool.water.report(h).damping_torque[2])

    free = damping_torque()
    assert free < 0
    assert damping_torque(locked_axes=rapier3d.LockedAxes.ROTATION_LOCKED) != pytest.approx(free, rel=1e-6)
    assert damping_torque(locked_axes=rapier3d.LockedAxes.empty()) == pytest.approx(free, rel=1e-12)
    pool.body(h).set_additional_mass(5000.0)
    pool.body(h).recompute_mass_properties_from_colliders(pool.world.colliders)
    # Heavier: a lower damping rate, the semi-implicit factor closer to 1.
    assert damping_torque() < free


def test_warnings_are_not_errors_here() -> None:
    # The adapter itself emits no warning in a plain run.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pool = Pool()
        pool.half_density_cube(0.2)
        pool.run(0.5)


# --- waves.rs -----------------------------------------------------------------------------------


def test_a_small_light_buoy_follows_a_long_swell() -> None:
    # waves.rs a_small_light_buoy_follows_a_long_swell: a ball 0.5 m across, a tenth as dense as
    # water, in a deep-water swell 20 m long (40 diameters) and 0.2 m high rides the surface:
    # over the last 5 periods of 60 s its heave has the wave's amplitude within 2 % and its phase
    # within 5°.
    amplitude, wavelength = 0.1, 20.0
    wave = buoyancy.AiryWave(amplitude, wavelength)
    omega = float(buoyancy.Waves([wave]).angular_frequencies(9.81)[0])
    pool = Pool(water=buoyancy.Water(waves=wave))
    buoy = pool.add(
        rapier3d.RigidBody.dynamic().translation((0.0, 0.05, 0.0)),
        rapier3d.Collider.ball(0.25).density(100.0),
        buoyancy.shapes.uv_sphere(0.25, 32, 16),
    )
    period = 2 * math.pi / omega
    start, end = 60.0 - 5 * period, 60.0
    times, heights = [], []
    steps = 0
    while pool.water.time < end:
        pool.step()
        steps += 1
        t = pool.water.time
        if t >= start:
            times.append(t)
            heights.append(pool.body(buoy).center_of_mass.y)
    assert np.isfinite(heights).all()
    # Least squares of y = A cos ωt + B sin ωt + C; the wave at x = 0 is a cos ωt: phase 0.
    t = np.array(times)
    basis = np.column_stack([np.cos(omega * t), np.sin(omega * t), np.ones_like(t)])
    (a, b, _), *_ = np.linalg.lstsq(basis, np.array(heights), rcond=None)
    heave, phase = math.hypot(a, b), math.degrees(math.atan2(b, a))
    assert abs(heave / amplitude - 1.0) < 0.02, f"heave amplitude {heave} m against {amplitude} m (phase {phase}°)"
    assert abs(phase) < 5.0, f"phase {phase}° (amplitude {heave} m)"
    # The time ran with the world: one dt (rapier's float32 1/60 s) per step.
    assert pool.water.time == pytest.approx(steps * pool.world.integration_parameters.dt, rel=1e-12)
    print(f"heave {heave / amplitude:.4f} of the wave, phase {phase:.2f}°")


def test_the_waves_time_runs_with_the_world_and_is_settable() -> None:
    swell = buoyancy.Water(waves=buoyancy.AiryWave(0.1, 20.0))
    pool = Pool(water=swell)
    assert pool.water.water is swell and pool.water.time == 0.0
    h = pool.half_density_cube(0.0)
    pool.world.integration_parameters.dt = 0.01
    pool.run(0.5)
    assert pool.water.time == pytest.approx(0.5, abs=1e-6)
    assert "time=0.5" in repr(pool.water)
    # At the time set, the body feels the surface then: the crest (t = 0) or the trough (half a period).
    omega = float(buoyancy.Waves([buoyancy.AiryWave(0.1, 20.0)]).angular_frequencies()[0])
    volumes = []
    for t in (0.0, math.pi / omega):
        pool.water.time = t
        rb = pool.body(h)
        pool.apply()
        assert pool.water.time == pytest.approx(t + 0.01)
        q = rb.rotation.quaternion
        expected = buoyancy.shapes.cube().buoyancy(tuple(rb.translation), q, water=swell, time=t)
        assert pool.water.report(h).submerged_volume == pytest.approx(expected.volume, rel=1e-9)
        volumes.append(expected.volume)
    assert volumes[0] - volumes[1] > 0.15  # 0.2 m of wave height on a 1 m cube
    with pytest.raises(ValueError, match="^time: must be finite"):
        pool.water.time = math.nan
    # The adapter's apply refuses a dt the controller cannot take, the time left as it was.
    before = pool.water.time
    with pytest.raises(ValueError, match="^dt: "):
        pool.water.apply(pool.world.rigid_bodies, math.nan)
    assert pool.water.time == before


def test_a_hull_at_its_design_draft_stays_at_rest() -> None:
    # waves.rs a_hull_at_its_design_draft_stays_at_rest: the demo's Wigley hull placed at its
    # design draft stays there for 30 s, in still water and with a calm surface (waves of zero
    # elevation, given as a function: the waves' path).
    example = load_example("waves_rapier")
    for calm in (False, True):
        if calm:
            water = buoyancy.Water(waves=lambda points, t: np.zeros(len(points)))
        else:
            water = buoyancy.Water()
        speed, spin, drift, turn = example.rest_check(30.0, water=water)
        assert speed < 1e-4 and spin < 1e-4, f"calm surface {calm}: speed {speed} m/s, spin {spin} rad/s"
        assert drift < 1e-4 and turn < 1e-3, f"calm surface {calm}: drifted {drift} m, turned {turn}°"


def test_two_bodies_ride_ten_minutes_of_a_jonswap_sea() -> None:
    # waves.rs three_bodies_ride_ten_minutes_of_a_jonswap_sea, with the demo's hull and buoy in
    # one world, 15 m apart across the waves, on the demo's sea with 32 components (γ = 3.3,
    # Hs 0.3 m, Tp 2.5 s, seed 7, along x) from rest: for 10 minutes every pose and velocity
    # finite, every body's forces applied, no heave beyond 2·Hs, no speed beyond 3 m/s, no spin
    # beyond 5 rad/s. So that it takes seconds, the meshes are coarse (the hull of 11 stations
    # and 5 waterlines, 218 triangles; the buoy's cylinder of 24 sides) and the world steps at
    # 30 Hz (18,000 steps; the sea's time follows the world's dt).
    example = load_example("waves_rapier")
    hs = 0.3
    sea = buoyancy.Water(waves=buoyancy.Waves.jonswap(hs, 2.5, gamma=3.3, n=32, seed=7))
    pool = Pool(water=sea)
    pool.world.integration_parameters.dt = 1 / 30
    mesh, density = example.hull_mesh(11, 5)
    handles = {
        "hull": example.add_hull(pool.world, pool.water, 0.0, mesh, density),
        "buoy": example.add_buoy(pool.world, pool.water, 15.0, segments=24),
    }
    rest = {name: pool.body(h).center_of_mass.y for name, h in handles.items()}
    largest = {name: [0.0, 0.0, 0.0] for name in handles}  # heave, speed, spin
    for step in range(18_000):
        pool.step()
        for name, h in handles.items():
            rb = pool.body(h)
            v, w = tuple(rb.linvel), tuple(rb.angvel)
            state = (*tuple(rb.translation), *v, *w)
            assert all(map(math.isfinite, state)), f"{name} at {step / 30} s: {state}"
            assert pool.water.report(h).outcome == "applied", f"{name} at {step / 30} s"
            now = (abs(rb.center_of_mass.y - rest[name]), math.hypot(*v), math.hypot(*w))
            largest[name] = [max(a, b) for a, b in zip(largest[name], now, strict=True)]
    assert pool.water.time == pytest.approx(18_000 * pool.world.integration_parameters.dt, rel=1e-12)
    assert pool.water.time == pytest.approx(600.0, rel=1e-6)
    for name, (heave, speed, spin) in largest.items():
        print(f"{name}: largest |heave| {heave:.3f} m, speed {speed:.2f} m/s, spin {spin:.2f} rad/s")
        assert heave <= 2 * hs and speed <= 3.0 and spin <= 5.0, f"{name}: heave {heave}, speed {speed}, spin {spin}"


def test_the_waves_example_runs_briefly(tmp_path: Any) -> None:
    example = load_example("waves_rapier")
    # The three bodies on the regular wave, 1 s of settling and 6 s of waves (the JONSWAP sea's
    # ten minutes are the test above).
    runs, seas, note = example.run(seconds=6.0, settle=1.0, sea_names=("regular",))
    names = [r.body for r in runs]
    assert [s.name for s in seas] == ["regular"]
    if sample_mesh_or_fallback("bunny.obj", "the example without its bunny") is not None:
        assert note is None and names == ["hull", "bunny", "buoy"]
    else:
        assert note is not None and "bunny" in note and names == ["hull", "buoy"]
    for r in runs:
        assert len(r.samples) == 6 * 20 + 1
        assert example.stats(r, stats_from=3.0).verdict == "ok", r.body
    text = example.table(runs, stats_from=3.0)
    assert text.count("| ok |") == len(runs)
    png = tmp_path / "waves_rapier.png"
    example.plot(runs, seas, png, 6.0, stats_from=3.0)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


# --- place_at_rest (crates/buoyancy-rapier/tests/place_at_rest.rs) --------------------------------


def loaded_box(pool: Pool) -> Any:
    """A box 2 × 0.5 × 1 m of 400 kg/m³ with a dense ball of 30 kg at (0.4, −0.1, 0.2) in it,
    started 1.5 m up and tilted: it floats heeled and trimmed."""
    ball_density = 30.0 / (4.0 / 3.0 * math.pi * 0.05**3)
    return pool.add(
        pose((0.5, 1.5, -0.3), axis_angle((1, 0, 0), 0.3), axis_angle((0, 0, 1), -0.25), axis_angle((0, 1, 0), 0.2)),
        [
            rapier3d.Collider.cuboid(1.0, 0.25, 0.5).density(400.0),
            rapier3d.Collider.ball(0.05).density(ball_density).translation((0.4, -0.1, 0.2)),
        ],
        buoyancy.shapes.cube().scaled((2.0, 0.5, 1.0)),
    )


def attitude(rb: Any) -> tuple[np.ndarray, np.ndarray]:
    """The world center of mass and the body's up axis (its y)."""
    q = np.array(rb.rotation.to_tuple())
    x, y, z, w = q
    up = np.array([2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)])
    return vec(rb.center_of_mass), up


def test_a_body_placed_at_rest_stays_there() -> None:
    pool = Pool()
    h = loaded_box(pool)
    rest = pool.water.place_at_rest(h, pool.world.rigid_bodies, pool.world.colliders)
    assert rest.stable
    assert pool.body(h).mass == pytest.approx(430.0, rel=1e-5)
    com, up = attitude(pool.body(h))
    tilt = math.degrees(math.acos(min(1.0, float(up[1]))))
    assert 1.0 < tilt < 10.0  # the load off center tilts it at rest (about 3°)
    pool.run(5.0)
    com_after, up_after = attitude(pool.body(h))
    assert np.linalg.norm(com_after - com) < 2e-3
    assert math.degrees(math.acos(min(1.0, float(up @ up_after)))) < 0.2


def test_the_rest_is_where_a_dropped_body_settles() -> None:
    dropped = Pool()
    h = loaded_box(dropped)
    dropped.run(40.0)
    dropped.assert_equilibrium(h, 2.0, "dropped box")
    placed = Pool()
    p = loaded_box(placed)
    placed.water.place_at_rest(p, placed.world.rigid_bodies, placed.world.colliders)
    placed.apply()  # rapier's world center of mass follows the new pose at the next step
    (com, up), (com_rest, up_rest) = attitude(dropped.body(h)), attitude(placed.body(p))
    assert abs(com[1] - com_rest[1]) < 1e-4
    assert math.degrees(math.acos(min(1.0, float(up @ up_rest)))) < 0.3


def test_place_at_rest_errors() -> None:
    pool = Pool()
    stone = pool.add(
        rapier3d.RigidBody.dynamic(), rapier3d.Collider.ball(0.5).density(2500.0), buoyancy.shapes.uv_sphere(0.5)
    )
    with pytest.raises(ValueError, match="does not float"):
        pool.water.place_at_rest(stone, pool.world.rigid_bodies, pool.world.colliders)
    loose = pool.world.add_body(rapier3d.RigidBody.dynamic(), [rapier3d.Collider.ball(0.5)])
    with pytest.raises(ValueError, match="^body: .* is not registered"):
        pool.water.place_at_rest(loose, pool.world.rigid_bodies, pool.world.colliders)


def test_place_at_rest_weighs_with_the_gravity_scale() -> None:
    pool = Pool()
    h = pool.add(
        rapier3d.RigidBody.dynamic().translation((0.0, 2.0, 0.0)).gravity_scale(0.5),
        rapier3d.Collider.cuboid(1.0, 0.25, 0.5).density(400.0),  # 400 kg at half gravity
        buoyancy.shapes.cube().scaled((2.0, 0.5, 1.0)),
    )
    rest = pool.water.place_at_rest(h, pool.world.rigid_bodies, pool.world.colliders)
    assert rest.draft == pytest.approx(0.1, rel=1e-6)  # 200 kg on a 2 × 1 m waterplane
    pool.run(3.0)
    assert abs(pool.body(h).translation.y - (0.25 - 0.1)) < 1e-4
