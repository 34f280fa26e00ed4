#!/usr/bin/env bash
# Runs every test of the project: unit, integration, property and doc tests of all crates,
# with and without the optional features.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo test --workspace --all-features
# The adapter's serial path (the line above runs it with rayon).
cargo test -p buoyancy-rapier
cargo test -p buoyancy-core --no-default-features --lib
# Builds the examples and the benchmarks (never runs them).
cargo build --workspace --all-targets --all-features
