#!/usr/bin/env bash
# A CI scene's ballistic sweep, committed as a regression table:
#
#   scripts/thresholds_ci.sh      2D: results/thresholds_ci{.csv,_runs.csv,_sweep.toml}
#   scripts/thresholds_ci.sh 3d   3D: results/thresholds3d_ci{.csv,_runs.csv,_sweep.toml}
#
# (thresholds, every run, the sweep's arguments and scene hash). tests/thresholds_ci.rs reruns
# the same sweeps and compares. Never edit these by hand; rerun this after a change to the
# physics or the scene.
#
# 2D: the range brackets both thresholds of the coarse scene (packing seed 1 scabs between 800
# and 1100 ft/s and perforates between 1100 and 1500: results/penetration/outcomes_ci.csv),
# with a coarser step and tolerance than the full study, to keep CI short.
# 3D: the level-0 slab (spheres of 1 in under the impact) scabs between 500 and 1000 ft/s and
# is not perforated up to 3000 ft/s (results/penetration/outcomes3d_ci.csv): the range brackets
# its scabbing, and its perforation stays unbounded, which the test checks too.
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-2d}" in
    2d) stem=thresholds_ci; scene=sweeps/penetration_ci.toml; v0=${V0:-700..1500}; step=${STEP:-200}; tol=${TOL:-25} ;;
    3d) stem=thresholds3d_ci; scene=sweeps/penetration3d_ci.toml; v0=${V0:-400..1200}; step=${STEP:-200}; tol=${TOL:-50} ;;
    *) echo "usage: scripts/thresholds_ci.sh [2d|3d]" >&2; exit 2 ;;
esac
. scripts/demsweep_bin.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" ballistic --scene "$scene" --v0 "$v0" --step "$step" --tol-fps "$tol" --out "$work" --quiet
for f in thresholds.csv:"$stem.csv" runs.csv:"${stem}_runs.csv" sweep.toml:"${stem}_sweep.toml"; do
    cp "$work/${f%%:*}" "results/${f#*:}.tmp" && mv "results/${f#*:}.tmp" "results/${f#*:}"
done
echo "wrote results/$stem.csv, results/${stem}_runs.csv, results/${stem}_sweep.toml"
