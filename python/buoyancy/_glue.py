"""What the engine adapters (:mod:`buoyancy.rapier`, :mod:`buoyancy.mujoco`) share: the water
an engine's gravity implies, the settings their controller holds, and the quaternions ``(x, y, z, w)`` that place parts on bodies."""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
import numpy.typing as npt

from ._core import Controller, DampingCoefficients, Water


def water_for_gravity(
    gravity: npt.ArrayLike, up_without_gravity: tuple[float, float, float] = (0.0, 1.0, 0.0)
) -> Water:
    """Fresh water whose surface passes through the origin, up opposite to gravity
    (``up_without_gravity`` when gravity is zero), with ``g = |gravity|``. A gravity that is not
    3 finite numbers is a ``ValueError`` naming it."""
    try:
        g = np.asarray(gravity, dtype=np.float64)
    except (TypeError, ValueError) as error:
        raise ValueError(f"gravity: expected 3 numbers, the gravity vector in m/s² ({error})") from None
    if g.shape != (3,):
        raise ValueError(f"gravity: expected 3 numbers, the gravity vector in m/s², got shape {g.shape}")
    if not np.isfinite(g).all():
        raise ValueError(f"gravity: has a NaN or infinite component: {tuple(g.tolist())}")
    with np.errstate(over="ignore"):
        norm = float(np.linalg.norm(g))
    if not math.isfinite(norm):
        raise ValueError(f"gravity: too large, its magnitude overflows: {tuple(g.tolist())}")
    if norm == 0.0:
        return Water(gravity=0.0, normal=up_without_gravity)
    return Water(gravity=norm, normal=tuple(-g / norm))


def quaternion_product(a: npt.ArrayLike, b: npt.ArrayLike) -> np.ndarray:
    """``a ⊗ b`` of quaternions ``(x, y, z, w)``: the rotation ``b``, then ``a``."""
    (ax, ay, az, aw), (bx, by, bz, bw) = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    return np.array(
        [
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz,
        ]
    )


def rotation_matrix(q: npt.ArrayLike) -> np.ndarray:
    """The rotation matrix of the unit quaternion ``(x, y, z, w)``."""
    q = np.asarray(q, dtype=np.float64)
    x, y, z, w = q / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


class ControllerSettings:
    """The settings of an adapter's :class:`~buoyancy.Controller` (``self._controller``), as
    properties: those of the bodies registered without their own."""

    _controller: Controller

    @property
    def water(self) -> Water:
        """The water, with its waves if it has any (setting it keeps the waves' time)."""
        return self._controller.water

    @water.setter
    def water(self, water: Water) -> None:
        self._controller.water = water

    @property
    def method(self) -> str:
        """The buoyancy method (its canonical name)."""
        return self._controller.method

    @method.setter
    def method(self, method: str) -> None:
        self._controller.method = method

    @property
    def damping(self) -> DampingCoefficients:
        """The damping coefficients."""
        return self._controller.damping

    @damping.setter
    def damping(self, damping: DampingCoefficients) -> None:
        self._controller.damping = damping

    @property
    def damping_resolution(self) -> int | Literal["full"]:
        """How finely the pressure drag is integrated: the most triangles of the reduced copy of
        each mesh, or ``"full"``. Setting it builds the reduced copies it asks for (once per
        mesh)."""
        return self._controller.damping_resolution

    @damping_resolution.setter
    def damping_resolution(self, resolution: int | Literal["full"]) -> None:
        self._controller.damping_resolution = resolution
