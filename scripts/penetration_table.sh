#!/usr/bin/env bash
# One summary row per impact velocity for a penetration scene, run two at a time, gathered into
# one CSV (the header once, rows in velocity order). Never edit its tables by hand.
#
#   scripts/penetration_table.sh SCENE OUT.csv V1 V2 ...
#
# scripts/penetration_ci_table.sh calls it.
set -euo pipefail
cd "$(dirname "$0")/.."
scene=$1; out=$2; shift 2
. scripts/demsweep_bin.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export bin scene work
printf '%s\n' "$@" | xargs -P "${JOBS:-2}" -I{} sh -c \
    'RAYON_NUM_THREADS=1 "$bin" run "$scene" --quiet --set projectile.v0_fps={} --out "$work/v{}" > "$work/v{}.log" 2>&1 || { cat "$work/v{}.log" >&2; exit 1; }'
first=1
for v in "$@"; do
    f=$(ls "$work/v$v"/*/summary.csv)
    if [ $first = 1 ]; then head -n 1 "$f"; first=0; fi
    tail -n +2 "$f"
done > "$work/table.csv"
mkdir -p "$(dirname "$out")"
mv "$work/table.csv" "$out"
echo "wrote $out ($# runs)"
