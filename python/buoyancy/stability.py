"""Stability of a hull from the command line: its equilibrium, metacentric heights, a
hydrostatic table and the righting-arm (GZ) curve, from a mesh file.

``python -m buoyancy.stability hull.stl --mass 1200 --cog 0 0 0.3 --up z --out DIR`` loads the
mesh (STL, OBJ or PLY; a hull without a deck with ``--close-openings``), finds where the body of
that mass and center of gravity (mesh frame, m) floats at rest, prints the equilibrium, the
metacentric heights there and a hydrostatic table over drafts around it, and writes to ``DIR``:

* ``gz_curve.csv`` and ``gz_curve.png``: the righting arm over heel, trim and draft solved at
  each heel (the PNG needs matplotlib, ``pip install buoyancy[plot]``);
* ``hydrostatic_table.csv``: the table printed.

Conventions: SI units, angles in degrees; ``--up`` is the mesh axis that points up when the hull
is upright (the water's normal), ``--axis`` its longitudinal axis (heel is about it). A positive
heel is right-handed about the longitudinal axis: with x forward and z up, it puts starboard
(-y) down. ``GZ`` is positive when it rights the hull.

Exit status: 0 when the hull floats upright in a stable equilibrium with a range of positive
stability; 1 when the results were written but a warning on stderr says otherwise (the
equilibrium is not stable, the hull floats capsized, past 90° of heel, ``GZ`` is not
positive at any heel, or an input looks to be in the wrong unit: a mesh in millimetres, a mass
in tonnes, a density in t/m³, heels in radians); 2 for an error, before anything is written (bad arguments, a file that
cannot be read, an output folder that cannot be written, a body that does not float, a solve
that does not converge).
"""

from __future__ import annotations

import argparse
import csv
import math
import os
import pathlib
import sys
import warnings as warnings_module
from collections.abc import Sequence

import numpy as np

from . import Equilibrium, GzCurve, HydrostaticTable, Mesh, Water, load

AXES = {
    "x": (1.0, 0.0, 0.0),
    "y": (0.0, 1.0, 0.0),
    "z": (0.0, 0.0, 1.0),
    "-x": (-1.0, 0.0, 0.0),
    "-y": (0.0, -1.0, 0.0),
    "-z": (0.0, 0.0, -1.0),
}

# The most heels of a GZ curve and drafts of a table the command line computes: each heel is a
# solve of the trim, each draft one of the table's rows; more is a mistyped step, not a finer curve.
MAX_HEELS = 100_000
MAX_ROWS = 100_000

# The printed columns of the hydrostatic table: heading and format.
TABLE_HEADINGS = {
    "draft": ("T", ".4f"),
    "displacement": ("disp", ".1f"),
    "kb": ("KB", ".4f"),
    "bm_transverse": ("BM_T", ".4f"),
    "bm_longitudinal": ("BM_L", ".4f"),
    "km_transverse": ("KM_T", ".4f"),
    "km_longitudinal": ("KM_L", ".4f"),
    "lcb": ("LCB", ".4f"),
    "lcf": ("LCF", ".4f"),
    "waterplane_area": ("A_wp", ".4f"),
    "tpc": ("TPC", ".4f"),
    "mct": ("MCT", ".2f"),
}


def extent(mesh: Mesh) -> str:
    """The mesh's bounding box in its own frame, as ``extent 4 × 2 × 1 m``."""
    vertices = np.asarray(mesh.vertices)
    size = vertices.max(axis=0) - vertices.min(axis=0)
    return "extent " + " × ".join(f"{s:.6g}" for s in size) + " m"


def table_drafts(draft: float, height: float, rows: int) -> np.ndarray:
    """``rows`` drafts from a fifth of ``draft`` to the lesser of 1.6 ``draft`` and ``height``."""
    top = min(1.6 * draft, height)
    return np.linspace(0.2 * draft, top, rows)


def table_height(mesh: Mesh, up: Sequence[float]) -> float:
    """The greatest draft of the table upright, m: the extent of the mesh along ``up``, or, for
    a hull whose openings were closed by lids, just below its lowest opening (the hull floods
    there)."""
    heights = mesh.vertices @ np.asarray(up, dtype=float)
    keel = float(heights.min())
    top = float(heights.max()) - keel
    for rim in mesh.openings:
        top = min(top, (1.0 - 1e-9) * (float(heights[rim].min()) - keel))
    return top


def print_equilibrium(rest: Equilibrium, mass: float, cog: Sequence[float]) -> None:
    h = rest.hydrostatics
    residual = float(np.abs(rest.residual).max())
    print(f"Equilibrium: mass {mass:g} kg, center of gravity ({', '.join(f'{c:g}' for c in cog)}) m")
    print(f"  draft     {rest.draft:10.4f} m")
    print(f"  heel      {rest.heel:10.3f} °")
    print(f"  trim      {rest.trim:10.3f} °")
    stable = "stable" if rest.stable else "NOT stable (neutral, or the restarts ran out)"
    print(
        f"  {stable}: {rest.iterations} Newton iterations, {rest.restarts} restarts, "
        f"largest relative residual {residual:.1e}"
    )
    print(f"  displaced volume {h.displaced_volume:.6g} m³, waterplane area {h.waterplane.area:.6g} m²")
    print(f"  KB {h.kb:.4f} m   KG {h.kg:.4f} m")
    print(f"  BM_T {h.bm_transverse:.4f} m   GM_T {h.gm_transverse:.4f} m")
    print(f"  BM_L {h.bm_longitudinal:.4f} m   GM_L {h.gm_longitudinal:.4f} m")


def print_table(table: HydrostaticTable) -> None:
    columns = table.as_dict()
    units = dict(zip(table.columns, table.units, strict=True))
    names = list(TABLE_HEADINGS)
    print("Hydrostatic table (upright):")
    print("  " + " ".join(f"{TABLE_HEADINGS[n][0]:>10}" for n in names))
    print("  " + " ".join(f"{'[' + units[n] + ']':>10}" for n in names))
    for i in range(len(table)):
        # `+ 0.0` prints a zero rounded from a tiny negative as 0, not -0.
        print(
            "  "
            + " ".join(
                f"{float(f'{columns[n][i]:{TABLE_HEADINGS[n][1]}}') + 0.0:10{TABLE_HEADINGS[n][1]}}" for n in names
            )
        )


def print_curve(curve: GzCurve) -> None:
    last = float(curve.heel[-1])
    print(f"GZ curve: {len(curve)} heels from {curve.heel[0]:g}° to {last:g}°")
    print(f"  maximum GZ {curve.max_gz:.4f} m at {curve.angle_of_max_gz:.1f}°")
    vanishing = {
        "vanishes": f"{curve.angle_of_vanishing_stability or 0.0:.1f}°",
        "beyond": f"beyond {last:g}° (GZ stays positive)",
        "none": "none: GZ is not positive at any heel of the curve",
    }[curve.positive_stability]
    print(f"  angle of vanishing stability {vanishing}")
    if curve.flooding_angle is not None:
        print(f"  the water reaches an opening at {curve.flooding_angle:g}°: the curve stops there")
    for upto in (30.0, 40.0):
        if upto <= last:
            print(f"  area under GZ to {upto:g}°: {curve.area_up_to(upto):.4f} m·rad")
    print(f"  area under GZ to {last:g}°: {curve.area:.4f} m·rad")


def warnings(rest: Equilibrium, curve: GzCurve) -> list[str]:
    """What makes the exit status 1: the hull does not float upright and stable."""
    found = []
    if not rest.stable:
        found.append("the equilibrium is not stable (neutral, or the solver's restarts ran out)")
    if abs(rest.heel) > 90.0:
        found.append(f"the hull floats capsized, at {rest.heel:.1f}° of heel")
    if curve.positive_stability == "none":
        found.append("GZ is not positive at any heel: no range of positive stability")
    if not math.isfinite(curve.max_gz):
        found.append("the GZ curve has no finite maximum")
    return found


def output_folder(path: pathlib.Path) -> str | None:
    """Makes the output folder; what is wrong with it, if it cannot be written."""
    if path.exists() and not path.is_dir():
        return f"--out {path}: is a file, not a folder"
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        return f"--out {path}: cannot make the folder ({error.strerror or error})"
    if not os.access(path, os.W_OK | os.X_OK):
        return f"--out {path}: the folder is not writable"
    return None


def write_csv(path: pathlib.Path, header: Sequence[str], rows: np.ndarray) -> None:
    with path.open("w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        for row in rows:
            writer.writerow([f"{v:.10g}" for v in row])


def plot_curve(curve: GzCurve, path: pathlib.Path, title: str) -> bool:
    """Writes the GZ curve as a PNG; ``False`` without matplotlib."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(curve.heel, curve.gz, "o-", color="tab:blue", markersize=3, label="GZ")
    ax.axhline(0.0, color="black", linewidth=0.8)
    ax.axvline(curve.angle_of_max_gz, color="tab:gray", linestyle=":", label=f"max {curve.max_gz:.3f} m")
    vanishing = curve.angle_of_vanishing_stability
    if vanishing is not None:
        ax.axvline(vanishing, color="tab:red", linestyle="--", label=f"vanishing {vanishing:.1f}°")
    ax.set_xlabel("heel [°]")
    ax.set_ylabel("GZ [m]")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return True


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m buoyancy.stability",
        description=(__doc__ or "").split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=(
            "Example: python -m buoyancy.stability hull.stl --mass 1200 --cog 0 0 0.3 --up z --out out/\n\n"
            "Exit status: 0 floats upright, stable, with positive GZ; 1 results written with a warning "
            "(not stable, capsized, no positive GZ, or units that look wrong); 2 an error, before anything is "
            "written."
        ),
    )
    parser.add_argument("mesh", type=pathlib.Path, help="STL, OBJ or PLY file of the hull (metres)")
    parser.add_argument("--mass", type=float, required=True, help="mass of the loaded hull, kg")
    parser.add_argument(
        "--cog", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"), help="center of gravity, mesh frame, m"
    )
    parser.add_argument("--up", choices=sorted(AXES), default="z", help="the mesh axis pointing up (default z)")
    parser.add_argument("--axis", choices=sorted(AXES), default="x", help="the longitudinal axis (default x)")
    parser.add_argument(
        "--density",
        type=float,
        default=1000.0,
        help="water density, kg/m³ (default 1000, fresh water, as the library's Water(); 1025 for the sea)",
    )
    parser.add_argument("--gravity", type=float, default=9.81, help="m/s² (default 9.81)")
    parser.add_argument("--heel-max", type=float, default=90.0, help="last heel of the GZ curve, ° (default 90)")
    parser.add_argument("--heel-step", type=float, default=2.5, help="heel step, ° (default 2.5)")
    parser.add_argument("--fixed-trim", action="store_true", help="hold the trim at the equilibrium's")
    parser.add_argument("--rows", type=int, default=9, help="drafts in the hydrostatic table (default 9)")
    parser.add_argument(
        "--close-openings",
        action="store_true",
        help="close the mesh's planar openings with lids (a hull without a deck); the GZ curve stops "
        "where the water reaches one",
    )
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."), help="output folder (default .)")
    args = parser.parse_args(argv)

    up, axis = AXES[args.up], AXES[args.axis]
    if abs(float(np.dot(up, axis))) > 0.5:
        parser.error(f"--axis {args.axis} is along --up {args.up}: the longitudinal axis must be horizontal")
    if not (args.heel_step > 0 and 0 < args.heel_max <= 180):
        parser.error("--heel-step must be positive and --heel-max in (0, 180]")
    heel_count = math.floor(args.heel_max / args.heel_step + 1e-9) + 1 if args.heel_step > 0 else 0
    if heel_count > MAX_HEELS:
        parser.error(
            f"--heel-step {args.heel_step:g} makes {heel_count:,} heels up to {args.heel_max:g}°; at most "
            f"{MAX_HEELS:,} (a step of at least {args.heel_max / (MAX_HEELS - 1):.3g}°)"
        )
    if not 1 <= args.rows <= MAX_ROWS:
        parser.error(f"--rows must be from 1 to {MAX_ROWS:,}, got {args.rows:,}")
    problem = output_folder(args.out)
    if problem is not None:
        print(f"error: {problem}", file=sys.stderr)
        return 2
    # What the library warns of (units that look wrong: a mesh in millimetres, a mass in tonnes),
    # printed as the command line's own warnings, once each.
    noted: list[str] = []
    try:
        mesh = load(args.mesh, close_openings=args.close_openings)
        # Before the solve, so that a failure can be read against the mesh's size.
        print(f"{args.mesh}: {mesh.n_triangles:,} triangles, {extent(mesh)}, volume {mesh.volume:.6g} m³")
        water = Water(density=args.density, gravity=args.gravity, normal=up)
        with warnings_module.catch_warnings(record=True) as caught:
            warnings_module.simplefilter("always")
            try:
                rest = mesh.equilibrium(args.mass, args.cog, water=water, axis=axis)
                heels = np.arange(0.0, args.heel_max + 1e-9, args.heel_step)
                trim = {"free_trim": False, "trim_deg": rest.trim} if args.fixed_trim else {}
                curve = mesh.gz_curve(args.mass, args.cog, heels, axis=axis, water=water, **trim)
                drafts = table_drafts(rest.draft, table_height(mesh, up), args.rows)
                table = mesh.hydrostatic_table(drafts, water=water, axis=axis, center_of_mass=args.cog)
            finally:
                for message in dict.fromkeys(str(w.message) for w in caught):
                    noted.append(message)
                    print(f"warning: {message}", file=sys.stderr)
    except (OSError, ValueError, RuntimeError, MemoryError) as error:
        message = str(error)
        if "open edges" in message and not args.close_openings:
            message += (
                "\nIf the hull is open on purpose (no deck), run with --close-openings: it closes each "
                "planar opening with a lid, and the GZ curve stops where the water reaches one."
            )
        print(f"error: {message}", file=sys.stderr)
        return 2

    print(
        f"water: {args.density:g} kg/m³, g = {args.gravity:g} m/s², up = mesh {args.up}, long axis = mesh {args.axis}"
    )
    print()
    print_equilibrium(rest, args.mass, args.cog)
    print()
    print_table(table)
    print()
    print_curve(curve)

    gz_csv = args.out / "gz_curve.csv"
    write_csv(gz_csv, ["heel_deg", "gz_m", "trim_deg", "draft_m"], np.c_[curve.heel, curve.gz, curve.trim, curve.draft])
    table_csv = args.out / "hydrostatic_table.csv"
    columns = table.as_dict()
    write_csv(
        table_csv,
        [f"{n}_{u}" for n, u in zip(table.columns, table.units, strict=True)],
        np.column_stack([columns[n] for n in table.columns]),
    )
    written = [gz_csv, table_csv]
    png = args.out / "gz_curve.png"
    trim_note = "trim held" if args.fixed_trim else "free trim"
    cog = ", ".join(f"{c:g}" for c in args.cog)
    if plot_curve(curve, png, f"{args.mesh.name}: {args.mass:g} kg, G ({cog}) m, {trim_note}"):
        written.append(png)
    else:
        print("note: matplotlib is not installed; gz_curve.png not written (pip install buoyancy[plot])")
    print()
    print("wrote " + ", ".join(str(p) for p in written))
    found = warnings(rest, curve)
    for warning in found:
        print(f"warning: {warning}", file=sys.stderr)
    return 1 if found or noted else 0


if __name__ == "__main__":
    raise SystemExit(main())
