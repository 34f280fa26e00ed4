"""``Buoyancy.wetted_area`` and ``BuoyancyBatch.wetted_area``: the area of the surface under water,
``1 + 4 d`` for a unit cube upright at draft ``d``; pickled, compared and built like the other
attributes."""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest

import buoyancy
from buoyancy import shapes

EXACT = ("exact", "improved", "exact_surface")
DRAFTS = (0.05, 0.25, 0.4, 0.5, 0.8337, 0.99)


@pytest.mark.parametrize("method", EXACT)
@pytest.mark.parametrize("traversal", ["auto", "scan", "hierarchy"])
def test_cube_wetted_area_is_bottom_plus_sides(method: str, traversal: str) -> None:
    cube = shapes.cube(4)
    for d in DRAFTS:
        b = cube.buoyancy(position=(0.3, 0.5 - d, -0.2), method=method, traversal=traversal)
        assert isinstance(b.wetted_area, float)
        assert b.wetted_area == pytest.approx(1 + 4 * d, rel=0, abs=1e-12), d
    # Wholly under water: every face.
    deep = cube.buoyancy(position=(0, -3, 0), method=method, traversal=traversal)
    assert deep.wetted_area == pytest.approx(6.0, rel=0, abs=1e-12)
    # Dry.
    assert cube.buoyancy(position=(0, 3, 0), method=method, traversal=traversal).wetted_area == 0.0


@pytest.mark.parametrize("method", ["fast", "fast_surface"])
def test_fast_methods_count_the_triangles_entirely_under_water(method: str) -> None:
    # The sides of the 4 × 4 cube in rows of 1/4: at draft 0.6 two rows are under water.
    b = shapes.cube(4).buoyancy(position=(0, 0.5 - 0.6, 0), method=method)
    assert b.wetted_area == pytest.approx(1 + 4 * 0.5, rel=0, abs=1e-12)


def surface_area(mesh: buoyancy.Mesh) -> float:
    a, b, c = (mesh.vertices[mesh.faces[:, k]] for k in range(3))
    return float(np.linalg.norm(np.cross(b - a, c - a), axis=1).sum() / 2)


def test_wetted_area_pickles_compares_and_builds() -> None:
    knot = shapes.torus_knot()
    b = knot.buoyancy((0.1, 0.05, 0), (0, 0, 0.6, 0.8), method="improved")
    assert 0 < b.wetted_area < surface_area(knot)
    deep = knot.buoyancy((0, -10, 0))
    assert deep.wetted_area == pytest.approx(surface_area(knot), rel=1e-12)
    for protocol in (2, pickle.HIGHEST_PROTOCOL):
        copy = pickle.loads(pickle.dumps(b, protocol=protocol))
        assert copy == b and copy.wetted_area == b.wetted_area
    args = (b.volume, b.center, b.force, b.torque, b.about, b.fully_submerged, b.partially_submerged, b.method)
    assert buoyancy.Buoyancy(*args, b.wetted_area) == b
    assert buoyancy.Buoyancy(*args, wetted_area=b.wetted_area) == b
    # Compared like every other attribute.
    assert buoyancy.Buoyancy(*args, wetted_area=b.wetted_area + 1e-9) != b
    assert buoyancy.Buoyancy(*args).wetted_area == 0.0
    for bad in (-1.0, math.nan, math.inf):
        with pytest.raises(ValueError, match="^wetted_area: must be finite and at least 0"):
            buoyancy.Buoyancy(*args, wetted_area=bad)
    with pytest.raises(TypeError, match="^wetted_area: expected a number"):
        buoyancy.Buoyancy(*args, wetted_area="1")  # type: ignore[arg-type]


def test_batch_wetted_area_is_an_array_of_the_single_results() -> None:
    cube = shapes.cube(4)
    positions = [(0, 0.5 - d, 0) for d in DRAFTS] + [(0, 3, 0), (0, -3, 0)]
    batch = cube.buoyancy_batch(positions, None, method="exact_surface")
    assert batch.wetted_area.shape == (len(positions),) and batch.wetted_area.dtype == np.float64
    assert batch.wetted_area is batch.wetted_area
    assert not batch.wetted_area.flags.writeable
    np.testing.assert_allclose(batch.wetted_area, [1 + 4 * d for d in DRAFTS] + [0.0, 6.0], rtol=0, atol=1e-12)
    for k, position in enumerate(positions):
        assert batch[k].wetted_area == batch.wetted_area[k]
        assert cube.buoyancy(position, method="exact_surface").wetted_area == batch.wetted_area[k]


def test_waves_wetted_area() -> None:
    cube = shapes.cube(4)
    still = cube.buoyancy(position=(0, -0.2, 0), method="exact_surface")
    calm = buoyancy.Water(waves=buoyancy.Waves([buoyancy.AiryWave(0.0, 3.0)]))
    assert cube.buoyancy(position=(0, -0.2, 0), water=calm).wetted_area == pytest.approx(still.wetted_area, rel=1e-12)
    # A crest over the cube wets more of it, never more than all of it.
    swell = buoyancy.Water(waves=buoyancy.Waves([buoyancy.AiryWave(0.1, 50.0)]))
    crest = cube.buoyancy(position=(0, -0.2, 0), water=swell, time=0.0).wetted_area
    assert still.wetted_area < crest < 6.0
    batch = cube.buoyancy_batch([(0, -0.2, 0)] * 2, None, water=swell, times=[0.0, 0.0])
    np.testing.assert_array_equal(batch.wetted_area, [crest, crest])


def test_froude_krylov_wets_the_hydrostatic_surface() -> None:
    knot = shapes.torus_knot()
    components = [buoyancy.AiryWave(0.2, 4.0, phase=0.3), buoyancy.AiryWave(0.05, 1.5, (0.3, 0, 1), 1.1)]
    hydrostatic = buoyancy.Water(waves=buoyancy.Waves(components, depth=6.0))
    fk = buoyancy.Water(waves=buoyancy.Waves(components, depth=6.0, pressure="froude_krylov"))
    for y in (0.8, 0.2, 0.0, -0.3):
        a = knot.buoyancy(position=(0.1, y, 0), time=0.7, water=hydrostatic).wetted_area
        b = knot.buoyancy(position=(0.1, y, 0), time=0.7, water=fk).wetted_area
        assert b == pytest.approx(a, rel=1e-12, abs=1e-12), y
    assert 0 < knot.buoyancy(position=(0.1, 0.0, 0), time=0.7, water=fk).wetted_area
