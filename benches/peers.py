"""Peers side by side: this project's wheel against trimesh, a numpy clip and navaltoolbox; on waves, against numpy.

A benchmark script, not a test. From the repository root:

    python3 -m venv .venv-peers
    .venv-peers/bin/pip install . numpy trimesh scipy shapely rtree mapbox-earcut networkx navaltoolbox
    .venv-peers/bin/python benches/peers.py            # [--budget 2.0] [--out benches/PEERS.md]
    .venv-peers/bin/python benches/peers.py --waves    # [--budget 2.0] [--out benches/PEERS_WAVES.md]

(trimesh's ``slice_plane(cap=True)`` needs scipy, shapely, rtree, mapbox-earcut and networkx besides
trimesh itself.) Every peer is optional: one that is not installed is skipped with a message.

On the same meshes and the same poses, for each implementation: the median time per evaluation
and the largest difference in submerged volume and in center of buoyancy from ours
(``buoyancy``, method ``exact``), the volume relative to the body's total volume and the center
relative to its bounding radius. Prints a Markdown table and writes it, with the machine, to
``benches/PEERS.md``.

Meshes: ``torusknot``, ``bunny`` and ``armadillo`` from ``$BUOYANCY_MESHES`` or
``../shared/meshes`` beside the repository (a missing file is skipped with a message), and a
procedural torus of 30,000 triangles, always available.

Poses: the paper's protocol, as in ``benches/common/mod.rs``: the body tilted by nalgebra's
``from_euler_angles(0.3, 0.5, 0.2)`` and lowered so that the water (y up, level 0) sweeps 100
heights from 5% to 95% of its vertical extent.

How each peer is called (the timed part is exactly what produces volume and center):

* ``buoyancy``: ``mesh.buoyancy(position, quaternion, method="exact")`` per pose, and
  ``mesh.buoyancy_batch(positions, quaternions, threads=1)`` over the 100 poses (its time
  divided by 100).
* trimesh: the mesh (centered on its centroid) sliced with ``slice_plane(origin, normal,
  cap=True)``, the plane brought into the mesh frame and its normal pointing *down*, since trimesh
  keeps the side the normal points to; then ``.volume`` and ``.center_mass``.
* numpy clip (``numpy_clip`` below): the divergence theorem with the reference point on the water
  plane, so the cap adds nothing; every triangle clipped against the plane with array operations
  (no Python loop over triangles), the clipped quads fanned into two triangles, the signed
  tetrahedra to the point on the plane summed. In the mesh frame, like trimesh.
* navaltoolbox: the body rotated and brought to a z-up frame, written once per mesh to a binary
  STL (float32 vertices), loaded as ``Hull``/``Vessel``; each pose is then
  ``HydrostaticsCalculator(vessel, 1000).from_draft(draft)``, the draft being the absolute z of the
  water plane in that frame (the poses differ only by height). ``.volume`` and ``.cob``. A second
  row times the literal recipe per pose: move the mesh so the water is z = 0, write the STL,
  ``Hull``, ``Vessel``, calculator, ``from_draft(0.0)``.

Timing: ``time.perf_counter_ns`` around each evaluation; a first pass over the 100 poses warms up
and gives the results; then passes are repeated (at least 3, or as many as fit in ``--budget``
seconds per implementation and mesh, at most 200). The median is over every (pass, pose)
sample; the table also gives the mean over poses of each pose's median, the paper's statistic.
The machine is shared, so figures are noisy: the load average is printed before and after.
numpy's BLAS is held to one thread (``OPENBLAS_NUM_THREADS`` etc. default to 1 here), as are ours.

Waves (``--waves``, numpy and the wheel only; writes ``benches/PEERS_WAVES.md``): the hydrostatic
pressure of the waves on the wetted surface, ours against the same model written in numpy, on the
same meshes and poses, the time advancing 0.05 s per pose, under the seas of ``benches/waves.rs``
(fresh water, y up, level 0): 8 Airy components (amplitude 0.05 m, wavelength 3 + 1.7 i m,
direction (cos i, 0, sin i), phase 0.7 i), a 64-component JONSWAP sea (``Waves.jonswap``: Hs
0.4 m, Tp 3 s, gamma 3.3, spreading 10, seed 1) and the 512² periodic ``HeightGrid`` of 0.25 m
spacing over 128 m. For each mesh and sea, the median time per evaluation (timed as above) of:

* ours: ``mesh.buoyancy(position, quaternion, water=water, method="exact_surface", time=t)`` per
  pose, and ``mesh.buoyancy_batch(positions, quaternions, water=water, method="exact_surface",
  threads=1, times=times)`` over the 100 poses (its time divided by 100; its results must be
  those of the per-pose calls, bit for bit, or a note says otherwise);
* numpy (``NumpyWaves``, the sums in ``numpy_wave_sums``), "Kerner-style" as game engines do it:
  the vertices moved to the pose, ``water.elevation(vertices, t)`` (the wheel's, so that both
  sides see the same sampled surface) and ``h = y − η`` per vertex; every triangle cut where its
  linear ``h`` is zero (the cut quads fanned into two triangles) and the linear pressure
  ``ρg(−h)`` integrated in closed form over each wetted piece, force and torque about the center
  of mass, with array operations over all the triangles (no Python loop over them), in the mesh
  frame about the centroid, rotated to the world at the end. A triangle under water all over
  contributes terms linear in its corners' depths, whose coefficients are computed once per mesh:
  per pose one matrix-vector product sums those triangles, and only the cut ones are clipped. The
  timed part is all of that, the elevation call included;
* the elevation call alone, ``water.elevation`` at the posed vertices (moved beforehand): the
  part of the numpy column spent in the wheel. Ours evaluates the surface only at the vertices
  that may be wet (at most the top of the surface's range over the body plus the longest edge
  above the still plane), numpy at every vertex, as Kerner's scheme does.

Both sides integrate the same piecewise-linear pressure exactly, so they should agree to
round-off: the table gives the largest, over the poses, ``|ΔF| / (ρ g V)`` and ``|Δτ| / (ρ g V R)``
(V the body's volume, R its bounding radius).
"""

from __future__ import annotations

import argparse
import importlib.metadata
import math
import os
import pathlib
import platform
import subprocess
import sys
import tempfile
import time
from typing import Any

# One thread everywhere: numpy's BLAS (OpenBLAS) otherwise runs its matrix-vector products on
# every core, which on a shared machine costs more than it saves (60× on a 90,000 × 6 product
# here). Set before numpy is imported; an explicit setting in the environment is kept.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")

import numpy as np

import buoyancy
from buoyancy._sample_meshes import find_sample_mesh, not_found_message

REPO = pathlib.Path(__file__).resolve().parents[1]
UP = np.array([0.0, 1.0, 0.0])
N_POSES = 100


# --------------------------------------------------------------------------------------------
# The numpy clip: also imported by tests/python/test_peers_numpy_clip.py.


def numpy_clip(triangles: np.ndarray, normal: np.ndarray, level: float) -> tuple[float, np.ndarray]:
    """Volume and centroid of the part of a closed, outward-wound mesh with ``normal·x <= level``.

    ``triangles`` is ``(M, 3, 3)`` (triangle, corner, xyz); ``normal`` a unit vector. The divergence
    theorem with the reference point ``o = level·normal`` on the plane: the submerged solid is
    bounded by the clipped triangles and by a cap lying in the plane, whose tetrahedra to ``o``
    have no volume, so only the clipped triangles are summed. Returns ``(0, o)`` when nothing
    is below the plane.
    """
    origin = normal * level
    p = triangles - origin  # corners relative to the point on the plane
    s = p @ normal  # (M, 3) signed heights
    below = s < 0.0
    count = below.sum(axis=1)
    full = p[count == 3]
    # Partially submerged triangles, cyclically rotated (orientation kept) so that corner 0 is
    # the odd one out: the only corner below (count 1) or the only corner above (count 2).
    partial = (count == 1) | (count == 2)
    pp, sp, bp, cp = p[partial], s[partial], below[partial], count[partial]
    odd = np.where(cp == 1, np.argmax(bp, axis=1), np.argmin(bp, axis=1))
    order = (odd[:, None] + np.arange(3)) % 3
    rows = np.arange(len(odd))[:, None]
    q, sq = pp[rows, order], sp[rows, order]
    p0, p1, p2 = q[:, 0], q[:, 1], q[:, 2]
    s0 = sq[:, 0:1]
    # Corner 0 and corners 1, 2 lie strictly on opposite sides (one s < 0, the other s >= 0):
    # the denominators are never zero.
    i1 = p0 + s0 / (s0 - sq[:, 1:2]) * (p1 - p0)
    i2 = p0 + s0 / (s0 - sq[:, 2:3]) * (p2 - p0)
    one = cp == 1  # the tip (p0, i1, i2) is under water
    two = ~one  # the quad (i1, p1, p2, i2) is, fanned from i1
    a = np.concatenate([full[:, 0], p0[one], i1[two], i1[two]])
    b = np.concatenate([full[:, 1], i1[one], p1[two], p2[two]])
    c = np.concatenate([full[:, 2], i2[one], p2[two], i2[two]])
    six_v = np.einsum("ij,ij->i", a, np.cross(b, c))  # 6 × signed tetrahedron volume to o
    volume6 = six_v.sum()
    if volume6 == 0.0:
        return 0.0, origin
    moment = six_v @ (a + b + c)  # 24 × first moment about o
    return volume6 / 6.0, origin + moment / (4.0 * volume6)


# --------------------------------------------------------------------------------------------
# Meshes and poses.


def models() -> list[tuple[str, buoyancy.Mesh]]:
    out = []
    for name in ("torusknot", "bunny", "armadillo"):
        path = find_sample_mesh(f"{name}.obj", REPO)
        if path is not None:
            mesh = buoyancy.load(path)
            out.append((f"{name} {mesh.n_triangles:,}", mesh))
        else:
            print(f"note: {not_found_message(REPO, f'{name}.obj')}; skipping {name}")
    torus = buoyancy.shapes.torus(1.0, 0.25, 200, 75)
    out.append((f"torus {torus.n_triangles:,} (procedural)", torus))
    return out


def euler_rotation(roll: float, pitch: float, yaw: float) -> tuple[np.ndarray, np.ndarray]:
    """nalgebra's ``UnitQuaternion::from_euler_angles``: R = Rz(yaw)·Ry(pitch)·Rx(roll).

    Returns the quaternion ``(x, y, z, w)`` and the matrix.
    """
    sr, cr = math.sin(roll / 2), math.cos(roll / 2)
    sp, cp = math.sin(pitch / 2), math.cos(pitch / 2)
    sy, cy = math.sin(yaw / 2), math.cos(yaw / 2)
    w = cr * cp * cy + sr * sp * sy
    x = sr * cp * cy - cr * sp * sy
    y = cr * sp * cy + sr * cp * sy
    z = cr * cp * sy - sr * sp * cy
    quat = np.array([x, y, z, w])
    rx = np.array([[1, 0, 0], [0, math.cos(roll), -math.sin(roll)], [0, math.sin(roll), math.cos(roll)]])
    ry = np.array([[math.cos(pitch), 0, math.sin(pitch)], [0, 1, 0], [-math.sin(pitch), 0, math.cos(pitch)]])
    rz = np.array([[math.cos(yaw), -math.sin(yaw), 0], [math.sin(yaw), math.cos(yaw), 0], [0, 0, 1]])
    matrix = rz @ ry @ rx
    from_quat = np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )
    assert np.allclose(matrix, from_quat, atol=1e-14)
    return quat, matrix


class Case:
    """One mesh under the paper's 100 poses, with what every implementation needs."""

    def __init__(self, name: str, mesh: buoyancy.Mesh) -> None:
        self.name, self.mesh = name, mesh
        self.quat, self.rot = euler_rotation(0.3, 0.5, 0.2)
        self.centroid = mesh.centroid
        self.vertices = np.ascontiguousarray(mesh.vertices, dtype=np.float64)
        self.faces = np.ascontiguousarray(mesh.faces, dtype=np.int64)
        self.centered = self.vertices - self.centroid  # mesh frame, about the centroid
        heights = self.centered @ self.rot.T @ UP
        lowest, highest = heights.min(), heights.max()
        fractions = 0.05 + 0.9 * np.arange(N_POSES) / (N_POSES - 1)
        #: the centroid's world height at each pose; the water is y = 0
        self.heights = -(lowest + (highest - lowest) * fractions)
        self.positions = self.heights[:, None] * UP - self.rot @ self.centroid  # (K, 3)
        #: the water plane in the centered mesh frame: normal·x = level[k], keep below
        self.normal_m = self.rot.T @ UP
        self.levels = -(self.positions @ UP) - self.normal_m @ self.centroid
        self.volume = mesh.volume
        self.radius = mesh.bounding_radius

    def to_world(self, k: int, centered_point: np.ndarray) -> np.ndarray:
        return self.rot @ (self.centroid + centered_point) + self.positions[k]


# --------------------------------------------------------------------------------------------
# Implementations: each gives, for a case, a timed `run(k)` doing all the work for pose k and an
# untimed `result(out, k)` giving (volume, world center) from what `run` returned.


class Impl:
    name = ""
    short = ""
    per_batch = False  # run() evaluates all the poses at once

    def prepare(self, case: Case) -> None: ...

    def run(self, k: int) -> Any: ...

    def result(self, out: Any, k: int) -> tuple[Any, np.ndarray]: ...


class Ours(Impl):
    name = "buoyancy `exact`, `mesh.buoyancy` per pose"
    short = "buoyancy"

    def prepare(self, case: Case) -> None:
        self.case = case
        self.positions = [tuple(p) for p in case.positions]
        self.quat = tuple(case.quat)

    def run(self, k: int) -> Any:
        return self.case.mesh.buoyancy(self.positions[k], self.quat, method="exact")

    def result(self, out: Any, k: int) -> tuple[float, np.ndarray]:
        return out.volume, out.center


class OursBatch(Impl):
    name = "buoyancy `exact`, `mesh.buoyancy_batch`, 1 thread"
    short = "buoyancy batch"
    per_batch = True

    def prepare(self, case: Case) -> None:
        self.case = case
        self.quats = np.tile(case.quat, (N_POSES, 1))

    def run(self, k: int) -> Any:
        return self.case.mesh.buoyancy_batch(self.case.positions, self.quats, method="exact", threads=1)

    def result(self, out: Any, k: int) -> tuple[float, np.ndarray]:
        return out.volume[k], out.center[k]


class NumpyClip(Impl):
    name = "numpy clip (vectorized, reference point on the plane)"
    short = "numpy clip"

    def prepare(self, case: Case) -> None:
        self.case = case
        self.triangles = np.ascontiguousarray(case.centered[case.faces])

    def run(self, k: int) -> Any:
        return numpy_clip(self.triangles, self.case.normal_m, self.case.levels[k])

    def result(self, out: Any, k: int) -> tuple[float, np.ndarray]:
        return out[0], self.case.to_world(k, out[1])


class Trimesh(Impl):
    name = "trimesh `slice_plane(cap=True)`, `.volume`, `.center_mass`"
    short = "trimesh"

    def __init__(self) -> None:
        import trimesh

        self.trimesh = trimesh

    def prepare(self, case: Case) -> None:
        self.case = case
        self.body = self.trimesh.Trimesh(case.centered, case.faces, process=False)
        self.down = -case.normal_m

    def run(self, k: int) -> Any:
        origin = self.case.normal_m * self.case.levels[k]
        part = self.body.slice_plane(origin, self.down, cap=True)
        return part.volume, part.center_mass

    def result(self, out: Any, k: int) -> tuple[float, np.ndarray]:
        return out[0], self.case.to_world(k, np.asarray(out[1]))


#: world (y up) to navaltoolbox's z-up frame: (x, y, z) -> (x, -z, y), a proper rotation
Z_UP = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


def write_stl(path: str, vertices: np.ndarray, faces: np.ndarray) -> None:
    """A binary STL (float32, as the format stores)."""
    tri = vertices[faces]
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    lengths = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.divide(normals, lengths, out=np.zeros_like(normals), where=lengths > 0)
    record = np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    data = np.zeros(len(faces), dtype=record)
    data["n"], data["v"] = normals, tri
    with open(path, "wb") as f:
        f.write(b"buoyancy benches/peers.py".ljust(80, b" "))
        f.write(np.uint32(len(faces)).tobytes())
        f.write(data.tobytes())


class NavalToolbox(Impl):
    name = "navaltoolbox `from_draft` (STL written once per mesh)"
    short = "navaltoolbox"

    def __init__(self) -> None:
        import navaltoolbox

        self.ntb = navaltoolbox
        self.tmp = tempfile.TemporaryDirectory(prefix="peers-")

    def prepare(self, case: Case) -> None:
        self.case = case
        # The body rotated, centroid at the origin, in the z-up frame; pose k lifts it by
        # heights[k], so its water plane z = 0 is z = -heights[k] here: that is the draft.
        zup = case.centered @ (Z_UP @ case.rot).T
        path = os.path.join(self.tmp.name, "body.stl")
        write_stl(path, zup, case.faces)
        self.calculator = self.ntb.HydrostaticsCalculator(self.ntb.Vessel(self.ntb.Hull(path)), 1000.0)

    def run(self, k: int) -> Any:
        state = self.calculator.from_draft(-self.case.heights[k])
        return state.volume, state.cob

    def result(self, out: Any, k: int) -> tuple[float, np.ndarray]:
        cob_zup = np.asarray(out[1]) + np.array([0.0, 0.0, self.case.heights[k]])
        return out[0], Z_UP.T @ cob_zup


class NavalToolboxPerPose(NavalToolbox):
    name = "navaltoolbox, STL written and loaded per pose, `from_draft(0)`"
    short = "navaltoolbox with an STL per pose"

    def prepare(self, case: Case) -> None:
        self.case = case
        self.path = os.path.join(self.tmp.name, "posed.stl")
        self.world = [case.vertices @ case.rot.T + p for p in case.positions]  # posed, y up

    def run(self, k: int) -> Any:
        write_stl(self.path, self.world[k] @ Z_UP.T, self.case.faces)  # water plane z = 0, z up
        ntb = self.ntb
        state = ntb.HydrostaticsCalculator(ntb.Vessel(ntb.Hull(self.path)), 1000.0).from_draft(0.0)
        return state.volume, state.cob

    def result(self, out: Any, k: int) -> tuple[float, np.ndarray]:
        return out[0], Z_UP.T @ np.asarray(out[1])


# --------------------------------------------------------------------------------------------
# Measuring.


def measure(impl: Impl, case: Case, budget: float) -> dict[str, Any]:
    impl.prepare(case)
    clock = time.perf_counter_ns
    results: list[tuple[Any, np.ndarray]] = []
    first: list[int] = []
    if impl.per_batch:
        t0 = clock()
        out = impl.run(0)
        first.append(clock() - t0)
        results = [impl.result(out, k) for k in range(N_POSES)]
    else:
        for k in range(N_POSES):
            t0 = clock()
            out = impl.run(k)
            first.append(clock() - t0)
            results.append(impl.result(out, k))
    passes = int(min(200, max(3, budget * 1e9 / max(sum(first), 1))))
    if impl.per_batch:
        samples = np.empty((passes, 1))
        for r in range(passes):
            t0 = clock()
            impl.run(0)
            samples[r, 0] = (clock() - t0) / N_POSES
    else:
        samples = np.empty((passes, N_POSES))
        for r in range(passes):
            for k in range(N_POSES):
                t0 = clock()
                impl.run(k)
                samples[r, k] = clock() - t0
    return {
        # (volumes, centers) in still water, (forces, torques) on waves
        "values": tuple(np.array(v) for v in zip(*results, strict=True)),
        "median_ns": float(np.median(samples)),
        "mean_of_medians_ns": float(np.mean(np.median(samples, axis=0))),
        "passes": passes,
    }


def fmt_time(ns: float) -> str:
    us = ns / 1e3
    if us < 1000:
        return f"{us:.1f} µs"
    return f"{us / 1e3:.2f} ms"


# The packages whose versions the reports list.
PACKAGES = (
    "buoyancy",
    "numpy",
    "trimesh",
    "scipy",
    "shapely",
    "rtree",
    "mapbox-earcut",
    "networkx",
    "navaltoolbox",
)


def machine(packages: tuple[str, ...] = PACKAGES) -> list[str]:
    """The report's header lines: the CPU, Python and the versions of ``packages``."""
    cpu = platform.processor() or "unknown CPU"
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    usable = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    versions = []
    for pkg in packages:
        try:
            versions.append(f"{pkg} {importlib.metadata.version(pkg)}")
        except importlib.metadata.PackageNotFoundError:
            versions.append(f"{pkg} (not installed)")
    return [
        f"CPU: {cpu}, {os.cpu_count()} logical cores ({usable} usable)",
        f"Python {platform.python_version()} ({platform.python_implementation()}), {platform.system()} {platform.machine()}",
        "Packages: " + ", ".join(versions),
    ]


def load_average() -> str:
    try:
        return "load average " + ", ".join(f"{x:.2f}" for x in os.getloadavg()) + " (1, 5, 15 min)"
    except OSError:
        return "load average unknown"


# --------------------------------------------------------------------------------------------
# Waves mode (--waves): the hydrostatic pressure of the waves on the wetted surface.


def wave_coefficients(corners: np.ndarray) -> np.ndarray:
    """The per-corner terms of ``numpy_wave_sums``, fixed for a mesh: shape ``(3, M, 6)``.

    ``corners`` is ``(3, M, 3)`` (corner, triangle, xyz) about the point the torque is taken
    about, wound outward. For corner ``k`` of a triangle of corners ``rᵢ`` and
    ``2A = (r₁ − r₀) × (r₂ − r₀)``: ``2A`` and ``(rₖ + Σrᵢ) × 2A``, the factors of its depth in
    the sums of the triangle when it is under water all over.
    """
    a, b, c = corners
    area2 = np.cross(b - a, c - a)
    torque = np.cross(corners + (a + b + c), area2)
    return np.concatenate([np.broadcast_to(area2, torque.shape), torque], axis=2)


def numpy_wave_sums(coefficients: np.ndarray, corners: np.ndarray, heights: np.ndarray) -> np.ndarray:
    """The pressure sums of a mesh whose corners lie ``heights`` above the free surface.

    ``corners`` is ``(3, M, 3)`` (corner, triangle, xyz) about the point the torque is taken
    about, wound outward; ``coefficients`` its ``wave_coefficients``; ``heights`` the ``(3, M)``
    heights ``h`` of the corners above the surface. (Corner-major: numpy's reductions and
    broadcasts over a last axis of length 3 are several times slower.) ``h`` is linear over each
    triangle, which is cut where it is zero; over each wetted piece (a triangle of corners
    ``rᵢ``, depths ``dᵢ = −hᵢ ≥ 0``, area vector ``A``) the linear pressure ``ρ g d`` integrates
    exactly to

        ∫ d dA = A·Σdᵢ/3,     ∫ d r dA = |A|·(Σ dᵢ rᵢ + Σdᵢ Σrᵢ)/12

    (from ``∫ φᵢ φⱼ dA = |A|(1 + δᵢⱼ)/12`` for the linear shape functions). Returns the six sums
    ``(Σ Σdᵢ·2A, Σ (Σ dᵢ rᵢ + Σdᵢ Σrᵢ) × 2A)`` over the pieces: the force is ``−ρg/6`` times the
    first three, the torque about the origin of ``corners`` ``−ρg/24`` times the last three.
    Over a triangle under water all over both are linear in its corners' depths: one
    matrix-vector product with the precomputed coefficients sums those triangles.
    """
    below = heights < 0.0
    count = below[0].view(np.int8) + below[1].view(np.int8) + below[2].view(np.int8)
    sums = -((heights * (count == 3)).reshape(-1) @ coefficients.reshape(-1, 6))
    # The cut triangles, rotated (orientation kept) so that corner 0 is the odd one out, as in
    # `numpy_clip`: the only corner under water (count 1) or the only one above (count 2).
    cut = np.flatnonzero((count == 1) | (count == 2))
    p, h, b, n = corners[:, cut], heights[:, cut], below[:, cut], count[cut]
    odd = np.where(n == 1, np.argmax(b, axis=0), np.argmin(b, axis=0))
    order = (odd + np.arange(3)[:, None]) % 3
    columns = np.arange(len(cut))
    (p0, p1, p2), (h0, h1, h2) = p[order, columns], h[order, columns]
    # Corner 0 and corners 1, 2 lie strictly on opposite sides: no zero denominator. The cut
    # points have depth 0.
    i1 = p0 + (h0 / (h0 - h1))[:, None] * (p1 - p0)
    i2 = p0 + (h0 / (h0 - h2))[:, None] * (p2 - p0)
    one, two = np.flatnonzero(n == 1), np.flatnonzero(n == 2)
    # The tip (p0, i1, i2) under water, depths (d0, 0, 0); or the quad (i1, p1, p2, i2), fanned
    # into (i1, p1, p2), depths (0, d1, d2), and (i1, p2, i2), depths (0, d2, 0).
    d0, d1, d2 = -h0[one, None], -h1[two, None], -h2[two, None]
    p0, i1o, i2o = p0[one], i1[one], i2[one]
    p1, p2, i1, i2 = p1[two], p2[two], i1[two], i2[two]
    a = np.concatenate([p0, i1, i1])
    area2 = np.cross(np.concatenate([i1o, p1, p2]) - a, np.concatenate([i2o, p2, i2]) - a)
    depth = np.concatenate([d0, d1 + d2, d2])
    first = np.concatenate(
        [d0 * (2.0 * p0 + i1o + i2o), d1 * p1 + d2 * p2 + (d1 + d2) * (i1 + p1 + p2), d2 * (i1 + 2.0 * p2 + i2)]
    )
    sums[:3] += depth[:, 0] @ area2
    sums[3:] += np.cross(first, area2).sum(axis=0)
    return sums


def seas() -> list[tuple[str, buoyancy.Water]]:
    """The seas of ``benches/waves.rs``, on fresh water (1000 kg/m³, 9.81 m/s², y up, level 0)."""
    airy = buoyancy.Waves(
        [
            buoyancy.AiryWave(0.05, 3.0 + 1.7 * i, direction=(math.cos(i), 0.0, math.sin(i)), phase=0.7 * i)
            for i in range(8)
        ]
    )
    jonswap = buoyancy.Waves.jonswap(0.4, 3.0, gamma=3.3, direction=(1.0, 0.0, 0.0), spreading=10.0, n=64, seed=1)
    # A smooth periodic field over 128 m: two crossing swells, 0.3 m high; heights[j, i] at
    # x = -64 + i·0.25, z = -64 + j·0.25.
    n = 512
    t = 2.0 * math.pi / n
    i, j = np.arange(n)[None, :], np.arange(n)[:, None]
    heights = 0.2 * np.cos(3.0 * t * i) + 0.1 * np.sin(5.0 * t * (i + j))
    grid = buoyancy.HeightGrid(heights, spacing=128.0 / n, origin=(-64.0, -64.0), periodic=True)
    return [
        ("Airy ×8", buoyancy.Water(waves=airy)),
        ("JONSWAP ×64", buoyancy.Water(waves=jonswap)),
        ("grid 512²", buoyancy.Water(waves=grid)),
    ]


class WaveCase(Case):
    """A mesh under the paper's 100 poses in a sea, the time advancing 0.05 s per pose."""

    def __init__(self, name: str, mesh: buoyancy.Mesh, sea: str, water: buoyancy.Water) -> None:
        super().__init__(name, mesh)
        self.sea, self.water = sea, water
        self.times = 0.05 * np.arange(N_POSES)
        #: the body's center of mass (the centroid moved by the pose) at each pose
        self.com = self.positions + self.rot @ self.centroid
        self.specific_weight = water.specific_weight


class OursWaves(Impl):
    name = "buoyancy `exact_surface`, `mesh.buoyancy` per pose"
    short = "buoyancy"

    def prepare(self, case: Case) -> None:
        assert isinstance(case, WaveCase)
        self.case = case
        self.positions = [tuple(p) for p in case.positions]
        self.quat = tuple(case.quat)
        self.times = [float(t) for t in case.times]

    def run(self, k: int) -> Any:
        c = self.case
        return c.mesh.buoyancy(self.positions[k], self.quat, water=c.water, method="exact_surface", time=self.times[k])

    def result(self, out: Any, k: int) -> tuple[np.ndarray, np.ndarray]:
        return out.force, out.torque


class OursWavesBatch(Impl):
    name = "buoyancy `exact_surface`, `mesh.buoyancy_batch`, 1 thread"
    short = "buoyancy batch"
    per_batch = True

    def prepare(self, case: Case) -> None:
        assert isinstance(case, WaveCase)
        self.case = case
        self.quats = np.tile(case.quat, (N_POSES, 1))

    def run(self, k: int) -> Any:
        c = self.case
        return c.mesh.buoyancy_batch(
            c.positions, self.quats, water=c.water, method="exact_surface", threads=1, times=c.times
        )

    def result(self, out: Any, k: int) -> tuple[np.ndarray, np.ndarray]:
        return out.force[k], out.torque[k]


class NumpyWaves(Impl):
    name = "numpy per-triangle clip (vectorized), `water.elevation` included"
    short = "numpy"

    def prepare(self, case: Case) -> None:
        assert isinstance(case, WaveCase)
        self.case = case
        # Mesh frame about the centroid (the center of mass): the triangles and their per-corner
        # coefficients are fixed; only the heights change from pose to pose.
        self.faces = np.ascontiguousarray(case.faces.T)  # corner-major, (3, M)
        self.corners = case.centered[self.faces]
        self.coefficients = wave_coefficients(self.corners)
        self.rot_t = np.ascontiguousarray(case.rot.T)

    def run(self, k: int) -> Any:
        c = self.case
        world = c.centered @ self.rot_t + c.com[k]  # the vertices at pose k
        eta = c.water.elevation(world, c.times[k])  # η below each vertex
        heights = (world @ UP - eta)[self.faces]  # h = y − η at each corner (level 0)
        sums = numpy_wave_sums(self.coefficients, self.corners, heights)
        rho_g = c.specific_weight
        return (-rho_g / 6.0) * (c.rot @ sums[:3]), (-rho_g / 24.0) * (c.rot @ sums[3:])

    def result(self, out: Any, k: int) -> tuple[np.ndarray, np.ndarray]:
        return out


class Elevation(Impl):
    name = "of which `water.elevation` at the vertices"
    short = "elevation"

    def prepare(self, case: Case) -> None:
        assert isinstance(case, WaveCase)
        self.case = case
        self.world = [case.centered @ case.rot.T + com for com in case.com]

    def run(self, k: int) -> Any:
        return self.case.water.elevation(self.world[k], self.case.times[k])

    def result(self, out: Any, k: int) -> tuple[np.ndarray, np.ndarray]:
        return np.zeros(3), np.zeros(3)


def git_state() -> str:
    try:
        out = subprocess.run(
            ["git", "-C", str(REPO), "describe", "--always", "--dirty", "--abbrev=12"],
            capture_output=True,
            text=True,
            check=True,
        )
        return out.stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def main_waves(args: argparse.Namespace, header: list[str], before: str) -> int:
    impls: list[Impl] = [OursWaves(), OursWavesBatch(), NumpyWaves(), Elevation()]
    rows = []
    notes: list[str] = []
    worst_f = worst_t = 0.0
    for name, mesh in models():
        for sea, water in seas():
            case = WaveCase(name, mesh, sea, water)
            print(f"## {name}, {sea}: volume {case.volume:.6g}, bounding radius {case.radius:.6g}", flush=True)
            m = {impl.short: measure(impl, case, args.budget) for impl in impls}
            ours, batch, peer = m["buoyancy"], m["buoyancy batch"], m["numpy"]
            scale_f = case.specific_weight * case.volume
            scale_t = scale_f * case.radius
            (forces, torques), (our_forces, our_torques) = peer["values"], ours["values"]
            df = np.linalg.norm(forces - our_forces, axis=1) / scale_f
            dt = np.linalg.norm(torques - our_torques, axis=1) / scale_t
            worst_f, worst_t = max(worst_f, df.max()), max(worst_t, dt.max())
            if not all(np.array_equal(b, o) for b, o in zip(batch["values"], ours["values"], strict=True)):
                notes.append(f"{name}, {sea}: `buoyancy_batch` differs from `mesh.buoyancy` per pose")
                print("  note: " + notes[-1])
            wet = np.linalg.norm(our_forces, axis=1) > 0
            ratio = peer["median_ns"] / ours["median_ns"]
            row = (
                name,
                sea,
                fmt_time(ours["median_ns"]),
                fmt_time(batch["median_ns"]),
                fmt_time(peer["median_ns"]),
                fmt_time(m["elevation"]["median_ns"]),
                f"{ratio:,.1f}×" if ratio < 10 else f"{ratio:,.0f}×",
                f"{df.max():.1e}",
                f"{dt.max():.1e}",
                f"{ours['passes']}, {batch['passes']}, {peer['passes']}, {m['elevation']['passes']}",
            )
            rows.append(row)
            print(
                f"  ours {row[2]}, batch {row[3]}, numpy {row[4]} (elevation {row[5]}), numpy/ours {row[6]}, "
                f"max ΔF/(ρgV) {row[7]}, max Δτ/(ρgVR) {row[8]} ({int(wet.sum())} of {N_POSES} poses wet)",
                flush=True,
            )
        print(flush=True)

    after = load_average()
    table = [
        "| mesh | sea | ours, `mesh.buoyancy` | ours, `buoyancy_batch` | numpy | of which `water.elevation` | "
        "numpy / ours | max \\|ΔF\\| / (ρgV) | max \\|Δτ\\| / (ρgVR) | passes (ours, batch, numpy, elevation) |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    table += ["| " + " | ".join(row) + " |" for row in rows]
    text = "\n".join(table)
    print(text)
    print(f"\nAfter: {after}")

    command = "python benches/peers.py --waves" + (f" --budget {args.budget:g}" if args.budget != 2.0 else "")
    doc = [
        "# Peers on waves",
        "",
        f"Written by `{command}` (see the top of `benches/peers.py` for the setup and what each column",
        "times). The hydrostatic pressure of the waves, sampled at the vertices, on the paper's 100 poses of",
        "each mesh (tilted by Euler angles (0.3, 0.5, 0.2), still water from 5% to 95% of the body's height),",
        "the time advancing 0.05 s per pose, under the seas of `benches/waves.rs`: ours (`exact_surface`)",
        "against a vectorized numpy clip of the same model, triangle by triangle (Kerner-style: h = y − η(x, z)",
        "at the vertices, each triangle cut where its linear h is zero, the linear pressure ρg(−h) integrated",
        "in closed form over each wetted piece). Median time per evaluation; the numpy column includes its",
        "call to `water.elevation` at every vertex (ours), timed alone in the next column; ours evaluates η",
        "only at the vertices that may be wet (below the top of the surface's range over the body plus the",
        "longest edge). Differences: the",
        "largest over the poses of |ΔF| over ρg times the body's volume V and of |Δτ| (about the center of",
        "mass) over ρgV times its bounding radius R. One thread everywhere. A busy machine interrupts a batch",
        "of 100 evaluations more often than a single one, whose median then misses the interruptions: under",
        "load the batch column can read slower than the per-pose one, for the same work.",
        "",
        *[f"- {line}" for line in header],
        f"- Checkout the script ran from: {git_state()} (`git describe --dirty`; the wheel is the installed `buoyancy`).",
        f"- Before: {before}; after: {after}. The machine has 2 cores shared with other work, so times are noisy.",
        *[f"- {line}" for line in notes],
        "",
        text,
        "",
        f"Largest differences over all meshes and seas: |ΔF|/(ρgV) {worst_f:.1e}, |Δτ|/(ρgVR) {worst_t:.1e}.",
        "",
    ]
    out = args.out or REPO / "benches" / "PEERS_WAVES.md"
    out.write_text("\n".join(doc))
    print(f"\nwrote {out}")
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--budget", type=float, default=2.0, help="seconds of repeated timing per implementation and mesh"
    )
    parser.add_argument(
        "--out", type=pathlib.Path, default=None, help="default benches/PEERS.md, with --waves benches/PEERS_WAVES.md"
    )
    parser.add_argument(
        "--waves", action="store_true", help="on waves: ours against a numpy per-triangle clip (see the docstring)"
    )
    args = parser.parse_args()

    header = machine()
    before = load_average()
    for line in header:
        print(line)
    print(f"Before: {before}\n")
    if args.waves:
        return main_waves(args, header, before)

    impls: list[Impl] = [Ours(), OursBatch(), NumpyClip()]
    skipped: list[str] = []
    for cls, pkg in ((Trimesh, "trimesh"), (NavalToolbox, "navaltoolbox"), (NavalToolboxPerPose, "navaltoolbox")):
        try:
            impls.append(cls())
        except ImportError as e:
            message = f"{pkg} is not installed ({e}); skipping `{cls.name}`"
            if message not in skipped:
                skipped.append(message)
                print("note: " + message)

    rows = []
    outliers: list[str] = []
    outlier_meshes: set[str] = set()
    ratios: dict[tuple[str, str], float] = {}  # (mesh, peer) -> its median over ours, 30k meshes
    exact_peers: dict[str, list[str]] = {}  # mesh -> the largest ΔV/V of trimesh and the numpy clip
    for name, mesh in models():
        case = Case(name, mesh)
        print(f"## {name}: volume {case.volume:.6g}, bounding radius {case.radius:.6g}", flush=True)
        ours = None
        for impl in impls:
            try:
                m = measure(impl, case, args.budget)
            except Exception as e:  # a peer failing on a mesh is reported, not fatal
                print(f"  {impl.name}: failed: {type(e).__name__}: {e}")
                rows.append((name, impl.name, "failed", "", "", "", "", f"{type(e).__name__}: {e}"))
                continue
            if ours is None:
                ours = m
            (volumes, centers), (our_volumes, our_centers) = m["values"], ours["values"]
            dv = np.max(np.abs(volumes - our_volumes)) / case.volume
            dc = np.max(np.linalg.norm(centers - our_centers, axis=1)) / case.radius
            ratio = m["median_ns"] / ours["median_ns"]
            row = (
                name,
                impl.name,
                fmt_time(m["median_ns"]),
                fmt_time(m["mean_of_medians_ns"]),
                f"{ratio:,.1f}×" if ratio < 10 else f"{ratio:,.0f}×",
                f"{dv:.1e}",
                f"{dc:.1e}",
                f"{m['passes']} batches of {N_POSES}" if impl.per_batch else f"{m['passes']} × {N_POSES}",
            )
            off = np.flatnonzero(np.abs(volumes - our_volumes) / case.volume > 1e-6)
            if len(off):
                outlier_meshes.add(name)
                outliers.append(
                    f"{impl.name} on {name}: volume off by more than 1e-6 of the body's at "
                    f"{len(off)} of {N_POSES} poses (pose {', '.join(map(str, off[:10]))}"
                    f"{', ...' if len(off) > 10 else ''}; 0 is the driest)"
                )
                print("  note: " + outliers[-1])
            rows.append(row)
            if mesh.n_triangles >= 25_000 and isinstance(impl, (Trimesh, NavalToolbox)):
                ratios[(name, impl.short)] = ratio
            if isinstance(impl, (Trimesh, NumpyClip)):
                exact_peers.setdefault(name, []).append(f"{impl.short} {dv:.0e}")
            print(f"  {impl.name}: median {row[2]}, {row[4]} ours, ΔV/V {row[5]}, Δc/R {row[6]}", flush=True)
        print(flush=True)

    after = load_average()
    title = (
        "| mesh | implementation | median per evaluation | mean of per-pose medians | vs ours | "
        "max ΔV / volume | max Δcenter / radius | timed calls |"
    )
    table = [title, "|---|---|---|---|---|---|---|---|"]
    for row in rows:
        table.append("| " + " | ".join(row) + " |")
    text = "\n".join(table)
    print(text)
    print(f"\nAfter: {after}")

    command = "python benches/peers.py" + (f" --budget {args.budget:g}" if args.budget != 2.0 else "")
    doc = [
        "# Peers",
        "",
        f"Written by `{command}` (see the top of `benches/peers.py` for the setup and what each row times).",
        "The paper's 100 poses on each mesh (tilted by Euler angles (0.3, 0.5, 0.2), water from 5% to 95% of",
        "the body's height); differences are from `buoyancy`'s `exact` at the same pose, the volume relative",
        'to the body\'s volume, the center relative to its bounding radius. "vs ours" is the median time',
        "over `mesh.buoyancy`'s. One thread everywhere.",
        "",
        *[f"- {line}" for line in header],
        f"- Before: {before}; after: {after}. The machine has 2 cores shared with other work, so times are noisy.",
        *[f"- Skipped: {message}" for message in skipped],
        "",
        text,
        "",
        *(["Volume differences above 1e-6 of the body's volume:", ""] if outliers else []),
        *[f"- {line}" for line in outliers],
        *(
            [
                "",
                "On those meshes the two independent exact peers' largest volume differences from ours are: "
                + "; ".join(f"{mesh}: {', '.join(v)}" for mesh, v in exact_peers.items() if mesh in outlier_meshes)
                + ".",
            ]
            if outliers
            else []
        ),
        "",
    ]
    if ratios:
        worst = min(ratios.values())
        doc += [
            "Goal (issue 5, a figure, not a test): `exact` at least 500× faster than trimesh and navaltoolbox "
            "from Python on the ~30,000-triangle meshes. Measured: "
            + "; ".join(f"{impl} on {mesh} {r:,.0f}×" for (mesh, impl), r in ratios.items())
            + f" ({'met' if worst >= 500 else 'not met'} in this run: the smallest is {worst:,.0f}×).",
            "",
        ]
    out = args.out or REPO / "benches" / "PEERS.md"
    out.write_text("\n".join(doc))
    print(f"\nwrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
