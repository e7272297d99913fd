#!/usr/bin/env bash
# The mesh study of [1/5]: the depth at 500 ft/s at refinement levels 0, 1, 2 on packings 1-3,
# the calibrated scene (sweeps/penetration.toml, its factor from level 1), two runs at a time.
# Extra arguments (words without spaces) are passed to every run (e.g. `--set concrete.rate=false`). Prints one row per
# run and the mean per level with its ratio to level 1's; writes $OUT (default
# results/penetration/mesh_depth.csv). About 5 minutes on two cores.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/demsweep_bin.sh
out="${OUT:-results/penetration/mesh_depth.csv}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export BIN="$bin" TMP="$tmp" EXTRA="$*"
for level in 0 1 2; do for seed in 1 2 3; do echo "$level $seed"; done; done |
    xargs -P 2 -L 1 bash -c '"$BIN" run sweeps/penetration.toml --quiet --set penetration.level=$0 --set target.seed=$1 $EXTRA --out "$TMP/$0-$1" > /dev/null'
{
    echo "level,seed,depth_in,end_reason,elements,wall_s"
    for level in 0 1 2; do for seed in 1 2 3; do
        awk -F, -v l="$level" -v s="$seed" 'NR==1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
            { printf "%s,%s,%.3f,%s,%s,%s\n", l, s, $c["depth_in"], $c["end_reason"], $c["elements"], $c["wall_s"] }' "$tmp/$level-$seed/penetration/summary.csv"
    done; done
} > "$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
awk -F, 'NR > 1 { s[$1] += $3; n[$1]++ } END { for (l = 0; l <= 2; l++) m[l] = s[l] / n[l];
    for (l = 0; l <= 2; l++) printf "level %d: mean depth %.3f in, %+.1f %% of level 1\n", l, m[l], 100 * (m[l] / m[1] - 1) }' "$out"
