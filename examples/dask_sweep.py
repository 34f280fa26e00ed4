"""A stability sweep on a Dask cluster: a family of hull variants, each under many loading
conditions, each with its equilibrium and righting-arm (GZ) curve.

``pip install buoyancy[dask]``, then::

    python examples/dask_sweep.py                      # a LocalCluster of 2 worker processes
    python examples/dask_sweep.py --workers 8 --conditions 400
    python examples/dask_sweep.py --scheduler tcp://10.0.0.5:8786   # any running cluster
    python examples/dask_sweep.py --compare            # also the serial loop, and the speed-up

The hulls are Wigley hulls of several beams (``buoyancy.shapes.wigley_hull``); a loading
condition is a mass (a fraction of the hull's full displacement) and a height of the center of
gravity. For each pair the sweep finds the equilibrium (``Mesh.equilibrium``) and the GZ curve
from 0° to 80° (``Mesh.gz_curve``), and keeps the draft, heel, GM, the maximum GZ and its angle,
the area under the curve to 40° and the angle of vanishing stability.

How it uses the cluster:

* the meshes are sent to the workers once (``client.scatter(..., broadcast=True)``): a task
  carries a reference, not the mesh;
* a task is a chunk of conditions for one hull, so that a task's work (milliseconds per
  condition) outweighs the scheduler's overhead per task (about a millisecond);
* each worker process runs one task at a time on one thread, and rayon (which
  ``Mesh.buoyancy_batch`` would use) is held to that thread with ``RAYON_NUM_THREADS=1``, so
  that the workers together use as many cores as there are workers, not cores²;
* the results come back as plain tuples, gathered into one table (``sweep.csv``) and a plot
  (``sweep.png``: the heel at rest and the maximum GZ against the height of G, one line per
  hull).

A sweep on the cluster gives exactly the rows of the serial loop (``sweep_serial``), bit for
bit: each row is computed by the same function, from the same mesh, in one thread.
"""

from __future__ import annotations

import argparse
import csv
import math
import pathlib
import sys
import time
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

import buoyancy

HEELS = np.arange(0.0, 80.0 + 1e-9, 5.0)
LENGTH, DRAFT, FREEBOARD = 4.0, 0.25, 0.15
COLUMNS = (
    "hull",
    "beam_m",
    "mass_kg",
    "kg_m",
    "draft_m",
    "heel_deg",
    "gm_transverse_m",
    "max_gz_m",
    "angle_of_max_gz_deg",
    "area_to_40_m_rad",
    "vanishing_angle_deg",
)

Row = tuple[Any, ...]


def hulls(beams: Sequence[float]) -> list[tuple[str, float, buoyancy.Mesh]]:
    """Wigley hulls of these beams (x forward, y up, keel at y = -draft)."""
    return [
        (f"wigley_b{beam:g}", beam, buoyancy.shapes.wigley_hull(LENGTH, beam, DRAFT, FREEBOARD, 41, 17))
        for beam in beams
    ]


def conditions(mesh: buoyancy.Mesh, count: int) -> list[tuple[float, float]]:
    """``count`` loading conditions (mass, height of G above the keel), spread over masses from
    a third to nine tenths of the full displacement and G from the keel to the deck."""
    capacity = 1000.0 * mesh.volume
    side = max(1, round(math.sqrt(count)))
    masses = np.linspace(0.35, 0.9, side) * capacity
    heights = np.linspace(0.05, 0.35, math.ceil(count / side))
    return [(float(m), float(h)) for m in masses for h in heights][:count]


def evaluate(name: str, beam: float, mesh: buoyancy.Mesh, mass: float, kg: float) -> Row:
    """One row: the equilibrium and the GZ curve of ``mesh`` of ``mass`` (kg) with its center
    of gravity ``kg`` (m) above the keel; NaN where the body does not float upright enough for a
    figure (an error is the row's, not the sweep's)."""
    cog = (0.0, kg - DRAFT, 0.0)  # mesh frame: the keel is at y = -DRAFT
    try:
        rest = mesh.equilibrium(mass, cog)
        curve = mesh.gz_curve(mass, cog, HEELS)
    except (ValueError, RuntimeError):
        return (name, beam, mass, kg) + (math.nan,) * (len(COLUMNS) - 4)
    vanishing = curve.angle_of_vanishing_stability
    return (
        name,
        beam,
        mass,
        kg,
        rest.draft,
        rest.heel,
        rest.hydrostatics.gm_transverse,
        curve.max_gz,
        curve.angle_of_max_gz,
        curve.area_up_to(40.0),
        math.nan if vanishing is None else vanishing,
    )


def evaluate_chunk(hull: tuple[str, float, buoyancy.Mesh], chunk: Sequence[tuple[float, float]]) -> list[Row]:
    """The rows of one hull under a chunk of conditions (one Dask task)."""
    name, beam, mesh = hull
    return [evaluate(name, beam, mesh, mass, kg) for mass, kg in chunk]


def chunks(items: Sequence[Any], size: int) -> Iterable[Sequence[Any]]:
    for start in range(0, len(items), size):
        yield items[start : start + size]


def sweep_serial(fleet: list[tuple[str, float, buoyancy.Mesh]], count: int) -> list[Row]:
    """The sweep in a plain loop, in this process."""
    return [row for hull in fleet for row in evaluate_chunk(hull, conditions(hull[2], count))]


def sweep(client: Any, fleet: list[tuple[str, float, buoyancy.Mesh]], count: int, chunk_size: int = 16) -> list[Row]:
    """The sweep on a Dask ``client``: the meshes scattered once, a task per chunk of
    conditions, the rows gathered in the serial loop's order."""
    futures = []
    for hull in fleet:
        shared = client.scatter(hull, broadcast=True)
        for chunk in chunks(conditions(hull[2], count), chunk_size):
            futures.append(client.submit(evaluate_chunk, shared, list(chunk), pure=False))
    return [row for rows in client.gather(futures) for row in rows]


def local_cluster(workers: int) -> Any:
    """A LocalCluster of ``workers`` processes, one thread each, rayon held to it."""
    from dask.distributed import LocalCluster

    return LocalCluster(
        n_workers=workers,
        threads_per_worker=1,
        processes=True,
        dashboard_address=None,
        env={"RAYON_NUM_THREADS": "1"},
    )


def write_csv(rows: list[Row], path: pathlib.Path) -> None:
    with path.open("w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(COLUMNS)
        writer.writerows(rows)


def plot(rows: list[Row], path: pathlib.Path) -> bool:
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    mass_of = {}
    for row in rows:
        mass_of.setdefault(row[0], row[2])  # the lightest condition's mass per hull
    for name in dict.fromkeys(row[0] for row in rows):
        own = [r for r in rows if r[0] == name and r[2] == mass_of[name]]
        kg = [r[3] for r in own]
        left.plot(kg, [abs(r[5]) for r in own], "o-", markersize=3, label=name)
        right.plot(kg, [r[7] for r in own], "o-", markersize=3, label=name)
    left.set(
        xlabel="KG [m]", ylabel="|heel| at rest [°]", title="heel at rest: upright until G passes M (lightest loading)"
    )
    right.set(xlabel="KG [m]", ylabel="max GZ [m]", title="maximum righting arm from upright (lightest loading)")
    for ax in (left, right):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def same_rows(a: list[Row], b: list[Row]) -> bool:
    """Equal, bit for bit (NaN equal to NaN)."""

    def key(row: Row) -> tuple[Any, ...]:
        return tuple(v.hex() if isinstance(v, float) else v for v in row)

    return len(a) == len(b) and all(key(x) == key(y) for x, y in zip(a, b, strict=True))


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--beams", type=float, nargs="+", default=[0.4, 0.5, 0.6, 0.7], help="hull beams, m")
    parser.add_argument("--conditions", type=int, default=64, help="loading conditions per hull (default 64)")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler instead of a LocalCluster")
    parser.add_argument("--chunk", type=int, default=16, help="conditions per task (default 16)")
    parser.add_argument("--compare", action="store_true", help="also run the serial loop: speed-up and equality")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("out"), help="output folder (default out)")
    args = parser.parse_args(argv)
    try:
        from dask.distributed import Client
    except ImportError:
        print("this example needs Dask: pip install buoyancy[dask]", file=sys.stderr)
        return 2

    fleet = hulls(args.beams)
    total = len(fleet) * args.conditions
    cluster = None if args.scheduler else local_cluster(args.workers)
    with Client(args.scheduler or cluster) as client:
        workers = len(client.scheduler_info()["workers"])
        print(
            f"{len(fleet)} hulls × {args.conditions} conditions = {total} equilibria and GZ curves on {workers} workers"
        )
        start = time.perf_counter()
        rows = sweep(client, fleet, args.conditions, args.chunk)
        elapsed = time.perf_counter() - start
    if cluster is not None:
        cluster.close()
    print(f"cluster: {elapsed:.2f} s, {total / elapsed:.0f} conditions/s")
    if args.compare:
        start = time.perf_counter()
        serial = sweep_serial(fleet, args.conditions)
        serial_time = time.perf_counter() - start
        print(f"serial loop: {serial_time:.2f} s, {total / serial_time:.0f} conditions/s")
        print(
            f"speed-up {serial_time / elapsed:.2f}× on {workers} workers; rows equal bit for bit: {same_rows(rows, serial)}"
        )
    args.out.mkdir(parents=True, exist_ok=True)
    write_csv(rows, args.out / "sweep.csv")
    written = [args.out / "sweep.csv"]
    if plot(rows, args.out / "sweep.png"):
        written.append(args.out / "sweep.png")
    floated = sum(1 for r in rows if not math.isnan(r[4]))
    print(f"{floated} of {total} conditions float; wrote " + ", ".join(map(str, written)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
