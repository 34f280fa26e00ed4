"""The hydrodynamic damping model through the bindings: Mesh.damping, Mesh.damping_stiffness,
Damping, DampingCoefficients."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import buoyancy
from buoyancy import shapes

from conftest import random_quaternions


def test_zero_when_dry_at_rest_or_off() -> None:
    cube = shapes.cube(4)
    v, w = (1.0, -3.0, 2.0), (0.5, 1.0, -2.0)
    for y in (2.0, 0.5, 1e6):  # far above, and touching the surface from above
        d = cube.damping((0, y, 0), None, v, w)
        assert d.force.tolist() == [0, 0, 0] and d.torque.tolist() == [0, 0, 0]
        assert d.wetted_area == 0 and d.wetted_fraction == 0
    at_rest = cube.damping((0, -0.2, 0))
    assert at_rest.force.tolist() == [0, 0, 0] and at_rest.torque.tolist() == [0, 0, 0]
    assert at_rest.wetted_area > 0
    off = cube.damping((0, -5, 0), None, (3, 1, 0), (1, 0, 0), coefficients=buoyancy.DampingCoefficients.off())
    assert off.force.tolist() == [0, 0, 0] and off.torque.tolist() == [0, 0, 0]


def test_hand_checked_values_match_the_rust_tests() -> None:
    # The cases of buoyancy-core's damping tests, with the numbers worked out by hand.
    cube = shapes.cube(4)
    # Fully submerged, sinking at 2 m/s: the bottom face (1 m²) alone faces the flow:
    # P = 1000·2 + ½·1000·1·2² = 4000 Pa, upwards; the sides are parallel to the motion.
    d = cube.damping(position=(0, -3, 0), linear_velocity=(0, -2, 0))
    np.testing.assert_allclose(d.force, [0, 4000, 0], rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(d.torque, 0, atol=1e-9)
    np.testing.assert_allclose(d.about, [0, -3, 0], atol=1e-12)
    assert d.wetted_area == pytest.approx(6.0, rel=1e-12) and d.wetted_fraction == pytest.approx(1.0)
    # Upright, 0.4 m draft, moving along +x at 1 m/s: the wetted 0.4 m² of the front face
    # feels 1000·1 + ½·1000·1 = 1500 Pa: F = −600 N along x; wetted area 1 + 4·0.4.
    d = cube.damping(position=(0, 0.1, 0), linear_velocity=(1, 0, 0))
    np.testing.assert_allclose(d.force, [-600, 0, 0], rtol=1e-12, atol=1e-9)
    assert d.wetted_area == pytest.approx(2.6, rel=1e-12)
    # Its torque about the centroid: the force acts at the wetted strip's center, 0.3 m below
    # the centroid (y = −0.2 in the body frame, −0.1 in the world).
    np.testing.assert_allclose(d.torque, [0, 0, -0.3 * 600], rtol=1e-12, atol=1e-9)
    # Spinning sphere, fully submerged: only the angular term, ρ·V^(5/3)·(a₁ + a₂·|ω|)·ω.
    ball = shapes.uv_sphere(1.0, 48, 24)
    d = ball.damping(position=(0, -3, 0), angular_velocity=(0, 3, 0))
    expected = 1000 * ball.volume ** (5 / 3) * (0.1 + 0.1 * 3) * 3
    assert d.torque[1] == pytest.approx(-expected, rel=0.05)
    half = ball.damping(position=(0, 0, 0), angular_velocity=(0, 3, 0))
    assert half.torque[1] / d.torque[1] == pytest.approx(0.5, abs=0.02)


def test_opposes_the_velocity(rng: np.random.Generator) -> None:
    cube = shapes.cube(4)
    for q in random_quaternions(rng, 10):
        p = rng.uniform(-0.5, 0.3, size=3)
        v = rng.normal(size=3)
        w = rng.normal(size=3)
        assert cube.damping(p, q, v).force @ v < 0
        d = cube.damping(p, q, v, w)
        # The power of the damping is never positive.
        assert d.force @ v + d.torque @ w < 0
        # Spinning alone: the torque opposes the spin.
        assert cube.damping(p, q, None, w).torque @ w < 0


def test_current_and_about() -> None:
    cube = shapes.cube(4)
    drifting = cube.damping((0, -0.3, 0), coefficients=buoyancy.DampingCoefficients(current=(1.5, 0, 0)))
    moving = cube.damping((0, -0.3, 0), linear_velocity=(-1.5, 0, 0))
    np.testing.assert_allclose(drifting.force, moving.force, rtol=1e-12)
    assert drifting.force[0] > 0
    # About another point: τ_q = τ + (c − q) × F.
    d = cube.damping((0.2, -0.3, 0.1), (0, 0, 0.6, 0.8), (1, -1, 0.5), (0.3, 0.2, -1))
    q = np.array([1.0, 2.0, -3.0])
    e = cube.damping((0.2, -0.3, 0.1), (0, 0, 0.6, 0.8), (1, -1, 0.5), (0.3, 0.2, -1), about=q)
    np.testing.assert_allclose(e.force, d.force)
    np.testing.assert_allclose(e.torque, d.torque + np.cross(d.about - q, d.force), rtol=1e-12, atol=1e-9)
    np.testing.assert_array_equal(e.about, q)


def test_stiffness_is_the_derivative_of_the_damping() -> None:
    # Against central differences of Mesh.damping, about the center of mass and about another
    # point (the velocity of that point varied, the torque about it), on a tilted torus half
    # under water.
    torus = shapes.torus(1.0, 0.4, 48, 24)
    rotation = np.array([0.2, -0.1, 0.3, 0.9])
    pose = dict(position=(0.3, 0.15, -0.2), rotation=rotation / np.linalg.norm(rotation))
    v, w = np.array([0.4, -0.9, 0.25]), np.array([0.6, -0.3, 1.1])
    center = torus.damping(**pose).about  # the centroid under the pose
    coefficients = buoyancy.DampingCoefficients(angular_drag_linear=0.3, angular_drag_quadratic=0.2)
    for about in (None, center + np.array([0.7, -0.4, 0.2])):
        q = center if about is None else np.asarray(about)
        k = torus.damping_stiffness(
            **pose, linear_velocity=v, angular_velocity=w, coefficients=coefficients, about=about
        )
        assert k.shape == (6, 6) and k.dtype == np.float64
        np.testing.assert_allclose(k, k.T, atol=1e-9 * np.abs(k).max())
        assert np.linalg.eigvalsh(k).min() > -1e-9 * np.abs(k).max()

        def wrench(motion: np.ndarray, q: np.ndarray = q) -> np.ndarray:
            # The velocity of `q` and ω, to the center of mass's velocity that damping takes.
            v_q, w = motion[:3], motion[3:]
            d = torus.damping(
                **pose,
                linear_velocity=v_q + np.cross(w, center - q),
                angular_velocity=w,
                coefficients=coefficients,
                about=q,
            )
            return np.concatenate([d.force, d.torque])

        motion = np.concatenate([v - np.cross(w, center - q), w])
        h = 1e-6
        columns = [(wrench(motion - h * e) - wrench(motion + h * e)) / (2 * h) for e in np.eye(6)]
        np.testing.assert_allclose(np.array(columns).T, k, atol=1e-6 * np.abs(k).max())
    with pytest.raises(ValueError, match="^water: the damping model assumes a flat water surface"):
        torus.damping_stiffness(water=buoyancy.Water(waves=buoyancy.AiryWave(0.1, 10.0)))
    assert np.count_nonzero(torus.damping_stiffness(position=(0, 5, 0), linear_velocity=v)) == 0  # dry


def test_coefficients() -> None:
    c = buoyancy.DampingCoefficients(
        linear_drag=500, drag_coefficient=0.5, angular_drag_linear=0.2, angular_drag_quadratic=0, current=[0, 0, 1]
    )
    assert (c.linear_drag, c.drag_coefficient, c.angular_drag_linear, c.angular_drag_quadratic) == (500, 0.5, 0.2, 0)
    np.testing.assert_array_equal(c.current, [0, 0, 1])
    assert not c.is_off and buoyancy.DampingCoefficients.off().is_off
    assert buoyancy.DampingCoefficients() == buoyancy.DampingCoefficients(1000, 1, 0.1, 0.1, (0, 0, 0))
    assert c != buoyancy.DampingCoefficients()
    assert repr(c) == (
        "DampingCoefficients(linear_drag=500, drag_coefficient=0.5, angular_drag_linear=0.2, "
        "angular_drag_quadratic=0, current=(0, 0, 1))"
    )
    with pytest.raises(AttributeError):
        c.linear_drag = 3  # type: ignore[misc]
    # Positional arguments in the core's order; numpy scalars and ints are numbers too.
    assert buoyancy.DampingCoefficients(np.float32(500), 0.5, np.int64(0), 0) == buoyancy.DampingCoefficients(
        linear_drag=500, drag_coefficient=0.5, angular_drag_linear=0, angular_drag_quadratic=0
    )
    # Halving the linear coefficient halves the linear part of the drag.
    cube = shapes.cube()
    linear_only = buoyancy.DampingCoefficients(drag_coefficient=0, angular_drag_linear=0, angular_drag_quadratic=0)
    half = buoyancy.DampingCoefficients(
        linear_drag=500, drag_coefficient=0, angular_drag_linear=0, angular_drag_quadratic=0
    )
    f1 = cube.damping((0, -2, 0), None, (0, 1, 0), coefficients=linear_only).force
    f2 = cube.damping((0, -2, 0), None, (0, 1, 0), coefficients=half).force
    np.testing.assert_allclose(f1, [0, -1000, 0], atol=1e-9)
    np.testing.assert_allclose(f2, f1 / 2, atol=1e-9)


def test_pickle_and_repr() -> None:
    c = buoyancy.DampingCoefficients(linear_drag=123.5, current=(0.1, 0.2, 0.3))
    assert pickle.loads(pickle.dumps(c)) == c
    d = shapes.cube().damping((0, -3, 0), None, (0, -2, 0))
    copy = pickle.loads(pickle.dumps(d, protocol=pickle.HIGHEST_PROTOCOL))
    assert copy == d and copy.wetted_area == d.wetted_area
    np.testing.assert_array_equal(copy.torque, d.torque)
    assert (
        repr(d) == "Damping(force=[0, 4000, 0], torque=[0, 0, 0], about=[0, -3, 0], wetted_area=6, wetted_fraction=1)"
    )
    with pytest.raises(AttributeError):
        d.wetted_area = 0  # type: ignore[misc]


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"linear_velocity": (np.nan, 0, 0)}, "^linear_velocity: has a NaN"),
        ({"angular_velocity": (0, np.inf, 0)}, "^angular_velocity: has a NaN"),
        ({"linear_velocity": (1, 2)}, r"^linear_velocity: expected 3 numbers"),
        ({"position": (0, np.nan, 0)}, "^position: has a NaN"),
        ({"rotation": (0, 0, 0, 2)}, "^rotation: the quaternion"),
        ({"about": (0, 0)}, "^about: expected 3 numbers"),
    ],
)
def test_argument_errors(kwargs, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        shapes.cube().damping(**kwargs)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"linear_drag": -1.0}, "^linear_drag: must be finite and non-negative$"),
        ({"drag_coefficient": np.nan}, "^drag_coefficient: must be finite and non-negative"),
        ({"angular_drag_linear": np.inf}, "^angular_drag_linear: must be finite"),
        ({"angular_drag_quadratic": -0.1}, "^angular_drag_quadratic: must be finite"),
        ({"current": (0, np.nan, 0)}, "^current: has a NaN"),
        ({"current": (0, 0)}, "^current: expected 3 numbers"),
    ],
)
def test_coefficient_errors(kwargs, match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ValueError, match=match):
        buoyancy.DampingCoefficients(**kwargs)


def test_wrong_types_name_the_argument() -> None:
    with pytest.raises(TypeError, match="^coefficients: expected a buoyancy.DampingCoefficients, got buoyancy.Water$"):
        shapes.cube().damping(coefficients=buoyancy.Water())  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="^water: expected a buoyancy.Water, got buoyancy.DampingCoefficients$"):
        shapes.cube().damping(water=buoyancy.DampingCoefficients())  # type: ignore[arg-type]
    for name in ("linear_drag", "drag_coefficient", "angular_drag_linear", "angular_drag_quadratic"):
        with pytest.raises(TypeError, match=f"^{name}: expected a number, got str$"):
            buoyancy.DampingCoefficients(**{name: "high"})  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="^wetted_area: expected a number, got list$"):
        buoyancy.Damping((0, 0, 0), (0, 0, 0), (0, 0, 0), wetted_area=[1.0])  # type: ignore[arg-type]


def test_results_are_read_only() -> None:
    d = shapes.cube().damping((0, -3, 0), None, (0, -2, 0))
    for array in (d.force, d.torque, d.about, buoyancy.DampingCoefficients(current=(1, 0, 0)).current):
        assert not array.flags.writeable
        with pytest.raises(ValueError, match="read-only"):
            array[0] = 1.0
