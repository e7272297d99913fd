#!/usr/bin/env bash
# The CI scene's ballistic sweep, committed as a regression table: results/thresholds_ci.csv
# (thresholds), results/thresholds_ci_runs.csv (every run) and results/thresholds_ci_sweep.toml
# (the sweep's arguments and scene hash). tests/thresholds_ci.rs reruns the same sweep and
# compares. Never edit these by hand; rerun this after a change to the physics or the scene.
#
# The range brackets both thresholds of the coarse scene (packing seed 1, which scabs between
# 800 and 1100 ft/s and perforates between 1100 and 1500: results/penetration/outcomes_ci.csv)
# with a coarser step and tolerance than the full study, to keep CI short.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/demsweep_bin.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" ballistic --scene sweeps/penetration_ci.toml --v0 "${V0:-700..1500}" --step "${STEP:-200}" --tol-fps "${TOL:-25}" --out "$work" --quiet
cp "$work/thresholds.csv" results/thresholds_ci.csv.tmp && mv results/thresholds_ci.csv.tmp results/thresholds_ci.csv
cp "$work/runs.csv" results/thresholds_ci_runs.csv.tmp && mv results/thresholds_ci_runs.csv.tmp results/thresholds_ci_runs.csv
cp "$work/sweep.toml" results/thresholds_ci_sweep.toml.tmp && mv results/thresholds_ci_sweep.toml.tmp results/thresholds_ci_sweep.toml
echo "wrote results/thresholds_ci.csv, results/thresholds_ci_runs.csv, results/thresholds_ci_sweep.toml"
