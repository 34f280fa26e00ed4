"""Shared fixtures: the sample meshes beside the repository, a seeded random generator, and the
runner of docstring examples."""

from __future__ import annotations

import doctest
import os
import pathlib

import numpy as np
import pytest

import buoyancy
from buoyancy._sample_meshes import not_found_message, sample_meshes_dir

REPO = pathlib.Path(__file__).resolve().parents[2]


def require_sample_mesh(name: str) -> pathlib.Path:
    """The path of the sample mesh ``name``. When it is missing, the test that needs it fails
    under ``CI=true`` (a CI run must test them) and skips otherwise, saying where it looked."""
    path = sample_meshes_dir(REPO) / name
    if not path.is_file():
        message = not_found_message(REPO, name)
        if os.environ.get("CI") == "true":
            pytest.fail(f"{message}; CI=true, so the tests that need it fail", pytrace=False)
        pytest.skip(f"{message}; the procedural meshes are still tested")
    return path


@pytest.fixture(scope="session")
def bunny() -> buoyancy.Mesh:
    return buoyancy.load(require_sample_mesh("bunny.obj"))


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


def run_examples(text: str, name: str) -> int:
    """Runs the `>>>` examples of a docstring; returns how many ran."""
    parser = doctest.DocTestParser()
    test = parser.get_doctest(text, {"buoyancy": buoyancy, "np": np}, name, None, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{name}: {result.failed} doctest examples failed"
    return result.attempted
