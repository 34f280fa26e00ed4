"""Figures of the paper, drawn with matplotlib (``pip install buoyancy[plot]``).

``python -m buoyancy.plots accuracy --out DIR`` reproduces Figure 4 of Fábián's *Approximate and
exact buoyancy calculation for real-time floating simulation of meshes*: the buoyant force of the
five methods, and its error against the analytic curve, versus the height h of the centroid,
for a unit cube (1,200 and 120,000 triangles, ``F(h) = 1/2 − h``) and a unit sphere (50² and 200²
segments, ``F(h) = π/3 (h − 1)² (h + 2)``), with ρg = 1 and the centroid at (0, h, 0).

It writes one PNG per body (``accuracy_<body>.png``: force above, absolute error below, log
scale) and ``figure4.png`` with all four, and prints the largest error of each method.

``python -m buoyancy.plots waves --out DIR`` draws a body on a wave (its triangles coloured by the
wave's hydrostatic pressure, side view) and the heave force on a box over a wave period against
the analytic curve (see :mod:`buoyancy.wave_plots`).
"""

from __future__ import annotations

import argparse
import math
import pathlib
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from . import METHODS, Mesh, Water, shapes

LABELS = {
    "fast": "Fast",
    "improved": "Improved",
    "exact": "Exact",
    "fast_surface": "Fast Surface",
    "exact_surface": "Exact Surface",
}
STYLES = {
    "fast": dict(color="tab:red", linestyle="-"),
    "improved": dict(color="tab:orange", linestyle="-"),
    "exact": dict(color="tab:blue", linestyle="-"),
    "fast_surface": dict(color="tab:purple", linestyle="--"),
    "exact_surface": dict(color="tab:green", linestyle=":"),
}


@dataclass
class Body:
    """A test body of the accuracy figure and its analytic buoyant force."""

    name: str
    title: str
    mesh: Mesh
    analytic: Callable[[npt.NDArray[np.float64]], npt.NDArray[np.float64]]
    half_range: float


def cube_force(h: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Buoyant force on the unit cube, ρg = 1, centroid at height h."""
    return np.clip(0.5 - h, 0.0, 1.0)


def sphere_force(h: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Buoyant force on the unit sphere, ρg = 1, center at height h (|h| ≤ 1)."""
    return math.pi / 3.0 * (h - 1.0) ** 2 * (h + 2.0)


def bodies(small: bool = False) -> list[Body]:
    """The paper's four bodies (``small``: the two coarse ones only)."""
    out = [
        Body("cube_1200", "cube, 1,200 triangles", shapes.cube(10), cube_force, 0.5),
        Body("sphere_4900", "sphere, 50² segments", shapes.uv_sphere(1.0, 50, 50), sphere_force, 1.0),
    ]
    if not small:
        out.insert(1, Body("cube_120000", "cube, 120,000 triangles", shapes.cube(100), cube_force, 0.5))
        out.append(Body("sphere_79600", "sphere, 200² segments", shapes.uv_sphere(1.0, 200, 200), sphere_force, 1.0))
    return out


def accuracy_data(
    body: Body, samples: int = 199
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], dict[str, npt.NDArray[np.float64]]]:
    """Heights, analytic force and each method's force (ρg = 1) for ``samples`` heights
    strictly inside (−half_range, half_range)."""
    h = body.half_range * np.linspace(-1.0, 1.0, samples + 2)[1:-1]
    positions = np.zeros((samples, 3))
    positions[:, 1] = h
    water = Water(density=1.0, gravity=1.0)
    forces = {
        method: body.mesh.buoyancy_batch(positions, None, water=water, method=method).force[:, 1] for method in METHODS
    }
    return h, body.analytic(h), forces


def _draw(ax_force, ax_error, body: Body, samples: int) -> dict[str, float]:  # type: ignore[no-untyped-def]
    h, analytic, forces = accuracy_data(body, samples)
    ax_force.plot(h, analytic, color="black", linewidth=3, alpha=0.25, label="analytic")
    worst = {}
    for method, f in forces.items():
        label = LABELS[method]
        ax_force.plot(h, f, label=label, **STYLES[method])
        error = np.abs(f - analytic)
        worst[method] = float(error.max())
        # Round-off-level errors (1e-16…1e-13) would vanish off a log axis at exactly 0.
        ax_error.semilogy(h, np.maximum(error, 1e-17), label=label, **STYLES[method])
    ax_force.set_title(body.title)
    ax_force.set_ylabel("buoyant force F (ρg = 1)")
    ax_error.set_xlabel("height of the centroid h")
    ax_error.set_ylabel("|F − F_analytic|")
    ax_force.grid(alpha=0.3)
    ax_error.grid(alpha=0.3)
    return worst


def accuracy(out: pathlib.Path, samples: int = 199, small: bool = False) -> list[pathlib.Path]:
    """Writes the accuracy figures into ``out``; returns the PNG paths."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out.mkdir(parents=True, exist_ok=True)
    written = []
    cases = bodies(small)
    overview, axes = plt.subplots(2, len(cases), figsize=(4.2 * len(cases), 7), sharex="col", squeeze=False)
    print(f"largest |F − F_analytic| over {samples} heights, ρg = 1")
    print("| body | " + " | ".join(LABELS[m] for m in METHODS) + " |")
    print("|---|" + "---|" * len(METHODS))
    for column, body in enumerate(cases):
        fig, (ax_force, ax_error) = plt.subplots(2, 1, figsize=(6, 7), sharex=True)
        worst = _draw(ax_force, ax_error, body, samples)
        ax_force.legend(fontsize="small")
        fig.tight_layout()
        path = out / f"accuracy_{body.name}.png"
        fig.savefig(path, dpi=120)
        plt.close(fig)
        written.append(path)
        _draw(axes[0, column], axes[1, column], body, samples)
        print(f"| {body.title} | " + " | ".join(f"{worst[m]:.1e}" for m in METHODS) + " |")
    axes[0, 0].legend(fontsize="small")
    overview.suptitle("Buoyant force and its error versus height (paper's Figure 4)")
    overview.tight_layout()
    path = out / "figure4.png"
    overview.savefig(path, dpi=110)
    plt.close(overview)
    written.append(path)
    for p in written:
        print(f"wrote {p}")
    return written


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m buoyancy.plots", description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    acc = commands.add_parser("accuracy", help="the paper's Figure 4: force and error versus h")
    acc.add_argument(
        "--out", type=pathlib.Path, default=pathlib.Path("out"), help="folder for the PNGs (default ./out)"
    )
    acc.add_argument("--samples", type=int, default=199, help="heights per body (default 199)")
    acc.add_argument("--small", action="store_true", help="the two coarse bodies only (quick)")
    wav = commands.add_parser("waves", help="a body on a wave, and a box's heave force over a wave period")
    wav.add_argument(
        "--out", type=pathlib.Path, default=pathlib.Path("out"), help="folder for the PNGs (default ./out)"
    )
    wav.add_argument("--samples", type=int, default=65, help="times over the wave period (default 65)")
    wav.add_argument("--small", action="store_true", help="coarser meshes (quick)")
    args = parser.parse_args(argv)
    if args.samples < 2:
        parser.error("--samples must be at least 2")
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("the plots need matplotlib: pip install 'buoyancy[plot]'", file=sys.stderr)
        return 2
    if args.command == "waves":
        from .wave_plots import waves

        waves(args.out, args.samples, args.small)
    else:
        accuracy(args.out, args.samples, args.small)
    return 0


if __name__ == "__main__":
    sys.exit(main())
