"""Procedural closed meshes, built by the Rust core (no files needed).

>>> from buoyancy import shapes
>>> shapes.cube(10).n_triangles           # the paper's 1,200-triangle cube
1200
>>> shapes.uv_sphere(1.0, 50, 50).n_triangles
4900
>>> shapes.wigley_hull(4.0, 0.6, 0.25, 0.15).n_triangles   # a ship-like hull, 4 m long
2798
"""

from ._core import cube, torus, torus_knot, uv_sphere, wigley_hull

__all__ = ["cube", "torus", "torus_knot", "uv_sphere", "wigley_hull"]
