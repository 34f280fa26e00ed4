"""`python -m buoyancy.plots accuracy`: the paper's Figure 4 as PNG files; `… waves`: a body on a
wave and a box's heave force over a wave period."""

from __future__ import annotations

import pathlib
import subprocess
import sys

import numpy as np
import pytest

import buoyancy
from buoyancy import METHODS, plots, wave_plots

from conftest import skip_unless_ci

try:
    import matplotlib  # noqa: F401
except ImportError as error:  # not installed, or installed but not loadable here
    skip_unless_ci(f"matplotlib cannot be imported ({error}); the plots need it (pip install 'buoyancy[plot]')")

PNG = b"\x89PNG\r\n\x1a\n"


def test_accuracy_data_follows_the_curves() -> None:
    for body in plots.bodies(small=True):
        h, analytic, forces = plots.accuracy_data(body, samples=31)
        assert h.shape == analytic.shape == (31,)
        assert set(forces) == set(METHODS)
        assert -body.half_range < h.min() and h.max() < body.half_range
        tolerance = 1e-12 if body.name.startswith("cube") else 2e-2
        for method in ("exact", "exact_surface"):
            assert np.max(np.abs(forces[method] - analytic)) < tolerance
        assert np.max(np.abs(forces["fast"] - analytic)) > 10 * tolerance


def test_accuracy_command_writes_pngs(tmp_path: pathlib.Path) -> None:
    out = tmp_path / "figures"
    run = subprocess.run(
        [sys.executable, "-m", "buoyancy.plots", "accuracy", "--out", str(out), "--small", "--samples", "15"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    names = sorted(p.name for p in out.iterdir())
    assert names == ["accuracy_cube_1200.png", "accuracy_sphere_4900.png", "figure4.png"]
    for name in names:
        data = (out / name).read_bytes()
        assert data.startswith(PNG) and len(data) > 10_000
    assert "Exact Surface" in run.stdout


def test_box_heave_follows_the_analytic_curve() -> None:
    box = wave_plots.BoxInWave(resolution=16)
    times, force, analytic = wave_plots.box_heave_data(box, samples=9)
    assert times.shape == force.shape == analytic.shape == (9,)
    reference = 1000 * 9.81 * box.beam * box.length * box.draft
    assert np.max(np.abs(force - analytic)) < 1e-3 * reference
    assert np.ptp(force) > 0.2 * reference  # the wave moves it


def test_vertex_pressures_are_hydrostatic_in_the_wave() -> None:
    water = buoyancy.Water(waves=lambda p, t: 0.1 + 0 * p[:, 0])
    vertices, pressure = wave_plots.vertex_pressures(buoyancy.shapes.cube(), (0, 0, 0), water, 0.0)
    expected = 1000 * 9.81 * np.maximum(0.1 - vertices[:, 1], 0.0)
    np.testing.assert_allclose(pressure, expected, rtol=1e-15)


def test_waves_command_writes_pngs(tmp_path: pathlib.Path) -> None:
    out = tmp_path / "figures"
    run = subprocess.run(
        [sys.executable, "-m", "buoyancy.plots", "waves", "--out", str(out), "--small", "--samples", "9"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    names = sorted(p.name for p in out.iterdir())
    assert names == ["waves_body.png", "waves_box_heave.png"]
    for name in names:
        data = (out / name).read_bytes()
        assert data.startswith(PNG) and len(data) > 10_000
    assert "largest |F − F_analytic| / ρgBLT" in run.stdout


def test_bad_arguments() -> None:
    with pytest.raises(SystemExit):
        plots.main(["accuracy", "--samples", "1"])
    with pytest.raises(SystemExit):
        plots.main(["nonsense"])
    with pytest.raises(SystemExit):
        plots.main(["waves", "--samples", "0"])
