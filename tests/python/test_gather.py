"""buoyancy._core._gather_bytes: the bulk read of buoyancy.rapier (bytes at fixed places of many
``bytes`` objects, side by side in one array)."""

from __future__ import annotations

import numpy as np
import pytest

from buoyancy._core import _gather_bytes


def test_ranges_from_the_start_and_the_end_side_by_side() -> None:
    blobs = [bytes(range(10)), bytes(range(100, 114))]  # of different lengths
    rows = _gather_bytes(blobs, [(1, 2), (-3, 3), (0, 1)])
    assert rows.dtype == np.uint8 and rows.shape == (2, 6) and rows.flags.c_contiguous
    assert rows.tolist() == [[1, 2, 7, 8, 9, 0], [101, 102, 111, 112, 113, 100]]
    assert not rows.flags.writeable


def test_no_blobs_or_no_ranges() -> None:
    assert _gather_bytes([], [(0, 4)]).shape == (0, 4)
    assert _gather_bytes([b"abc"], []).shape == (1, 0)


@pytest.mark.parametrize("ranges", [[(8, 3)], [(-11, 1)], [(12, 0)]])
def test_a_range_outside_a_blob_is_an_error_naming_it(ranges: list[tuple[int, int]]) -> None:
    with pytest.raises(ValueError, match=r"^blobs\[1\]: 10 bytes: no"):
        _gather_bytes([bytes(20), bytes(10)], ranges)


def test_only_bytes() -> None:
    with pytest.raises(TypeError, match=r"^blobs\[0\]: expected bytes, got str"):
        _gather_bytes(["abc"], [(0, 1)])  # type: ignore[list-item]
