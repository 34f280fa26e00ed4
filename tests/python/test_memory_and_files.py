"""Requests too large for the memory are a ``MemoryError`` naming the argument, never the
allocator's abort (which ended the interpreter with SIGABRT); files that are not regular files
are refused before they are opened (a FIFO waits forever for a writer, /dev/zero never ends);
bytes that are not a mesh are a ``MeshError`` in every format.

The memory cases run in a child interpreter whose address space is capped at 3 GiB
(``RLIMIT_AS``), so that what cannot be allocated is the same on every machine."""

from __future__ import annotations

import os
import pathlib
import subprocess
import sys
import textwrap

import pytest

import buoyancy
from buoyancy.stability import main

LIMIT = 3 << 30


def run_capped(code: str) -> subprocess.CompletedProcess[str]:
    """``code`` in a child interpreter limited to ``LIMIT`` bytes of address space."""
    prelude = f"import resource\nresource.setrlimit(resource.RLIMIT_AS, ({LIMIT}, {LIMIT}))\n"
    return subprocess.run(
        [sys.executable, "-c", prelude + textwrap.dedent(code)], capture_output=True, text=True, timeout=300
    )


@pytest.mark.skipif(sys.platform != "linux", reason="RLIMIT_AS caps the address space on Linux")
@pytest.mark.parametrize(
    "call, argument",
    [
        # 10⁸ drafts: 62 GB of rows (the input array itself is 0.8 GB).
        ("b.shapes.cube().hydrostatic_table(np.linspace(0.1, 0.9, 10**8))", "drafts"),
        # 10⁸ heels: 11 GB of points.
        ("b.shapes.cube().gz_curve(500.0, (0, 0, 0), heel_deg=np.linspace(0, 90, 10**8))", "heel_deg"),
        # 10⁹ components of a sea state: 48 GB.
        ("b.Waves.jonswap(hs=1.0, tp=8.0, n=10**9)", "n"),
        # 1.8·10⁹ vertices: 43 GB.
        ("b.shapes.uv_sphere(1.0, 60000, 30000)", "slices"),
        # 4·10⁸ triangles, whose preparation needs 150 GB.
        ("b.shapes.torus(1.0, 0.25, 20000, 10000)", "segments"),
        # The cube's lattice of 25,000³ points: 62 TB.
        ("b.shapes.cube(25000)", "n"),
        ("b.shapes.capsule(1.0, 1.0, 8, 4 * 10**8)", "stacks"),
    ],
)
def test_a_request_too_large_for_memory_is_a_memory_error(call: str, argument: str) -> None:
    result = run_capped(
        f"""
        import numpy as np
        import buoyancy as b
        try:
            {call}
        except MemoryError as error:
            print("MemoryError:", error)
        """
    )
    assert result.returncode == 0, f"the interpreter died ({result.returncode}): {result.stderr[-2000:]}"
    assert result.stdout.startswith(f"MemoryError: {argument} asks for "), result.stdout + result.stderr
    assert "of memory, more than can be allocated" in result.stdout


@pytest.mark.skipif(sys.platform != "linux", reason="RLIMIT_AS caps the address space on Linux")
def test_a_mesh_too_large_to_prepare_is_a_memory_error(tmp_path: pathlib.Path) -> None:
    # A binary STL that declares 10⁸ triangles and holds them (5 GB sparse file, never read
    # whole): refused before it is read, by the memory reading it would take.
    path = tmp_path / "huge.stl"
    with path.open("wb") as f:
        f.write(b"\0" * 80 + (10**8).to_bytes(4, "little"))
        f.truncate(84 + 50 * 10**8)
    result = run_capped(
        f"""
        import buoyancy
        try:
            buoyancy.load({str(path)!r})
        except MemoryError as error:
            print("MemoryError:", error)
        """
    )
    assert result.returncode == 0, result.stderr[-2000:]
    assert result.stdout.startswith("MemoryError: path asks for 15.000 GB of memory"), result.stdout


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs named pipes")
def test_a_fifo_is_refused_without_waiting_for_a_writer(tmp_path: pathlib.Path) -> None:
    fifo = tmp_path / "hull.stl"
    os.mkfifo(fifo)
    # In a child, so that a regression hangs the child (and fails on the timeout), not the suite.
    result = subprocess.run(
        [
            sys.executable,
            "-c",
            f"import buoyancy\ntry:\n buoyancy.load({str(fifo)!r})\nexcept OSError as e:\n print(e)",
        ],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert "not a regular file (a FIFO, device or socket)" in result.stdout, result.stdout + result.stderr


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="needs /dev/zero")
def test_a_device_is_refused(tmp_path: pathlib.Path) -> None:
    link = tmp_path / "zero.stl"
    link.symlink_to("/dev/zero")
    with pytest.raises(OSError, match="not a regular file"):
        buoyancy.load(link)


def test_a_folder_is_an_is_a_directory_error(tmp_path: pathlib.Path) -> None:
    folder = tmp_path / "hull.obj"
    folder.mkdir()
    with pytest.raises(IsADirectoryError):
        buoyancy.load(folder)


@pytest.mark.parametrize("extension", ["obj", "stl", "ply"])
def test_garbage_is_a_mesh_error_in_every_format(tmp_path: pathlib.Path, extension: str) -> None:
    path = tmp_path / f"garbage.{extension}"
    # Not UTF-8 (an OBJ read as text was an OSError), not a mesh in any format.
    path.write_bytes(bytes(range(256)) * 8)
    with pytest.raises(buoyancy.MeshError, match="cannot parse the mesh"):
        buoyancy.load(path)


def test_an_obj_with_a_latin1_comment_still_reads(tmp_path: pathlib.Path) -> None:
    path = tmp_path / "tet.obj"
    text = "# t\xe9tra\xe8dre\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
    path.write_bytes(text.encode("latin-1"))
    assert buoyancy.load(path).volume == pytest.approx(1 / 6)


def write_box(path: pathlib.Path) -> pathlib.Path:
    box = buoyancy.shapes.cube().scaled((4.0, 2.0, 1.0)).translated((0, 0, 0.5))
    lines = [f"v {x:.17g} {y:.17g} {z:.17g}" for x, y, z in box.vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in box.faces]
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize(
    "options, message",
    [
        (["--heel-step", "1e-9"], r"--heel-step 1e-09 makes 90,000,000,001 heels up to 90°; at most 100,000"),
        (["--rows", "100000000"], "--rows must be from 1 to 100,000, got 100,000,000"),
        (["--rows", "0"], "--rows must be from 1 to 100,000, got 0"),
    ],
)
def test_the_command_line_refuses_sizes_it_cannot_mean(
    tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str], options: list[str], message: str
) -> None:
    mesh = write_box(tmp_path / "box.obj")
    with pytest.raises(SystemExit) as exit:
        main([str(mesh), "--mass", "2050", "--cog", "0", "0", "0.4", "--out", str(tmp_path), *options])
    assert exit.value.code == 2
    assert message in capsys.readouterr().err
