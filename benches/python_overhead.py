"""Python-side performance of the bindings (a benchmark script, not a test).

    python benches/python_overhead.py [--poses 10000] [--repeat 7]

1. Per-call cost of ``mesh.buoyancy`` on the 12-triangle cube (goal: at most 3 µs), for the
   argument forms people use: tuples, numpy arrays, keywords with water and method.
2. ``buoyancy_batch`` over 10,000 poses of the Stanford bunny (5,002 triangles; the torus knot if
   the shared meshes are absent), on a pool of 1 and of 2 threads (goal: at least 1.7× faster
   on 2). Best of ``--repeat`` runs each; the machine's other load makes every figure noisy.
"""

from __future__ import annotations

import argparse
import os
import pathlib
import sys
import time
import timeit

import numpy as np

import buoyancy
from buoyancy._sample_meshes import find_sample_mesh, not_found_message

REPO = pathlib.Path(__file__).resolve().parents[1]


def best_per_call(stmt, number: int, repeat: int) -> float:  # type: ignore[no-untyped-def]
    return min(timeit.repeat(stmt, number=number, repeat=repeat)) / number


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--poses", type=int, default=10_000)
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()

    print(f"buoyancy {buoyancy.__version__}, Python {sys.version.split()[0]}, {os.cpu_count()} CPUs\n")
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
    return 0


if __name__ == "__main__":
    sys.exit(main())
