#!/usr/bin/env bash
# Pictures of the default scene's target (sweeps/penetration.toml, its packing) at first
# scabbing and at first perforation: one run at the velocity where that packing first scabs
# and one where it first perforates (read them off results/ballistic/thresholds.csv, the
# packing's `bisection seed 1` rows: the upper end of each bracket), each with snapshots every
# 0.25 ms; the frame at (or just after) the time the outcome was first seen is copied to
#   results/penetration/scabbed_<V>fps.png and results/penetration/perforated_<V>fps.png,
# and the run's last frame beside it (..._final.png).
# Usage: scripts/pictures.sh SCAB_V0_FPS PERF_V0_FPS
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/demsweep_bin.sh
scab_v=${1:?usage: scripts/pictures.sh SCAB_V0_FPS PERF_V0_FPS}
perf_v=${2:?usage: scripts/pictures.sh SCAB_V0_FPS PERF_V0_FPS}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The value of column $2 in the one-row CSV $1.
column() {
    awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) k = i } NR == 2 { print $k }' "$1"
}

# The first frame of the series in $1 at or after time $2 (s).
frame_at() {
    sed -n 's/.*timestep="\([^"]*\)".*file="\([^"]*\)\.vtu".*/\1 \2/p' "$1/series.pvd" |
        awk -v t="$2" '$1 + 0 >= t + 0 { print $2 ".png"; exit }'
}

for what in scabbed perforated; do
    if [ "$what" = scabbed ]; then v=$scab_v; time_col=scab_time_s; else v=$perf_v; time_col=perforation_time_s; fi
    "$bin" run sweeps/penetration.toml --set projectile.v0_fps="$v" --set penetration.name="$what" \
        --out "$work" --snapshots "$work/$what-frames" --snapshot-every-ms 0.25 --quiet
    t=$(column "$work/$what/summary.csv" "$time_col")
    if [ -z "$t" ]; then
        echo "pictures.sh: the run at $v ft/s was not $what (column $time_col empty)" >&2
        exit 1
    fi
    frame=$(frame_at "$work/$what-frames" "$t")
    stem=$(printf '%s_%sfps' "$what" "$v")
    cp "$work/$what-frames/$frame" "results/penetration/$stem.png.tmp" && mv "results/penetration/$stem.png.tmp" "results/penetration/$stem.png"
    cp "$work/$what-frames/final.png" "results/penetration/${stem}_final.png.tmp" && mv "results/penetration/${stem}_final.png.tmp" "results/penetration/${stem}_final.png"
    echo "wrote results/penetration/$stem.png ($frame, first $what at $t s) and ${stem}_final.png"
done
