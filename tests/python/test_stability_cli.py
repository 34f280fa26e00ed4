"""``python -m buoyancy.stability`` on a box written to a file: what it prints against the box
formulas, the files it writes, and its errors."""

import csv
import pathlib
import subprocess
import sys

import numpy as np
import pytest

from buoyancy import shapes
from buoyancy.stability import main

RHO = 1000.0  # the default density, as the library's Water()
LENGTH, BEAM, DEPTH = 4.0, 2.0, 1.0


def write_box(path: pathlib.Path) -> pathlib.Path:
    """A box 4 m long (x), 2 m wide (y), 1 m deep (z, up), its bottom at z = 0, as OBJ."""
    box = shapes.cube(2).scaled((LENGTH, BEAM, DEPTH)).translated((0, 0, DEPTH / 2))
    lines = [f"v {x:.17g} {y:.17g} {z:.17g}" for x, y, z in box.vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in box.faces]
    path.write_text("\n".join(lines) + "\n")
    return path


def read_csv(path: pathlib.Path) -> tuple[list[str], np.ndarray]:
    with path.open() as f:
        rows = list(csv.reader(f))
    return rows[0], np.array(rows[1:], dtype=float)


def test_box_equilibrium_table_and_gz_curve(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    draft, kg = 0.25, 0.4
    mass = RHO * LENGTH * BEAM * draft
    mesh = write_box(tmp_path / "box.obj")
    out = tmp_path / "out"
    code = main([str(mesh), "--mass", str(mass), "--cog", "0", "0", str(kg), "--up", "z", "--out", str(out)])
    printed = capsys.readouterr().out
    assert code == 0, printed
    assert "water: 1000 kg/m³, g = 9.81 m/s², up = mesh z" in printed  # the defaults, said
    kb, bm_t, bm_l = draft / 2, BEAM**2 / (12 * draft), LENGTH**2 / (12 * draft)
    values = {
        line.split()[0]: line.split()[1] for line in printed.splitlines() if line.startswith("  ") and line.split()
    }
    assert float(values["draft"]) == pytest.approx(draft, abs=1e-4)
    assert float(values["heel"]) == pytest.approx(0, abs=1e-3)
    assert f"GM_T {kb + bm_t - kg:.4f} m" in printed
    assert f"GM_L {kb + bm_l - kg:.4f} m" in printed
    assert "stable:" in printed

    header, gz = read_csv(out / "gz_curve.csv")
    assert header == ["heel_deg", "gz_m", "trim_deg", "draft_m"]
    heel = np.radians(gz[:, 0])
    assert gz[0, 0] == 0 and gz[-1, 0] == 90
    # Wall-sided while the bilge stays wet (tan φ < T / (B/2), below 14°).
    wall = gz[:, 0] < 14
    gm = kb + bm_t - kg
    expected = np.sin(heel) * (gm + bm_t * np.tan(heel) ** 2 / 2)
    np.testing.assert_allclose(gz[wall, 1], expected[wall], atol=1e-8)
    np.testing.assert_allclose(gz[:, 2], 0, atol=1e-7)  # a symmetric box does not trim

    header, table = read_csv(out / "hydrostatic_table.csv")
    assert header[0] == "draft_m" and "displacement_kg" in header and "tpc_t/cm" in header
    drafts = table[:, 0]
    np.testing.assert_allclose(table[:, header.index("displacement_kg")], RHO * LENGTH * BEAM * drafts, rtol=1e-9)
    np.testing.assert_allclose(table[:, header.index("kb_m")], drafts / 2, rtol=1e-9)
    assert drafts[0] == pytest.approx(0.2 * draft) and drafts[-1] == pytest.approx(1.6 * draft)
    if (out / "gz_curve.png").exists():
        assert (out / "gz_curve.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_errors_exit_with_a_message(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    mesh = write_box(tmp_path / "box.obj")
    too_heavy = RHO * LENGTH * BEAM * DEPTH * 1.01
    assert main([str(mesh), "--mass", str(too_heavy), "--cog", "0", "0", "0.5", "--out", str(tmp_path)]) == 2
    assert "does not float" in capsys.readouterr().err
    assert main([str(tmp_path / "missing.stl"), "--mass", "1", "--cog", "0", "0", "0"]) == 2
    assert "missing.stl" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main([str(mesh), "--mass", "1", "--cog", "0", "0", "0", "--up", "x", "--axis", "x"])
    assert "longitudinal axis must be horizontal" in capsys.readouterr().err


def test_runs_as_a_module(tmp_path: pathlib.Path) -> None:
    mesh = write_box(tmp_path / "box.obj")
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "buoyancy.stability",
            str(mesh),
            "--mass",
            "2050",
            "--cog",
            "0",
            "0",
            "0.4",
            "--heel-max",
            "30",
            "--heel-step",
            "10",
            "--rows",
            "3",
            "--out",
            str(tmp_path / "o"),
        ],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    assert "Hydrostatic table" in result.stdout and "GZ curve: 4 heels" in result.stdout


def write_open_box(path: pathlib.Path) -> pathlib.Path:
    """The box without its deck (the triangles of its top face dropped), as OBJ."""
    box = shapes.cube(2).scaled((LENGTH, BEAM, DEPTH)).translated((0, 0, DEPTH / 2))
    top = box.vertices[box.faces].min(axis=1)[:, 2] > DEPTH - 1e-9
    lines = [f"v {x:.17g} {y:.17g} {z:.17g}" for x, y, z in box.vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in box.faces[~top]]
    path.write_text("\n".join(lines) + "\n")
    return path


def test_a_hull_without_positive_stability_says_so(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    """G far above the metacenter: GZ negative at every heel to 90°. Once printed as
    "beyond 90° (GZ stays positive)" with exit 0; now "none" and exit 1, with warnings."""
    mesh = write_box(tmp_path / "box.obj")
    mass = RHO * LENGTH * BEAM * 0.5
    code = main([str(mesh), "--mass", str(mass), "--cog", "0", "0", "3", "--out", str(tmp_path / "o")])
    captured = capsys.readouterr()
    assert code == 1, captured
    assert "angle of vanishing stability none: GZ is not positive at any heel" in captured.out
    assert "stays positive" not in captured.out
    assert "warning: GZ is not positive at any heel" in captured.err
    # The equilibrium found is the box upside down (it floats capsized): said, too.
    assert "warning: the hull floats capsized" in captured.err
    assert (tmp_path / "o" / "gz_curve.csv").exists()


def test_positive_stability_beyond_the_curve(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    mesh = write_box(tmp_path / "box.obj")
    mass = RHO * LENGTH * BEAM * 0.25
    args = [str(mesh), "--mass", str(mass), "--cog", "0", "0", "0.4", "--heel-max", "10", "--out", str(tmp_path)]
    assert main(args) == 0
    assert "angle of vanishing stability beyond 10° (GZ stays positive)" in capsys.readouterr().out


def test_neutral_buoyancy_does_not_float(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Within 1e-12 of neutral buoyancy: once a draft of 2.79 m for a box 1 m high, exit 0."""
    mesh = write_box(tmp_path / "box.obj")
    neutral = RHO * LENGTH * BEAM * DEPTH * (1 - 1e-12)
    assert main([str(mesh), "--mass", repr(neutral), "--cog", "0", "0", "0.5", "--out", str(tmp_path)]) == 2
    assert "does not float" in capsys.readouterr().err


def test_out_is_checked_before_the_work(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    """`--out` naming a file, or a folder that cannot be made: `error:` and exit 2, before the
    solve (once a traceback and exit 1 after it)."""
    mesh = write_box(tmp_path / "box.obj")
    args = [str(mesh), "--mass", "2050", "--cog", "0", "0", "0.4", "--out"]
    assert main([*args, str(mesh)]) == 2
    captured = capsys.readouterr()
    assert f"error: --out {mesh}: is a file, not a folder" in captured.err
    assert "Equilibrium" not in captured.out
    assert main([*args, str(mesh / "below")]) == 2
    captured = capsys.readouterr()
    assert "error: --out" in captured.err and "cannot make the folder" in captured.err
    assert "Equilibrium" not in captured.out


def test_an_open_hull_is_pointed_at_close_openings(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    mesh = write_open_box(tmp_path / "open.obj")
    args = [str(mesh), "--mass", "2050", "--cog", "0", "0", "0.4", "--heel-max", "20", "--out", str(tmp_path)]
    assert main(args) == 2
    assert "run with --close-openings" in capsys.readouterr().err
    assert main([*args, "--close-openings"]) == 0
    assert "--close-openings" not in capsys.readouterr().err


def test_a_hull_in_millimetres_is_told_so(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    """The commonest CAD mistake: a 4 × 2 × 1 m box written in millimetres, its mass in kg. Once
    "the equilibrium solver did not converge … raise max_iterations", a remedy that does not
    help; now the extent comes first and the error says what to check."""
    box = shapes.cube(2).scaled((4000.0, 2000.0, 1000.0)).translated((0, 0, 500.0))
    path = tmp_path / "box_mm.obj"
    lines = [f"v {x:.17g} {y:.17g} {z:.17g}" for x, y, z in box.vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in box.faces]
    path.write_text("\n".join(lines) + "\n")
    code = main([str(path), "--mass", "2050", "--cog", "0", "0", "400", "--out", str(tmp_path / "out")])
    captured = capsys.readouterr()
    assert "extent 4000 × 2000 × 1000 m, volume 8e+09 m³" in captured.out
    assert "warning: units: the mesh spans" in captured.err and "scale the mesh by 0.001" in captured.err
    # Either the solve fails, and says to check the units, or it is written with the warning.
    assert code in (1, 2)
    if code == 2:
        assert "but first check the units" in captured.err


def test_heels_in_radians_are_warned_of(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    mesh = write_box(tmp_path / "box.obj")
    radians = ["--heel-max", "1.5", "--heel-step", "0.1"]
    code = main([str(mesh), "--mass", "2050", "--cog", "0", "0", "0.4", *radians, "--out", str(tmp_path / "out")])
    assert code == 1
    assert "warning: heel_deg: the heels reach only 1.5°" in capsys.readouterr().err
