"""The paper's analytic curves (ρg = 1, centroid at (0, h, 0)) and exact hydrostatic identities."""

from __future__ import annotations

import math

import numpy as np
import pytest

import buoyancy
from buoyancy import shapes

from conftest import quaternion_matrix, random_quaternions

UNIT = buoyancy.Water(density=1.0, gravity=1.0)
EXACT = ("exact", "exact_surface")
APPROXIMATE = ("fast", "improved", "fast_surface")


def heights(half_range: float, n: int = 41) -> np.ndarray:
    return half_range * np.linspace(-1, 1, n + 2)[1:-1]


@pytest.mark.parametrize("n", [1, 10, 100])
@pytest.mark.parametrize("method", EXACT)
def test_cube_curve_is_exact(n: int, method: str) -> None:
    cube = shapes.cube(n)
    for h in heights(0.5):
        b = cube.buoyancy((0, h, 0), water=UNIT, method=method)
        assert b.force[1] == pytest.approx(0.5 - h, abs=1e-12)
        assert b.volume == pytest.approx(0.5 - h, abs=1e-12)
        assert abs(b.force[0]) < 1e-12 and abs(b.force[2]) < 1e-12
        # The center of the submerged box, halfway between its bottom and the surface.
        np.testing.assert_allclose(b.center, [0, (h - 0.5) / 2, 0], atol=1e-12)


@pytest.mark.parametrize("method", APPROXIMATE[:2])
def test_approximate_methods_miss_the_curve_on_the_coarse_cube(method: str) -> None:
    cube = shapes.cube(10)
    errors = [abs(cube.buoyancy((0, h, 0), water=UNIT, method=method).force[1] - (0.5 - h)) for h in heights(0.5)]
    assert max(errors) > 1e-3


@pytest.mark.parametrize("segments, tolerance", [(50, 2e-2), (200, 1.5e-3)])
@pytest.mark.parametrize("method", EXACT)
def test_sphere_curve(segments: int, tolerance: float, method: str) -> None:
    sphere = shapes.uv_sphere(1.0, segments, segments)
    hs = heights(1.0, 21)
    batch = sphere.buoyancy_batch(np.c_[0 * hs, hs, 0 * hs], None, water=UNIT, method=method)
    analytic = math.pi / 3 * (hs - 1) ** 2 * (hs + 2)
    error = batch.force[:, 1] - analytic
    assert np.max(np.abs(error)) < tolerance
    # The polyhedron is inscribed in the sphere: it never displaces more than the ball.
    assert np.all(error < 1e-12)
    # Deep enough, it displaces its own volume.
    deep = sphere.buoyancy((0, -1.5, 0), water=UNIT, method=method)
    assert deep.volume == pytest.approx(sphere.volume, rel=1e-12)


def test_exact_methods_agree_with_each_other(rng: np.random.Generator) -> None:
    knot = shapes.torus_knot()
    positions = rng.uniform(-0.8, 0.8, size=(50, 3))
    rotations = random_quaternions(rng, 50)
    a = knot.buoyancy_batch(positions, rotations, method="exact")
    b = knot.buoyancy_batch(positions, rotations, method="exact_surface")
    np.testing.assert_allclose(a.volume, b.volume, atol=1e-12 * knot.volume)
    np.testing.assert_allclose(a.force, b.force, atol=1e-9 * 9810 * knot.volume)
    np.testing.assert_allclose(a.torque, b.torque, atol=1e-8 * 9810 * knot.volume)


def test_fully_submerged_body_displaces_its_volume_at_its_centroid(rng: np.random.Generator) -> None:
    torus = shapes.torus()
    for q in random_quaternions(rng, 10):
        position = np.array([3.0, -5.0, 1.0])
        b = torus.buoyancy(position, q, method="exact")
        assert b.volume == pytest.approx(torus.volume, rel=1e-12)
        center_of_mass = quaternion_matrix(q) @ torus.centroid + position
        np.testing.assert_allclose(b.about, center_of_mass, atol=1e-12)
        np.testing.assert_allclose(b.center, center_of_mass, atol=1e-9)
        np.testing.assert_allclose(b.force, [0, 9810 * torus.volume, 0], rtol=1e-12)
        assert np.linalg.norm(b.torque) < 1e-8 * 9810 * torus.volume


def test_water_of_any_orientation_and_level(rng: np.random.Generator) -> None:
    """Rotating the body and the water together rotates the result."""
    knot = shapes.torus_knot()
    for q in random_quaternions(rng, 5):
        r = quaternion_matrix(q)
        level = 0.37
        up = buoyancy.Water(density=1025.0, gravity=9.8, level=level)
        turned = buoyancy.Water(density=1025.0, gravity=9.8, level=level, normal=r @ [0, 1, 0])
        position = np.array([0.1, 0.2 + level, -0.3])
        a = knot.buoyancy(position, water=up)
        b = knot.buoyancy(r @ position, r, water=turned)
        assert b.volume == pytest.approx(a.volume, rel=1e-9)
        np.testing.assert_allclose(b.force, r @ a.force, atol=1e-8 * np.linalg.norm(a.force))
        np.testing.assert_allclose(b.center, r @ a.center, atol=1e-9)
        np.testing.assert_allclose(b.torque, r @ a.torque, atol=1e-8 * np.linalg.norm(a.force))


def test_volumes_above_and_below_add_up(rng: np.random.Generator) -> None:
    """The part under the plane with normal n plus the part under −n is the whole body."""
    knot = shapes.torus_knot()
    for q in random_quaternions(rng, 10):
        n = rng.normal(size=3)
        below = knot.buoyancy((0.1, 0, 0), q, water=buoyancy.Water(normal=n, level=0.05))
        above = knot.buoyancy((0.1, 0, 0), q, water=buoyancy.Water(normal=-n, level=-0.05))
        assert below.volume + above.volume == pytest.approx(knot.volume, rel=1e-12)


def test_torque_is_the_moment_of_the_force_at_the_center(rng: np.random.Generator) -> None:
    knot = shapes.torus_knot()
    for q in random_quaternions(rng, 10):
        for method in ("exact", "improved", "fast"):
            b = knot.buoyancy((0, 0.3, 0), q, method=method)
            np.testing.assert_allclose(
                b.torque, np.cross(b.center - b.about, b.force), atol=1e-8 * np.linalg.norm(b.force) + 1e-12
            )
            point = rng.normal(size=3)
            moved = knot.buoyancy((0, 0.3, 0), q, method=method, about=point)
            np.testing.assert_array_equal(moved.about, point)
            np.testing.assert_allclose(
                moved.torque, b.torque + np.cross(b.about - point, b.force), atol=1e-9 * np.linalg.norm(b.force) + 1e-12
            )


def test_dry_body_has_no_force() -> None:
    b = shapes.cube().buoyancy((1.0, 3.0, 2.0))
    assert b.volume == 0.0
    np.testing.assert_array_equal(b.force, 0.0)
    np.testing.assert_array_equal(b.torque, 0.0)
    np.testing.assert_array_equal(b.center, [1.0, 0.0, 2.0])
    assert (b.fully_submerged, b.partially_submerged) == (0, 0)
