#!/usr/bin/env bash
# The full-resolution study: the seed's scene (sweeps/penetration.toml), 500..1500 ft/s by 50,
# both thresholds bisected to 5 ft/s, on every core. Writes results/ballistic/ (runs.csv,
# runs.parquet, thresholds.csv, ballistic.png, sweep.toml) and copies the thresholds to
# results/thresholds_full.csv with the command in a comment-free companion
# results/thresholds_full_command.txt. About 15 minutes on this 2-core machine.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/demsweep_bin.sh
cmd=(ballistic --scene sweeps/penetration.toml --v0 500..1500 --step 50 --tol-fps 5 --out results/ballistic)
start=$(date +%s)
"$bin" "${cmd[@]}" "$@"
end=$(date +%s)
cp results/ballistic/thresholds.csv results/thresholds_full.csv
printf 'demsweep %s\n# wall %s s on %s threads\n' "${cmd[*]}" "$((end - start))" "$(nproc)" > results/thresholds_full_command.txt
echo "wrote results/thresholds_full.csv"
