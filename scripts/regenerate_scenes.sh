#!/usr/bin/env bash
# Regenerate the validation scenes under sweeps/ from their generators (never edit them by hand).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin="${CARGO_TARGET_DIR:-target}/release/demsweep"
$bin scene cracked-plate-energy > sweeps/cracked_plate_energy.toml
$bin scene cracked-plate-toughness > sweeps/cracked_plate_toughness.toml
$bin scene cantilever > sweeps/cantilever.toml
