"""Construction from any array-like, properties, files, trimesh, pickling, reprs, docstrings."""

from __future__ import annotations

import importlib
import importlib.util
import pathlib
import pickle
import re
import struct

import numpy as np
import pytest

import buoyancy
from buoyancy import shapes
from buoyancy._sample_meshes import sample_meshes_dir

from conftest import (
    REPO,
    quaternion_matrix,
    random_quaternions,
    require_sample_mesh,
    run_examples,
    skip_unless_ci,
    under_ci,
)

TET_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TET_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


@pytest.mark.parametrize("vdtype", [np.float64, np.float32, np.int32, np.int64, object])
@pytest.mark.parametrize("fdtype", [np.int64, np.int32, np.uint16, np.uint32, np.float64])
def test_any_dtype(vdtype, fdtype) -> None:  # type: ignore[no-untyped-def]
    mesh = buoyancy.Mesh(np.array(TET_V, dtype=vdtype), np.array(TET_F, dtype=fdtype))
    assert mesh.volume == pytest.approx(1 / 6, rel=1e-15)
    np.testing.assert_allclose(mesh.centroid, [0.25, 0.25, 0.25], rtol=1e-15)
    assert (mesh.n_vertices, mesh.n_triangles) == (4, 4)


def test_lists_tuples_and_views() -> None:
    big = np.zeros((4, 6))
    big[:, ::2] = TET_V  # a strided, non-contiguous view
    for vertices in (TET_V, [list(v) for v in TET_V], tuple(TET_V), big[:, ::2]):
        assert buoyancy.Mesh(vertices, TET_F).volume == pytest.approx(1 / 6)


def test_fortran_ordered_arrays_are_read_in_index_order() -> None:
    cube = shapes.cube()
    fortran = buoyancy.Mesh(np.asfortranarray(cube.vertices), np.asfortranarray(cube.faces))
    assert fortran == cube
    positions = np.asfortranarray([[0.0, 0.3, 0.0], [0.0, -0.2, 0.0]])
    assert not positions.flags.c_contiguous
    assert cube.buoyancy_batch(positions, None).volume.round(12).tolist() == [0.2, 0.7]


def test_properties() -> None:
    mesh = buoyancy.Mesh(TET_V, TET_F)
    assert mesh.vertices.dtype == np.float64 and mesh.vertices.shape == (4, 3)
    np.testing.assert_array_equal(mesh.vertices, TET_V)
    np.testing.assert_array_equal(mesh.faces, TET_F)
    assert mesh.faces.dtype == np.int64
    assert not mesh.was_reoriented
    assert mesh.bounding_radius == pytest.approx(np.linalg.norm(np.array([1, 0, 0]) - 0.25))


def test_array_attributes_are_read_only() -> None:
    mesh = buoyancy.Mesh(TET_V, TET_F)
    b = mesh.buoyancy((0, 0.3, 0))
    arrays = {
        "Mesh.vertices": mesh.vertices,
        "Mesh.faces": mesh.faces,
        "Mesh.centroid": mesh.centroid,
        "Water.normal": buoyancy.Water().normal,
        "Buoyancy.center": b.center,
        "Buoyancy.force": b.force,
        "Buoyancy.torque": b.torque,
        "Buoyancy.about": b.about,
    }
    for name, array in arrays.items():
        assert not array.flags.writeable, name
        with pytest.raises(ValueError, match="read-only"):
            array[0] = 7
    # A copy is the array to change.
    vertices = np.array(mesh.vertices)
    vertices[0] = 7
    np.testing.assert_array_equal(mesh.vertices, TET_V)


def test_inward_winding_is_flipped() -> None:
    inward = [(a, c, b) for a, b, c in TET_F]
    mesh = buoyancy.Mesh(TET_V, inward)
    assert mesh.was_reoriented
    assert mesh.volume == pytest.approx(1 / 6)
    np.testing.assert_array_equal(mesh.faces, TET_F)


def test_reprs() -> None:
    mesh = buoyancy.Mesh(TET_V, TET_F)
    assert repr(mesh) == "Mesh(n_vertices=4, n_triangles=4, volume=0.166667, centroid=[0.25, 0.25, 0.25])"
    assert repr(buoyancy.Water()) == "Water(density=1000, gravity=9.81, level=0, normal=(0, 1, 0))"
    b = shapes.cube().buoyancy((0, -0.25, 0))
    assert (
        repr(b)
        == "Buoyancy(volume=0.75, center=[0, -0.375, 0], force=[0, 7357.5, 0], torque=[0, 0, 0], method='exact')"
    )


def test_water() -> None:
    w = buoyancy.Water(density=1025.0, gravity=9.8, level=2.0, normal=[0, 0, 5])
    assert (w.density, w.gravity, w.level, w.specific_weight) == (1025.0, 9.8, 2.0, 1025.0 * 9.8)
    np.testing.assert_array_equal(w.normal, [0, 0, 1])
    assert w == buoyancy.Water(1025.0, 9.8, 2.0, (0, 0, 1))
    assert w != buoyancy.Water()
    assert buoyancy.Water() == buoyancy.Water(1000.0, 9.81, 0.0, (0.0, 1.0, 0.0))
    # The default water is the one used when none is given.
    cube = shapes.cube()
    np.testing.assert_array_equal(
        cube.buoyancy((0, -0.2, 0)).force, cube.buoyancy((0, -0.2, 0), water=buoyancy.Water()).force
    )


def test_argument_forms_agree(rng: np.random.Generator) -> None:
    knot = shapes.torus_knot()
    for q in random_quaternions(rng, 5):
        p = rng.uniform(-0.5, 0.5, size=3)
        ref = knot.buoyancy(tuple(p), tuple(q))
        for position, rotation in [(list(p), list(q)), (p, q), (p.astype(np.float32).astype(float), q)]:
            b = knot.buoyancy(position, rotation)
            if position is not None and np.array_equal(np.asarray(position, float), p):
                np.testing.assert_array_equal(b.force, ref.force)
        # A rotation matrix gives the same result as its quaternion, up to round-off.
        m = knot.buoyancy(p, quaternion_matrix(q))
        np.testing.assert_allclose(m.force, ref.force, rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(m.torque, ref.torque, rtol=1e-9, atol=1e-8)
        np.testing.assert_allclose(m.center, ref.center, atol=1e-12)
        # Keywords, and a nearly unit quaternion, normalised.
        n = knot.buoyancy(position=p, rotation=q * (1 + 5e-6), method="EXACT")
        np.testing.assert_allclose(n.force, ref.force, rtol=1e-12)
        assert n.method == "exact"


def test_methods_constant() -> None:
    assert buoyancy.METHODS == ("fast", "improved", "exact", "fast_surface", "exact_surface")
    for m in buoyancy.METHODS:
        assert shapes.cube().buoyancy(method=m).method == m


@pytest.mark.parametrize(
    "spellings, name",
    [
        (("exact_surface", "ExactSurface", "exact-surface", "EXACT_SURFACE", "exactSurface"), "exact_surface"),
        (("fast_surface", "FastSurface", "fast-surface"), "fast_surface"),
        (("improved", "Improved", "IMPROVED"), "improved"),
    ],
)
def test_method_names_in_any_spelling(spellings: tuple[str, ...], name: str) -> None:
    knot = shapes.torus_knot()
    expected = knot.buoyancy((0, 0.1, 0), method=name)
    for spelling in spellings:
        b = knot.buoyancy((0, 0.1, 0), method=spelling)
        assert b == expected and b.method == name, spelling
        batch = knot.buoyancy_batch([(0, 0.1, 0)], None, method=spelling)
        assert batch.method == name and batch[0] == expected, spelling
    with pytest.raises(ValueError, match="^method: unknown method"):
        knot.buoyancy(method="exact surface")


def test_traversal_names_in_any_spelling() -> None:
    knot = shapes.torus_knot()
    for traversal, spellings in (
        ("scan", ("Scan", "SCAN")),
        ("hierarchy", ("Hierarchy", "HIERARCHY")),
        ("auto", ("Auto",)),
    ):
        expected = knot.buoyancy((0, 0.1, 0), traversal=traversal)
        for spelling in spellings:
            assert knot.buoyancy((0, 0.1, 0), traversal=spelling) == expected, spelling
            np.testing.assert_array_equal(
                knot.buoyancy_batch([(0, 0.1, 0)], None, traversal=spelling).force[0], expected.force
            )


def obj_text(mesh: buoyancy.Mesh) -> str:
    lines = [f"v {float(x)!r} {float(y)!r} {float(z)!r}" for x, y, z in mesh.vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in mesh.faces]
    return "\n".join(lines) + "\n"


def stl_ascii(mesh: buoyancy.Mesh) -> str:
    out = ["solid test"]
    for t in mesh.faces:
        out.append("facet normal 0 0 0\nouter loop")
        out += [f"vertex {float(x)!r} {float(y)!r} {float(z)!r}" for x, y, z in mesh.vertices[t]]
        out.append("endloop\nendfacet")
    return "\n".join([*out, "endsolid test"]) + "\n"


def stl_binary(mesh: buoyancy.Mesh) -> bytes:
    data = bytearray(b"binary".ljust(80, b" ") + struct.pack("<I", mesh.n_triangles))
    for t in mesh.faces:
        data += struct.pack("<3f", 0, 0, 0)
        for v in mesh.vertices[t]:
            data += struct.pack("<3f", *v)
        data += b"\0\0"
    return bytes(data)


def test_load_obj_and_stl(tmp_path: pathlib.Path) -> None:
    knot = shapes.torus_knot()
    (tmp_path / "knot.obj").write_text(obj_text(knot))
    (tmp_path / "knot.STL").write_text(stl_ascii(knot))
    (tmp_path / "knot_bin.stl").write_bytes(stl_binary(knot))
    obj = buoyancy.load(tmp_path / "knot.obj")
    ascii_ = buoyancy.load(str(tmp_path / "knot.STL"))
    binary = buoyancy.load(tmp_path / "knot_bin.stl")
    for mesh in (obj, ascii_):
        assert mesh.n_triangles == knot.n_triangles and mesh.n_vertices == knot.n_vertices
        assert mesh.volume == pytest.approx(knot.volume, rel=1e-12)
    # float32 in the binary file: the same shape to single precision.
    assert binary.n_vertices == knot.n_vertices
    assert binary.volume == pytest.approx(knot.volume, rel=1e-5)


def test_load_ply(tmp_path: pathlib.Path) -> None:
    knot = shapes.torus_knot()
    header = [
        "ply",
        "format ascii 1.0",
        f"element vertex {knot.n_vertices}",
        "property double x",
        "property double y",
        "property double z",
        f"element face {knot.n_triangles}",
        "property list uchar int vertex_indices",
        "end_header",
    ]
    body = [f"{float(x)!r} {float(y)!r} {float(z)!r}" for x, y, z in knot.vertices]
    body += [f"3 {a} {b} {c}" for a, b, c in knot.faces]
    (tmp_path / "knot.PLY").write_text("\n".join(header + body) + "\n")
    mesh = buoyancy.load(tmp_path / "knot.PLY")
    np.testing.assert_array_equal(mesh.vertices, knot.vertices)
    np.testing.assert_array_equal(mesh.faces, knot.faces)
    assert mesh == knot


def test_sample_meshes() -> None:
    armadillo = buoyancy.load(require_sample_mesh("armadillo.obj"))
    assert armadillo.was_reoriented and armadillo.volume == pytest.approx(1.902, rel=1e-3)
    bunny = buoyancy.load(require_sample_mesh("bunny.obj"))
    assert (bunny.n_vertices, bunny.n_triangles) == (2503, 5002)
    assert bunny.volume == pytest.approx(749.38, rel=1e-4)


def test_missing_sample_meshes_fail_under_ci_and_skip_otherwise(
    tmp_path: pathlib.Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("BUOYANCY_MESHES", str(tmp_path / "nowhere"))
    monkeypatch.setenv("CI", "true")
    with pytest.raises(pytest.fail.Exception, match=r"bunny.obj not found in .*nowhere .*BUOYANCY_MESHES.*CI=true"):
        require_sample_mesh("bunny.obj")
    monkeypatch.delenv("CI")
    with pytest.raises(pytest.skip.Exception, match=r"bunny.obj not found in .*nowhere"):
        require_sample_mesh("bunny.obj")
    # The folder named by $BUOYANCY_MESHES is the one used.
    (tmp_path / "nowhere").mkdir()
    (tmp_path / "nowhere" / "bunny.obj").write_text(obj_text(buoyancy.Mesh(TET_V, TET_F)))
    assert require_sample_mesh("bunny.obj") == tmp_path / "nowhere" / "bunny.obj"
    # Without it, ../shared/meshes beside the repository.
    monkeypatch.delenv("BUOYANCY_MESHES")
    assert sample_meshes_dir(REPO) == REPO.parent / "shared" / "meshes"


class FakeTrimesh:
    """What Mesh.from_trimesh needs from a trimesh.Trimesh: numpy vertices and faces."""

    def __init__(self, offset: float = 0.0) -> None:
        self.vertices = np.array(TET_V, dtype=np.float64) + offset
        self.faces = np.array(TET_F, dtype=np.int64)


class FakeScene:
    """What Mesh.from_trimesh needs from a trimesh.Scene: ``to_geometry()``, its parts in place."""

    def __init__(self, *parts: FakeTrimesh) -> None:
        self.parts = parts

    def to_geometry(self) -> FakeTrimesh:
        whole = FakeTrimesh()
        whole.vertices = np.concatenate([p.vertices for p in self.parts])
        whole.faces = np.concatenate([p.faces + 4 * k for k, p in enumerate(self.parts)])
        return whole


def test_from_trimesh() -> None:
    mesh = buoyancy.Mesh.from_trimesh(FakeTrimesh())
    assert isinstance(mesh, buoyancy.Mesh)
    assert mesh.volume == pytest.approx(1 / 6)
    assert mesh == buoyancy.Mesh(TET_V, TET_F)


def test_from_trimesh_scene_concatenates_its_geometry() -> None:
    two = buoyancy.Mesh.from_trimesh(FakeScene(FakeTrimesh(), FakeTrimesh(offset=5.0)))
    assert (two.n_vertices, two.n_triangles) == (8, 8)
    assert two.volume == pytest.approx(2 / 6)
    np.testing.assert_allclose(two.centroid, 0.25 + 2.5)


class PointCloudScene:
    """A scene whose geometry has vertices but no faces (a trimesh.PointCloud)."""

    def to_geometry(self) -> object:
        class Points:
            vertices = np.zeros((3, 3))

        return Points()


def test_from_trimesh_scene_without_faces_is_a_type_error() -> None:
    with pytest.raises(TypeError, match=r"^obj: expected .*; the scene's geometry has no faces, got .*Points$"):
        buoyancy.Mesh.from_trimesh(PointCloudScene())  # type: ignore[arg-type]


def test_from_real_trimesh_and_scene() -> None:
    try:
        import trimesh
    except ImportError as error:  # not installed, or installed but not loadable here
        skip_unless_ci(f"trimesh cannot be imported ({error}); the stand-ins above test the same calls")
    box = buoyancy.Mesh.from_trimesh(trimesh.creation.box(extents=(1, 2, 3)))
    assert box.volume == pytest.approx(6.0)
    moved = trimesh.creation.icosphere(subdivisions=2, radius=0.5)
    moved.apply_translation((3.0, 0.0, 0.0))
    scene = trimesh.Scene([trimesh.creation.box(extents=(1, 2, 3)), moved])
    both = buoyancy.Mesh.from_trimesh(scene)
    assert both.volume == pytest.approx(6.0 + moved.volume, rel=1e-12)
    assert both.n_triangles == 12 + len(moved.faces)


def test_pickle_round_trip(rng: np.random.Generator) -> None:
    for mesh in (shapes.torus_knot(), buoyancy.Mesh(TET_V, [(a, c, b) for a, b, c in TET_F])):
        copy = pickle.loads(pickle.dumps(mesh))
        assert copy == mesh and hash(copy) == hash(mesh)
        assert copy.volume == mesh.volume and copy.was_reoriented == mesh.was_reoriented
        np.testing.assert_array_equal(copy.vertices, mesh.vertices)
        np.testing.assert_array_equal(copy.faces, mesh.faces)
        np.testing.assert_array_equal(copy.centroid, mesh.centroid)
        water = buoyancy.Water(1025.0, 9.80665, 0.1, (0.1, 0.9, 0.05))
        water_copy = pickle.loads(pickle.dumps(water, protocol=pickle.HIGHEST_PROTOCOL))
        assert water_copy == water
        np.testing.assert_array_equal(water_copy.normal, water.normal)
        positions = rng.uniform(-0.5, 0.5, size=(20, 3))
        rotations = random_quaternions(rng, 20)
        a = mesh.buoyancy_batch(positions, rotations, water=water)
        b = copy.buoyancy_batch(positions, rotations, water=water_copy)
        for field in ("volume", "center", "force", "torque"):
            np.testing.assert_array_equal(getattr(a, field), getattr(b, field))


def test_mesh_equality_is_by_value() -> None:
    mesh = buoyancy.Mesh(TET_V, TET_F)
    same = buoyancy.Mesh(np.array(TET_V, dtype=np.float32), np.array(TET_F, dtype=np.uint16))
    assert mesh == same and hash(mesh) == hash(same) and mesh is not same
    assert len({mesh, same}) == 1
    assert mesh != buoyancy.Mesh([(0, 0, 0), (2, 0, 0), (0, 1, 0), (0, 0, 1)], TET_F)  # another vertex
    assert mesh != buoyancy.Mesh(TET_V, [(0, 1, 3), (0, 3, 2), (0, 2, 1), (1, 2, 3)])  # the faces in another order
    assert mesh != buoyancy.Mesh(TET_V, [(a, c, b) for a, b, c in TET_F])  # wound inward as given
    assert mesh != "a mesh"
    # -0.0 equals 0.0, and hashes alike.
    signed = buoyancy.Mesh([(-0.0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], TET_F)
    assert signed == mesh and hash(signed) == hash(mesh)


def test_buoyancy_pickles_and_compares_by_value() -> None:
    knot = shapes.torus_knot()
    b = knot.buoyancy((0.1, 0.05, 0), (0, 0, 0.6, 0.8), method="improved", about=(1, 2, 3))
    for protocol in (2, pickle.HIGHEST_PROTOCOL):
        copy = pickle.loads(pickle.dumps(b, protocol=protocol))
        assert copy == b and copy is not b
        assert (copy.volume, copy.method, copy.fully_submerged, copy.partially_submerged) == (
            b.volume,
            "improved",
            b.fully_submerged,
            b.partially_submerged,
        )
        for field in ("center", "force", "torque", "about"):
            np.testing.assert_array_equal(getattr(copy, field), getattr(b, field))
    assert b != knot.buoyancy((0.1, 0.05, 0), (0, 0, 0.6, 0.8), method="improved")  # about differs
    assert b != knot.buoyancy((0.1, 0.05, 0), (0, 0, 0.6, 0.8), method="exact", about=(1, 2, 3))
    built = buoyancy.Buoyancy(
        b.volume,
        b.center,
        b.force,
        b.torque,
        b.about,
        b.fully_submerged,
        b.partially_submerged,
        "Improved",
        wetted_area=b.wetted_area,
    )
    assert built == b
    assert copy.wetted_area == b.wetted_area > 0
    assert buoyancy.Buoyancy(0.5, (0, 0, 0), (0, 1, 0), (0, 0, 0), (0, 0, 0)).method == "exact"
    with pytest.raises(ValueError, match="^force: has a NaN"):
        buoyancy.Buoyancy(0.5, (0, 0, 0), (0, np.nan, 0), (0, 0, 0), (0, 0, 0))


def assert_same_mesh(a: buoyancy.Mesh, b: buoyancy.Mesh, atol: float = 0.0) -> None:
    np.testing.assert_allclose(a.vertices, b.vertices, rtol=0, atol=atol)
    np.testing.assert_array_equal(a.faces, b.faces)
    assert a.volume == pytest.approx(b.volume, rel=1e-12)
    np.testing.assert_allclose(a.centroid, b.centroid, rtol=0, atol=max(atol, 1e-12))


def test_transformed_copies() -> None:
    knot = shapes.torus_knot()
    v, f = knot.vertices, knot.faces
    # translated: every vertex moved, the volume kept, the centroid moved.
    offset = np.array([0.5, -2.0, 3.0])
    moved = knot.translated(offset)
    assert_same_mesh(moved, buoyancy.Mesh(v + offset, f), atol=1e-12)
    np.testing.assert_allclose(moved.centroid, knot.centroid + offset, atol=1e-12)
    # scaled: one factor, or one per axis; the volume scales by their product.
    assert knot.scaled(2).volume == pytest.approx(8 * knot.volume, rel=1e-12)
    stretched = knot.scaled((1.0, 2.0, 0.5))
    assert_same_mesh(stretched, buoyancy.Mesh(v * (1.0, 2.0, 0.5), f), atol=1e-12)
    assert stretched.volume == pytest.approx(knot.volume, rel=1e-12)
    # A mirror keeps the faces wound outward: the volume stays positive.
    mirrored = knot.scaled((-1, 1, 1))
    assert mirrored.volume == pytest.approx(knot.volume, rel=1e-12)
    np.testing.assert_allclose(mirrored.centroid, knot.centroid * (-1, 1, 1), atol=1e-12)
    # transformed: x' = A x + b.
    a = np.array([[0.0, -1.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 1.5]])
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = a, (1.0, 2.0, 3.0)
    mapped = knot.transformed(m)
    assert_same_mesh(mapped, buoyancy.Mesh(v @ a.T + (1.0, 2.0, 3.0), f), atol=1e-12)
    assert mapped.volume == pytest.approx(3 * knot.volume, rel=1e-12)
    # The original is unchanged.
    np.testing.assert_array_equal(knot.vertices, v)


def test_transformed_copies_pickle_bit_for_bit() -> None:
    knot = shapes.torus_knot()
    m = np.eye(4)
    m[:3, :3] = [[0.0, -1.1, 0.0], [0.9, 0.0, 0.0], [0.0, 0.0, 1.3]]
    m[:3, 3] = (0.1, 0.2, 0.3)
    for copy in (knot.transformed(m), knot.scaled((0.3, -0.7, 1.9)), knot.translated((1e-3, 7.0, -0.1))):
        restored = pickle.loads(pickle.dumps(copy))
        assert restored == copy
        np.testing.assert_array_equal(restored.centroid, copy.centroid)
        position = copy.centroid + np.array([0.0, 0.05, 0.0])
        assert restored.buoyancy(position, (0, 0, 0.6, 0.8)) == copy.buoyancy(position, (0, 0, 0.6, 0.8))


@pytest.mark.parametrize(
    "call, error, match",
    [
        (lambda m: m.translated((0, np.nan, 0)), ValueError, "^offset: has a NaN or infinite component$"),
        (lambda m: m.translated((0, 1)), ValueError, r"^offset: expected 3 numbers"),
        (
            lambda m: m.scaled(0),
            ValueError,
            "^factor: invalid transform: every scale factor must be finite and non-zero$",
        ),
        (lambda m: m.scaled((1, np.inf, 1)), ValueError, "^factor: has a NaN or infinite component$"),
        (lambda m: m.scaled((1, 2)), ValueError, r"^factor: expected 3 numbers"),
        (
            lambda m: m.transformed(np.eye(3)),
            ValueError,
            r"^matrix: expected a 4×4 homogeneous matrix .* got shape \(3, 3\)$",
        ),
        (lambda m: m.transformed(np.full((4, 4), np.nan)), ValueError, "^matrix: has a NaN or infinite component$"),
        (lambda m: m.transformed(np.ones((4, 4))), ValueError, "^matrix: invalid transform: the last row"),
        (
            lambda m: m.transformed(np.diag([1.0, 0.0, 1.0, 1.0])),
            buoyancy.MeshError,
            "^matrix: the mesh encloses no volume",
        ),
    ],
)
def test_transform_errors_name_the_argument(call, error: type[Exception], match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(error, match=match):
        call(shapes.cube())


def test_docstring_examples() -> None:
    objects = {
        "buoyancy": buoyancy,
        "buoyancy.shapes": buoyancy.shapes,
        "buoyancy._sample_meshes": buoyancy._sample_meshes,
        "Mesh": buoyancy.Mesh,
        "Mesh.buoyancy": buoyancy.Mesh.buoyancy,
        "Mesh.buoyancy_batch": buoyancy.Mesh.buoyancy_batch,
        "Mesh.from_trimesh": buoyancy.Mesh.from_trimesh,
        "Mesh.welded": buoyancy.Mesh.welded,
        "Mesh.transformed": buoyancy.Mesh.transformed,
        "Mesh.scaled": buoyancy.Mesh.scaled,
        "Mesh.translated": buoyancy.Mesh.translated,
        "Buoyancy": buoyancy.Buoyancy,
        "MeshDefect": buoyancy.MeshDefect,
        "load": buoyancy.load,
        "cube": buoyancy.shapes.cube,
        "uv_sphere": buoyancy.shapes.uv_sphere,
        "torus": buoyancy.shapes.torus,
        "torus_knot": buoyancy.shapes.torus_knot,
        "cuboid": buoyancy.shapes.cuboid,
        "ellipsoid": buoyancy.shapes.ellipsoid,
        "cylinder": buoyancy.shapes.cylinder,
        "capsule": buoyancy.shapes.capsule,
        "Water": buoyancy.Water,
        "Mesh.damping": buoyancy.Mesh.damping,
        "Mesh.damping_stiffness": buoyancy.Mesh.damping_stiffness,
        "DampingCoefficients": buoyancy.DampingCoefficients,
        "DampingCoefficients.off": buoyancy.DampingCoefficients.off,
        "AiryWave": buoyancy.AiryWave,
        "Waves": buoyancy.Waves,
        "Waves.jonswap": buoyancy.Waves.jonswap,
        "Waves.pierson_moskowitz": buoyancy.Waves.pierson_moskowitz,
        "Waves.angular_frequencies": buoyancy.Waves.angular_frequencies,
        "GerstnerWaves": buoyancy.GerstnerWaves,
        "HeightGrid": buoyancy.HeightGrid,
        "HeightGrid.set_heights": buoyancy.HeightGrid.set_heights,
        "Water.elevation": buoyancy.Water.elevation,
    }
    attempted = {name: run_examples(obj.__doc__ or "", name) for name, obj in objects.items()}
    assert all(attempted.values()), f"docstrings without examples: {[n for n, k in attempted.items() if not k]}"


def importable(module: str) -> bool:
    try:
        importlib.import_module(module)
    except ImportError:
        return False
    return True


def test_readme_python_example() -> None:
    readme = (REPO / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    assert blocks, "the README has a ```python example"
    for block in blocks:
        # The buoyancy.rapier and buoyancy.mujoco examples skip without their package, as
        # tests/python/test_rapier.py and test_mujoco.py do; under CI=true they run, and fail.
        if "import rapier3d" in block and not importable("rapier3d") and not under_ci():
            continue
        if "import mujoco" in block and not importable("mujoco") and not under_ci():
            continue
        if ">>>" in block:
            run_examples(block, "README")
        else:
            exec(compile(block, "README.md", "exec"), {})


def test_the_stub_docstrings_are_the_modules() -> None:
    """Every docstring of ``_core.pyi`` is the compiled module's own (the Rust doc comment), as
    ``scripts/stub_docstrings.py`` writes it: a doc comment changed without the stub fails here.
    The stub checked is the repository's; the module, the installed wheel's."""
    spec = importlib.util.spec_from_file_location("stub_docstrings", REPO / "scripts" / "stub_docstrings.py")
    assert spec is not None and spec.loader is not None
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    stub = script.STUB.read_text(encoding="utf-8")
    rendered = script.render(stub, buoyancy._core)
    assert rendered == stub, "the stub's docstrings have drifted: run python scripts/stub_docstrings.py"
    # The check can fail: a stub docstring edited by hand is put back.
    edited = stub.replace('"""A closed triangle mesh, validated', '"""A mesh, validated', 1)
    assert edited != stub and script.render(edited, buoyancy._core) == stub


def test_stubs_match_the_module() -> None:
    stub = (pathlib.Path(buoyancy.__file__).parent / "_core.pyi").read_text()
    for name in (
        "Mesh",
        "Water",
        "Buoyancy",
        "BuoyancyBatch",
        "Damping",
        "DampingCoefficients",
        "MeshError",
        "MeshDefect",
        "AiryWave",
        "Waves",
        "GerstnerWaves",
        "HeightGrid",
        "load",
        "cube",
        "uv_sphere",
        "torus",
        "torus_knot",
    ):
        assert re.search(rf"^(class|def) {name}\b", stub, re.M), name
        assert hasattr(buoyancy._core, name)
    for cls in (
        buoyancy.Mesh,
        buoyancy.Water,
        buoyancy.Buoyancy,
        buoyancy.BuoyancyBatch,
        buoyancy.Damping,
        buoyancy.DampingCoefficients,
        buoyancy.MeshDefect,
        buoyancy.AiryWave,
        buoyancy.Waves,
        buoyancy.GerstnerWaves,
        buoyancy.HeightGrid,
    ):
        public = {n for n in dir(cls) if not n.startswith("_")}
        for n in public:
            assert re.search(rf"def {n}\b", stub), f"{cls.__name__}.{n} missing from the stub"
    assert (pathlib.Path(buoyancy.__file__).parent / "py.typed").exists()
