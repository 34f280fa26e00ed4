"""Peers side by side for hydrostatics: this project's wheel against navaltoolbox and capytaine.

A benchmark script, not a test. From the repository root:

    python3 -m venv .venv-hpeers
    .venv-hpeers/bin/pip install . numpy navaltoolbox capytaine
    .venv-hpeers/bin/python benches/peers_hydrostatics.py    # [--budget 2.0] [--out benches/PEERS_HYDROSTATICS.md]

Each peer is optional: one that is not installed is skipped with a message (and the Markdown says
so). Prints Markdown tables and writes them, with the machine, to ``benches/PEERS_HYDROSTATICS.md``.

The frame is navaltoolbox's, for every implementation: x forward (0 at the stern), y to port, z up,
the keel at z = 0, fresh water (ρ = 1000 kg/m³, g = 9.81 m/s²). Every mesh is built by the wheel
(``buoyancy.shapes``) and handed to the peers as it is: written once to a binary STL for
navaltoolbox (``Hull(path)``, ``Vessel``, ``HydrostaticsCalculator(vessel, 1000)``), passed as
vertices and triangles to capytaine (``cpt.Mesh``, ``cpt.FloatingBody`` with the rigid-body
degrees of freedom about G and ``center_of_mass`` G, ``compute_hydrostatics(rho, g)``, the mesh
moved down so that the water is its z = 0 and horizontally so that G is on its z axis, since
capytaine takes the metacentric radii about the mesh frame's axes). Ours: ``buoyancy.Water(1000, 9.81, level, (0, 0, 1))``.
Heel: both ours and navaltoolbox's are positive with starboard (−y) down.

Cases, each against the analytic value:

1. Box 2 × 1 × 0.5 m (L × B × D, 12 triangles), 500 kg (draft 0.25 m upright), G at
   (1, 0.02, 0.25): the equilibrium heel. Wall-sided (the deck edge stays dry, the bilge wet), the
   waterline pivots about the centerline and, heeled by a (port down), B in the body frame is at
   y_B = BM·tan a, z_B = KB + ½·BM·tan²a. The lever between B and G across the earth's vertical,
   (y_B − y_G)·cos a + (z_B − z_G)·sin a, vanishes when

       tan a · (GM + ½·BM·tan²a) = y_G,    GM = KB + BM − KG,  KB = T/2,  BM = B²/(12 T).

   The cubic in tan a has one real root; the heel is −a (G to port: port down, negative heel).
   The table gives, at each implementation's heel, that lever (analytic, wall-sided): what is
   left of the heeling moment over m·g.
2. The same box meshed by ``shapes.cube(2)``: a row of vertices lies exactly on the waterline at
   draft 0.25 m. Upright at that draft (and at 1e-9 m more): volume L·B·T, waterplane area L·B,
   GM_T = KB + BM_T − KG with KG = 0.25 m; then navaltoolbox's draft-for-displacement solve for
   500 kg.
3. A Wigley hull (``shapes.wigley_hull``, half-breadth (B/2)(1 − (2x/L)²)(1 − (z/T)²), L 4,
   B 0.6, T 0.25, freeboard 0.15, 41 stations, 17 waterlines, 2,798 triangles) upright at T:
   V = 4LBT/9, A_wp = 2LB/3, KB = 5T/8, BM_T = 3B²/(35T), BM_L = 3L²/(40T). The mesh's chords
   miss the curved hull: ours converges to these as the square of the spacing, shown on four
   meshes, each twice as fine as the one before.
4. The heave, roll and pitch stiffness about G (the rigid-body one, with the weight's term:
   ρg·A_wp, ρgV·GM_T, ρgV·GM_L) on the boxes and the Wigley hull, against capytaine's
   ``hydrostatic_stiffness`` and navaltoolbox's ``stiffness_matrix`` (its diagonal).

Timing (``time.perf_counter_ns`` around each call, a first call untimed, then at least 5 calls or
as many as fit in ``--budget`` seconds, at most 200; the median): ours ``mesh.equilibrium(mass,
G)`` against navaltoolbox's ``from_displacement(mass, cog=G)`` (its draft, trim and heel for a
mass and a center of gravity), on the box of case 1 and on the Wigley hull with G 0.01 m to port,
its mass that of the upright hull at T (a row of vertices on the waterline) or at 0.24 m (between
rows); then the hydrostatics at a given pose: ours ``mesh.hydrostatics``, navaltoolbox's
``from_draft``, capytaine's ``compute_hydrostatics``. The load average is printed before and after each row.
"""

from __future__ import annotations

import argparse
import math
import os
import pathlib
import sys
import tempfile
import time
from collections.abc import Callable
from typing import Any

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")

import numpy as np

import buoyancy

from peers import git_state, machine

REPO = pathlib.Path(__file__).resolve().parents[1]
RHO, G = 1000.0, 9.81
UP = (0.0, 0.0, 1.0)

# The box of cases 1, 2 and 4.
BOX_L, BOX_B, BOX_D, BOX_T, BOX_KG, BOX_OFFSET = 2.0, 1.0, 0.5, 0.25, 0.25, 0.02
# The Wigley hull of cases 3 and 4.
W_L, W_B, W_T, W_FREEBOARD, W_KG = 4.0, 0.6, 0.25, 0.15, 0.2
# A draft between the Wigley mesh's rows of vertices (every T/16 below the waterline).
W_T_BETWEEN = 0.24


def water(level: float = 0.0) -> buoyancy.Water:
    return buoyancy.Water(RHO, G, level, UP)


# --------------------------------------------------------------------------------------------
# Meshes: z up, x from 0 (stern) to L, y to port, keel at z = 0.


def box(n: int) -> buoyancy.Mesh:
    """``shapes.cube(n)`` (a unit cube about the origin, n quads a side) as the box L × B × D."""
    return buoyancy.shapes.cube(n).scaled((BOX_L, BOX_B, BOX_D)).translated((BOX_L / 2, 0.0, BOX_D / 2))


def wigley(stations: int = 41, waterlines: int = 17) -> buoyancy.Mesh:
    """``shapes.wigley_hull`` (y up, x about 0, waterline y = 0) turned z up, keel at z = 0."""
    hull = buoyancy.shapes.wigley_hull(W_L, W_B, W_T, W_FREEBOARD, stations, waterlines)
    v = np.asarray(hull.vertices, dtype=np.float64)
    # (x, y, z) -> (x, -z, y): a proper rotation, so the winding stays outward.
    zup = np.column_stack([v[:, 0] - v[:, 0].min(), -v[:, 2], v[:, 1] - v[:, 1].min()])
    return buoyancy.Mesh(zup, np.asarray(hull.faces))


def write_stl(path: str, mesh: buoyancy.Mesh) -> None:
    """A binary STL (float32, as the format stores)."""
    vertices, faces = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    tri = vertices[faces]
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    lengths = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.divide(normals, lengths, out=np.zeros_like(normals), where=lengths > 0)
    record = np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    data = np.zeros(len(faces), dtype=record)
    data["n"], data["v"] = normals, tri
    with open(path, "wb") as f:
        f.write(b"buoyancy benches/peers_hydrostatics.py".ljust(80, b" "))
        f.write(np.uint32(len(faces)).tobytes())
        f.write(data.tobytes())


# --------------------------------------------------------------------------------------------
# The peers: each optional.


class NavalToolbox:
    name = "navaltoolbox"

    def __init__(self) -> None:
        import navaltoolbox

        self.ntb = navaltoolbox
        self.tmp = tempfile.TemporaryDirectory(prefix="hpeers-")
        self.count = 0

    def calculator(self, mesh: buoyancy.Mesh) -> Any:
        """The mesh written once to an STL and loaded: ``HydrostaticsCalculator(Vessel(Hull))``."""
        self.count += 1
        path = os.path.join(self.tmp.name, f"hull{self.count}.stl")
        write_stl(path, mesh)
        return self.ntb.HydrostaticsCalculator(self.ntb.Vessel(self.ntb.Hull(path)), RHO)


def stiffness_ntb(state: Any) -> np.ndarray:
    """navaltoolbox's 6 × 6 ``stiffness_matrix``: its heave, roll, pitch block."""
    k = np.asarray(state.stiffness_matrix, dtype=np.float64).reshape(6, 6)
    return k[2:5, 2:5]


class Capytaine:
    name = "capytaine"

    def __init__(self) -> None:
        import logging

        import capytaine

        logging.getLogger("capytaine").setLevel(logging.ERROR)
        self.cpt = capytaine

    def body(self, mesh: buoyancy.Mesh, draft: float, cog: np.ndarray, under_g: bool = True) -> Any:
        """The mesh moved down by ``draft`` (capytaine's water is z = 0), dofs and mass about G.

        With ``under_g`` the mesh is also moved horizontally so that G lies on the z axis:
        capytaine's metacentric radii are taken about the mesh frame's axes, not about the center
        of flotation.
        """
        shift = np.array([cog[0], cog[1], 0.0]) if under_g else np.zeros(3)
        shift[2] = draft
        v = np.asarray(mesh.vertices, dtype=np.float64) - shift
        g = np.asarray(cog, dtype=np.float64) - shift
        cpt = self.cpt
        return cpt.FloatingBody(
            mesh=cpt.Mesh(vertices=v, faces=np.asarray(mesh.faces)),
            dofs=cpt.rigid_body_dofs(rotation_center=tuple(g)),
            center_of_mass=tuple(g),
        )

    def hydrostatics(self, body: Any) -> dict[str, Any]:
        return body.compute_hydrostatics(rho=RHO, g=G)


def stiffness_cpt(h: dict[str, Any]) -> np.ndarray:
    k = np.asarray(h["hydrostatic_stiffness"], dtype=np.float64)
    return k[2:5, 2:5]


# --------------------------------------------------------------------------------------------
# Formatting and measuring.


def num(x: float | None, digits: int = 6) -> str:
    if x is None:
        return "—"
    if isinstance(x, str):
        return x
    return f"{x:.{digits}g}"


def rel(x: float | None, exact: float) -> str:
    """The difference from the analytic value, relative (absolute when it is 0)."""
    if x is None or isinstance(x, str) or not math.isfinite(x):
        return "—"
    if exact == 0.0:
        return f"{x - exact:+.1e} (abs.)"
    return f"{(x - exact) / abs(exact):+.1e}"


def fmt_time(ns: float) -> str:
    us = ns / 1e3
    if us < 1000:
        return f"{us:.1f} µs"
    return f"{us / 1e3:.2f} ms"


def median_ns(fn: Callable[[], Any], budget: float) -> tuple[float, int]:
    clock = time.perf_counter_ns
    t0 = clock()
    fn()
    first = clock() - t0
    runs = int(min(200, max(5, budget * 1e9 / max(first, 1))))
    samples = []
    for _ in range(runs):
        t0 = clock()
        fn()
        samples.append(clock() - t0)
    return float(np.median(samples)), runs


def load_average() -> str:
    try:
        return "load " + ", ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        return "load unknown"


def table(header: list[str], rows: list[list[str]]) -> list[str]:
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(row) + " |" for row in rows]
    return out


def peer_columns(peers: list[Any]) -> list[str]:
    cols = ["quantity", "analytic", "ours", "ours − analytic"]
    for p in peers:
        cols += [p.name, f"{p.name} − analytic"]
    return cols


def value_row(label: str, exact: float, ours: float, peer_values: list[Any], digits: int = 6) -> list[str]:
    row = [label, num(exact, digits), num(ours, digits), rel(ours, exact)]
    for v in peer_values:
        row += [num(v, digits), rel(v, exact)]
    return row


# --------------------------------------------------------------------------------------------
# Case 1: the equilibrium heel of a box with G off the centerline.


def wall_sided_heel(gm: float, bm: float, offset: float) -> float:
    """The root ``t = tan a`` of ``t·(GM + ½·BM·t²) = offset`` (one real root when GM > 0), degrees."""
    t = offset / gm
    for _ in range(100):
        f = t * (gm + 0.5 * bm * t * t) - offset
        t_new = t - f / (gm + 1.5 * bm * t * t)
        if abs(t_new - t) <= 1e-16 * max(1.0, abs(t)):
            t = t_new
            break
        t = t_new
    return math.degrees(math.atan(t))


def wall_sided_lever(heel_deg: float, gm: float, bm: float, offset: float) -> float:
    """The horizontal lever B − G at a heel (port down for negative), over the earth's vertical, m."""
    a = math.radians(-heel_deg)  # port down positive
    t = math.tan(a)
    return math.cos(a) * (t * (gm + 0.5 * bm * t * t) - offset)


def case_equilibrium(ntb: NavalToolbox | None, lines: list[str], notes: list[str]) -> None:
    mesh = box(1)
    mass = RHO * BOX_L * BOX_B * BOX_T
    cog = (BOX_L / 2, BOX_OFFSET, BOX_KG)
    kb, bm = BOX_T / 2, BOX_B**2 / (12 * BOX_T)
    gm = kb + bm - BOX_KG
    a = wall_sided_heel(gm, bm, BOX_OFFSET)
    exact_heel = -a
    t = math.tan(math.radians(a))
    assert BOX_B / 2 * t < min(BOX_T, BOX_D - BOX_T), "wall-sided: the deck edge dry and the bilge wet"

    eq = mesh.equilibrium(mass, cog, water=water())
    ours_volume = eq.hydrostatics.displaced_volume
    header = ["", "heel (°)", "heel − analytic (°)", "trim (°)", "ρV − m (kg)", "B − G lever at that heel (m)"]
    rows = [
        ["analytic", num(exact_heel, 8), "0", "0", "0", f"{wall_sided_lever(exact_heel, gm, bm, BOX_OFFSET):+.1e}"],
        [
            f"ours (`equilibrium`, {eq.iterations} iterations)",
            num(eq.heel, 8),
            f"{eq.heel - exact_heel:+.1e}",
            f"{eq.trim:.1e}",
            f"{RHO * ours_volume - mass:+.1e}",
            f"{wall_sided_lever(eq.heel, gm, bm, BOX_OFFSET):+.1e}",
        ],
    ]
    print(f"case 1: analytic heel {exact_heel:.6f}°, ours {eq.heel:.9f}° ({eq.iterations} iterations)")
    if ntb is not None:
        calc = ntb.calculator(mesh)
        try:
            s = calc.from_displacement(mass, cog=cog)
            rows.append(
                [
                    "navaltoolbox (`from_displacement(m, cog=G)`)",
                    num(s.heel, 8),
                    f"{s.heel - exact_heel:+.2f}",
                    f"{s.trim:.1e}",
                    f"{RHO * s.volume - mass:+.1e}",
                    f"{wall_sided_lever(s.heel, gm, bm, BOX_OFFSET):+.1e}",
                ]
            )
            print(f"  navaltoolbox heel {s.heel:.6f}°")
            notes.append(
                f"Box equilibrium: navaltoolbox heels {s.heel:.2f}° where the equilibrium is {exact_heel:.2f}° "
                f"({s.heel - exact_heel:+.2f}°, {100 * (s.heel - exact_heel) / abs(exact_heel):+.0f}%); at its heel "
                f"B and G are {abs(wall_sided_lever(s.heel, gm, bm, BOX_OFFSET)) * 1e3:.1f} mm apart across the "
                f"vertical, a heeling moment of {abs(wall_sided_lever(s.heel, gm, bm, BOX_OFFSET)) * mass * G:.0f} N·m "
                f"left. Ours: {eq.heel - exact_heel:+.0e}°."
            )
        except Exception as e:  # a peer failing is reported, not fatal
            rows.append(["navaltoolbox", f"failed: {type(e).__name__}: {e}", "", "", "", ""])
    lines += [
        "## 1. Box, G off the centerline: the equilibrium heel",
        "",
        f"Box {BOX_L:g} × {BOX_B:g} × {BOX_D:g} m (12 triangles, `shapes.cube(1)`), {mass:g} kg (draft "
        f"{BOX_T:g} m upright), G at ({cog[0]:g}, {cog[1]:g}, {cog[2]:g}): {BOX_OFFSET:g} m to port. "
        f"KB = T/2 = {kb:g} m, BM = B²/(12T) = {bm:.6f} m, GM = KB + BM − KG = {gm:.6f} m. Wall-sided, heeled by "
        "a (port down): B at y = BM·tan a, z = KB + ½·BM·tan²a in the body frame; the lever "
        "(y_B − y_G)·cos a + (z_B − z_G)·sin a = cos a·(tan a·(GM + ½·BM·tan²a) − y_G) vanishes at "
        f"tan a = {t:.9f}, a = {a:.6f}°. Positive heel is starboard down in both tools, so the "
        f"equilibrium heel is −a = {exact_heel:.6f}° (the deck edge rises {BOX_B / 2 * t:.3f} m of the "
        f"{BOX_D - BOX_T:g} m freeboard: wall-sided holds). Last column: that lever at each tool's heel.",
        "",
        *table(header, rows),
        "",
    ]


# --------------------------------------------------------------------------------------------
# Case 2: a box with a row of vertices on the waterline.


def ours_upright(mesh: buoyancy.Mesh, draft: float, cog: tuple[float, float, float]) -> Any:
    return mesh.hydrostatics(cog, water=water(draft), keel=(cog[0], cog[1], 0.0))


def case_vertex_row(ntb: NavalToolbox | None, cpt: Capytaine | None, lines: list[str], notes: list[str]) -> None:
    mesh = box(2)
    zs = sorted(set(np.round(np.asarray(mesh.vertices)[:, 2], 12)))
    assert BOX_T in zs, zs
    cog = (BOX_L / 2, 0.0, BOX_KG)
    mass = RHO * BOX_L * BOX_B * BOX_T
    exact = {
        "volume (m³)": BOX_L * BOX_B * BOX_T,
        "waterplane area (m²)": BOX_L * BOX_B,
        "KB (m)": BOX_T / 2,
        "GM_T (m)": BOX_T / 2 + BOX_B**2 / (12 * BOX_T) - BOX_KG,
        "GM_L (m)": BOX_T / 2 + BOX_L**2 / (12 * BOX_T) - BOX_KG,
    }

    def ours_values(draft: float) -> list[float]:
        h = ours_upright(mesh, draft, cog)
        return [h.displaced_volume, h.waterplane.area, h.kb, h.gm_transverse, h.gm_longitudinal]

    ours = ours_values(BOX_T)
    above = ours_values(BOX_T + 1e-9)
    peers: list[Any] = []
    peer_values: list[list[Any]] = []
    ntb_solve = ""
    if ntb is not None:
        peers.append(ntb)
        calc = ntb.calculator(mesh)
        s = calc.from_draft(BOX_T, vcg=BOX_KG)
        s_above = calc.from_draft(BOX_T + 1e-9, vcg=BOX_KG)
        peer_values.append([s.volume, s.waterplane_area, s.vcb, s.gmt, s.gml])
        try:
            d = calc.from_displacement(mass, cog=cog)
            ntb_solve = (
                f"navaltoolbox's `from_displacement({mass:g} kg, cog=G)` on this mesh: draft {d.draft:.6g} m "
                f"(analytic {BOX_T:g}), heel {d.heel:.3g}°, trim {d.trim:.3g}°, volume {d.volume:.6g} m³."
            )
        except Exception as e:
            ntb_solve = (
                f"navaltoolbox's `from_displacement({mass:g} kg, cog=G)` on this mesh fails: {type(e).__name__}: {e}."
            )
        notes.append(
            f"Vertex row on the waterline: navaltoolbox's volume {s.volume:.4g} m³ ({rel(s.volume, exact['volume (m³)'])}), "
            f"waterplane area {s.waterplane_area:.4g} m², GM_T {s.gmt:.4g} m (analytic {exact['GM_T (m)']:.4g}); "
            f"1e-9 m deeper it gives {s_above.volume:.6g} m³, {s_above.waterplane_area:.6g} m², GM_T "
            f"{s_above.gmt:.6g} m. {ntb_solve}"
        )
    if cpt is not None:
        peers.append(cpt)
        h = cpt.hydrostatics(cpt.body(mesh, BOX_T, np.array(cog)))
        peer_values.append(
            [
                h["disp_volume"],
                h["waterplane_area"],
                float(h["center_of_buoyancy"][2]) + BOX_T,
                h["transversal_metacentric_height"],
                h["longitudinal_metacentric_height"],
            ]
        )
        c = peer_values[-1]
        notes.append(
            f"Vertex row on the waterline, capytaine: volume {rel(c[0], exact['volume (m³)'])}, waterplane area "
            f"{rel(c[1], exact['waterplane area (m²)'])}, KB {rel(c[2], exact['KB (m)'])}; GM_T "
            f"{rel(c[3], exact['GM_T (m)'])} and GM_L {rel(c[4], exact['GM_L (m)'])}, from its second moments "
            "(the centroid rule below), not from the row."
        )
    rows = [
        value_row(label, value, ours[i], [pv[i] for pv in peer_values])
        for i, (label, value) in enumerate(exact.items())
    ]
    dmax = max(abs(a - b) / abs(b) for a, b in zip(above, ours, strict=True))
    print(f"case 2: ours {ours}, 1e-9 above: largest relative change {dmax:.1e}")
    lines += [
        "## 2. Box with a row of vertices on the waterline",
        "",
        f"The same box meshed by `shapes.cube(2)` (48 triangles): a row of vertices at z = {BOX_T:g} m, "
        f"the draft. Upright at that draft, KG = {BOX_KG:g} m. Ours 1e-9 m deeper: the largest relative "
        f"change of these values is {dmax:.1e}.",
        *([f"{ntb_solve}"] if ntb_solve else []),
        "",
        *table(peer_columns(peers), rows),
        "",
    ]


# --------------------------------------------------------------------------------------------
# Case 3: the Wigley hull at its design draft.


def wigley_exact() -> dict[str, float]:
    return {
        "volume (m³)": 4 * W_L * W_B * W_T / 9,
        "waterplane area (m²)": 2 * W_L * W_B / 3,
        "KB (m)": 5 * W_T / 8,
        "BM_T (m)": 3 * W_B**2 / (35 * W_T),
        "BM_L (m)": 3 * W_L**2 / (40 * W_T),
    }


def case_wigley(ntb: NavalToolbox | None, cpt: Capytaine | None, lines: list[str], notes: list[str]) -> None:
    exact = wigley_exact()
    cog = (W_L / 2, 0.0, W_KG)

    def ours_values(mesh: buoyancy.Mesh) -> list[float]:
        h = ours_upright(mesh, W_T, cog)
        return [h.displaced_volume, h.waterplane.area, h.kb, h.bm_transverse, h.bm_longitudinal]

    mesh = wigley()
    ours = ours_values(mesh)
    peers: list[Any] = []
    peer_values: list[list[Any]] = []
    if ntb is not None:
        peers.append(ntb)
        calc = ntb.calculator(mesh)
        s = calc.from_draft(W_T, vcg=W_KG)
        s_above = calc.from_draft(W_T + 1e-9, vcg=W_KG)
        peer_values.append([s.volume, s.waterplane_area, s.vcb, s.bmt, s.bml])
        notes.append(
            f"Wigley hull (a row of vertices on its waterline too): navaltoolbox's volume {s.volume:.6g} m³, "
            f"waterplane area {s.waterplane_area:.6g} m², BM_T {s.bmt:.6g} m; 1e-9 m deeper {s_above.volume:.6g} m³, "
            f"{s_above.waterplane_area:.6g} m², {s_above.bmt:.6g} m (ours on the same mesh: {ours[0]:.6g} m³, "
            f"{ours[1]:.6g} m², {ours[3]:.6g} m)."
        )
    if cpt is not None:
        peers.append(cpt)
        h = cpt.hydrostatics(cpt.body(mesh, W_T, np.array(cog)))
        peer_values.append(
            [
                h["disp_volume"],
                h["waterplane_area"],
                float(h["center_of_buoyancy"][2]) + W_T,
                h["transversal_metacentric_radius"],
                h["longitudinal_metacentric_radius"],
            ]
        )
        stern = cpt.hydrostatics(cpt.body(mesh, W_T, np.array(cog), under_g=False))
        diffs = ", ".join(
            f"{label.split(' ')[0]} {(c - o) / abs(o):+.1e}"
            for label, c, o in zip(exact, peer_values[-1], ours, strict=True)
        )
        notes.append(
            f"Wigley hull, capytaine against ours on the same mesh: {diffs}. Its metacentric radii are taken about "
            "the mesh frame's axes: with the mesh's origin at the stern (x = 0) instead of under G, its BM_L is "
            f"{stern['longitudinal_metacentric_radius']:.6g} m (analytic {exact['BM_L (m)']:.6g}); the tables "
            "give capytaine the mesh with its origin under G."
        )
    rows = [
        value_row(label, value, ours[i], [pv[i] for pv in peer_values])
        for i, (label, value) in enumerate(exact.items())
    ]

    # Ours on meshes twice as fine each time: the error over the spacing squared.
    conv_rows = []
    previous = None
    for stations, waterlines in ((21, 9), (41, 17), (81, 33), (161, 65)):
        m = wigley(stations, waterlines)
        values = ours_values(m)
        errors = [abs(v - e) / e for v, e in zip(values, exact.values(), strict=True)]
        ratio = "—" if previous is None else ", ".join(f"{p / e:.2f}" for p, e in zip(previous, errors, strict=True))
        conv_rows.append(
            [f"{stations} × {waterlines} ({m.n_triangles:,} triangles)", *[f"{e:.2e}" for e in errors], ratio]
        )
        previous = errors
    print(f"case 3: ours {ours}; convergence {conv_rows}")
    lines += [
        "## 3. Wigley hull at its design draft",
        "",
        f"`shapes.wigley_hull({W_L:g}, {W_B:g}, {W_T:g}, {W_FREEBOARD:g})`: 41 stations, 17 waterlines, "
        f"{mesh.n_triangles:,} triangles, turned z up; upright at T = {W_T:g} m, where a row of vertices lies. "
        "The analytic values are the smooth hull's; the mesh's chords cut inside it, so every implementation "
        "on this mesh differs from them by the discretisation error (ours below: it falls as the spacing squared).",
        "",
        *table(peer_columns(peers), rows),
        "",
        "Ours against the analytic values as the mesh is refined (stations × waterlines; the last column, the "
        "ratio of each error to the previous mesh's, tends to 4 when the error goes as the spacing squared):",
        "",
        *table(
            ["mesh", *[f"{k.split(' ')[0]} rel. error" for k in exact], "ratios to the coarser mesh"],
            conv_rows,
        ),
        "",
    ]


# --------------------------------------------------------------------------------------------
# Case 4: the stiffness against capytaine's (and navaltoolbox's diagonal).


def centroid_rule_stiffness(mesh: buoyancy.Mesh, draft: float, cog: tuple[float, float, float]) -> tuple[float, float]:
    """Roll and pitch stiffness about G from a one-point (centroid) rule on a box's bottom triangles."""
    v, f = np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces)
    tri = v[f]
    area_z = np.abs(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])[:, 2]) / 2
    c = tri.mean(axis=1)
    bottom = np.all(np.abs(tri[:, :, 2]) < 1e-12, axis=1)
    volume = area_z[bottom].sum() * draft  # a box: the bottom's area times the draft
    lever = volume * (draft / 2 - cog[2])
    iy = float(((c[bottom, 1] - cog[1]) ** 2 * area_z[bottom]).sum())
    ix = float(((c[bottom, 0] - cog[0]) ** 2 * area_z[bottom]).sum())
    return RHO * G * (iy + lever), RHO * G * (ix + lever)


def case_stiffness(ntb: NavalToolbox | None, cpt: Capytaine | None, lines: list[str], notes: list[str]) -> None:
    header = ["hull", "entry", "analytic (N/m, N·m/rad)", "ours", "ours − analytic"]
    if cpt is not None:
        header += ["capytaine", "capytaine − analytic"]
    if ntb is not None:
        header += ["navaltoolbox", "navaltoolbox − analytic"]
    rows = []
    we = wigley_exact()
    hulls = [
        (
            "box, 12 triangles",
            box(1),
            BOX_T,
            (BOX_L / 2, 0.0, BOX_KG),
            BOX_L * BOX_B,
            BOX_L * BOX_B * BOX_T,
            BOX_T / 2 + BOX_B**2 / (12 * BOX_T) - BOX_KG,
            BOX_T / 2 + BOX_L**2 / (12 * BOX_T) - BOX_KG,
        ),
        (
            "box, 48 triangles (row at T)",
            box(2),
            BOX_T,
            (BOX_L / 2, 0.0, BOX_KG),
            BOX_L * BOX_B,
            BOX_L * BOX_B * BOX_T,
            BOX_T / 2 + BOX_B**2 / (12 * BOX_T) - BOX_KG,
            BOX_T / 2 + BOX_L**2 / (12 * BOX_T) - BOX_KG,
        ),
        (
            "Wigley, 2,798 triangles",
            wigley(),
            W_T,
            (W_L / 2, 0.0, W_KG),
            we["waterplane area (m²)"],
            we["volume (m³)"],
            we["KB (m)"] + we["BM_T (m)"] - W_KG,
            we["KB (m)"] + we["BM_L (m)"] - W_KG,
        ),
    ]
    rule_parts: list[str] = []
    coupling: list[str] = []
    ntb_parts: list[str] = []
    ours_worst = 0.0
    for name, mesh, draft, cog, awp, volume, gmt, gml in hulls:
        exact = [RHO * G * awp, RHO * G * volume * gmt, RHO * G * volume * gml]
        h = ours_upright(mesh, draft, cog)
        ours = np.asarray(h.stiffness)
        kc = stiffness_cpt(cpt.hydrostatics(cpt.body(mesh, draft, np.array(cog)))) if cpt is not None else None
        kn = stiffness_ntb(ntb.calculator(mesh).from_draft(draft, vcg=cog[2])) if ntb is not None else None
        for i, entry in enumerate(("heave", "roll", "pitch")):
            row = [name, entry, num(exact[i], 7), num(ours[i, i], 7), rel(ours[i, i], exact[i])]
            if mesh.n_triangles <= 48:
                ours_worst = max(ours_worst, abs(ours[i, i] - exact[i]) / exact[i])
            for k in (kc, kn):
                if k is not None:
                    row += [num(k[i, i], 7), rel(k[i, i], exact[i])]
            rows.append(row)
        if kc is not None and mesh.n_triangles <= 48:
            rule = centroid_rule_stiffness(mesh, draft, cog)
            rule_parts.append(
                f"on the {name} it gives {kc[1, 1]:.6g} and {kc[2, 2]:.6g} N·m/rad "
                f"({rel(kc[1, 1], exact[1])}, {rel(kc[2, 2], exact[2])}), and the centroid rule "
                f"{rule[0]:.6g} and {rule[1]:.6g}"
            )
        if kc is not None and mesh.n_triangles > 48:
            rule_parts.append(
                f"on the {name}, against ours on the same mesh: heave "
                f"{(kc[0, 0] - ours[0, 0]) / ours[0, 0]:+.1e}, roll {(kc[1, 1] - ours[1, 1]) / ours[1, 1]:+.1e}, "
                f"pitch {(kc[2, 2] - ours[2, 2]) / ours[2, 2]:+.1e}"
            )
        for peer, k in [("ours", ours)] + ([("capytaine", kc)] if kc is not None else []):
            scale = max(abs(k[i, i]) for i in range(3))
            offd = max(abs(k[i, j]) for i in range(3) for j in range(3) if i != j) / scale
            if offd > 1e-9:
                coupling.append(f"{peer} {offd:.1e} on the {name}")
        if kn is not None:
            ntb_parts.append(
                f"{name}: heave {rel(kn[0, 0], exact[0])}, roll {rel(kn[1, 1], exact[1])}, "
                f"pitch {rel(kn[2, 2], exact[2])}"
            )
    if ntb_parts:
        notes.append(
            "navaltoolbox's stiffness (the diagonal of `stiffness_matrix`) against the analytic values: "
            + "; ".join(ntb_parts)
            + "."
        )
    if rule_parts:
        notes.append(
            "capytaine's roll and pitch stiffness follow a one-point (centroid) rule for the waterplane's second "
            "moments, ρg·(Σ y_c²·|n_z|·area + V·(z_B − z_G)) over the bottom's triangles (likewise in x): "
            + "; ".join(rule_parts)
            + ". Exact for no flat panel, the rule converges as the panels shrink."
        )
    if coupling:
        notes.append(
            "Heave-roll-pitch coupling, zero for these hulls (symmetric about G's vertical): the largest "
            "off-diagonal entry over the largest diagonal one, " + "; ".join(coupling) + "."
        )
    exactly = "equal to the analytic values" if ours_worst == 0.0 else f"within {ours_worst:.1e} of the analytic values"
    notes.append(
        f"Ours: the stiffness on both boxes {exactly}; on the Wigley hull, the mesh's discretisation error (case 3)."
    )
    print("case 4: done")
    lines += [
        "## 4. Heave, roll and pitch stiffness about G",
        "",
        "Upright at the draft, about G (rotation center and center of mass there for capytaine): "
        "C33 = ρg·A_wp, C44 = ρgV·GM_T, C55 = ρgV·GM_L, the weight's term included; the Wigley hull's "
        "analytic values are the smooth hull's (the mesh's own error: case 3). "
        "navaltoolbox: the diagonal of its `stiffness_matrix` from `from_draft(T, vcg=KG)`.",
        "",
        *table(header, rows),
        "",
    ]


# --------------------------------------------------------------------------------------------
# Timing.


def lever_mm(mesh: buoyancy.Mesh, mass: float, cog: tuple[float, float, float], heel: float) -> str:
    """How far apart B and G are across the vertical at a heel: ours' GZ there (trim free), mm."""
    gz = mesh.gz_curve(mass, cog, [heel], water=water()).gz[0]
    return f"B, G {abs(gz) * 1e3:.2g} mm apart"


def timing(ntb: NavalToolbox | None, cpt: Capytaine | None, budget: float, lines: list[str], notes: list[str]) -> None:
    rows = []
    ratios = []
    w = wigley()
    cases = [
        ("box, 12 triangles", box(1), BOX_T, (BOX_L / 2, BOX_OFFSET, BOX_KG), RHO * BOX_L * BOX_B * BOX_T),
        (
            f"Wigley, {w.n_triangles:,} triangles, draft T (a vertex row)",
            w,
            W_T,
            (W_L / 2, 0.01, W_KG),
            RHO * ours_upright(w, W_T, (W_L / 2, 0.0, W_KG)).displaced_volume,
        ),
        (
            f"Wigley, {w.n_triangles:,} triangles, draft {W_T_BETWEEN:g} m (between rows)",
            w,
            W_T_BETWEEN,
            (W_L / 2, 0.01, W_KG),
            RHO * ours_upright(w, W_T_BETWEEN, (W_L / 2, 0.0, W_KG)).displaced_volume,
        ),
    ]
    for name, mesh, _draft, cog, mass in cases:
        wat = water()
        before = load_average()
        eq = mesh.equilibrium(mass, cog, water=wat)
        t_ours, n_ours = median_ns(
            lambda mesh=mesh, mass=mass, cog=cog, wat=wat: mesh.equilibrium(mass, cog, water=wat), budget
        )
        row = [
            name,
            "equilibrium for m, G",
            f"{fmt_time(t_ours)} ({n_ours})",
            f"heel {eq.heel:.4f}°, trim {eq.trim:.1e}°, {lever_mm(mesh, mass, cog, eq.heel)}",
        ]
        if ntb is not None:
            calc = ntb.calculator(mesh)
            try:
                s = calc.from_displacement(mass, cog=cog)
                t_ntb, n_ntb = median_ns(
                    lambda calc=calc, mass=mass, cog=cog: calc.from_displacement(mass, cog=cog), budget
                )
                ratio = t_ntb / t_ours
                ratios.append((name, ratio))
                result = f"heel {s.heel:.4f}°, trim {s.trim:.1e}°, {lever_mm(mesh, mass, cog, s.heel)}"
                if name.startswith("Wigley"):
                    notes.append(
                        f"{name}, G 0.01 m to port: navaltoolbox's equilibrium heel {s.heel:.2f}° where ours is "
                        f"{eq.heel:.2f}° ({s.heel - eq.heel:+.2f}°); at its heel {lever_mm(mesh, mass, cog, s.heel)}, "
                        f"at ours {lever_mm(mesh, mass, cog, eq.heel)} (ours' GZ, trim free)."
                    )
                row += [f"{fmt_time(t_ntb)} ({n_ntb})", result, f"{ratio:,.1f}×"]
            except Exception as e:
                row += [f"failed: {type(e).__name__}: {e}", "", ""]
        row.append(f"{before} → {load_average()}")
        rows.append(row)
        print("timing:", row, flush=True)
    header = ["hull", "solve", "ours (calls)", "ours' result"]
    if ntb is not None:
        header += ["navaltoolbox `from_displacement` (calls)", "its result", "navaltoolbox / ours"]
    header.append("load average (1, 5, 15 min) before → after")

    # Hydrostatics at a given pose.
    rows2 = []
    for name, mesh, draft, cog, _mass in cases:
        g0 = (cog[0], 0.0, cog[2])
        wat = water(draft)
        before = load_average()
        t_ours, n_ours = median_ns(lambda mesh=mesh, g0=g0, wat=wat: mesh.hydrostatics(g0, water=wat), budget)
        row = [name, f"{fmt_time(t_ours)} ({n_ours})"]
        if ntb is not None:
            calc = ntb.calculator(mesh)
            t, n = median_ns(lambda calc=calc, draft=draft, g0=g0: calc.from_draft(draft, vcg=g0[2]), budget)
            row += [f"{fmt_time(t)} ({n})", f"{t / t_ours:,.0f}×"]
        if cpt is not None:
            body = cpt.body(mesh, draft, np.array(g0))
            t, n = median_ns(lambda body=body: cpt.hydrostatics(body), budget)
            row += [f"{fmt_time(t)} ({n})", f"{t / t_ours:,.0f}×"]
        row.append(f"{before} → {load_average()}")
        rows2.append(row)
        print("timing:", row, flush=True)
    header2 = ["hull", "ours `hydrostatics` (calls)"]
    if ntb is not None:
        header2 += ["navaltoolbox `from_draft` (calls)", "navaltoolbox / ours"]
    if cpt is not None:
        header2 += ["capytaine `compute_hydrostatics` (calls)", "capytaine / ours"]
    header2.append("load average before → after")

    goal = ""
    if ratios:
        worst = min(r for _, r in ratios)
        met = [n for n, r in ratios if r >= 100]
        missed = [n for n, r in ratios if r < 100]
        verdict = (
            "met on every hull"
            if not missed
            else "not met on any hull"
            if not met
            else f"met on {'; '.join(met)}, not met on {'; '.join(missed)}"
        )
        goal = (
            "Goal (issue 16): the equilibrium solve at least 100× faster than navaltoolbox's. Measured: "
            + "; ".join(f"{n} {r:,.1f}×" for n, r in ratios)
            + f". In this run the goal is {verdict} (the smallest ratio {worst:,.1f}×)."
        )
    lines += [
        "## Time",
        "",
        "Median wall time per call (`time.perf_counter_ns`; the number of timed calls in parentheses), one "
        "thread. The equilibrium: ours `mesh.equilibrium(m, G)` (draft, heel and trim, a Newton solve on the "
        "potential with exact volumes at each step, to the default relative tolerance ε^(2/3) ≈ 3.7e-11), navaltoolbox's "
        "`from_displacement(m, cog=G)` (draft, trim and heel for the mass and center of gravity, its own "
        "tolerances, and a full set of hydrostatics at the end: wetted surface, sectional areas, coefficients). "
        "Ours starts from the upright pose (its default); each mesh is loaded once, outside the timing. "
        '"B, G apart": the horizontal distance between B and G at the heel a solve returns, from ours\' GZ at '
        "that heel (draft and trim solved), zero at the equilibrium. Not quite like for like: the two "
        "solves stop at different tolerances and navaltoolbox's lands elsewhere (case 1), and it returns more "
        "quantities.",
        "",
        *table(header, rows),
        "",
        *([goal, ""] if goal else []),
        "Hydrostatics at a given pose (upright at the draft, G on the centerline): ours `mesh.hydrostatics(G)` "
        "(volume, B, waterplane, KB, BM, GM, stiffness), navaltoolbox `from_draft(T, vcg=KG)`, capytaine "
        "`compute_hydrostatics(rho, g)` (which clips the mesh at z = 0 on each call).",
        "",
        *table(header2, rows2),
        "",
    ]


# --------------------------------------------------------------------------------------------


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--budget", type=float, default=2.0, help="seconds of repeated timing per implementation")
    parser.add_argument("--out", type=pathlib.Path, default=REPO / "benches" / "PEERS_HYDROSTATICS.md")
    args = parser.parse_args()

    header = machine(("buoyancy", "numpy", "navaltoolbox", "capytaine"))
    start = load_average()
    for line in header:
        print(line)
    print(f"Start: {start}\n", flush=True)

    skipped: list[str] = []
    ntb: NavalToolbox | None = None
    cpt: Capytaine | None = None
    try:
        ntb = NavalToolbox()
    except ImportError as e:
        skipped.append(f"navaltoolbox is not installed ({e}): its columns are left out")
    try:
        cpt = Capytaine()
    except ImportError as e:
        skipped.append(f"capytaine is not installed ({e}): its columns are left out")
    for message in skipped:
        print("note: " + message)

    body: list[str] = []
    notes: list[str] = []
    case_equilibrium(ntb, body, notes)
    case_vertex_row(ntb, cpt, body, notes)
    case_wigley(ntb, cpt, body, notes)
    case_stiffness(ntb, cpt, body, notes)
    timing_lines: list[str] = []
    timing(ntb, cpt, args.budget, timing_lines, notes)
    end = load_average()

    command = "python benches/peers_hydrostatics.py" + (f" --budget {args.budget:g}" if args.budget != 2.0 else "")
    doc = [
        "# Peers: hydrostatics and equilibrium",
        "",
        f"Written by `{command}` (see the top of `benches/peers_hydrostatics.py` for the setup and how each "
        "peer is called). Ours (`buoyancy`) against navaltoolbox and capytaine on the same meshes, each "
        "against the analytic value: a box's equilibrium heel with G off the centerline, a box with a row of "
        "vertices on the waterline, a Wigley hull at its design draft, the heave, roll and pitch stiffness; "
        "then the time of the equilibrium solve and of the hydrostatics at a pose. Frame: x forward, y to "
        "port, z up, keel at z = 0, fresh water (1000 kg/m³, g = 9.81 m/s²); positive heel is starboard "
        "down. Relative differences unless marked.",
        "",
        *[f"- {line}" for line in header],
        f"- Checkout: {git_state()} (`git describe --dirty`; the wheel is the installed `buoyancy`).",
        f"- Load average (1, 5, 15 min) at the start: {start.removeprefix('load ')}; at the end: "
        f"{end.removeprefix('load ')}. The machine has 2 cores shared with other work, so times are noisy.",
        *[f"- Skipped: {message}" for message in skipped],
        "",
        *body,
        "## Differences",
        "",
        *[f"- {note}" for note in notes],
        "",
        *timing_lines,
    ]
    args.out.write_text("\n".join(doc))
    print(f"\nwrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
