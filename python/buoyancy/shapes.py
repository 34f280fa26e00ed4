"""Procedural closed meshes, built by the Rust core (no files needed).

>>> from buoyancy import shapes
>>> shapes.cube(10).n_triangles           # the paper's 1,200-triangle cube
1200
>>> shapes.uv_sphere(1.0, 50, 50).n_triangles
4900
"""

from ._core import cube, torus, torus_knot, uv_sphere

__all__ = ["cube", "torus", "torus_knot", "uv_sphere"]
