"""Peak memory of preparing a mesh (a benchmark script, not a test).

    python benches/mesh_memory.py [--triangles 2000000]

Each case runs in a fresh interpreter and reads its peak resident size (Linux's ``VmHWM``)
before and after: ``Mesh(vertices, faces)`` from numpy arrays of a UV sphere, and ``load`` of the
same sphere written as a binary STL (50 bytes a triangle). The figure per triangle is what
``buoyancy-core``'s ``Mesh::new`` checks it can have before it starts
(``PREPARED_BYTES_PER_TRIANGLE``, rounded up), so that a mesh too large is a ``MemoryError``,
not an abort.
"""

from __future__ import annotations

import argparse
import pathlib
import struct
import subprocess
import sys
import tempfile

import numpy as np

import buoyancy

CASE = r"""
import re, sys, numpy as np, buoyancy
# The peak resident size of this process (Linux's VmHWM; ru_maxrss would carry the parent's over
# the exec).
peak = lambda: int(re.search(r"VmHWM:\s+(\d+) kB", open("/proc/self/status").read()).group(1)) * 1024
if sys.argv[1] == "arrays":
    data = np.load(sys.argv[2])
    v, f = data["v"], data["f"]
    before = peak()
    mesh = buoyancy.Mesh(v, f)
else:
    before = peak()
    mesh = buoyancy.load(sys.argv[2])
print(mesh.n_triangles, peak() - before)
"""


def sphere(triangles: int) -> buoyancy.Mesh:
    """A UV sphere of about ``triangles`` triangles (2·slices·(stacks − 1), slices = 2·stacks)."""
    stacks = max(2, round((triangles / 4) ** 0.5))
    return buoyancy.shapes.uv_sphere(1.0, 2 * stacks, stacks)


def write_stl(mesh: buoyancy.Mesh, path: pathlib.Path) -> None:
    record = np.zeros(mesh.n_triangles, dtype=[("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    record["v"] = np.asarray(mesh.vertices)[np.asarray(mesh.faces)]
    with path.open("wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", mesh.n_triangles) + record.tobytes())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--triangles", type=int, default=2_000_000)
    args = parser.parse_args()
    mesh = sphere(args.triangles)
    with tempfile.TemporaryDirectory() as folder:
        arrays = pathlib.Path(folder) / "sphere.npz"
        np.savez(arrays, v=np.asarray(mesh.vertices), f=np.asarray(mesh.faces))
        stl = pathlib.Path(folder) / "sphere.stl"
        write_stl(mesh, stl)
        print("| case | triangles | file | peak | bytes per triangle |\n|---|---|---|---|---|")
        for case, path in [("Mesh(vertices, faces)", arrays), ("load (binary STL)", stl)]:
            kind = "arrays" if path == arrays else "file"
            out = subprocess.run(
                [sys.executable, "-c", CASE, kind, str(path)], check=True, capture_output=True, text=True
            )
            n, peak = map(int, out.stdout.split())
            size = path.stat().st_size if kind == "file" else 0
            file = f"{size / 1e6:.0f} MB ({peak / size:.1f}× peak)" if size else "–"
            print(f"| {case} | {n:,} | {file} | {peak / 1e6:.0f} MB | {peak / n:.0f} |")


if __name__ == "__main__":
    main()
