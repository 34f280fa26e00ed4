"""Arguments of the wrong kind: booleans and complex numbers are not coordinates or indices,
integers out of range say so (and give the value), every part form the stubs advertise works, and
every public object pickles (or says why it cannot), so that results and errors cross process
boundaries."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import buoyancy
from buoyancy import shapes

BOX = shapes.cuboid((1.0, 0.5, 0.25))


@pytest.mark.parametrize(
    "vertices, faces, match",
    [
        (BOX.vertices > 0, BOX.faces, r"vertices: expected an array of real numbers, got an array of booleans"),
        (BOX.vertices.astype(complex), BOX.faces, r"vertices: .* got an array of complex numbers"),
        (BOX.vertices + 1j, BOX.faces, r"vertices: .* got an array of complex numbers"),
        (BOX.vertices, BOX.faces.astype(bool), r"faces: expected an array of real numbers, got an array of booleans"),
        (BOX.vertices, BOX.faces.astype(complex), r"faces: .* complex numbers"),
        (BOX.vertices.astype(str), BOX.faces, r"vertices: .* strings"),
    ],
)
def test_mesh_arrays_of_booleans_complex_numbers_or_strings_are_refused(vertices, faces, match) -> None:
    # NumPy would read True as 1 and drop an imaginary part (with a warning at most).
    with pytest.raises(buoyancy.MeshError, match=match):
        buoyancy.Mesh(vertices, faces)


@pytest.mark.parametrize(
    "position, match",
    [
        ((True, False, False), r"position: expected an array of real numbers, got a bool at \[0\]"),
        ([1, 0, True], r"position: expected an array of real numbers, got a bool at \[2\]"),
        (np.array([1j, 0, 0]), "position: .* complex numbers"),
        ((1j, 0, 0), "position: .* complex numbers"),
    ],
)
def test_vectors_of_booleans_or_complex_numbers_are_type_errors(position, match) -> None:
    with pytest.raises(TypeError, match=match):
        BOX.buoyancy(position=position)


def test_a_mixed_list_of_ints_and_floats_is_still_numbers() -> None:
    assert BOX.buoyancy(position=[0, -0.1, 0.0]).volume == pytest.approx(2.0 * 0.6 * 0.5)


@pytest.mark.parametrize("value", [True, np.bool_(True)])
def test_a_boolean_is_not_a_count_or_a_number(value) -> None:
    with pytest.raises(TypeError, match="n: expected an integer, got .*bool"):
        buoyancy.Waves.jonswap(hs=1.0, tp=8.0, n=value)
    with pytest.raises(TypeError, match="hs: expected a number, got .*bool"):
        buoyancy.Waves.jonswap(hs=value, tp=8.0)


@pytest.mark.parametrize("seed", [-1, 2**64, 2**100])
def test_a_seed_out_of_range_is_a_value_error_that_gives_it(seed) -> None:
    with pytest.raises(ValueError, match=rf"seed: must be an integer from 0 to 2\*\*64 - 1, got {seed}"):
        buoyancy.Waves.jonswap(hs=1.0, tp=8.0, seed=seed)
    # Both ends of the range are seeds.
    buoyancy.Waves.jonswap(hs=1.0, tp=8.0, seed=0, n=4)
    buoyancy.Waves.jonswap(hs=1.0, tp=8.0, seed=np.uint64(2**64 - 1), n=4)  # type: ignore[arg-type]


def test_a_count_beyond_64_bits_says_so() -> None:
    with pytest.raises(ValueError, match=rf"n: must be at most 9223372036854775807, got {2**70}"):
        buoyancy.Waves.jonswap(hs=1.0, tp=8.0, n=2**70)


def test_indices_beyond_64_bits_are_index_errors_that_give_them() -> None:
    controller = buoyancy.Controller()
    controller.add(BOX)
    with pytest.raises(IndexError, match=rf"index: no body {2**70}; the controller has 1"):
        controller.parts(2**70)
    with pytest.raises(TypeError, match="index: expected an integer, got bool"):
        controller.remove(True)
    batch = BOX.buoyancy_batch(positions=np.zeros((2, 3)), rotations=np.tile([0, 0, 0, 1.0], (2, 1)))
    with pytest.raises(IndexError, match=rf"pose index {2**70} out of range for a batch of 2"):
        batch[2**70]
    with pytest.raises(IndexError, match=rf"pose index {-(2**70)} out of range"):
        batch[-(2**70)]
    assert batch[-2].volume == batch[0].volume


def test_a_part_as_one_mesh_position_quaternion_tuple() -> None:
    # The form `_Part` advertises, alone or in a list.
    controller = buoyancy.Controller()
    alone = controller.add((BOX, (0.0, 1.0, 0.0), (0.0, 0.0, 0.0, 1.0)))
    listed = controller.add([(BOX, (0.0, 1.0, 0.0), (0.0, 0.0, 0.0, 1.0))])
    ((mesh, position, _),) = controller.parts(alone)
    assert mesh is BOX and position.tolist() == [0.0, 1.0, 0.0]
    assert [p[1].tolist() for p in controller.parts(listed)] == [[0.0, 1.0, 0.0]]
    # Three meshes in a tuple stay three parts.
    three = controller.add((BOX, BOX, BOX))
    assert len(controller.parts(three)) == 3


def test_gz_curve_errors_name_degrees_for_arguments_in_degrees() -> None:
    water = buoyancy.Water(normal=(0, 0, 1))
    with pytest.raises(ValueError, match=r"heel_deg: .*\(degrees\)") as error:
        BOX.gz_curve(200.0, (0, 0, 0), heel_deg=[0, float("nan")], water=water)
    assert "(rad)" not in str(error.value)


# -- pickling -------------------------------------------------------------------------------------


def _mesh_error() -> buoyancy.MeshError:
    try:
        buoyancy.Mesh(BOX.vertices, BOX.faces[:-1])
    except buoyancy.MeshError as error:
        return error
    raise AssertionError("an open box is refused")


def _objects() -> dict[str, object]:
    z_up = buoyancy.Water(normal=(0, 0, 1))
    return {
        "Mesh": BOX,
        "Water": z_up,
        "Buoyancy": BOX.buoyancy(position=(0.1, -0.1, 0.0)),
        "BuoyancyBatch": BOX.buoyancy_batch(
            positions=[(0, -0.1, 0), (0, 0.1, 0)], rotations=np.tile([0, 0, 0, 1.0], (2, 1))
        ),
        "Waterplane": BOX.waterplane(position=(0, -0.1, 0)),
        "Hydrostatics": BOX.hydrostatics(center_of_mass=(0, 0, -0.1), water=z_up),
        "Equilibrium": BOX.equilibrium(200.0, (0, 0, -0.1), water=z_up),
        "GzCurve": BOX.gz_curve(200.0, (0, 0, -0.1), heel_deg=[0, 10, 20], water=z_up),
        "HydrostaticTable": BOX.hydrostatic_table(drafts=[0.1, 0.2], water=z_up),
        "AiryWave": buoyancy.AiryWave(amplitude=0.5, wavelength=20.0),
        "Waves": buoyancy.Waves.jonswap(hs=1.0, tp=8.0, n=8),
        "GerstnerWaves": buoyancy.GerstnerWaves([buoyancy.AiryWave(amplitude=0.5, wavelength=20.0)]),
        "HeightGrid": buoyancy.HeightGrid(np.zeros((4, 4)), spacing=1.0),
        "DampingCoefficients": buoyancy.DampingCoefficients(),
        "MeshDefect": _mesh_error().defects[0],
    }


@pytest.mark.parametrize("name", sorted(_objects()))
def test_every_public_object_pickles_to_an_equal_one(name) -> None:
    obj = _objects()[name]
    copy = pickle.loads(pickle.dumps(obj))
    assert type(copy) is type(obj)
    assert repr(copy) == repr(obj)
    # What the object holds, not only what it prints: every public attribute that is data.
    for attribute in dir(obj):
        if attribute.startswith("_"):
            continue
        value = getattr(obj, attribute)
        if callable(value):
            continue
        expected = np.asarray(value) if isinstance(value, np.ndarray) else value
        got = getattr(copy, attribute)
        if isinstance(expected, np.ndarray):
            np.testing.assert_array_equal(got, expected, err_msg=attribute)
        elif isinstance(expected, (int, float, str, bool, tuple, type(None))):
            assert got == expected or repr(got) == repr(expected), attribute


def test_a_mesh_error_keeps_its_defects_through_pickle() -> None:
    error = _mesh_error()
    copy = pickle.loads(pickle.dumps(error))
    assert isinstance(copy, buoyancy.MeshError)
    assert str(copy) == str(error)
    assert [(d.kind, d.count, d.examples) for d in copy.defects] == [
        (d.kind, d.count, d.examples) for d in error.defects
    ]
    assert copy.triangle_soup == error.triangle_soup


def test_a_mesh_defect_of_an_unknown_kind_is_refused() -> None:
    with pytest.raises(ValueError, match="kind: must be one of non_finite_vertex, .*got 'hole'"):
        buoyancy.MeshDefect("hole", 1, ())  # type: ignore[arg-type]


def test_a_controller_refuses_to_pickle_and_says_what_to_do() -> None:
    controller = buoyancy.Controller()
    controller.add(BOX)
    with pytest.raises(TypeError, match="a Controller cannot be pickled: .*meshes"):
        pickle.dumps(controller)


def test_results_and_errors_cross_a_process_pool() -> None:
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(max_workers=1) as pool:
        curve = pool.submit(_gz_in_worker).result()
        assert curve.gz[0] == pytest.approx(0.0, abs=1e-9) and curve.gz[1] > 0
        error = pool.submit(_broken_mesh_in_worker).exception()
    assert isinstance(error, buoyancy.MeshError)
    assert error.defects and error.defects[0].kind == "open_edge"


def _gz_in_worker() -> buoyancy.GzCurve:
    water = buoyancy.Water(normal=(0, 0, 1))
    return shapes.cuboid((1.0, 0.5, 0.25)).gz_curve(200.0, (0, 0, -0.1), heel_deg=[0, 10], water=water)


def _broken_mesh_in_worker() -> None:
    box = shapes.cuboid((1.0, 0.5, 0.25))
    buoyancy.Mesh(box.vertices, box.faces[:-1])
