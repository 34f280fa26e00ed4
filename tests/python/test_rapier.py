"""buoyancy.rapier with rapier's Python binding (the rapier3d package): the example settles
within 1% of theory, the user's own forces are preserved, the damping clamp, far and deep
bodies, bookkeeping."""

from __future__ import annotations

import importlib.util
import sys
from typing import Any

import numpy as np
import pytest

import buoyancy
from buoyancy._sample_meshes import find_sample_mesh

from conftest import REPO

try:
    import rapier3d
except ImportError as error:  # not installed, or installed but not loadable here
    pytest.skip(
        f"rapier3d (rapier's Python binding, pip install rapier3d) cannot be imported ({error}); "
        "scripts/test.sh installs it when the package index allows",
        allow_module_level=True,
    )
from buoyancy.rapier import FloatingBodies, FloatReport


def load_example() -> Any:
    path = REPO / "examples" / "float_rapier.py"
    spec = importlib.util.spec_from_file_location("float_rapier", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["float_rapier"] = module  # dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def test_example_settles_within_one_percent_of_theory() -> None:
    example = load_example()
    results, note = example.run(seconds=30.0)
    assert [r.name for r in results][1] == "cube"
    if find_sample_mesh("bunny.obj", REPO) is not None:
        assert note is None and results[0].name == "bunny"
    else:
        assert note is not None and "torus knot" in note
    for r in results:
        # Theory from the body's actual (rapier) mass: submerged volume = m / ρ.
        assert r.theory == pytest.approx(r.density / 1000.0, rel=1e-5), r
        assert abs(r.error) < 0.01, f"{r.name}: submerged {r.simulated:.4f} vs {r.theory:.4f}"
        assert r.residual_speed < 0.01, f"{r.name} still moves at {r.residual_speed} m/s"


def world_with_cube(y: float = 1.0, density: float = 500.0, **body: Any) -> tuple[Any, Any]:
    world = rapier3d.PhysicsWorld(gravity=(0.0, -9.81, 0.0))
    builder = rapier3d.RigidBody.dynamic().translation((0.0, y, 0.0)).can_sleep(False)
    for name, value in body.items():
        builder = getattr(builder, name)(value)
    handle = world.add_body(builder, [rapier3d.Collider.cuboid(0.5, 0.5, 0.5).density(density)])
    return world, handle


def vec(v: Any) -> np.ndarray:
    return np.array(tuple(v), dtype=np.float64)


def test_the_users_own_forces_are_preserved() -> None:
    world, h = world_with_cube(y=0.3)
    fb = FloatingBodies.for_world(world)
    fb.register(h, buoyancy.shapes.cube())
    thrust, twist = np.array([30.0, 0.0, -20.0]), np.array([0.0, 5.0, 0.0])
    rb = world.rigid_bodies[h]
    rb.add_force(tuple(thrust))
    rb.add_torque(tuple(twist))
    for _ in range(120):
        fb.apply(world.rigid_bodies, world.integration_parameters.dt)
        report = fb.report(h)
        assert isinstance(report, FloatReport) and not report.skipped
        rb = world.rigid_bodies[h]
        scale = 1e-5 * (np.linalg.norm(report.force) + 1)
        np.testing.assert_allclose(vec(rb.user_force), thrust + report.force, atol=scale)
        np.testing.assert_allclose(vec(rb.user_torque), twist + report.torque, atol=scale)
        world.step()
    # The thrust kept pushing the cube along x and -z all along.
    position = vec(world.rigid_bodies[h].translation)
    assert position[0] > 0.05 and position[2] < -0.03
    # Resetting: the adapter is told, and adds its whole share again.
    world.rigid_bodies[h].reset_forces()
    world.rigid_bodies[h].reset_torques()
    fb.forget_applied(h)
    fb.apply(world.rigid_bodies, world.integration_parameters.dt)
    np.testing.assert_allclose(vec(world.rigid_bodies[h].user_force), fb.report(h).force, rtol=1e-5, atol=1e-3)
    # Unregistering takes the adapter's share back off, leaving the user's.
    world.rigid_bodies[h].add_force(tuple(thrust))
    assert fb.unregister(h, world.rigid_bodies) and h not in fb and len(fb) == 0
    np.testing.assert_allclose(vec(world.rigid_bodies[h].user_force), thrust, atol=1e-2)
    assert not fb.unregister(h, world.rigid_bodies)


def test_report_matches_the_core_at_the_body_pose() -> None:
    # A rotated, moving cube whose center of mass is off the mesh centroid (an extra mass).
    world, h = world_with_cube(y=-0.2, rotation=(0.3, 0.2, 0.1), linvel=(0.5, -1.0, 0.2), angvel=(0.4, 0.0, -0.6))
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
    # Light damping: no clamp, so the report is the core's damping at the centroid's velocity.
    v, w = vec(rb.linvel), vec(rb.angvel)
    centroid = cube.buoyancy(vec(rb.translation), q / np.linalg.norm(q)).about
    d = cube.damping(
        vec(rb.translation), q / np.linalg.norm(q), v + np.cross(w, centroid - com), w, fb.water, fb.damping, about=com
    )
    np.testing.assert_allclose(report.damping_force, d.force, rtol=1e-9)
    np.testing.assert_allclose(report.damping_torque, d.torque, rtol=1e-9, atol=1e-9)
    assert report.damping_force @ v < 0


def test_damping_is_clamped_to_stop_the_motion_at_most() -> None:
    # A neutrally buoyant cube under water moving down fast, with a huge drag: unclamped, one
    # step of drag would throw it upwards; clamped, it can at most stop.
    world, h = world_with_cube(y=-3.0, density=1000.0, linvel=(0.0, -5.0, 0.0), angvel=(0.0, 4.0, 0.0))
    fb = FloatingBodies.for_world(world, damping=buoyancy.DampingCoefficients(linear_drag=1e7, angular_drag_linear=1e5))
    fb.register(h, buoyancy.shapes.cube())
    dt = world.integration_parameters.dt
    mass = world.rigid_bodies[h].mass
    fb.step(world)
    report = fb.report(h)
    assert np.linalg.norm(report.damping_force) * dt <= mass * 5.0 * (1 + 1e-9)
    assert report.damping_force[1] > 0.5 * mass * 5.0 / dt  # it did brake hard
    rb = world.rigid_bodies[h]
    assert -5.0 < rb.linvel.y <= 0.05 and abs(rb.angvel.y) <= 4.0 * 1.01
    assert np.isfinite(vec(rb.translation)).all()


@pytest.mark.parametrize("y", [1e6, 50.0, -50.0, -1e5])
def test_no_nan_far_above_or_deep_below(y: float) -> None:
    world, h = world_with_cube(y=y, linvel=(0.0, -2.0, 0.0), angvel=(0.1, 0.2, 0.3))
    fb = FloatingBodies.for_world(world)
    fb.register(h, buoyancy.shapes.cube())
    for _ in range(5):
        fb.step(world)
    report, rb = fb.report(h), world.rigid_bodies[h]
    assert not report.skipped
    for value in (report.force, report.torque, report.center_of_buoyancy, vec(rb.user_force), vec(rb.translation)):
        assert np.isfinite(value).all()
    if y > 0:
        assert report.submerged_volume == 0 and np.linalg.norm(report.force) == 0
        assert np.linalg.norm(vec(rb.user_force)) == 0
    else:
        assert report.submerged_volume == pytest.approx(1.0, rel=1e-9)
        assert report.buoyancy_force[1] == pytest.approx(1000.0 * fb.water.gravity, rel=1e-9)
        assert fb.water.gravity == pytest.approx(9.81, rel=1e-6)  # rapier's float32 gravity


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
    world, h = world_with_cube(y=-0.2)
    fixed = world.add_body(
        rapier3d.RigidBody.fixed().translation((3.0, -0.2, 0.0)), [rapier3d.Collider.cuboid(0.5, 0.5, 0.5)]
    )
    fb = FloatingBodies()
    cube = buoyancy.shapes.cube()
    fb.register(h, cube)
    fb.register(fixed, cube)
    assert len(fb) == 2 and h in fb and fb.mesh(h) is cube
    assert fb.report(h).submerged_volume == 0 and not fb.report(h).skipped
    assert "2 bodies" in repr(fb)
    fb.step(world)
    assert fb.report(fixed).force.tolist() == [0, 0, 0] and not fb.report(fixed).skipped
    assert fb.report(h).submerged_volume == pytest.approx(0.7)
    # Removed bodies are forgotten.
    world.remove_body(h)
    fb.step(world)
    assert h not in fb and len(fb) == 1 and fb.report(h) is None
    with pytest.raises(TypeError, match="^mesh: expected a buoyancy.Mesh"):
        fb.register(fixed, "cube")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="^method: .*exact"):
        fb.register(fixed, cube, method="bogus")
    with pytest.raises(ValueError, match="^method:"):
        FloatingBodies(method="bogus")
    with pytest.raises(TypeError, match="^damping:"):
        FloatingBodies(damping=buoyancy.Water())  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="^gravity:"):
        FloatingBodies((0.0, float("nan"), 0.0))


@pytest.mark.parametrize(
    "gravity, match",
    [
        ((0.0, float("nan"), 0.0), r"^gravity: has a NaN or infinite component: \(0.0, nan, 0.0\)$"),
        ((0.0, -float("inf"), 0.0), "^gravity: has a NaN or infinite component"),
        ((1.5e308, 1.5e308, 0.0), "^gravity: too large, its magnitude overflows"),
        ((0.0, -9.81), r"^gravity: expected 3 numbers, the gravity vector in m/s², got shape \(2,\)$"),
        (-9.81, r"^gravity: expected 3 numbers, the gravity vector in m/s², got shape \(\)$"),
        ("down", "^gravity: expected 3 numbers, the gravity vector in m/s²"),
    ],
)
def test_invalid_gravity_is_a_value_error_naming_it(gravity: Any, match: str) -> None:
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


def test_module_docstring_example_runs() -> None:
    import textwrap

    import buoyancy.rapier

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


def test_beyond_float32_is_skipped_not_infinite() -> None:
    # Finite in float64, but water of 1e38 kg/m³ makes forces beyond rapier's float32.
    world, h = world_with_cube(y=-0.2)
    fb = FloatingBodies.for_world(world, water=buoyancy.Water(density=1e38))
    fb.register(h, buoyancy.shapes.cube())
    fb.apply(world.rigid_bodies, 1 / 60)
    assert fb.report(h).skipped
    assert vec(world.rigid_bodies[h].user_force).tolist() == [0, 0, 0]
    # Back to normal water: the body floats again.
    fb.water = buoyancy.Water(gravity=9.81)
    fb.apply(world.rigid_bodies, 1 / 60)
    assert not fb.report(h).skipped and world.rigid_bodies[h].user_force.y > 0
