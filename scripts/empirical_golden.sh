#!/usr/bin/env bash
# Regenerate the golden sweep tables of the empirical formulas (never edit them by hand):
# x, h_s, h_p of every formula at 500..1500 ft/s by 50, for the report's scenario, one file per
# nose shape. tests/empirical_golden.rs recomputes them and compares with an explicit tolerance.
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_BUILD_JOBS="${CARGO_BUILD_JOBS:-1}"
cargo build --release --quiet
bin="${CARGO_TARGET_DIR:-target}/release/demsweep"
out=results/empirical
mkdir -p "$out"
for nose in flat blunt spherical very-sharp; do
    "$bin" empirical --format csv --nose "$nose" --v0 500..1500 --step 50 > "$out/sweep_$nose.csv.tmp"
    mv "$out/sweep_$nose.csv.tmp" "$out/sweep_$nose.csv"
done
"$bin" empirical --format csv --thresholds --nose spherical > "$out/thresholds_spherical.csv"
echo "wrote $(ls "$out" | wc -l) files to $out"
