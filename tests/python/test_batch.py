"""`buoyancy_batch`: equal to a loop of single calls, bit for bit, whatever the thread count."""

from __future__ import annotations

import threading

import numpy as np
import pytest

import buoyancy
from buoyancy import shapes

from conftest import quaternion_matrix, random_quaternions

FIELDS = ("volume", "center", "force", "torque", "about")


def assert_batch_is_loop(mesh, positions, rotations, **kwargs) -> buoyancy.BuoyancyBatch:  # type: ignore[no-untyped-def]
    batch = mesh.buoyancy_batch(positions, rotations, **kwargs)
    about = kwargs.pop("about", None)
    assert len(batch) == len(positions)
    for k in range(len(positions)):
        point = about if about is None or np.ndim(about) == 1 else about[k]
        single = mesh.buoyancy(positions[k], None if rotations is None else rotations[k], about=point, **kwargs)
        for field in FIELDS:
            np.testing.assert_array_equal(
                getattr(batch, field)[k], getattr(single, field), err_msg=f"pose {k}, {field}"
            )
        assert batch.fully_submerged[k] == single.fully_submerged
        assert batch.partially_submerged[k] == single.partially_submerged
    return batch


@pytest.mark.parametrize("method", buoyancy.METHODS)
def test_batch_equals_loop_quaternions(method: str, rng: np.random.Generator) -> None:
    knot = shapes.torus_knot()
    positions = rng.uniform(-1, 1, size=(40, 3))
    batch = assert_batch_is_loop(knot, positions, random_quaternions(rng, 40), method=method)
    assert batch.method == method
    assert batch.volume.shape == (40,) and batch.force.shape == (40, 3)


def test_batch_equals_loop_matrices_water_and_about(rng: np.random.Generator) -> None:
    torus = shapes.torus()
    positions = rng.uniform(-1, 1, size=(30, 3))
    matrices = np.array([quaternion_matrix(q) for q in random_quaternions(rng, 30)])
    water = buoyancy.Water(density=1025.0, level=0.2, normal=(0, 0, 1))
    assert_batch_is_loop(torus, positions, matrices, water=water)
    assert_batch_is_loop(torus, positions, matrices, water=water, about=np.array([1.0, 2.0, 3.0]))
    assert_batch_is_loop(torus, positions, matrices, water=water, about=rng.normal(size=(30, 3)))
    assert_batch_is_loop(torus, positions, None, water=water)


def test_batch_on_the_bunny(bunny: buoyancy.Mesh, rng: np.random.Generator) -> None:
    positions = bunny.centroid + rng.uniform(-8, 8, size=(25, 3))
    assert_batch_is_loop(bunny, positions, random_quaternions(rng, 25))


def test_thread_counts_give_identical_results(rng: np.random.Generator) -> None:
    knot = shapes.torus_knot()
    positions = rng.uniform(-1, 1, size=(300, 3))
    rotations = random_quaternions(rng, 300)
    one = knot.buoyancy_batch(positions, rotations, threads=1)
    for threads in (2, 3, None):
        other = knot.buoyancy_batch(positions, rotations, threads=threads)
        for field in FIELDS:
            np.testing.assert_array_equal(getattr(one, field), getattr(other, field))


def test_empty_batch() -> None:
    batch = shapes.cube().buoyancy_batch(np.zeros((0, 3)), np.zeros((0, 4)))
    assert len(batch) == 0
    assert batch.volume.shape == (0,)
    assert batch.center.shape == batch.force.shape == batch.torque.shape == (0, 3)
    assert "0 poses" in repr(batch)


def test_indexing_and_repr() -> None:
    cube = shapes.cube()
    batch = cube.buoyancy_batch([[0, 0, 0], [0, -2, 0]], [[0, 0, 0, 1], [0, 0, 0, 1]])
    assert batch[-1].volume == pytest.approx(1.0) and batch[0].volume == pytest.approx(0.5)
    assert isinstance(batch[1], buoyancy.Buoyancy)
    with pytest.raises(IndexError, match="^pose index 2 out of range for a batch of 2 poses$"):
        batch[2]
    with pytest.raises(IndexError, match="^pose index -3 out of range"):
        batch[-3]
    assert batch[np.int64(1)] == batch[-1]
    assert batch.volume is batch.volume  # built once, not per access
    assert repr(batch).startswith("BuoyancyBatch(2 poses")


def test_batch_arrays_are_read_only() -> None:
    batch = shapes.cube().buoyancy_batch([[0, 0, 0], [0, -2, 0]], None)
    for field in (*FIELDS, "fully_submerged", "partially_submerged"):
        array = getattr(batch, field)
        assert not array.flags.writeable, field
        with pytest.raises(ValueError, match="read-only"):
            array[0] = 0
    # What batch[k] reads is what the arrays hold.
    for k in range(len(batch)):
        for field in FIELDS:
            np.testing.assert_array_equal(getattr(batch[k], field), getattr(batch, field)[k])


def test_four_python_threads_at_once(rng: np.random.Generator) -> None:
    knot = shapes.torus_knot(segments=200, sides=20)
    water = buoyancy.Water(density=1025.0)
    jobs = [(rng.uniform(-1, 1, size=(400, 3)), random_quaternions(rng, 400)) for _ in range(4)]
    expected = [knot.buoyancy_batch(p, q, water=water, threads=1) for p, q in jobs]
    results: list[object] = [None] * 4
    barrier = threading.Barrier(4)

    def work(i: int) -> None:
        barrier.wait()
        for _ in range(3):
            results[i] = knot.buoyancy_batch(*jobs[i], water=water)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for got, want in zip(results, expected, strict=True):
        assert isinstance(got, buoyancy.BuoyancyBatch)
        for field in FIELDS:
            np.testing.assert_array_equal(getattr(got, field), getattr(want, field))


def test_single_calls_from_threads_on_a_shared_mesh(rng: np.random.Generator) -> None:
    sphere = shapes.uv_sphere(1.0, 64, 64)  # large enough that the call releases the GIL
    positions = rng.uniform(-1, 1, size=(4, 50, 3))
    expected = [[sphere.buoyancy(p).force for p in ps] for ps in positions]
    results: list[list[np.ndarray]] = [[] for _ in range(4)]

    def work(i: int) -> None:
        results[i] = [sphere.buoyancy(p).force for p in positions[i]]

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    np.testing.assert_array_equal(np.array(results), np.array(expected))


def test_traversals_agree_and_bad_names_are_named() -> None:
    """Scan and hierarchy give the same result to round-off, single and batch."""
    knot = buoyancy.shapes.torus_knot(segments=120, sides=12)
    rng = np.random.default_rng(7)
    positions = rng.uniform(-1.0, 1.0, size=(40, 3))
    rotations = rng.normal(size=(40, 4))
    rotations /= np.linalg.norm(rotations, axis=1, keepdims=True)
    scale_v = knot.volume
    for method in buoyancy.METHODS:
        batches = {
            t: knot.buoyancy_batch(positions, rotations, method=method, traversal=t)
            for t in ("auto", "scan", "hierarchy")
        }
        for t in ("auto", "hierarchy"):
            assert np.max(np.abs(batches[t].volume - batches["scan"].volume)) <= 1e-10 * scale_v
            assert np.max(np.abs(batches[t].force - batches["scan"].force)) <= 1e-10 * 9810 * scale_v
        single = knot.buoyancy(positions[3], rotations[3], method=method, traversal="scan")
        assert single.volume == batches["scan"].volume[3]
    with pytest.raises(ValueError, match="traversal.*auto, scan, hierarchy"):
        knot.buoyancy(traversal="bvh")
    with pytest.raises(ValueError, match="traversal"):
        knot.buoyancy_batch(positions, rotations, traversal="linear")
