"""Mesh.waterplane, Mesh.hydrostatics and Mesh.stiffness against the box formulas, an annulus
and the buoyancy they are derivatives of."""

import math

import numpy as np
import pytest

import buoyancy
from buoyancy import shapes

from conftest import run_examples

RHO_G = 1000.0 * 9.81


def box(length: float = 4.0, depth: float = 1.0, beam: float = 2.0) -> buoyancy.Mesh:
    """A box about the origin: x long, y up (the default water's normal), z across."""
    return shapes.cube(2).scaled((length, depth, beam))


@pytest.mark.parametrize("draft", [0.2, 0.5, 0.85])
def test_box_matches_the_formulas(draft: float) -> None:
    length, depth, beam = 4.0, 1.0, 2.0
    kg = 0.3
    # The box's bottom is at y = -depth/2; lower it so that the water is `draft` above it.
    position = (0.0, depth / 2 - draft, 0.0)
    cog = (0.0, -depth / 2 + kg, 0.0)  # mesh frame
    h = box(length, depth, beam).hydrostatics(cog, position=position)
    assert h.displaced_volume == pytest.approx(length * beam * draft, rel=1e-12)
    assert h.kb == pytest.approx(draft / 2, rel=1e-12)
    assert h.kg == pytest.approx(kg, rel=1e-12)
    assert h.bm_transverse == pytest.approx(beam**2 / (12 * draft), rel=1e-12)
    assert h.bm_longitudinal == pytest.approx(length**2 / (12 * draft), rel=1e-12)
    assert h.gm_transverse == pytest.approx(draft / 2 + beam**2 / (12 * draft) - kg, rel=1e-12)
    assert h.gm_longitudinal == pytest.approx(draft / 2 + length**2 / (12 * draft) - kg, rel=1e-12)
    np.testing.assert_allclose(h.gm_principal, sorted([h.gm_transverse, h.gm_longitudinal]), rtol=1e-12)
    np.testing.assert_allclose(h.keel[1], -draft, atol=1e-12)
    w = h.waterplane
    assert w.area == pytest.approx(length * beam, rel=1e-12)
    np.testing.assert_allclose(w.center_of_flotation, (0, 0, 0), atol=1e-12)
    np.testing.assert_allclose(
        w.second_moments, [[length * beam**3 / 12, 0], [0, beam * length**3 / 12]], rtol=1e-12, atol=1e-9
    )
    # In equilibrium (the default mass is rho V) about G: C33 = rho g A, C44 = rho g V GM_T.
    c = h.stiffness
    assert c.shape == (3, 3)
    np.testing.assert_allclose(c, c.T, atol=1e-6)
    assert c[0, 0] == pytest.approx(RHO_G * length * beam, rel=1e-12)
    assert c[1, 1] == pytest.approx(RHO_G * h.displaced_volume * h.gm_transverse, rel=1e-9)
    assert c[2, 2] == pytest.approx(RHO_G * h.displaced_volume * h.gm_longitudinal, rel=1e-9)
    np.testing.assert_array_equal(box(length, depth, beam).stiffness(cog, position=position), c)


def test_stiffness_is_the_derivative_of_the_buoyancy() -> None:
    """A small heave changes the buoyant force by -C33 times it (the force at a pose of the mesh,
    computed by Mesh.buoyancy, not by the hydrostatics)."""
    hull = shapes.wigley_hull()
    h = hull.hydrostatics((0, 0, 0))
    step = 1e-5
    up = hull.buoyancy(position=(0, step, 0)).force[1]
    down = hull.buoyancy(position=(0, -step, 0)).force[1]
    assert (up - down) / (2 * step) == pytest.approx(-h.stiffness[0, 0], rel=1e-6)


def test_torus_at_its_equator_is_an_annulus() -> None:
    segments = 48
    ring = shapes.torus(1.0, 0.25, segments, 16)
    w = ring.waterplane()
    polygon = segments / 2 * math.sin(2 * math.pi / segments)  # area of the unit-circumradius polygon
    assert w.area == pytest.approx(polygon * (1.25**2 - 0.75**2), rel=1e-12)
    np.testing.assert_allclose(w.center_of_flotation, 0, atol=1e-12)
    moments = w.principal_moments
    assert moments[0] == pytest.approx(moments[1], rel=1e-9)  # a regular polygon: isotropic
    np.testing.assert_allclose(np.cross(w.axes[0], w.axes[1]), (0, 1, 0), atol=1e-12)


def test_a_dry_body_has_no_waterplane() -> None:
    w = shapes.cube().waterplane(position=(0, 2, 0))
    assert w.area == 0.0
    assert np.isfinite(w.center_of_flotation).all()


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"center_of_mass": (0, np.nan, 0)}, "^center_of_mass"),
        ({"center_of_mass": (0, 0, 0), "mass": -1.0}, "^mass"),
        ({"center_of_mass": (0, 0, 0), "mass": math.inf}, "^mass"),
        ({"center_of_mass": (0, 0, 0), "axis": (0, 1, 0)}, "^axis"),
        ({"center_of_mass": (0, 0, 0), "axis": (0, 0, 0)}, "^axis"),
        ({"center_of_mass": (0, 0)}, "^center_of_mass"),
        (
            {"center_of_mass": (0, 0, 0), "water": buoyancy.Water(waves=buoyancy.AiryWave(0.1, 10.0))},
            "^water",
        ),
    ],
)
def test_bad_arguments_name_the_argument(kwargs: dict, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        box().hydrostatics(**kwargs)


def test_waterplane_rejects_waves_and_bad_poses() -> None:
    with pytest.raises(ValueError, match="^water"):
        box().waterplane(water=buoyancy.Water(waves=buoyancy.AiryWave(0.1, 10.0)))
    with pytest.raises(ValueError, match="^position"):
        box().waterplane(position=(0, np.inf, 0))


@pytest.mark.parametrize(
    "obj",
    [
        buoyancy.Mesh.waterplane,
        buoyancy.Mesh.hydrostatics,
        buoyancy.Mesh.stiffness,
        buoyancy.Waterplane,
        buoyancy.Hydrostatics,
    ],
    ids=lambda o: o.__qualname__,
)
def test_docstring_examples(obj: object) -> None:
    assert run_examples(obj.__doc__ or "", getattr(obj, "__qualname__", "?")) > 0
