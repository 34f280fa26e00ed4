"""examples/dask_sweep.py: a small sweep on a 2-worker LocalCluster gives the serial loop's rows
bit for bit."""

import importlib.util
import math
import pathlib

import pytest

from conftest import skip_unless_ci

try:
    from dask import distributed
except ImportError as error:  # not installed, or installed but not loadable here
    skip_unless_ci(
        f"dask.distributed cannot be imported ({error}); pip install 'buoyancy[dask]' (scripts/test.sh installs it)"
    )

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "dask_sweep.py"


def load_example():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("dask_sweep", EXAMPLE)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_cluster_sweep_equals_the_serial_loop() -> None:
    sweep = load_example()
    fleet = sweep.hulls([0.45, 0.6])
    serial = sweep.sweep_serial(fleet, 9)
    with sweep.local_cluster(2) as cluster, distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        rows = sweep.sweep(client, fleet, 9, chunk_size=4)
    assert len(rows) == 18
    assert sweep.same_rows(rows, serial)
    # The rows are figures, not placeholders: every condition floats, with a finite GM, and
    # the heaviest G of the narrow hull lolls.
    assert all(r[4] == r[4] and r[6] > 0 for r in rows)
    assert any(abs(r[5]) > 1 for r in rows) and any(abs(r[5]) < 1e-6 for r in rows)
    # A changed row is seen.
    changed = list(serial)
    changed[3] = (*changed[3][:4], math.nextafter(changed[3][4], math.inf), *changed[3][5:])
    assert not sweep.same_rows(rows, changed)


def test_main_writes_the_table(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    sweep = load_example()
    code = sweep.main(["--beams", "0.5", "--conditions", "4", "--workers", "2", "--out", str(tmp_path)])
    assert code == 0
    lines = (tmp_path / "sweep.csv").read_text().splitlines()
    assert lines[0].split(",") == list(sweep.COLUMNS) and len(lines) == 5
    assert "4 of 4 conditions float" in capsys.readouterr().out
