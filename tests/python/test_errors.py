"""Every error path: the exception type, and a message naming the argument and what is wrong."""

from __future__ import annotations

import pathlib

import numpy as np
import pytest

import buoyancy
from buoyancy import shapes

TET_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TET_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
NAN = float("nan")
INF = float("inf")


def test_mesh_error_is_a_value_error() -> None:
    assert issubclass(buoyancy.MeshError, ValueError)
    assert buoyancy.MeshError.__module__ == "buoyancy"


@pytest.mark.parametrize(
    "vertices, faces, match",
    [
        (TET_V, [], "no triangles"),
        ([(0, 0, 0), (1, 0, 0), (0, NAN, 0), (0, 0, 1)], TET_F, "vertex 2 has a NaN"),
        ([(0, 0, 0), (1, 0, 0), (0, INF, 0), (0, 0, 1)], TET_F, "vertex 2 has a NaN or infinite"),
        (TET_V, TET_F[:3] + [(1, 2, 9)], "triangle 3 refers to vertex 9, but the mesh has only 4"),
        (TET_V, [(0, 2, 1), (0, 1, 1), (0, 3, 2), (1, 2, 3)], r"triangle 1 uses a vertex twice"),
        (TET_V, TET_F[:3], r"not closed: edge \(1, 2\) of triangle 0"),
        (TET_V, TET_F[:3] + [(1, 3, 2)], r"triangles 0 and 3 are oriented inconsistently: both traverse edge 2 -> 1"),
        (TET_V + [(1, 1, -1)], TET_F + [(1, 2, 4), (2, 1, 4)], r"edge \(1, 2\) is shared by 4 triangles"),
        (TET_V, [(0, 1, 2), (0, 2, 1)], "encloses no volume"),
        (np.zeros((4, 2)), TET_F, r"vertices: expected shape \(N, 3\), got shape \(4, 2\)"),
        (np.zeros(12), TET_F, r"vertices: expected shape \(N, 3\), got shape \(12,\)"),
        (TET_V, np.zeros((4, 4), int), r"faces: expected shape \(M, 3\)"),
        (TET_V, TET_F[:3] + [(1, 2, 3.5)], r"faces\[3\]: 3.5 is not a vertex index"),
        (TET_V, TET_F[:3] + [(1, 2, -3)], r"faces\[3\]: -3 is not a vertex index"),
        ([("a", "b", "c")] * 4, TET_F, "vertices: expected an array of numbers"),
        ([(0, 0, 0), (1, 0)], TET_F, "vertices: expected an array of numbers"),
    ],
)
def test_mesh_errors(vertices, faces, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(buoyancy.MeshError, match=match):
        buoyancy.Mesh(vertices, faces)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(density=0.0), "invalid water density"),
        (dict(density=-1.0), "invalid water density"),
        (dict(density=NAN), "invalid water density"),
        (dict(gravity=-9.81), "invalid water gravity"),
        (dict(gravity=INF), "invalid water gravity"),
        (dict(level=NAN), "invalid water level"),
        (dict(normal=(0, 0, 0)), "invalid water normal: is the zero vector"),
        (dict(normal=(0, NAN, 0)), "normal: has a NaN or infinite component"),
        (dict(normal=(0, 1)), r"normal: expected 3 numbers \(shape \(3,\)\), got shape \(2,\)"),
        (dict(normal="up"), "normal: expected an array of numbers"),
    ],
)
def test_water_errors(kwargs, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        buoyancy.Water(**kwargs)


def test_water_type_errors() -> None:
    with pytest.raises(TypeError):
        buoyancy.Water(density="dense")  # type: ignore[arg-type]
    with pytest.raises(TypeError):
        shapes.cube().buoyancy(water="sea")  # type: ignore[arg-type]


ROT_45 = np.array([[np.cos(0.7), -np.sin(0.7), 0], [np.sin(0.7), np.cos(0.7), 0], [0, 0, 1]])


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(position=(1, 2)), r"position: expected 3 numbers \(shape \(3,\)\), got shape \(2,\)"),
        (dict(position=np.zeros((1, 3))), r"position: expected 3 numbers .* got shape \(1, 3\)"),
        (dict(position=(NAN, 0, 0)), "position: has a NaN or infinite component"),
        (dict(position=np.array([0, INF, 0])), "position: has a NaN or infinite component"),
        (dict(position="abc"), "position: expected an array of numbers"),
        (dict(rotation=(0, 0, 0, 2)), "rotation: the quaternion .* has norm 2, not 1"),
        (dict(rotation=(0, 0, 0, 0)), "rotation: the quaternion .* has norm 0, not 1"),
        (dict(rotation=(0, 0, 0, 1.001)), "rotation: the quaternion .* not 1"),
        (dict(rotation=(NAN, 0, 0, 1)), "rotation: has a NaN or infinite component"),
        (dict(rotation=(0, 0, 1)), r"rotation: expected a quaternion .* got shape \(3,\)"),
        (dict(rotation=np.ones((3, 3))), "rotation: the 3×3 matrix is not a rotation"),
        (dict(rotation=2 * np.eye(3)), "rotation: the 3×3 matrix is not a rotation"),
        (dict(rotation=np.diag([1.0, 1.0, -1.0])), "rotation: the 3×3 matrix is a reflection"),
        (dict(rotation=ROT_45 * np.array([1, 1, NAN])), "rotation: has a NaN or infinite component"),
        (dict(rotation=np.eye(4)), r"rotation: expected a quaternion .* got shape \(4, 4\)"),
        (dict(method="slow"), "method: unknown method \"slow\"; valid methods are fast, improved, exact, fast_surface, exact_surface"),
        (dict(about=(0, 0)), r"about: expected 3 numbers .* got shape \(2,\)"),
        (dict(about=(0, NAN, 0)), "about: has a NaN or infinite component"),
    ],
)
def test_buoyancy_argument_errors(kwargs, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        shapes.cube().buoyancy(**kwargs)


def test_overflow_is_an_error_not_infinity() -> None:
    water = buoyancy.Water(density=1e300, gravity=1e10)
    with pytest.raises(ValueError, match="overflowed"):
        shapes.cube().buoyancy((0, -1e300, 0), water=water)
    with pytest.raises(ValueError, match="pose 0: .*overflowed"):  # ρg itself overflows: every pose
        shapes.cube().buoyancy_batch([(0, 5, 0), (0, -1e300, 0)], None, water=water)


GOOD = np.zeros((3, 3))
QUATS = np.tile([0.0, 0.0, 0.0, 1.0], (3, 1))


@pytest.mark.parametrize(
    "args, kwargs, match",
    [
        ((np.zeros((3, 2)), QUATS), {}, r"positions: expected shape \(K, 3\), got shape \(3, 2\)"),
        ((np.zeros(3), QUATS), {}, r"positions: expected shape \(K, 3\), got shape \(3,\)"),
        ((np.array([[0, 0, 0], [0, NAN, 0], [0, 0, 0]]), QUATS), {}, r"positions\[1\]: has a NaN"),
        ((GOOD, np.zeros((3, 3))), {}, r"rotations: expected quaternions .* got shape \(3, 3\)"),
        ((GOOD, QUATS[:2]), {}, "rotations: has 2 rotations for 3 positions"),
        ((GOOD, np.array([[0, 0, 0, 1], [0, 0, 0, 3], [0, 0, 0, 1]])), {}, r"rotations\[1\]: the quaternion .* has norm 3"),
        ((GOOD, np.array([[0, 0, 0, 1], [0, 0, 0, 1], [INF, 0, 0, 1]])), {}, r"rotations\[2\]: has a NaN"),
        ((GOOD, np.array([np.eye(3), np.eye(3), -np.eye(3)])), {}, r"rotations\[2\]: the 3×3 matrix is a reflection"),
        ((GOOD, np.array([np.eye(3), 3 * np.eye(3), np.eye(3)])), {}, r"rotations\[1\]: the 3×3 matrix is not a rotation"),
        ((GOOD, QUATS), dict(method="Exactly"), "method: unknown method"),
        ((GOOD, QUATS), dict(about=np.zeros((2, 3))), r"about: expected one point \(3,\) or one per pose \(3, 3\), got shape \(2, 3\)"),
        ((GOOD, QUATS), dict(about=(0, NAN, 0)), "about: has a NaN"),
        ((GOOD, QUATS), dict(threads=0), "threads: must be at least 1"),
    ],
)
def test_batch_argument_errors(args, kwargs, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        shapes.cube().buoyancy_batch(*args, **kwargs)


def test_load_errors(tmp_path: pathlib.Path) -> None:
    with pytest.raises(FileNotFoundError, match="no such file"):
        buoyancy.load(tmp_path / "missing.obj")
    (tmp_path / "mesh.ply").write_text("ply\n")
    with pytest.raises(OSError, match="unknown format"):
        buoyancy.load(tmp_path / "mesh.ply")
    (tmp_path / "bad.obj").write_text("v 0 0 0\nv 1 x 0\n")
    with pytest.raises(buoyancy.MeshError, match="line 2"):
        buoyancy.load(tmp_path / "bad.obj")
    (tmp_path / "open.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(buoyancy.MeshError, match="not closed"):
        buoyancy.load(tmp_path / "open.obj")
    (tmp_path / "short.stl").write_bytes(b"\0" * 80 + (5).to_bytes(4, "little"))
    with pytest.raises(buoyancy.MeshError):
        buoyancy.load(tmp_path / "short.stl")


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: shapes.cube(0), "n: must be at least 1"),
        (lambda: shapes.uv_sphere(-1.0), "radius: must be finite and positive"),
        (lambda: shapes.uv_sphere(1.0, 2, 8), "slices: must be at least 3"),
        (lambda: shapes.torus(1.0, 2.0), "minor: must be smaller than major"),
        (lambda: shapes.torus_knot(sides=2), "sides: must be at least 3"),
        (lambda: shapes.torus_knot(p=0), "p: must be at least 1"),
        (lambda: shapes.cube(100_000), "n: too large"),
    ],
)
def test_shape_errors(call, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        call()
