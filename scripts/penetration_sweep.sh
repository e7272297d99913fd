#!/usr/bin/env bash
# The full-resolution study of [4/6]: sweeps/penetration.toml at 500..1500 ft/s by 50
# (21 runs, two at a time; about ten minutes on two cores). [5/6]'s `demsweep ballistic` does
# this and bisects; this script only steps.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/penetration_table.sh sweeps/penetration.toml results/penetration/sweep_full.csv $(seq 500 50 1500)
