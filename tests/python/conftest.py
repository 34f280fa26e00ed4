"""Shared fixtures: the sample meshes beside the repository, a seeded random generator, the
runner of docstring examples, and the rule for what a test needs and cannot find: it skips,
saying so, except under ``CI=true``, where it fails."""

from __future__ import annotations

import doctest
import os
import pathlib
import warnings
from typing import NoReturn

import numpy as np
import pytest

import buoyancy
from buoyancy._sample_meshes import find_sample_mesh, not_found_message, sample_meshes_dir

REPO = pathlib.Path(__file__).resolve().parents[2]


def under_ci() -> bool:
    """Whether this is a CI run (``CI=true``), which must run every test: there, a test whose
    requirements are missing fails instead of skipping."""
    return os.environ.get("CI") == "true"


def fail_under_ci(reason: str) -> None:
    """Under ``CI=true``, fails the test that needs what ``reason`` says is missing; otherwise
    does nothing."""
    __tracebackhide__ = True  # reports name the caller's line, not this one
    if under_ci():
        pytest.fail(f"{reason}; CI=true, so the tests that need it fail", pytrace=False)


def skip_unless_ci(reason: str) -> NoReturn:
    """Skips the tests that need what ``reason`` says is missing (every test of the module when
    called at import time, as after a failed optional import); under ``CI=true`` fails them
    instead, so that a CI run cannot pass without running them."""
    __tracebackhide__ = True  # reports name the caller's line, not this one
    fail_under_ci(reason)
    pytest.skip(reason, allow_module_level=True)


def require_sample_mesh(name: str) -> pathlib.Path:
    """The path of the sample mesh ``name``. When it is missing, the test that needs it skips,
    saying where it looked, or fails under ``CI=true`` (see :func:`skip_unless_ci`)."""
    __tracebackhide__ = True  # reports name the caller's line, not this one
    path = sample_meshes_dir(REPO) / name
    if not path.is_file():
        skip_unless_ci(f"{not_found_message(REPO, name)}; the procedural meshes are still tested")
    return path


def sample_mesh_or_fallback(name: str, fallback: str) -> pathlib.Path | None:
    """The path of the sample mesh ``name``, or ``None`` when it is missing, for a test that then
    runs on ``fallback`` instead: it says so in a warning naming the folder it looked in. Under
    ``CI=true`` a missing mesh fails the test instead, as in :func:`require_sample_mesh`."""
    __tracebackhide__ = True  # reports name the caller's line, not this one
    path = find_sample_mesh(name, REPO)
    if path is None:
        message = not_found_message(REPO, name)
        fail_under_ci(message)
        warnings.warn(f"{message}; testing {fallback} instead", UserWarning, stacklevel=2)
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
