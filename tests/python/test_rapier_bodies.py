"""buoyancy._core._rapier_bodies: the bulk read of buoyancy.rapier, on serialisations made up here
(tests/python/test_rapier.py holds it to rapier3d's getters on real bodies)."""

from __future__ import annotations

import struct

import numpy as np
import pytest

from buoyancy._core import _rapier_bodies, _world_inverse_inertias

from conftest import quaternion_matrix

HEADER = b"RPYS\x01\x00\x00\x00"


def blob(
    rotation: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0),
    inverse_mass: float = 0.5,
    body_type: int = 0,
    enabled: int = 1,
    sleeping: int = 0,
    locked: int = 0,
    colliders: int = 1,
) -> bytes:
    """A serialised body as rapier3d's ``RigidBody.to_bytes`` lays it out (see rapier_bodies.rs),
    each other field a number of its own."""
    data = bytearray(range(256)) * 2  # filler
    data[:8] = HEADER
    data[24:40] = struct.pack("<4f", *rotation)
    data[40:52] = struct.pack("<3f", 1.0, 2.0, 3.0)  # translation
    data[96:120] = struct.pack("<6f", 4.0, 5.0, 6.0, 7.0, 8.0, 9.0)  # velocities
    data[144:172] = struct.pack("<7f", 0.5, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0)  # gravity scale, wrench
    data[173:185] = struct.pack("<3f", 16.0, 17.0, 18.0)  # world center of mass
    data[233:237] = struct.pack("<f", inverse_mass)
    data[265] = locked
    data = data[:300] + bytes(8 * colliders) + bytes(121)  # the colliders' handles, then the tail
    data[-91] = sleeping
    data[-54:-50] = struct.pack("<I", body_type)
    data[-49] = enabled
    return bytes(data)


def test_the_fields_as_the_getters_return_them() -> None:
    q = (0.1, 0.2, 0.3, 0.9)
    parsed = _rapier_bodies([blob(q), blob(inverse_mass=0.0, body_type=2, sleeping=1, locked=9, colliders=3)], HEADER)
    assert parsed is not None
    values, wrench, flags, keys = parsed
    assert values.shape == (2, 18) and wrench.shape == (2, 6) and flags.shape == (2, 3)
    assert not (values.flags.writeable or wrench.flags.writeable or flags.flags.writeable)
    # The rotation normalised in float32, the squares summed as rapier3d's getter sums them.
    x, y, z, w = np.array(q, dtype=np.float32)
    assert (
        values[0, :4].tolist() == (np.array(q, dtype=np.float32) / np.sqrt((x * x + z * z) + (y * y + w * w))).tolist()
    )
    assert values[0, 4:16].tolist() == [1.0, 2.0, 3.0, 16.0, 17.0, 18.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]
    assert values[:, 16:].tolist() == [[2.0, 0.5], [0.0, 0.5]]  # mass (0 for a zero inverse), gravity scale
    assert wrench.tolist() == [[10.0, 11.0, 12.0, 13.0, 14.0, 15.0], [0.0] * 6]  # none on a kinematic body
    assert flags.tolist() == [[1, 0, 0], [0, 1, 9]]
    assert keys == [blob(q)[221:265], blob(inverse_mass=0.0)[221:265]]


@pytest.mark.parametrize(
    "bad",
    [
        blob()[:356],
        b"RPYS\x02\x00\x00\x00" + blob()[8:],
        blob(body_type=4),
        blob(enabled=2),
        blob(sleeping=2),
        blob(locked=64),
    ],
)
def test_none_when_a_serialisation_does_not_look_as_expected(bad: bytes) -> None:
    assert _rapier_bodies([blob(), bad], HEADER) is None


def test_no_bodies_and_not_bytes() -> None:
    parsed = _rapier_bodies([], HEADER)
    assert parsed is not None and [a.shape for a in parsed[:3]] == [(0, 18), (0, 6), (0, 3)] and parsed[3] == []
    with pytest.raises(TypeError, match=r"^blobs\[0\]: expected bytes, got str"):
        _rapier_bodies(["abc"], HEADER)  # type: ignore[list-item]


def test_world_inverse_inertias_turn_the_local_tensors() -> None:
    rng = np.random.default_rng(7)
    quaternions = rng.normal(size=(50, 4))
    quaternions /= np.linalg.norm(quaternions, axis=1)[:, None]
    quaternions[3] = (np.nan, 0.0, 0.0, 1.0)  # counts as no rotation
    local = rng.normal(size=(50, 3, 3))
    local = local @ local.transpose(0, 2, 1)  # symmetric, as inverse inertias are
    world = _world_inverse_inertias(quaternions, local)
    assert world.shape == (50, 3, 3) and world.dtype == np.float64
    for i, (q, tensor) in enumerate(zip(quaternions, local, strict=True)):
        if i == 3:
            np.testing.assert_array_equal(world[i], tensor)
            continue
        r = quaternion_matrix(q)
        np.testing.assert_allclose(world[i], r @ tensor @ r.T, rtol=0, atol=1e-13 * np.abs(tensor).max())
        # The eigenvalues (the principal inverse inertias) do not turn.
        np.testing.assert_allclose(np.linalg.eigvalsh(world[i]), np.linalg.eigvalsh(tensor), atol=1e-12)
    assert _world_inverse_inertias(np.zeros((0, 4)), np.zeros((0, 3, 3))).shape == (0, 3, 3)


def test_world_inverse_inertias_name_the_bad_argument() -> None:
    with pytest.raises(ValueError, match="inverse_inertias"):
        _world_inverse_inertias(np.zeros((2, 4)), np.zeros((3, 3, 3)))
    with pytest.raises(ValueError, match="quaternions"):
        _world_inverse_inertias(np.zeros((2, 3)), np.zeros((2, 3, 3)))
