"""The numpy clip of `benches/peers.py` (a peer in the benchmark) on the unit cube, against the
analytic submerged volume and centroid."""

from __future__ import annotations

import importlib.util
import math
import pathlib

import numpy as np
import pytest

import buoyancy

PEERS = pathlib.Path(__file__).resolve().parents[2] / "benches" / "peers.py"


@pytest.fixture(scope="module")
def numpy_clip():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("peers", PEERS)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.numpy_clip


@pytest.fixture(scope="module")
def cube() -> np.ndarray:
    mesh = buoyancy.shapes.cube(3)  # [-0.5, 0.5]³, 108 triangles
    assert np.allclose(mesh.vertices.min(axis=0), -0.5) and np.allclose(mesh.vertices.max(axis=0), 0.5)
    return mesh.vertices[mesh.faces]


@pytest.mark.parametrize("level", [-0.6, -0.5, -0.49, -0.2, 0.0, 1 / 3, 0.5, 0.7])
def test_axis_aligned_plane(numpy_clip, cube: np.ndarray, level: float) -> None:  # type: ignore[no-untyped-def]
    volume, center = numpy_clip(cube, np.array([0.0, 0.0, 1.0]), level)
    depth = min(max(level + 0.5, 0.0), 1.0)
    assert volume == pytest.approx(depth, abs=1e-14)
    if depth > 0:
        np.testing.assert_allclose(center, [0.0, 0.0, depth / 2 - 0.5], atol=1e-14)


@pytest.mark.parametrize("leg", [0.1, 0.5, 1.0])
def test_corner_cut(numpy_clip, cube: np.ndarray, leg: float) -> None:  # type: ignore[no-untyped-def]
    # x + y + z <= -1.5 + leg cuts the corner (-½, -½, -½) off as a right tetrahedron of legs `leg`.
    normal = np.ones(3) / math.sqrt(3)
    volume, center = numpy_clip(cube, normal, (-1.5 + leg) / math.sqrt(3))
    assert volume == pytest.approx(leg**3 / 6, rel=1e-12)
    np.testing.assert_allclose(center, np.full(3, -0.5 + leg / 4), atol=1e-12)


def test_tilted_half(numpy_clip, cube: np.ndarray) -> None:  # type: ignore[no-untyped-def]
    # Any plane through the center halves the cube, the halves' centroids mirror each other.
    normal = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    below, c_below = numpy_clip(cube, normal, 0.0)
    above, c_above = numpy_clip(cube, -normal, 0.0)
    assert below == pytest.approx(0.5, abs=1e-14) and above == pytest.approx(0.5, abs=1e-14)
    np.testing.assert_allclose(c_below, -c_above, atol=1e-14)
    assert c_below @ normal < 0
