#!/usr/bin/env bash
# Runs every test of the project: unit, integration, property and doc tests of all crates,
# with and without the optional features.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo test --workspace --all-features
cargo test -p buoyancy-core --no-default-features --lib
cargo build --workspace --all-targets --all-features
