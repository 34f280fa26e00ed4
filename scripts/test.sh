#!/usr/bin/env bash
# Runs every test of the project: unit, integration, property and doc tests of all crates,
# with and without the optional features; the Bevy plugin's on both backends (and its harbor
# example, headless, then in a web page in headless Chromium); then builds the Python wheel
# into a fresh virtual environment (.venv-test/) with `pip install .` (and rapier3d and mujoco,
# for buoyancy.rapier and buoyancy.mujoco) and runs its pytest suite (tests/python), checks the
# stubs against the compiled module (mypy's stubtest) and lints the Python code (ruff).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo test --workspace --all-features
# The core without std and rayon: its unit tests, and the controller's bodies stepped one after
# another (the line above steps them in parallel; tests/controller.rs holds both to the same
# commands). The adapters have no code of their own that depends on the feature.
cargo test -p buoyancy-core --no-default-features --lib --test controller
# Builds the benchmarks (never runs them) with the tests' profile and dependencies; `cargo test`
# above has built the examples.
cargo test --workspace --all-features --benches --no-run

echo "== Bevy plugin: crates/buoyancy-bevy (its own workspace, rustc 1.97.1), both backends"
# Its tests (the same scenarios on bevy_rapier3d and avian3d, headless), then the harbor example
# headless on each backend: it exits 1 if a body is more than 1 cm off its theoretical draft.
rustup toolchain install 1.97.1 --profile minimal --component rustfmt,clippy >/dev/null
(
  cd crates/buoyancy-bevy
  cargo test --features rapier,avian
  cargo run --features rapier,avian --example harbor -- --headless --backend rapier
  cargo run --features rapier,avian --example harbor -- --headless --backend avian
)

echo "== the harbor in a web page: wasm32, headless Chromium"
# Builds the page (installing the wasm32 target, wasm-bindgen-cli, wasm-opt and chromium if
# missing), opens it in calm water and fails if a body is off its draft by more than 1 cm or the
# console logs an error.
bash scripts/web.sh

echo "== Python: pip install . into a fresh .venv-test, then pytest, the stubs and the linter"
PYTHON="${PYTHON:-python3}"
rm -rf .venv-test
"$PYTHON" -m venv .venv-test
VPY=.venv-test/bin/python
"$VPY" -m pip install --quiet --upgrade pip
# hypothesis for the property suite (tests/python/test_properties.py); trimesh for
# Mesh.from_trimesh's tests; Dask for examples/dask_sweep.py's; mypy (its stubtest)
# and ruff for the checks after pytest (ruff within one minor version, whose formatting style is
# fixed).
"$VPY" -m pip install --quiet numpy pytest hypothesis matplotlib trimesh 'mypy>=2.4' 'ruff~=0.17.6' \
  'dask[distributed]>=2024.1'
# rapier's Python binding, for buoyancy.rapier (a prebuilt abi3 wheel); without it the rapier
# tests skip, saying so.
"$VPY" -m pip install --quiet 'rapier3d>=0.36.1' \
  || echo "note: rapier3d could not be installed; tests/python/test_rapier.py will skip"
# MuJoCo and Gymnasium, for buoyancy.mujoco and examples/mujoco_wave_energy.py (their tests
# skip without them, saying so, and fail under CI=true).
"$VPY" -m pip install --quiet 'mujoco>=3.3' 'gymnasium>=1.0' \
  || echo "note: mujoco could not be installed; tests/python/test_mujoco.py will skip"
"$VPY" -m pip install --quiet .
# MuJoCo renders offscreen (examples/mujoco_wave_energy.py's frame) through OSMesa unless told
# otherwise; it reads MUJOCO_GL when it is first imported.
export MUJOCO_GL="${MUJOCO_GL:-osmesa}"
# From the tests folder's parent, so that `import buoyancy` is the installed wheel.
"$VPY" -m pytest tests/python -q -p no:cacheprovider
echo "== Python: the hand-written stubs (python/buoyancy/_core.pyi) against the compiled module"
"$VPY" -m mypy.stubtest buoyancy._core
echo "== Python: ruff (configured in pyproject.toml)"
"$VPY" -m ruff check python tests/python benches examples scripts
"$VPY" -m ruff format --check python tests/python benches examples scripts
