"""The primitives of physics engines hold their solids' volumes exactly."""

import math

import numpy as np
import pytest

from buoyancy import shapes


@pytest.mark.parametrize(
    ("mesh", "volume"),
    [
        (lambda: shapes.cuboid((1.0, 0.5, 0.25)), 1.0),
        (lambda: shapes.cuboid(np.array([0.1, 2.0, 3.0])), 4.8),
        (lambda: shapes.ellipsoid((1.0, 0.5, 2.0)), 4 / 3 * math.pi),
        (lambda: shapes.ellipsoid((0.3, 0.3, 0.3), 5, 3), 4 / 3 * math.pi * 0.027),
        (lambda: shapes.cylinder(0.5, 1.0), math.pi / 2),
        (lambda: shapes.cylinder(2.0, 0.1, segments=3), math.pi * 0.8),
        (lambda: shapes.capsule(0.5, 1.0), math.pi * 0.25 * (2 + 2 / 3)),
        (lambda: shapes.capsule(0.2, 3.0, 6, 2), math.pi * 0.04 * (6 + 0.8 / 3)),
    ],
)
def test_primitive_holds_its_volume_closed_and_centred(mesh, volume):
    m = mesh()
    assert m.volume == pytest.approx(volume, rel=1e-12)
    assert np.abs(m.centroid).max() < 1e-12
    assert not m.was_reoriented and m.openings == []


def test_primitive_axes_follow_the_arguments():
    def bounds(mesh):
        return mesh.vertices.min(axis=0), mesh.vertices.max(axis=0)

    lo, hi = bounds(shapes.ellipsoid((1.0, 0.5, 2.0)))
    assert hi == pytest.approx([1.0054, 0.5027, 2.0108], rel=1e-3)
    lo, hi = bounds(shapes.cylinder(0.5, 1.0))
    assert hi[1] == 1.0 and lo[1] == -1.0
    lo, hi = bounds(shapes.capsule(0.5, 1.0))
    assert 1.5 < hi[1] < 1.51 and lo[1] == -hi[1]


@pytest.mark.parametrize(
    ("call", "argument"),
    [
        (lambda: shapes.cuboid((1.0, 0.0, 1.0)), "half_extents"),
        (lambda: shapes.cuboid((1.0, 1.0)), "half_extents"),
        (lambda: shapes.ellipsoid((1.0, math.nan, 1.0)), "radii"),
        (lambda: shapes.ellipsoid((1.0, 1.0, 1.0), slices=2), "slices"),
        (lambda: shapes.cylinder(-1.0, 1.0), "radius"),
        (lambda: shapes.cylinder(1.0, math.inf), "half_height"),
        (lambda: shapes.capsule(1.0, 1.0, stacks=3), "stacks"),
        (lambda: shapes.capsule(1.0, 1.0, segments=-1), "segments"),
    ],
)
def test_bad_arguments_name_themselves(call, argument):
    with pytest.raises((ValueError, TypeError), match=argument):
        call()
