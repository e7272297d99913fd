#!/usr/bin/env bash
# The main job as committed: `demsweep ballistic` with its defaults (sweeps/penetration.toml,
# five packings, 500..1500 ft/s by 100, each packing's thresholds bisected to 25 ft/s, V50s with
# 90 % intervals), on every core, from scratch. Writes results/ballistic/ (runs.csv,
# runs.parquet, thresholds.csv, ballistic.png, sweep.toml) and copies the thresholds to
# results/thresholds_full.csv with the command and its wall time in
# results/thresholds_full_command.txt. Extra arguments go to ballistic (e.g. --step 50).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/demsweep_bin.sh
cmd=(ballistic --out results/ballistic --fresh)
start=$(date +%s)
"$bin" "${cmd[@]}" "$@"
end=$(date +%s)
cp results/ballistic/thresholds.csv results/thresholds_full.csv
printf 'demsweep %s\n# wall %s s on %s threads\n' "${cmd[*]}" "$((end - start))" "$(nproc)" > results/thresholds_full_command.txt
echo "wrote results/thresholds_full.csv"
