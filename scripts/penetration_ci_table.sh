#!/usr/bin/env bash
# The committed outcomes of the CI scenes (2D and 3D) at a few velocities, which tests/penetration_ci.rs
# recomputes and compares (outcomes exactly, numbers within a stated tolerance).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/penetration_table.sh sweeps/penetration_ci.toml results/penetration/outcomes_ci.csv 500 800 1100 1500
scripts/penetration_table.sh sweeps/penetration3d_ci.toml results/penetration/outcomes3d_ci.csv 200 500 1000 3000
