"""Python-side performance of the bindings (a benchmark script, not a test).

    python benches/python_overhead.py [--poses 10000] [--repeat 7]
                                      [--only calls|batch|rapier|mujoco|add]
                                      [--bodies 100] [--steps 30] [--before REV]

1. Per-call cost of ``mesh.buoyancy`` on the 12-triangle cube (goal: at most 3 µs), for the
   argument forms people use: tuples, numpy arrays, keywords with water and method.
2. ``buoyancy_batch`` over 10,000 poses of the Stanford bunny (5,002 triangles; the torus knot if
   the shared meshes are absent), on a pool of 1 and of 2 threads (goal: at least 1.7× faster
   on 2). Best of ``--repeat`` runs each; the machine's other load makes every figure noisy.
3. ``buoyancy.rapier``: ``FloatingBodies.apply`` per body for 100 bodies of rapier3d (the
   12-triangle cube, and the bunny scaled to a bounding radius of 0.3 m as in the Rust adapter's
   ``cargo bench -p buoyancy-rapier --bench step``), half submerged, tilted and moving; against
   the cost of the controller's own step (``Controller.step`` on the same arrays: the Rust work,
   with its argument checks), so that the difference is the Python glue (goal: at most 5 µs per
   body). ``--before REV`` times the ``buoyancy/rapier.py`` of a git revision too (the Python
   re-implementation before the controller: ``--before ced904e``). Each figure is the median
   step of a burst of ``--steps`` steps, the best of ``--repeat`` bursts, the implementations
   taking turns so that the machine's load weighs on all of them alike.
4. ``buoyancy.mujoco``: ``FloatingBodies.apply`` per body for 100 bodies of a MuJoCo model
   (box geoms of 12 triangles; the same boxes floating with the bunny's mesh; and boxes on
   hinges, whose masses the adapter reads through the joints, ``J·M⁻¹·Jᵀ``), half submerged,
   tilted and moving; against ``Controller.step`` on the same arrays, so that the difference is
   the Python glue (goal: at most 5 µs per body), and ``mj_step`` for scale. Medians of bursts
   of ``--steps`` steps, best of ``--repeat``.
5. ``Controller.add`` of 1,000 bodies of a sphere of 2,352 triangles (more than the damping's
   reduced copy takes): all of one ``Mesh``, and each of its own equal ``Mesh`` (built in the
   loop, its own cost timed apart). The bodies share the core mesh and its reduced copy, built
   once; best of ``--repeat`` runs. First, on Linux, the memory the process holds once the
   1,000 bodies of equal ``Mesh``es are added (resident set growth, from ``/proc/self/statm``).
"""

from __future__ import annotations

import argparse
import os
import pathlib
import subprocess
import sys
import time
import timeit
import types
from typing import Any

import numpy as np

import buoyancy
from buoyancy._sample_meshes import find_sample_mesh, not_found_message

REPO = pathlib.Path(__file__).resolve().parents[1]


def best_per_call(stmt, number: int, repeat: int) -> float:  # type: ignore[no-untyped-def]
    return min(timeit.repeat(stmt, number=number, repeat=repeat)) / number


def calls(args: argparse.Namespace) -> None:
    cube = buoyancy.shapes.cube(1)
    assert cube.n_triangles == 12
    water = buoyancy.Water(density=1025.0)
    p_tuple, q_tuple = (0.1, -0.2, 0.05), (0.0, 0.0, 0.19509032201612825, 0.9807852804032304)
    p_np, q_np = np.array(p_tuple), np.array(q_tuple)
    cases = {
        "cube.buoyancy()": lambda: cube.buoyancy(),
        "cube.buoyancy(p) [tuple]": lambda: cube.buoyancy(p_tuple),
        "cube.buoyancy(p, q) [tuples]": lambda: cube.buoyancy(p_tuple, q_tuple),
        "cube.buoyancy(p, q) [numpy arrays]": lambda: cube.buoyancy(p_np, q_np),
        "cube.buoyancy(p, q, water=w, method='exact')": lambda: cube.buoyancy(
            p_tuple, q_tuple, water=water, method="exact"
        ),
        "cube.buoyancy(p, q).force  [+ result array]": lambda: cube.buoyancy(p_tuple, q_tuple).force,
    }
    print("## Per call, 12-triangle cube (goal <= 3 µs)\n")
    print("| call | µs per call |")
    print("|---|---|")
    for name, f in cases.items():
        print(f"| `{name}` | {best_per_call(f, 20_000, args.repeat) * 1e6:.2f} |")


def batch(args: argparse.Namespace) -> None:
    bunny = find_sample_mesh("bunny.obj", REPO)
    if bunny is not None:
        mesh, name = buoyancy.load(bunny), "bunny"
    else:
        print(f"\nnote: {not_found_message(REPO, 'bunny.obj')}; using a procedural torus knot instead")
        mesh, name = buoyancy.shapes.torus_knot(segments=250, sides=10), "torus knot"
    rng = np.random.default_rng(1)
    k = args.poses
    positions = mesh.centroid + rng.uniform(-0.6, 0.6, size=(k, 3)) * 2 * mesh.bounding_radius
    q = rng.normal(size=(k, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    print(f"\n## buoyancy_batch, {name} ({mesh.n_triangles} triangles), {k} random poses (goal: 2 threads >= 1.7x)\n")
    print("| threads | ms per batch (best) | µs per pose | speed-up | CPU ms | CPU time / wall time |")
    print("|---|---|---|---|---|---|")
    base = None
    cpu_used = {}
    for threads in (1, 2):
        mesh.buoyancy_batch(positions[:100], q[:100], threads=threads)  # build the pool, warm up
        best, utilisation = float("inf"), 0.0
        for _ in range(args.repeat):
            wall, cpu = time.perf_counter(), time.process_time()
            mesh.buoyancy_batch(positions, q, threads=threads)
            wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
            if wall < best:
                best, utilisation, cpu_used[threads] = wall, cpu / wall, cpu
        base = base or best
        print(
            f"| {threads} | {best * 1e3:.1f} | {best / k * 1e6:.2f} | {base / best:.2f}x "
            f"| {cpu_used[threads] * 1e3:.0f} | {utilisation:.2f} |"
        )
    # On a machine shared with other work, the wall-clock speed-up is capped by the CPU share
    # this process gets. The CPU time tells the parallel overhead regardless: with the work
    # split evenly (rayon's work stealing), two idle cores give 2 × cpu(1) / cpu(2).
    print(f"\nspeed-up expected on 2 idle cores from the CPU times: {2 * cpu_used[1] / cpu_used[2]:.2f}x")
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(
        f"\n(load average over the last minute when done: {load:.2f} on {os.cpu_count()} CPUs; "
        "a busy machine caps the speed-up)"
    )
    b = mesh.buoyancy_batch(positions, q)
    print(f"\n({int(np.sum(b.partially_submerged > 0))} of {k} poses cut by the surface)")


def bunny_or_knot() -> tuple[str, buoyancy.Mesh]:
    """The bunny scaled to a bounding radius of 0.3 m about its centroid (the torus knot when the
    shared meshes are absent), as in the Rust adapter's benchmark."""
    path = find_sample_mesh("bunny.obj", REPO)
    if path is None:
        name, mesh = "torus knot", buoyancy.shapes.torus_knot(2, 3, 1.0, 0.3, 256, 16)
    else:
        name, mesh = "bunny", buoyancy.load(path)
    return name, buoyancy.Mesh((mesh.vertices - mesh.centroid) * (0.3 / mesh.bounding_radius), mesh.faces)


def rapier_module_at(revision: str) -> types.ModuleType:
    """``buoyancy/rapier.py`` as it was at the git ``revision``, as a module of the installed
    package (its relative imports are the installed ``buoyancy._core``'s)."""
    source = subprocess.run(
        ["git", "-C", str(REPO), "show", f"{revision}:python/buoyancy/rapier.py"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    module = types.ModuleType("buoyancy._rapier_before")
    module.__package__ = "buoyancy"
    module.__file__ = f"{revision}:python/buoyancy/rapier.py"
    sys.modules[module.__name__] = module  # dataclasses look their module up
    exec(compile(source, module.__file__, "exec"), module.__dict__)
    return module


class Scene:
    """``bodies`` bodies of ``mesh`` (density 500 kg/m³) in a rapier3d world, floating with the
    ``FloatingBodies`` of ``adapter``: half submerged, tilted and moving, awake."""

    def __init__(self, adapter: Any, mesh: buoyancy.Mesh, bodies: int) -> None:
        import rapier3d

        self.world = rapier3d.PhysicsWorld(gravity=(0.0, -9.81, 0.0))
        self.floating = adapter.FloatingBodies.for_world(self.world)
        self.bodies = bodies
        spacing = 2.5 * mesh.bounding_radius
        size = 2.0 * mesh.bounding_radius
        vertices, faces = mesh.vertices.astype(np.float32), mesh.faces.astype(np.uint32)
        for i in range(bodies):
            position = ((i % 10) * spacing, size * (-0.05 + 0.01 * (i % 7)), (i // 10) * spacing)
            body = rapier3d.RigidBody.dynamic().translation(position).rotation((0.1 * (i % 5), 0.3, 0.0))
            body = body.linvel((0.2, -0.5, 0.1)).angvel((0.3, 0.0, -0.2)).can_sleep(False)
            handle = self.world.add_body(body, [rapier3d.Collider.trimesh(vertices, faces).density(500.0)])
            self.floating.register(handle, mesh)
        self.dt = self.world.integration_parameters.dt

    def burst(self, steps: int) -> dict[str, float]:
        """Over ``steps`` steps, the medians, s per body, of ``apply``, of the glue in it
        (``apply`` less the time inside ``Controller.step``, NaN for an adapter without a
        controller), of the glue's CPU time on this thread (which the machine's other load does
        not inflate as it does wall-clock times), and of ``world.step``."""
        inner: list[tuple[float, float]] = []
        controller = getattr(self.floating, "_controller", None)
        if controller is not None:
            self.floating._controller = _Timed(controller, inner)
        times: dict[str, list[float]] = {"apply": [], "glue": [], "glue_cpu": [], "world": []}
        try:
            for _ in range(steps):
                inner.clear()
                t0, c0 = time.perf_counter(), time.thread_time()
                self.floating.apply(self.world.rigid_bodies, self.dt)
                t1, c1 = time.perf_counter(), time.thread_time()
                self.world.step()
                t2 = time.perf_counter()
                times["apply"].append(t1 - t0)
                times["glue"].append(t1 - t0 - sum(t for t, _ in inner) if controller is not None else np.nan)
                times["glue_cpu"].append(c1 - c0 - sum(c for _, c in inner) if controller is not None else np.nan)
                times["world"].append(t2 - t1)
        finally:
            if controller is not None:
                self.floating._controller = controller
        return {key: float(np.median(t)) / self.bodies for key, t in times.items()}

    def controller_burst(self, steps: int) -> float:
        """The median ``Controller.step`` alone on the arrays of the scene's current state, s per
        body (the controller-based adapter's)."""
        floating = self.floating
        _, record, scalars = floating._read(self.world.rigid_bodies)
        states = list(floating._states(record, scalars))
        # Each call a velocity other than the last call's (a nudge of 10⁻⁶ m/s back and forth),
        # as in a simulation: the same inputs again would take the last evaluations again.
        velocities = (np.array(states[3]), np.array(states[3]) + np.array([1e-6, 0.0, 0.0]))
        step = floating._controller.step
        times = []
        for k in range(steps):
            states[3] = velocities[k % 2]
            t0 = time.perf_counter()
            step(self.dt, *states)
            times.append(time.perf_counter() - t0)
        return float(np.median(times)) / self.bodies


class _Timed:
    """A controller whose ``step`` calls add their wall-clock duration and this thread's CPU
    time in them to ``times``."""

    def __init__(self, controller: Any, times: list[tuple[float, float]]) -> None:
        self._controller, self._times = controller, times

    def step(self, *args: Any) -> Any:
        t0, c0 = time.perf_counter(), time.thread_time()
        try:
            return self._controller.step(*args)
        finally:
            self._times.append((time.perf_counter() - t0, time.thread_time() - c0))

    def __getattr__(self, name: str) -> Any:
        return getattr(self._controller, name)


def rapier_overhead(args: argparse.Namespace) -> None:
    try:
        import rapier3d

        import buoyancy.rapier as after
    except ImportError as error:
        print(f"\n## buoyancy.rapier: skipped, rapier3d cannot be imported ({error})")
        return
    before = rapier_module_at(args.before) if args.before else None
    name, bunny = bunny_or_knot()
    meshes = [("cube", buoyancy.shapes.cube()), (name, bunny)]
    print(
        f"\n## buoyancy.rapier: FloatingBodies.apply for {args.bodies} bodies, µs per body "
        f"(rapier3d {rapier3d._rapier3d.__version__}; goal: glue <= 5 µs)\n"
    )
    header = "| mesh | triangles |" + (f" before ({args.before}) |" if before else "")
    header += " apply | Controller.step | glue: apply − Controller.step | glue, CPU time | world.step |"
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    for label, mesh in meshes:
        scenes = {"after": Scene(after, mesh, args.bodies)}
        if before is not None:
            scenes["before"] = Scene(before, mesh, args.bodies)
        best: dict[str, float] = {}
        steps = args.steps if mesh.n_triangles < 1000 else max(5, args.steps // 3)
        for _ in range(args.repeat):
            for key, scene in scenes.items():
                timings = scene.burst(steps)
                best[key] = min(best.get(key, np.inf), timings["apply"])
                if key == "after":
                    for name in ("glue", "glue_cpu", "world"):
                        best[name] = min(best.get(name, np.inf), timings[name])
            best["controller"] = min(best.get("controller", np.inf), scenes["after"].controller_burst(steps))
        row = f"| {label} | {mesh.n_triangles} |"
        if before is not None:
            row += f" {best['before'] * 1e6:.1f} |"
        row += f" {best['after'] * 1e6:.2f} | {best['controller'] * 1e6:.2f} | {best['glue'] * 1e6:.2f} |"
        row += f" {best['glue_cpu'] * 1e6:.2f} | {best['world'] * 1e6:.2f} |"
        print(row)
    print(
        "\n(apply: read every body's state from rapier3d, one Controller.step, add the forces; "
        "Controller.step: the Rust step alone, with its argument checks, on the arrays of one state; "
        "glue: apply less the time spent inside its Controller.step, step by step, in wall-clock "
        "time and in this thread's CPU time; world.step: rapier's own step, for scale. The "
        "machine's other load makes every wall-clock figure noisy)"
    )


class MujocoScene:
    """``bodies`` boxes (half extents 0.3 × 0.2 × 0.15 m, density 500 kg/m³) in a MuJoCo model,
    on free joints or on hinges (``hinged``), floating with ``buoyancy.mujoco`` (on ``mesh`` when
    given, their geoms otherwise): half submerged, tilted and moving."""

    def __init__(self, bodies: int, mesh: buoyancy.Mesh | None, hinged: bool) -> None:
        import mujoco

        from buoyancy.mujoco import FloatingBodies

        joint = '<joint type="hinge" axis="1 0 0"/>' if hinged else "<freejoint/>"
        xml = "".join(
            f'<body name="b{i}" pos="{(i % 10) * 1.0} {(i // 10) * 1.0} {-0.02 + 0.005 * (i % 7)}" '
            f'euler="{3 * (i % 5)} 10 0">{joint}<geom type="box" size="0.3 0.2 0.15" density="500"/></body>'
            for i in range(bodies)
        )
        self.model = mujoco.MjModel.from_xml_string(f"<mujoco><worldbody>{xml}</worldbody></mujoco>")
        self.data = mujoco.MjData(self.model)
        rng = np.random.default_rng(1)
        self.data.qvel[:] = rng.uniform(-0.3, 0.3, self.model.nv)
        self.floating = FloatingBodies.for_model(self.model)
        for i in range(bodies):
            self.floating.register(f"b{i}", mesh)
        self.bodies = bodies
        self.mujoco = mujoco
        mujoco.mj_forward(self.model, self.data)

    def burst(self, steps: int) -> dict[str, float]:
        """Over ``steps`` steps, the medians, s per body, of ``apply``, of the glue in it
        (``apply`` less the time inside ``Controller.step``), of the glue's CPU time on this
        thread, and of the rest of MuJoCo's step (``mj_step2`` after ``mj_step1``)."""
        mujoco, model, data = self.mujoco, self.model, self.data
        inner: list[tuple[float, float]] = []
        controller = self.floating._controller
        self.floating._controller = _Timed(controller, inner)
        times: dict[str, list[float]] = {"apply": [], "glue": [], "glue_cpu": [], "world": []}
        try:
            for _ in range(steps):
                inner.clear()
                mujoco.mj_step1(model, data)
                t0, c0 = time.perf_counter(), time.thread_time()
                self.floating.apply(data)
                t1, c1 = time.perf_counter(), time.thread_time()
                mujoco.mj_step2(model, data)
                t2 = time.perf_counter()
                times["apply"].append(t1 - t0)
                times["glue"].append(t1 - t0 - sum(t for t, _ in inner))
                times["glue_cpu"].append(c1 - c0 - sum(c for _, c in inner))
                times["world"].append(t2 - t1)
        finally:
            self.floating._controller = controller
        return {key: float(np.median(t)) / self.bodies for key, t in times.items()}


def mujoco_overhead(args: argparse.Namespace) -> None:
    try:
        import mujoco
    except ImportError as error:
        print(f"\n## buoyancy.mujoco: skipped, mujoco cannot be imported ({error})")
        return
    name, bunny = bunny_or_knot()
    cases = [
        ("box geoms, free", None, False),
        (f"{name} mesh, free", bunny, False),
        ("box geoms, hinged", None, True),
    ]
    print(
        f"\n## buoyancy.mujoco: FloatingBodies.apply for {args.bodies} bodies, µs per body "
        f"(mujoco {mujoco.__version__}; goal: glue <= 5 µs)\n"
    )
    header = (
        "| bodies | triangles | apply | Controller.step | glue: apply − Controller.step | glue, CPU time | mj_step2 |"
    )
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    for label, mesh, hinged in cases:
        scene = MujocoScene(args.bodies, mesh, hinged)
        triangles = scene.floating.parts("b0")[0][0].n_triangles
        best: dict[str, float] = {}
        steps = args.steps if mesh is None else max(5, args.steps // 3)
        for _ in range(args.repeat):
            for key, value in scene.burst(steps).items():
                best[key] = min(best.get(key, np.inf), value)
        controller = best["apply"] - best["glue"]
        print(
            f"| {label} | {triangles} | {best['apply'] * 1e6:.2f} | {controller * 1e6:.2f} | "
            f"{best['glue'] * 1e6:.2f} | {best['glue_cpu'] * 1e6:.2f} | {best['world'] * 1e6:.2f} |"
        )
    print(
        "\n(apply: read every body's kinematics from MjData (and, for hinged bodies, their masses "
        "through the joints), one Controller.step, add the forces to xfrc_applied; Controller.step: "
        "the Rust step inside it (best apply less best glue); glue: apply less the time spent inside "
        "its Controller.step, step by step, in wall-clock time and in this thread's CPU time; "
        "mj_step2: the rest of MuJoCo's own step, for scale)"
    )


def add_bodies(args: argparse.Namespace) -> None:
    sphere = buoyancy.shapes.uv_sphere(0.62, 49, 25)
    vertices, faces = sphere.vertices, sphere.faces
    n = 1000

    def one_mesh() -> None:
        controller = buoyancy.Controller()
        for _ in range(n):
            controller.add(sphere)

    def equal_meshes() -> None:
        controller = buoyancy.Controller()
        for _ in range(n):
            controller.add(buoyancy.Mesh(vertices, faces))

    def meshes_alone() -> None:
        for _ in range(n):
            buoyancy.Mesh(vertices, faces)

    def resident_mib() -> float | None:
        try:
            pages = int(pathlib.Path("/proc/self/statm").read_text().split()[1])
        except (OSError, ValueError, IndexError):
            return None
        return pages * os.sysconf("SC_PAGE_SIZE") / 2**20

    before = resident_mib()
    controller = buoyancy.Controller()
    for _ in range(n):
        controller.add(buoyancy.Mesh(vertices, faces))
    after = resident_mib()
    del controller
    if before is not None and after is not None:
        print(f"Memory held once {n} bodies of equal Meshes are added: {after - before:.0f} MiB (resident set growth)")
    repeat = max(1, min(args.repeat, 3))
    print(f"Controller.add of {n} bodies of a sphere of {sphere.n_triangles} triangles, best of {repeat}:")
    for name, run in (
        ("one Mesh", one_mesh),
        ("equal Meshes", equal_meshes),
        ("(building the Meshes alone)", meshes_alone),
    ):
        best = min(timeit.repeat(run, number=1, repeat=repeat))
        print(f"  {name:<28} {best:8.3f} s  ({best / n * 1e6:8.1f} µs a body)")
    print()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--poses", type=int, default=10_000)
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--only", choices=["calls", "batch", "rapier", "mujoco", "add"], help="run one section only")
    parser.add_argument(
        "--bodies", type=int, default=100, help="bodies of the rapier and mujoco sections (default 100)"
    )
    parser.add_argument(
        "--steps", type=int, default=30, help="steps per burst of the rapier and mujoco sections (default 30)"
    )
    parser.add_argument(
        "--before", metavar="REV", help="also time buoyancy/rapier.py of this git revision (e.g. ced904e)"
    )
    args = parser.parse_args()

    print(f"buoyancy {buoyancy.__version__}, Python {sys.version.split()[0]}, {os.cpu_count()} CPUs\n")
    sections = {"calls": calls, "batch": batch, "rapier": rapier_overhead, "mujoco": mujoco_overhead, "add": add_bodies}
    for key, section in sections.items():
        if args.only in (None, key):
            section(args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
