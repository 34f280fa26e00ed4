"""Shared fixtures: the test meshes beside the repository, and a seeded random generator."""

from __future__ import annotations

import os
import pathlib

import numpy as np
import pytest

import buoyancy

REPO = pathlib.Path(__file__).resolve().parents[2]


def meshes_dir() -> pathlib.Path | None:
    """``$BUOYANCY_MESHES``, else ``../shared/meshes`` beside the repository, if it exists."""
    env = os.environ.get("BUOYANCY_MESHES")
    path = pathlib.Path(env) if env else REPO.parent / "shared" / "meshes"
    return path if path.is_dir() else None


@pytest.fixture(scope="session")
def shared_meshes() -> pathlib.Path:
    path = meshes_dir()
    if path is None:
        pytest.skip(
            "test meshes not found in $BUOYANCY_MESHES or ../shared/meshes beside the repository; "
            "the procedural meshes are still tested"
        )
    return path


@pytest.fixture(scope="session")
def bunny(shared_meshes: pathlib.Path) -> buoyancy.Mesh:
    return buoyancy.load(shared_meshes / "bunny.obj")


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(20240605)


def random_quaternions(rng: np.random.Generator, k: int) -> np.ndarray:
    """K uniformly random unit quaternions (x, y, z, w)."""
    q = rng.normal(size=(k, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def quaternion_matrix(q: np.ndarray) -> np.ndarray:
    """The rotation matrix of a unit quaternion (x, y, z, w), written out independently."""
    x, y, z, w = q
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )
