"""Every error path: the exception type, and a message naming the argument and what is wrong."""

from __future__ import annotations

import os
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
        # The core's messages, passed through (their wording is tested in buoyancy-core).
        (TET_V, [], "no triangles"),
        ([(0, 0, 0), (1, 0, 0), (0, NAN, 0), (0, 0, 1)], TET_F, "NaN or infinite coordinate: vertex 2"),
        ([(0, 0, 0), (1, 0, 0), (0, INF, 0), (0, 0, 1)], TET_F, "NaN or infinite coordinate: vertex 2"),
        (TET_V, [*TET_F[:3], (1, 2, 9)], "triangle 3 refers to vertex 9"),
        (TET_V, [(0, 2, 1), (0, 1, 1), (0, 3, 2), (1, 2, 3)], r"uses a vertex twice: triangle 1 \[0, 1, 1\]"),
        (TET_V, TET_F[:3], r"not closed\): edge \(1, 2\) of triangle 0"),
        (TET_V, [*TET_F[:3], (1, 3, 2)], r"triangles 0 and 3 both traverse edge 2 -> 1"),
        ([*TET_V, (1, 1, -1)], [*TET_F, (1, 2, 4), (2, 1, 4)], r"edge \(1, 2\) shared by triangles 0, 3, 4, 5"),
        (TET_V, [(0, 1, 2), (0, 2, 1)], "encloses no volume"),
        (np.zeros((4, 2)), TET_F, r"vertices: expected shape \(N, 3\), got shape \(4, 2\)"),
        (np.zeros(12), TET_F, r"vertices: expected shape \(N, 3\), got shape \(12,\)"),
        (TET_V, np.zeros((4, 4), int), r"faces: expected shape \(M, 3\)"),
        (TET_V, [*TET_F[:3], (1, 2, 3.5)], r"faces\[3\]: 3.5 is not a vertex index"),
        (TET_V, [*TET_F[:3], (1, 2, -3)], r"faces\[3\]: -3 is not a vertex index"),
        ([("a", "b", "c")] * 4, TET_F, "vertices: expected an array of real numbers, got an array of strings"),
        ([(0, 0, 0), (1, 0)], TET_F, "vertices: expected an array of numbers"),
    ],
)
def test_mesh_errors(vertices, faces, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(buoyancy.MeshError, match=match):
        buoyancy.Mesh(vertices, faces)


def test_mesh_error_carries_the_defects() -> None:
    # A tetrahedron with a face missing, a repeated index and a NaN vertex: every kind counted.
    vertices = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (NAN, 0, 0)]
    with pytest.raises(buoyancy.MeshError) as error:
        buoyancy.Mesh(vertices, [(0, 2, 1), (0, 1, 3), (0, 3, 3)])
    defects = {d.kind: d for d in error.value.defects}
    assert list(defects) == ["non_finite_vertex", "repeated_index", "open_edge"]
    assert (defects["non_finite_vertex"].count, defects["non_finite_vertex"].examples) == (1, ({"vertex": 4},))
    assert defects["repeated_index"].examples == ({"triangle": 2, "indices": (0, 3, 3)},)
    assert defects["open_edge"].count == 4
    assert defects["open_edge"].examples[0] == {"edge": (0, 2), "triangles": (0,)}
    assert all(isinstance(d, buoyancy.MeshDefect) for d in error.value.defects)
    assert repr(defects["repeated_index"]) == (
        "MeshDefect(kind='repeated_index', count=1, examples=({'triangle': 2, 'indices': (0, 3, 3)},))"
    )
    assert not error.value.triangle_soup and not error.value.one_based_indices


def test_mesh_error_of_a_triangle_soup_and_of_one_based_indices() -> None:
    cube = shapes.cube()
    soup_vertices = cube.vertices[cube.faces].reshape(-1, 3)  # every triangle its own 3 vertices
    soup_faces = np.arange(3 * cube.n_triangles).reshape(-1, 3)
    with pytest.raises(buoyancy.MeshError, match="weld") as error:
        buoyancy.Mesh(soup_vertices, soup_faces)
    assert error.value.triangle_soup and error.value.coincident_vertices > 0
    assert [(d.kind, d.count) for d in error.value.defects] == [("open_edge", 36)]
    assert len(error.value.defects[0].examples) == 5
    with pytest.raises(buoyancy.MeshError) as error:
        buoyancy.Mesh(TET_V, np.array(TET_F) + 1)
    assert error.value.one_based_indices
    out_of_range = error.value.defects[0]
    assert (out_of_range.kind, out_of_range.count) == ("index_out_of_range", 3)
    assert out_of_range.examples == tuple({"triangle": t, "index": 4} for t in (1, 2, 3))


def test_mesh_error_without_defects_of_the_triangles() -> None:
    for vertices, faces in ((TET_V, []), (np.zeros((4, 2)), TET_F), (TET_V, [(0, 1, 2), (0, 2, 1)])):
        with pytest.raises(buoyancy.MeshError) as error:
            buoyancy.Mesh(vertices, faces)
        assert error.value.defects == ()
        assert (error.value.triangle_soup, error.value.coincident_vertices, error.value.one_based_indices) == (
            False,
            0,
            False,
        )


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(density=0.0), r"^density: must be finite and positive \(kg/m³\)$"),
        (dict(density=-1.0), "^density: must be finite and positive"),
        (dict(density=NAN), "^density: must be finite and positive"),
        (dict(gravity=-9.81), r"^gravity: must be finite and non-negative \(m/s², a magnitude\)$"),
        (dict(gravity=INF), "^gravity: must be finite and non-negative"),
        (dict(level=NAN), "^level: must be finite"),
        (dict(normal=(0, 0, 0)), "^normal: is the zero vector"),
        (dict(normal=(0, NAN, 0)), "^normal: has a NaN or infinite component"),
        (dict(normal=(0, 1)), r"normal: expected 3 numbers \(shape \(3,\)\), got shape \(2,\)"),
    ],
)
def test_water_errors(kwargs, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        buoyancy.Water(**kwargs)


def test_a_string_for_a_vector_is_a_type_error() -> None:
    with pytest.raises(TypeError, match="^normal: expected an array of real numbers, got an array of strings$"):
        buoyancy.Water(normal="up")  # type: ignore[arg-type]


def test_gravity_as_a_vector_says_how_to_write_it() -> None:
    message = (
        r"^gravity: expected a number, the magnitude of gravity in m/s², got tuple; its direction is -normal: "
        r"for the vector \(0, 0, -9.81\) write Water\(gravity=9.81, normal=\(0, 0, 1\)\)$"
    )
    with pytest.raises(TypeError, match=message):
        buoyancy.Water(gravity=(0, 0, -9.81))  # type: ignore[arg-type]
    with pytest.raises(
        TypeError, match=r"^gravity: .* got numpy.ndarray; .* write Water\(gravity=9.81, normal=\(1, 0, 0\)\)$"
    ):
        buoyancy.Water(gravity=np.array([-9.81, 0, 0]))  # type: ignore[arg-type]
    with pytest.raises(
        TypeError,
        match="^gravity: expected a number, the magnitude of gravity in m/s², got str; its direction is -normal$",
    ):
        buoyancy.Water(gravity="down")  # type: ignore[arg-type]
    # What the message suggests is the same water as rapier's gravity vector (0, 0, -9.81) means.
    assert buoyancy.Water(gravity=9.81, normal=(0, 0, 1)).normal.tolist() == [0, 0, 1]


TET = buoyancy.Mesh(TET_V, TET_F)


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: buoyancy.Water(density="dense"), "density: expected a number, got str"),
        (lambda: buoyancy.Water(level=[0.0]), "level: expected a number, got list"),
        (lambda: TET.buoyancy(water="sea"), "water: expected a buoyancy.Water, got str"),
        (lambda: TET.buoyancy(method=3), "method: expected a method name such as 'exact', got int"),
        (lambda: TET.buoyancy(traversal=b"scan"), "traversal: expected a traversal name such as 'auto', got bytes"),
        (lambda: TET.buoyancy_batch([(0, 0, 0)], None, water=1000), "water: expected a buoyancy.Water, got int"),
        (lambda: TET.buoyancy_batch([(0, 0, 0)], None, threads="2"), "threads: expected an integer, got str"),
        (lambda: TET.buoyancy_batch([(0, 0, 0)], None, threads=2.0), "threads: expected an integer, got float"),
        (lambda: TET.damping(coefficients=0.5), "coefficients: expected a buoyancy.DampingCoefficients, got float"),
        (lambda: buoyancy.load(3), "path: expected a str or os.PathLike, got int"),
        (
            lambda: buoyancy.Mesh.from_trimesh(3),
            "obj: expected a trimesh.Trimesh or trimesh.Scene (an object with vertices and faces arrays), got int",
        ),
        (lambda: shapes.cube("a"), "n: expected an integer, got str"),
        (lambda: shapes.cube(2.5), "n: expected an integer, got float"),
        (lambda: shapes.uv_sphere(radius="1"), "radius: expected a number, got str"),
        (lambda: shapes.uv_sphere(slices=None, stacks=1.5), "stacks: expected an integer, got float"),
        (lambda: shapes.torus(major=(1, 2)), "major: expected a number, got tuple"),
        (lambda: shapes.torus(segments=[3]), "segments: expected an integer, got list"),
        (lambda: shapes.torus_knot(p="2"), "p: expected an integer, got str"),
        (lambda: shapes.torus_knot(tube_radius=None, sides=object()), "sides: expected an integer, got object"),
        (
            lambda: buoyancy.Buoyancy("1", (0, 0, 0), (0, 0, 0), (0, 0, 0), (0, 0, 0)),
            "volume: expected a number, got str",
        ),
        (
            lambda: buoyancy.Buoyancy(1, (0, 0, 0), (0, 0, 0), (0, 0, 0), (0, 0, 0), 1.5),
            "fully_submerged: expected an integer, got float",
        ),
        (lambda: TET.buoyancy_batch([(0, 0, 0)], None)["0"], "index: expected an integer, got str"),
    ],
)
def test_wrong_types_name_the_argument(call, message: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(TypeError) as error:
        call()
    assert str(error.value) == message


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: shapes.cube(-2), "^n: must be a non-negative integer, got -2$"),
        (lambda: shapes.torus_knot(q=2**40), f"^q: must be at most 4294967295, got {2**40}$"),
        (lambda: shapes.uv_sphere(slices=2**70), f"^slices: must be at most 9223372036854775807, got {2**70}$"),
        (
            lambda: TET.buoyancy_batch([(0, 0, 0)], None, threads=-1),
            "^threads: must be a non-negative integer, got -1$",
        ),
    ],
)
def test_out_of_range_integers_name_the_argument(call, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        call()


ROT_45 = np.array([[np.cos(0.7), -np.sin(0.7), 0], [np.sin(0.7), np.cos(0.7), 0], [0, 0, 1]])


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(position=(1, 2)), r"position: expected 3 numbers \(shape \(3,\)\), got shape \(2,\)"),
        (dict(position=np.zeros((1, 3))), r"position: expected 3 numbers .* got shape \(1, 3\)"),
        (dict(position=(NAN, 0, 0)), "position: has a NaN or infinite component"),
        (dict(position=np.array([0, INF, 0])), "position: has a NaN or infinite component"),
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
        (
            dict(method="slow"),
            'method: unknown method "slow"; valid methods are fast, improved, exact, fast_surface, exact_surface',
        ),
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


@pytest.mark.parametrize("scale", [1e300, 1e-300])
def test_a_huge_or_tiny_normal_is_normalised(scale: float) -> None:
    """A normal of 1e300 once normalised to zero (its squared norm overflowed), and the water
    gave no force; 1e-300 was called the zero vector."""
    water = buoyancy.Water(normal=(0, scale, scale))
    np.testing.assert_allclose(water.normal, [0, 0.5**0.5, 0.5**0.5], atol=1e-15)
    unit = buoyancy.Water(normal=(0, 1, 1))
    force = shapes.cube().buoyancy((0, 0, 0), water=water).force
    np.testing.assert_array_equal(force, shapes.cube().buoyancy((0, 0, 0), water=unit).force)
    assert np.linalg.norm(force) > 0


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
        (
            (GOOD, np.array([[0, 0, 0, 1], [0, 0, 0, 3], [0, 0, 0, 1]])),
            {},
            r"rotations\[1\]: the quaternion .* has norm 3",
        ),
        ((GOOD, np.array([[0, 0, 0, 1], [0, 0, 0, 1], [INF, 0, 0, 1]])), {}, r"rotations\[2\]: has a NaN"),
        ((GOOD, np.array([np.eye(3), np.eye(3), -np.eye(3)])), {}, r"rotations\[2\]: the 3×3 matrix is a reflection"),
        (
            (GOOD, np.array([np.eye(3), 3 * np.eye(3), np.eye(3)])),
            {},
            r"rotations\[1\]: the 3×3 matrix is not a rotation",
        ),
        ((GOOD, QUATS), dict(method="Exactly"), "method: unknown method"),
        (
            (GOOD, QUATS),
            dict(about=np.zeros((2, 3))),
            r"about: expected one point \(3,\) or one per pose \(3, 3\), got shape \(2, 3\)",
        ),
        ((GOOD, QUATS), dict(about=(0, NAN, 0)), "about: has a NaN"),
        ((GOOD, QUATS), dict(threads=0), "threads: must be at least 1"),
    ],
)
def test_batch_argument_errors(args, kwargs, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        shapes.cube().buoyancy_batch(*args, **kwargs)


def test_load_errors(tmp_path: pathlib.Path) -> None:
    with pytest.raises(FileNotFoundError, match="^cannot read .*missing.obj: "):
        buoyancy.load(tmp_path / "missing.obj")
    (tmp_path / "folder.obj").mkdir()
    with pytest.raises(IsADirectoryError, match="folder.obj"):
        buoyancy.load(tmp_path / "folder.obj")
    (tmp_path / "mesh.xyz").write_text("0 0 0\n")
    with pytest.raises(ValueError, match="^cannot read .*mesh.xyz: unknown format") as unknown:
        buoyancy.load(tmp_path / "mesh.xyz")
    assert not isinstance(unknown.value, (OSError, buoyancy.MeshError))
    (tmp_path / "bad.obj").write_text("v 0 0 0\nv 1 x 0\n")
    with pytest.raises(buoyancy.MeshError, match="line 2"):
        buoyancy.load(tmp_path / "bad.obj")
    (tmp_path / "open.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(buoyancy.MeshError, match="not closed"):
        buoyancy.load(tmp_path / "open.obj")
    (tmp_path / "short.stl").write_bytes(b"\0" * 80 + (5).to_bytes(4, "little"))
    with pytest.raises(buoyancy.MeshError):
        buoyancy.load(tmp_path / "short.stl")


@pytest.mark.skipif(
    not hasattr(os, "geteuid") or os.geteuid() == 0, reason="root reads any file: no permission error to provoke"
)
def test_load_unreadable_file_is_a_permission_error(tmp_path: pathlib.Path) -> None:
    path = tmp_path / "locked.obj"
    path.write_text("v 0 0 0\n")
    path.chmod(0)
    with pytest.raises(PermissionError, match="locked.obj"):
        buoyancy.load(path)


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: shapes.cube(0), "n: must be at least 1"),
        (lambda: shapes.uv_sphere(-1.0), "radius: must be finite and positive"),
        (lambda: shapes.uv_sphere(1.0, 2, 8), "slices: must be at least 3"),
        (lambda: shapes.torus(1.0, 2.0), "minor: must be smaller than major"),
        (lambda: shapes.torus_knot(sides=2), "sides: must be at least 3"),
        (lambda: shapes.torus_knot(p=0), "p: must be at least 1"),
        # Self-covering meshes (once accepted, their volume counted twice or more).
        (lambda: shapes.torus_knot(p=4, q=6), r"^q: must have no common factor with p: .* gcd\(p, q\) = d > 1"),
        (
            lambda: shapes.torus_knot(tube_radius=0.5),
            "^tube_radius: is too large for the knot: the tube would run into",
        ),
        (lambda: shapes.cube(100_000), "n: too large"),
    ],
)
def test_shape_errors(call, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        call()
