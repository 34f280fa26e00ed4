"""Procedural closed meshes, built by the Rust core (no files needed).

>>> from buoyancy import shapes
>>> shapes.cube(10).n_triangles           # the paper's 1,200-triangle cube
1200
>>> shapes.uv_sphere(1.0, 50, 50).n_triangles
4900
>>> shapes.wigley_hull(4.0, 0.6, 0.25, 0.15).n_triangles   # a ship-like hull, 4 m long
2798
>>> shapes.cylinder(0.5, 1.0).n_triangles   # a primitive holding its solid's volume exactly
128
"""

from ._core import (
    capsule,
    cube,
    cuboid,
    cylinder,
    ellipsoid,
    torus,
    torus_knot,
    uv_sphere,
    wigley_hull,
)

__all__ = [
    "capsule",
    "cube",
    "cuboid",
    "cylinder",
    "ellipsoid",
    "torus",
    "torus_knot",
    "uv_sphere",
    "wigley_hull",
]
