"""buoyancy.Controller, the binding of the core's engine-independent controller: its arrays in
and out (shapes, dtypes, errors naming the argument), a cube at rest half under water, the books
of the applied share (take-back, forget, a wiped share), inactive and not-finite bodies, waking,
bodies of several parts, per-body settings."""

from __future__ import annotations

import pickle
import threading
from typing import Any

import numpy as np
import pytest

import buoyancy

from conftest import run_examples

WEIGHT = 500.0 * 9.81  # N, of the half-density 1 m cube: its buoyancy half under water
IDENTITY = (0.0, 0.0, 0.0, 1.0)


def states(n: int, **change: Any) -> dict[str, Any]:
    """The keyword arguments of ``step`` for ``n`` 1 m cubes of 500 kg at rest, their center at
    the water level, holding no force; ``change`` replaces some."""
    arrays: dict[str, Any] = {
        "positions": np.zeros((n, 3)),
        "quaternions": np.tile(IDENTITY, (n, 1)),
        "centers_of_mass": np.zeros((n, 3)),
        "linear_velocities": np.zeros((n, 3)),
        "angular_velocities": np.zeros((n, 3)),
        "masses": np.full(n, 500.0),
        "inverse_masses": np.full((n, 3), 1 / 500.0),
        "inverse_inertias": np.tile(np.eye(3) * 6 / 500.0, (n, 1, 1)),
        "gravity_scales": np.ones(n),
        "applied_forces": np.zeros((n, 3), np.float32),
        "applied_torques": np.zeros((n, 3), np.float32),
        "dynamic": np.ones(n, bool),
        "sleeping": np.zeros(n, bool),
    }
    arrays.update(change)
    return arrays


def cubes(n: int, **settings: Any) -> buoyancy.Controller:
    controller = buoyancy.Controller(**settings)
    for _ in range(n):
        controller.add(buoyancy.shapes.cube())
    return controller


class Engine:
    """What an engine like rapier keeps: each body's applied force and torque, float32, to which
    the commands add."""

    def __init__(self, controller: buoyancy.Controller, n: int) -> None:
        self.controller = controller
        self.forces = np.zeros((n, 3), np.float32)
        self.torques = np.zeros((n, 3), np.float32)

    def step(self, **change: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        n = len(self.forces)
        f, t, wake = self.controller.step(
            1 / 60, **states(n, applied_forces=self.forces, applied_torques=self.torques, **change)
        )
        dynamic = np.asarray(change.get("dynamic", np.ones(n, bool)))
        # Like rapier: a body that is not dynamic ignores what is added.
        self.forces[dynamic] += f[dynamic]
        self.torques[dynamic] += t[dynamic]
        return f, t, wake


def test_a_cube_at_rest_half_under_water_gets_its_weight() -> None:
    engine = Engine(cubes(1), 1)
    f, t, wake = engine.step()
    assert f.dtype == np.float32 and t.dtype == np.float32 and wake.dtype == np.bool_
    assert f.shape == (1, 3) and t.shape == (1, 3) and wake.shape == (1,)
    np.testing.assert_allclose(f[0], [0.0, WEIGHT, 0.0], atol=1e-3)
    np.testing.assert_allclose(t[0], 0.0, atol=1e-3)
    report = engine.controller.report(0)
    assert report.outcome == "applied"
    assert report.submerged_volume == pytest.approx(0.5, abs=1e-12)
    np.testing.assert_allclose(report.center_of_buoyancy, [0.0, -0.25, 0.0], atol=1e-12)
    np.testing.assert_allclose(report.force, report.buoyancy_force + report.damping_force)
    assert report.wetted_area == pytest.approx(3.0)
    # The engine holds it now: the next step adds nothing.
    f, t, wake = engine.step()
    assert not f.any() and not t.any() and not wake.any()


def test_the_take_back_returns_the_share() -> None:
    controller = cubes(3)
    engine = Engine(controller, 3)
    engine.step(positions=np.array([[0.0, 0.0, 0.0], [0.0, -0.25, 0.0], [0.0, 5.0, 0.0]]))
    held = engine.forces.copy()
    force, torque = controller.remove(0)
    assert force.dtype == np.float32 and force.shape == (3,) and torque.shape == (3,)
    np.testing.assert_array_equal(force, -held[0])
    np.testing.assert_array_equal(torque, -engine.torques[0])
    # The last body took number 0.
    assert len(controller) == 2
    assert controller.report(0).submerged_volume == 0.0 and controller.report(1).submerged_volume == 0.75
    force, _ = controller.remove(1)
    np.testing.assert_array_equal(force, -held[1])
    with pytest.raises(IndexError, match="^index: no body 1; the controller has 1"):
        controller.remove(1)


def test_forget_applied_and_a_wiped_share() -> None:
    engine = Engine(cubes(1), 1)
    engine.step()
    # The application reset the body's forces and says so: the whole share again.
    engine.forces[:] = 0
    engine.torques[:] = 0
    engine.controller.forget_applied(0)
    f, _, _ = engine.step()
    assert f[0, 1] == pytest.approx(WEIGHT)
    # Reset without saying so (rapier's NaN quarantine): both exactly zero, noticed.
    engine.forces[:] = 0
    f, _, _ = engine.step()
    assert f[0, 1] == pytest.approx(WEIGHT)
    np.testing.assert_allclose(engine.forces[0], [0, WEIGHT, 0], atol=1e-3)


def test_the_applications_own_force_stays() -> None:
    engine = Engine(cubes(1), 1)
    engine.forces[0] = [10.0, 0.0, 0.0]  # a thrust the application added once
    f, _, _ = engine.step()
    np.testing.assert_allclose(f[0], [0.0, WEIGHT, 0.0], atol=1e-3)
    np.testing.assert_allclose(engine.forces[0], [10.0, WEIGHT, 0.0], atol=1e-3)


def test_inactive_bodies_get_nothing_and_keep_their_share() -> None:
    engine = Engine(cubes(2), 2)
    engine.step()
    held = engine.forces.copy()
    inactive = np.array([False, True])
    # rapier reads zero forces for a body that is not dynamic: no wiped share for it.
    f, t, _ = engine.step(dynamic=inactive, positions=np.full((2, 3), -0.1))
    assert not f[0].any() and not t[0].any()
    assert f[1].any()
    report = engine.controller.report(0)
    assert report.outcome == "inactive" and report.submerged_volume == 0.0
    assert report.center_of_buoyancy.tolist() == report.center_of_mass.tolist()
    # Dynamic again, where it was: the share it kept is still right, nothing to add.
    f, _, _ = engine.step()
    assert not f[0].any()
    np.testing.assert_array_equal(engine.forces[0], held[0])
    # And the take-back is the share it kept.
    np.testing.assert_array_equal(engine.controller.remove(0)[0], -held[0])


def test_a_body_that_is_not_finite_gets_no_force() -> None:
    engine = Engine(cubes(2), 2)
    engine.step()
    velocities = np.array([[np.nan, 0.0, 0.0], [0.0, 0.0, 0.0]])
    f, _, _ = engine.step(linear_velocities=velocities)
    assert engine.controller.report(0).outcome == "not_finite"
    np.testing.assert_allclose(f[0], [0.0, -WEIGHT, 0.0], atol=1e-3)  # the share taken back
    assert not f[1].any()
    # A quaternion that is not finite too, without an error.
    quaternions = np.array([[np.nan] * 4, IDENTITY])
    engine.step(quaternions=quaternions)
    assert engine.controller.report(0).outcome == "not_finite"
    f, _, _ = engine.step()
    assert engine.controller.report(0).outcome == "applied" and f[0, 1] == pytest.approx(WEIGHT)


def test_waking() -> None:
    engine = Engine(cubes(1), 1)
    sleeping = np.array([True])
    _, _, wake = engine.step(sleeping=sleeping)
    assert wake.tolist() == [True]  # from nothing to its weight
    # A change far below 0.1 % of the weight: added, without waking the sleeping body...
    _, _, wake = engine.step(sleeping=sleeping, positions=np.array([[0.0, -1e-5, 0.0]]))
    assert engine.forces[0, 1] > WEIGHT and wake.tolist() == [False]
    # ...but such changes add up.
    for k in range(2, 200):
        f, _, wake = engine.step(sleeping=sleeping, positions=np.array([[0.0, -1e-5 * k, 0.0]]))
        if wake[0]:
            break
    assert wake[0] and 0.001 * WEIGHT < f[0, 1] * k


def test_a_body_asleep_out_of_balance_is_woken_once_per_pose() -> None:
    engine = Engine(cubes(1), 1)
    high = np.array([[0.0, 0.01, 0.0]])  # 1 cm above its rest: 98 N short of its weight
    engine.step(positions=high)  # awake: the engine holds the buoyancy
    asleep = np.array([True])
    add, _, wake = engine.step(positions=high, sleeping=asleep)
    # Nothing changed, nothing to add; but 98 N out of balance (over 0.1 % of 4905 N): woken.
    assert not add.any() and wake.tolist() == [True]
    # Asleep again at the same pose: something holds it there (the ground): left asleep.
    _, _, wake = engine.step(positions=high, sleeping=asleep)
    assert wake.tolist() == [False]
    # In balance, a sleeping body is not woken.
    engine = Engine(cubes(1), 1)
    engine.step()
    _, _, wake = engine.step(sleeping=asleep)
    assert wake.tolist() == [False]


def test_bodies_of_several_parts_and_per_body_settings() -> None:
    cube = buoyancy.shapes.cube()
    controller = buoyancy.Controller()
    controller.add([(cube, (-1.0, 0.0, 0.0), IDENTITY), (cube, (1.0, 0.0, 0.0), np.eye(3))])
    controller.add(cube, water=buoyancy.Water(density=1025.0), method="fast_surface")
    controller.add(cube, damping=buoyancy.DampingCoefficients.off())
    f, _, _ = controller.step(1 / 60, **states(3, linear_velocities=np.tile([0.0, -1.0, 0.0], (3, 1))))
    two, sea, undamped = (controller.report(i) for i in range(3))
    assert two.submerged_volume == pytest.approx(1.0) and two.buoyancy_force[1] == pytest.approx(2 * WEIGHT)
    np.testing.assert_allclose(two.buoyancy_torque, 0.0, atol=1e-9)  # symmetric about the center of mass
    assert sea.buoyancy_force[1] == pytest.approx(1025.0 * 9.81 * 0.5)
    assert undamped.damping_force.tolist() == [0, 0, 0] and sea.damping_force[1] > 0
    parts = controller.parts(0)
    assert [p[0] for p in parts] == [cube, cube] and parts[0][0] is cube
    assert parts[1][1].tolist() == [1.0, 0.0, 0.0] and parts[1][2].tolist() == list(IDENTITY)
    # Replacing keeps the books: the engine holds the old share, the command adds the difference.
    controller.replace(2, [cube, cube])
    f2, _, _ = controller.step(1 / 60, **states(3, applied_forces=f))
    assert f2[2, 1] == pytest.approx(WEIGHT, rel=1e-6)


def test_a_mesh_equal_to_one_held_is_replaced_by_it() -> None:
    """A Mesh built apart but equal to one a body is made of (same vertices and faces) is
    replaced by that one, so that the controller keeps one object of equal meshes; within one
    call too; a different mesh is kept as given; and the forces are those of the mesh held."""
    held = buoyancy.shapes.cube()
    equal = [buoyancy.Mesh(held.vertices, held.faces) for _ in range(3)]
    other = buoyancy.shapes.cube(2)
    assert all(m == held and m is not held for m in equal) and other != held
    controller = buoyancy.Controller()
    controller.add(held)
    controller.add([equal[0], (other, (0.0, 2.0, 0.0), IDENTITY)])
    kept = [p[0] for p in controller.parts(1)]
    assert kept[0] is held and kept[1] is other
    controller.replace(0, equal[1])
    assert controller.parts(0)[0][0] is held
    alone = buoyancy.Controller()
    alone.add([equal[1], equal[2]])
    assert [p[0] for p in alone.parts(0)] == [equal[1], equal[1]]
    assert alone.parts(0)[1][0] is equal[1]
    reference = buoyancy.Controller()
    reference.add(held)
    reference.add([held, (other, (0.0, 2.0, 0.0), IDENTITY)])
    moving = {"linear_velocities": np.tile([0.1, -0.3, 0.2], (2, 1))}
    np.testing.assert_array_equal(
        controller.step(1 / 60, **states(2, **moving))[0], reference.step(1 / 60, **states(2, **moving))[0]
    )


def test_settings() -> None:
    controller = buoyancy.Controller(buoyancy.Water(level=1.0), "ExactSurface", buoyancy.DampingCoefficients.off())
    assert controller.water == buoyancy.Water(level=1.0)
    assert controller.method == "exact_surface" and controller.damping.is_off
    controller.water = buoyancy.Water(density=1025.0)
    controller.method = "fast"
    controller.damping = buoyancy.DampingCoefficients(linear_drag=5.0)
    assert controller.water.density == 1025.0 and controller.method == "fast"
    assert controller.damping.linear_drag == 5.0
    assert repr(controller).startswith("Controller(0 bodies, water=Water(density=1025")
    assert buoyancy.Controller().method == "exact" and buoyancy.Controller().damping == buoyancy.DampingCoefficients()


def test_damping_resolution() -> None:
    # A sphere of 2,352 triangles, half under water, sinking and turning: its pressure drag over
    # the reduced copy (the default, at most 384 triangles) is close to, not the same as, the
    # drag over every triangle; a resolution above its triangle count takes the mesh itself.
    sphere = buoyancy.shapes.uv_sphere(0.62, 49, 25)
    assert sphere.n_triangles == 2352

    def damping_forces(controller: buoyancy.Controller) -> np.ndarray:
        n = len(controller)
        moving = {
            "linear_velocities": np.tile([0.3, -1.0, 0.0], (n, 1)),
            "angular_velocities": np.tile([0.0, 0.5, 2.0], (n, 1)),
        }
        controller.step(1 / 60, **states(n, **moving))
        return np.array([controller.report(i).damping_force for i in range(len(controller))])

    default = buoyancy.Controller()
    assert default.damping_resolution == 384
    for resolution in (None, "full", 100_000):
        default.add(sphere, damping_resolution=resolution)
    assert [default.body_damping_resolution(i) for i in range(3)] == [384, "full", 100_000]
    reduced, full, whole = damping_forces(default)
    assert full.tolist() == whole.tolist()
    assert 0 < np.linalg.norm(reduced - full) < 0.05 * np.linalg.norm(full)
    everywhere = buoyancy.Controller(damping_resolution="full")
    everywhere.add(sphere)
    assert everywhere.damping_resolution == "full" and everywhere.body_damping_resolution(0) == "full"
    assert damping_forces(everywhere)[0].tolist() == full.tolist()
    # The controller's resolution reaches the bodies without their own; replacing a body
    # replaces its resolution too.
    default.damping_resolution = "full"
    assert [default.body_damping_resolution(i) for i in range(3)] == ["full", "full", 100_000]
    assert damping_forces(default)[0].tolist() == full.tolist()
    default.replace(1, sphere)
    default.damping_resolution = 200
    assert [default.body_damping_resolution(i) for i in range(3)] == [200, 200, 100_000]


@pytest.mark.parametrize(
    ("value", "error", "match"),
    [
        (0, ValueError, r"^damping_resolution: expected 'full' or the most triangles .*, got 0$"),
        ("coarse", ValueError, r"^damping_resolution: expected 'full' .*, got \"coarse\"$"),
        (1.5, TypeError, r"^damping_resolution: expected 'full' or .*, got float$"),
        (True, TypeError, r"^damping_resolution: expected .*, got bool$"),
    ],
)
def test_damping_resolution_errors(value: Any, error: type[Exception], match: str) -> None:
    with pytest.raises(error, match=match):
        buoyancy.Controller(damping_resolution=value)
    controller = cubes(1)
    with pytest.raises(error, match=match):
        controller.add(buoyancy.shapes.cube(), damping_resolution=value)
    with pytest.raises(error, match=match):
        controller.damping_resolution = value
    with pytest.raises(TypeError, match=r"^damping_resolution: expected"):
        controller.damping_resolution = None
    assert len(controller) == 1 and controller.damping_resolution == 384


@pytest.mark.parametrize(
    ("argument", "value", "match"),
    [
        ("positions", np.zeros((3, 3)), r"^positions: expected shape \(N, 3\) .*N = 2, .*got shape \(3, 3\)$"),
        ("positions", np.zeros((2, 4)), r"^positions: expected shape \(N, 3\) .*got shape \(2, 4\)$"),
        ("positions", np.zeros(6), r"^positions: expected shape \(N, 3\) .*got shape \(6,\)$"),
        ("positions", [["a", "b", "c"]] * 2, r"^positions: expected a float64 array of shape \(N, 3\).*string"),
        ("quaternions", np.zeros((2, 3)), r"^quaternions: expected shape \(N, 4\) \(one quaternion \(x, y, z, w\)"),
        ("quaternions", np.array([IDENTITY, (0.0, 0.0, 0.0, 2.0)]), r"^quaternions\[1\]: the quaternion .* norm 2"),
        ("centers_of_mass", np.zeros((2, 3, 1)), r"^centers_of_mass: expected shape \(N, 3\)"),
        ("linear_velocities", None, r"^linear_velocities: expected shape \(N, 3\) .*got shape \(\)$"),
        ("angular_velocities", np.zeros((1, 3)), r"^angular_velocities: expected shape \(N, 3\)"),
        ("masses", np.zeros((2, 1)), r"^masses: expected shape \(N,\) \(one mass per body\)"),
        ("masses", np.array([500.0, -1.0]), r"^masses\[1\]: must be finite and non-negative$"),
        ("masses", np.array([np.inf, 1.0]), r"^masses\[0\]: must be finite and non-negative$"),
        ("inverse_masses", np.zeros((2, 2)), r"^inverse_masses: expected shape \(N, 3\) or \(N,\)"),
        ("inverse_masses", np.array([[0.0, 0.0, 0.0], [0.0, -1.0, 0.0]]), r"^inverse_masses\[1\]: must be finite"),
        ("inverse_inertias", np.zeros((2, 3)), r"^inverse_inertias: expected shape \(N, 3, 3\)"),
        ("inverse_inertias", np.full((2, 3, 3), np.nan), r"^inverse_inertias\[0\]: has a NaN or infinite component$"),
        ("gravity_scales", np.ones(3), r"^gravity_scales: expected shape \(N,\)"),
        ("gravity_scales", np.array([1.0, np.nan]), r"^gravity_scales\[1\]: has a NaN or infinite component$"),
        ("applied_forces", np.zeros((2, 2), np.float32), r"^applied_forces: expected shape \(N, 3\)"),
        ("applied_torques", np.zeros((3, 3), np.float32), r"^applied_torques: expected shape \(N, 3\)"),
        ("dynamic", np.ones(3, bool), r"^dynamic: expected shape \(N,\) \(one flag per body\)"),
        ("sleeping", True, r"^sleeping: expected shape \(N,\) .*got shape \(\)$"),
    ],
)
def test_step_errors_name_the_argument(argument: str, value: Any, match: str) -> None:
    controller = cubes(2)
    with pytest.raises(ValueError, match=match):
        controller.step(1 / 60, **states(2, **{argument: value}))
    # Nothing was computed.
    assert controller.report(0).outcome == "not_evaluated"


@pytest.mark.parametrize("dt", [-0.1, float("nan"), float("inf")])
def test_step_dt_must_be_finite_and_non_negative(dt: float) -> None:
    with pytest.raises(ValueError, match="^dt: must be finite and non-negative"):
        cubes(1).step(dt, **states(1))
    with pytest.raises(TypeError, match="^dt: expected a number, got str"):
        cubes(1).step("0.1", **states(1))  # type: ignore[arg-type]


def test_step_converts_other_dtypes_and_layouts() -> None:
    reference, _, _ = cubes(2).step(1 / 60, **states(2))
    table = np.zeros((2, 8))
    table[:, 6] = 1.0
    variants: list[dict[str, Any]] = [
        # Lists, float32, ints, Fortran order, strided columns of one table.
        {"positions": [[0, 0, 0], [0, 0, 0]], "masses": [500, 500], "dynamic": [1, 1], "sleeping": [0, 0]},
        {"positions": np.zeros((2, 3), np.float32), "inverse_masses": np.full(2, 1 / 500.0)},
        {"applied_forces": np.zeros((2, 3)), "applied_torques": [[0, 0, 0]] * 2},
        {"inverse_inertias": np.asfortranarray(np.tile(np.eye(3) * 6 / 500.0, (2, 1, 1)))},
        {"positions": table[:, 0:3], "quaternions": table[:, 3:7], "centers_of_mass": table[:, 0:6:2]},
    ]
    for change in variants:
        f, _, _ = cubes(2).step(1 / 60, **states(2, **change))
        np.testing.assert_array_equal(f, reference, err_msg=str(change))


def test_no_bodies() -> None:
    f, t, wake = buoyancy.Controller().step(0.01, **states(0))
    assert f.shape == (0, 3) and t.shape == (0, 3) and wake.shape == (0,)


def test_add_and_index_errors() -> None:
    controller = buoyancy.Controller()
    cube = buoyancy.shapes.cube()
    with pytest.raises(ValueError, match="^parts: a floating body needs at least one mesh$"):
        controller.add([])
    with pytest.raises(TypeError, match="^parts: expected a Mesh, or a list of parts, .* got str$"):
        controller.add("cube")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"^parts\[1\]: expected a Mesh or a \(mesh, position, quaternion\) tuple"):
        controller.add([cube, 3])  # type: ignore[list-item]
    with pytest.raises(TypeError, match=r"^parts\[0\]: expected .* got a tuple of 2 items$"):
        controller.add([(cube, (0, 0, 0))])  # type: ignore[list-item]
    with pytest.raises(TypeError, match=r"^parts\[0\]\[0\]: expected a buoyancy.Mesh, got str$"):
        controller.add([("cube", (0, 0, 0), IDENTITY)])  # type: ignore[list-item]
    with pytest.raises(ValueError, match=r"^parts\[0\]\[1\] \(position\): expected 3 numbers"):
        controller.add([(cube, (0, 0), IDENTITY)])
    with pytest.raises(ValueError, match=r"^parts\[0\]\[2\] \(quaternion\): the quaternion .* norm"):
        controller.add([(cube, (0, 0, 0), (0, 0, 0, 2))])
    with pytest.raises(ValueError, match="^method: "):
        controller.add(cube, method="bogus")
    with pytest.raises(TypeError, match="^water: expected a buoyancy.Water, got float$"):
        controller.add(cube, water=1000.0)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="^water: a body's water must be still.*the waves are the controller's"):
        controller.add(cube, water=buoyancy.Water(waves=buoyancy.AiryWave(0.1, 5.0)))
    with pytest.raises(TypeError, match="^damping: expected a buoyancy.DampingCoefficients, got buoyancy.Water$"):
        controller.add(cube, damping=buoyancy.Water())  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="^water: expected a buoyancy.Water, got NoneType$"):
        controller.water = None  # type: ignore[assignment]
    assert len(controller) == 0  # nothing was added
    assert controller.add(cube) == 0 and controller.add([cube]) == 1
    for call in (controller.report, controller.forget_applied, controller.remove, controller.parts):
        with pytest.raises(IndexError, match="^index: no body 2; the controller has 2"):
            call(2)
        with pytest.raises(IndexError, match="^index: no body -1"):
            call(-1)
        with pytest.raises(TypeError, match="^index: expected an integer, got str$"):
            call("0")  # type: ignore[arg-type]
    with pytest.raises(IndexError, match="^index: no body 5"):
        controller.replace(5, cube)


def test_float_report() -> None:
    controller = cubes(1)
    controller.step(1 / 60, **states(1, linear_velocities=np.array([[0.3, -0.2, 0.0]])))
    report = controller.report(0)
    assert pickle.loads(pickle.dumps(report)) == report
    assert repr(report).startswith("FloatReport(outcome='applied', submerged_volume=0.5, ")
    assert report != buoyancy.FloatReport()
    assert buoyancy.FloatReport().outcome == "not_evaluated"
    with pytest.raises(ValueError, match="^outcome: unknown outcome 'done'; expected one of 'not_evaluated'"):
        buoyancy.FloatReport(outcome="done")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="^center_of_mass: expected 3 numbers"):
        buoyancy.FloatReport(center_of_mass=(1, 2))
    with pytest.raises(ValueError, match="read-only"):
        report.buoyancy_force[0] = 1.0
    with pytest.warns(DeprecationWarning, match="outcome"):
        assert report.skipped is False


def test_threads_share_nothing() -> None:
    # The step releases the interpreter lock: controllers stepped from several threads at once
    # give what they give one at a time.
    n = 50
    rng = np.random.default_rng(5)
    change = {
        "positions": rng.uniform(-0.5, 0.5, (n, 3)),
        "linear_velocities": rng.normal(size=(n, 3)),
        "angular_velocities": rng.normal(size=(n, 3)),
    }
    mesh = buoyancy.shapes.uv_sphere(0.5, 64, 32)

    def run() -> np.ndarray:
        controller = buoyancy.Controller()
        for _ in range(n):
            controller.add(mesh)
        return controller.step(1 / 60, **states(n, **change))[0]

    expected = run()
    results: list[np.ndarray] = []
    threads = [threading.Thread(target=lambda: results.append(run())) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert len(results) == 4
    for result in results:
        np.testing.assert_array_equal(result, expected)


def test_one_controller_shared_by_threads_takes_their_calls_in_turn() -> None:
    # Once `RuntimeError('Already borrowed')` for a call while another thread stepped (the step
    # runs without the interpreter lock). Now each call waits for the one before: four threads
    # stepping and reading one controller get what the same calls give one after another.
    n = 40
    mesh = buoyancy.shapes.uv_sphere(0.5, 64, 32)
    change = {"positions": np.random.default_rng(3).uniform(-0.5, 0.5, (n, 3))}
    controller = buoyancy.Controller()
    for _ in range(n):
        controller.add(mesh)
    expected = buoyancy.Controller()
    for _ in range(n):
        expected.add(mesh)
    reference = expected.step(0.0, **states(n, **change))[0]
    errors: list[BaseException] = []
    forces: list[np.ndarray] = []
    barrier = threading.Barrier(4)

    def work() -> None:
        try:
            barrier.wait()
            for _ in range(20):
                forces.append(controller.step(0.0, **states(n, **change))[0])
                assert len(controller) == n
                assert controller.report(0).submerged_volume > 0
                repr(controller)
        except BaseException as error:  # reported below, in the main thread
            errors.append(error)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert errors == []
    assert len(forces) == 80
    # dt = 0 and no force held by the engine at each step: every step of the same states adds
    # the whole buoyancy again, as the first of a fresh controller does.
    for force in forces:
        np.testing.assert_array_equal(force, reference)


def test_a_surface_function_that_calls_its_controller_is_told_it_cannot() -> None:
    controller = buoyancy.Controller()

    def surface(points: np.ndarray, t: float) -> np.ndarray:
        len(controller)  # from within the controller's own step
        return np.zeros(len(points))

    controller.water = buoyancy.Water(waves=surface)
    controller.add(buoyancy.shapes.cube())
    with pytest.raises(RuntimeError, match="called from within its own step"):
        controller.step(1 / 60, **states(1))
    # The controller is not left locked.
    controller.water = buoyancy.Water()
    controller.step(1 / 60, **states(1))
    assert len(controller) == 1


@pytest.mark.parametrize("name", ["Controller", "Controller.add", "FloatReport", "shapes.wigley_hull"])
def test_docstring_examples(name: str) -> None:
    obj: Any = buoyancy
    for part in name.split("."):
        obj = getattr(obj, part)
    assert run_examples(obj.__doc__ or "", name) > 0


def test_stubs_list_every_public_name() -> None:
    import pathlib
    import re

    stub = (pathlib.Path(buoyancy.__file__).parent / "_core.pyi").read_text()
    for cls in (buoyancy.Controller, buoyancy.FloatReport):
        assert re.search(rf"^class {cls.__name__}\b", stub, re.M), cls.__name__
        for name in (n for n in dir(cls) if not n.startswith("_")):
            assert re.search(rf"def {name}\b", stub), f"{cls.__name__}.{name} missing from the stub"


# --- waves -------------------------------------------------------------------------------------

SWELL = buoyancy.AiryWave(amplitude=0.1, wavelength=20.0)  # along +x, deep water
K = 2 * np.pi / 20.0  # rad/m
OMEGA = np.sqrt(9.81 * K)  # rad/s, deep-water dispersion


def tilted() -> np.ndarray:
    """A unit quaternion (x, y, z, w): 10° about z, then 5° about x."""
    a, b = np.radians(10.0) / 2, np.radians(5.0) / 2
    qz = np.array([0.0, 0.0, np.sin(a), np.cos(a)])
    qx = np.array([np.sin(b), 0.0, 0.0, np.cos(b)])
    x1, y1, z1, w1 = qx
    x2, y2, z2, w2 = qz
    return np.array(
        [
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
            w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
        ]
    )


def held(position: Any, quaternion: Any, center: Any, velocity: Any = (0.0, 0.0, 0.0)) -> dict[str, Any]:
    """``step``'s pose and velocity arrays of one body held at a pose."""
    return {
        "positions": np.array([position], float),
        "quaternions": np.array([quaternion], float),
        "centers_of_mass": np.array([center], float),
        "linear_velocities": np.array([velocity], float),
    }


def test_on_waves_a_body_held_fixed_feels_the_buoyancy_at_the_controllers_time() -> None:
    # Against the mesh's own buoyancy on the same water at the controller's time: a tilted cube
    # 0.1 m below its half-submerged height, 1.3 m along the wave, held there for two seconds
    # (a fifth of a period of the 20 m swell, 3.58 s), no damping.
    water = buoyancy.Water(waves=SWELL)
    controller = cubes(1, water=water, damping=buoyancy.DampingCoefficients.off())
    assert controller.water is water and controller.time == 0.0
    engine = Engine(controller, 1)
    cube = buoyancy.shapes.cube()
    position, q = np.array([1.3, -0.1, 0.4]), tilted()
    center = position + np.array([0.05, -0.1, 0.0])
    volumes = []
    for k in range(120):
        t = controller.time
        assert t == pytest.approx(k / 60, abs=1e-12)
        engine.step(**held(position, q, center))
        expected = cube.buoyancy(position, q, water=water, about=center, time=t)
        report = controller.report(0)
        assert report.outcome == "applied"
        assert report.submerged_volume == pytest.approx(expected.volume, rel=1e-12)
        np.testing.assert_allclose(report.center_of_buoyancy, expected.center, atol=1e-12)
        np.testing.assert_allclose(report.buoyancy_force, expected.force, rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(report.buoyancy_torque, expected.torque, rtol=1e-12, atol=1e-9)
        np.testing.assert_array_equal(report.damping_force, 0.0)
        # What the engine holds is the buoyancy, in float32 (added up step after step).
        np.testing.assert_allclose(engine.forces[0], expected.force, rtol=1e-6, atol=1e-3)
        volumes.append(report.submerged_volume)
    assert controller.time == pytest.approx(2.0, abs=1e-12)
    # The wave moved: the volume under water changed by a good part of the wave's 0.1 m.
    assert max(volumes) - min(volumes) > 0.05


def test_on_waves_the_damping_is_relative_to_the_orbital_velocity() -> None:
    # The deep-water orbital velocity of η = a cos(kx − ωt) at depth y: a ω e^{ky} (cos, sin).
    water = buoyancy.Water(waves=SWELL)
    controller = cubes(1, water=water)
    controller.time = 0.7
    position = np.array([2.0, -0.2, 0.0])
    phase = K * position[0] - OMEGA * controller.time
    orbital = 0.1 * OMEGA * np.exp(K * position[1]) * np.array([np.cos(phase), np.sin(phase), 0.0])
    # Moving with the water: no damping.
    controller.step(1 / 60, **states(1, **held(position, IDENTITY, position, orbital)))
    np.testing.assert_allclose(controller.report(0).damping_force, 0.0, atol=1e-9)
    np.testing.assert_allclose(controller.report(0).damping_torque, 0.0, atol=1e-9)
    # At rest in the moving water: dragged along with it.
    controller.time = 0.7
    controller.step(1 / 60, **states(1, **held(position, IDENTITY, position)))
    drag = controller.report(0).damping_force
    assert np.dot(drag, orbital) > 0.5 * np.linalg.norm(drag) * np.linalg.norm(orbital)
    # In still water the same body at rest feels no damping.
    still = cubes(1)
    still.step(1 / 60, **states(1, **held(position, IDENTITY, position)))
    np.testing.assert_array_equal(still.report(0).damping_force, 0.0)


def test_time_advances_by_dt_and_is_settable() -> None:
    controller = cubes(2, water=buoyancy.Water(waves=SWELL))
    for dt in (0.01, 0.25, 0.0, 1 / 60):
        before = controller.time
        controller.step(dt, **states(2))
        assert controller.time == before + dt
    controller.time = 100.0
    assert controller.time == 100.0
    controller.step(0.5, **states(2))
    assert controller.time == 100.5
    # A NaN, infinite or negative dt is refused, the time left as it was.
    for dt in (float("nan"), float("inf"), -0.1):
        with pytest.raises(ValueError, match="^dt: must be finite and non-negative"):
            controller.step(dt, **states(2))
        assert controller.time == 100.5
    with pytest.raises(ValueError, match="^time: must be finite"):
        controller.time = float("nan")
    with pytest.raises(TypeError, match="^time: expected a number"):
        controller.time = None  # type: ignore[assignment]
    assert controller.time == 100.5
    # The time runs in still water too, and a new water keeps it.
    controller.water = buoyancy.Water()
    controller.step(0.5, **states(2))
    assert controller.time == 101.0
    controller.water = buoyancy.Water(waves=SWELL)
    assert repr(controller).endswith("method='exact', time=101)")


def test_every_surface_of_water_floats_the_bodies() -> None:
    # An Airy wave, the same as Waves, as a callable, and as a Gerstner wave or a height grid
    # of the same elevation along a crest: the same buoyancy as the mesh's on that water.
    cube = buoyancy.shapes.cube(2)
    position, q = np.array([0.7, 0.05, -0.3]), tilted()

    def airy(points: np.ndarray, t: float) -> np.ndarray:
        return 0.1 * np.cos(K * points[:, 0] - OMEGA * t)

    x = np.arange(64) * 0.5
    grid = buoyancy.HeightGrid(np.tile(0.1 * np.cos(2 * np.pi * x / 32.0), (4, 1)), spacing=0.5)
    for waves in (
        SWELL,
        buoyancy.Waves([SWELL]),
        airy,
        buoyancy.GerstnerWaves([buoyancy.AiryWave(0.05, 10.0)]),
        grid,
    ):
        water = buoyancy.Water(waves=waves)
        controller = buoyancy.Controller(water, damping=buoyancy.DampingCoefficients.off())
        for _ in range(8):  # in parallel: the callable takes the interpreter lock from each thread
            controller.add(cube)
        controller.time = 1.25
        controller.step(
            1 / 60, **states(8, **{k: np.repeat(v, 8, axis=0) for k, v in held(position, q, position).items()})
        )
        expected = cube.buoyancy(position, q, water=water, about=position, time=1.25)
        for i in range(8):
            report = controller.report(i)
            assert report.submerged_volume == pytest.approx(expected.volume, rel=1e-12), waves
            np.testing.assert_allclose(report.buoyancy_force, expected.force, rtol=1e-12, atol=1e-9)
    # The callable is the Airy wave: the same force.
    on_airy = [buoyancy.Controller(buoyancy.Water(waves=w)) for w in (SWELL, airy)]
    for c in on_airy:
        c.add(cube)
        c.step(1 / 60, **states(1, **held(position, q, position)))
    np.testing.assert_allclose(
        on_airy[0].report(0).buoyancy_force, on_airy[1].report(0).buoyancy_force, rtol=1e-12, atol=1e-9
    )


def test_a_height_grid_set_between_steps_floats_the_next_step() -> None:
    grid = buoyancy.HeightGrid(np.zeros((4, 4)), spacing=2.0)
    controller = cubes(1, water=buoyancy.Water(waves=grid), damping=buoyancy.DampingCoefficients.off())
    controller.step(1 / 60, **states(1))
    assert controller.report(0).submerged_volume == pytest.approx(0.5, abs=1e-12)
    grid.set_heights(np.full((4, 4), 0.2))
    controller.step(1 / 60, **states(1))
    assert controller.report(0).submerged_volume == pytest.approx(0.7, abs=1e-12)


def test_a_surface_function_that_fails_undoes_the_step() -> None:
    calls = []

    def surface(points: np.ndarray, t: float) -> np.ndarray:
        calls.append(t)
        if len(calls) > 2:
            raise ZeroDivisionError("the sea broke")
        return np.full(len(points), 0.1)

    controller = cubes(2, water=buoyancy.Water(waves=surface))
    engine = Engine(controller, 2)
    engine.step()
    assert controller.time == pytest.approx(1 / 60)
    reports = [controller.report(i) for i in range(2)]
    forces = engine.forces.copy()
    with pytest.raises(ZeroDivisionError, match="the sea broke"):
        engine.step(positions=np.array([[0.0, 0.1, 0.0], [0.0, -0.1, 0.0]]))
    # Nothing applied, the books and the time as they were.
    assert controller.time == pytest.approx(1 / 60)
    assert [controller.report(i) for i in range(2)] == reports
    np.testing.assert_array_equal(engine.forces, forces)
    # A function that returns the wrong shape: a ValueError naming the water.
    controller.water = buoyancy.Water(waves=lambda p, t: np.zeros(2))
    with pytest.raises(ValueError, match=r"^water: waves: the surface function returned shape \(2,\)"):
        engine.step()
    assert controller.time == pytest.approx(1 / 60)
    # Back to a good one: the step goes on from the books as they were.
    controller.water = buoyancy.Water(waves=lambda p, t: np.full(len(p), 0.1))
    f, _, _ = engine.step()
    np.testing.assert_allclose(f, 0.0, atol=1e-3)  # the buoyancy the engine holds already
    assert controller.time == pytest.approx(2 / 60)


def test_waves_of_the_froude_krylov_pressure_are_taken_and_a_flat_method_is_refused() -> None:
    fk = buoyancy.Water(waves=buoyancy.Waves([SWELL], pressure="froude_krylov"))
    hydrostatic = buoyancy.Water(waves=buoyancy.Waves([SWELL]))
    forces = {}
    for name, water in [("fk", fk), ("hydrostatic", hydrostatic)]:
        controller = cubes(1, water=water)
        controller.step(1 / 60, **states(1, positions=np.array([[0.0, -0.8, 0.0]])))
        report = controller.report(0)
        assert report.outcome == "applied"
        forces[name] = report.buoyancy_force
    # The cube's top 0.3 m under the still level: the same mesh's buoyancy under each pressure.
    cube = buoyancy.shapes.cube()
    for name, water in [("fk", fk), ("hydrostatic", hydrostatic)]:
        expected = cube.buoyancy(position=(0, -0.8, 0), water=water, time=0.0).force
        np.testing.assert_allclose(forces[name], expected, rtol=1e-9, atol=1e-6)
    assert not np.allclose(forces["fk"], forces["hydrostatic"], rtol=1e-6)
    # A method that assumes a flat surface: no force, and the report says why.
    controller = cubes(1, water=hydrostatic, method="fast")
    controller.step(1 / 60, **states(1, positions=np.array([[0.0, -0.2, 0.0]])))
    assert controller.report(0).outcome == "unsupported"
    np.testing.assert_array_equal(controller.report(0).buoyancy_force, 0.0)
