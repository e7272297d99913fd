#!/usr/bin/env bash
# One large run on one thread and on two ([6/6]: ≥ 1.8× on two threads, bitwise the same): the
# level-2 penetration event (sweeps/penetration.toml at level 2: 54 253 elements, 3 700 steps),
# PAIRS alternating pairs (default 3), each pair's speed-up T1/T2 from the runs' own wall_s
# (the stepping loop), the two-thread run's share of its two cores busy (CPU seconds / 2 wall),
# and a check that each pair's summaries agree in every column but the timings.
# The machine's spells move a pair's ratio by ±10 %: quote the median of several pairs.
# With CEILING=1 (the default) each pair also runs two one-thread runs at once, one pinned to
# each core: 2 × T1 / (their mean wall) is what the two cores give this working set with no
# serial part and no synchronisation at all (shared cache, memory and clock as the two-thread
# run has them), the ceiling the two-thread speed-up is measured against. CEILING=0 skips it.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/demsweep_bin.sh
pairs=${PAIRS:-3}
scene=${SCENE:-sweeps/penetration.toml}
set_args=(--set "penetration.level=${LEVEL:-2}")
[ -x /usr/bin/time ] || { apt-get update -qq && apt-get install -y -qq time; }
work=$(mktemp -d /tmp/demsweep-large.XXXXXX)
col() { awk -F, -v name="$2" 'NR==1 {for (i=1;i<=NF;i++) if ($i==name) c=i} NR==2 {print $c}' "$1"; }
# Every column but the timings.
same() { diff <(cut -d, -f1-46,49- "$1") <(cut -d, -f1-46,49- "$2") > /dev/null; }
ceiling=${CEILING:-1}
run1() { RAYON_NUM_THREADS=1 taskset -c "$1" "$bin" run "$scene" "${set_args[@]}" --quiet --out "$2" > /dev/null 2>&1; }
printf '%-5s %9s %9s %9s %10s %8s %9s %13s %9s\n' pair T1_s T2_s T1/T2 busy_2T steps same_bits 2xT1_at_once ceiling
for k in $(seq 1 "$pairs"); do
    for t in 1 2; do
        RAYON_NUM_THREADS=$t /usr/bin/time -f '%U %S %e' -o "$work/cpu-$t-$k" "$bin" run "$scene" "${set_args[@]}" --quiet --out "$work/$t-$k" > /dev/null 2>&1
    done
    together="- -"
    if [ "$ceiling" = 1 ]; then
        run1 0 "$work/a-$k" & pa=$!
        run1 1 "$work/b-$k" & pb=$!
        wait "$pa" "$pb"
        together="$(col "$(ls "$work"/a-"$k"/*/summary.csv)" wall_s) $(col "$(ls "$work"/b-"$k"/*/summary.csv)" wall_s)"
    fi
    s1=$(ls "$work"/1-"$k"/*/summary.csv); s2=$(ls "$work"/2-"$k"/*/summary.csv)
    [ "$(head -1 "$s1" | cut -d, -f47-48)" = "wall_s,element_steps_per_s" ] || { echo "summary columns moved: fix same() in $0" >&2; exit 1; }
    w1=$(col "$s1" wall_s); w2=$(col "$s2" wall_s)
    read -r u s e < "$work/cpu-2-$k"
    bits=no; same "$s1" "$s2" && bits=yes
    echo "$w1 $w2 $together" >> "$work/walls"
    awk -v k="$k" -v w1="$w1" -v w2="$w2" -v cpu="$u $s $e" -v n="$(col "$s1" steps)" -v bits="$bits" -v tog="$together" 'BEGIN {
        split(cpu, c, " "); split(tog, g, " ")
        at = (g[1] == "-") ? "-" : sprintf("%.2f/%.2f", g[1], g[2]); ce = (g[1] == "-") ? "-" : sprintf("%.3f", 2 * w1 / ((g[1] + g[2]) / 2))
        printf "%-5s %9.2f %9.2f %9.3f %9.0f%% %8d %9s %13s %9s\n", k, w1, w2, w1 / w2, 100 * (c[1] + c[2]) / (2 * c[3]), n, bits, at, ce }'
    [ "$bits" = yes ] || { echo "pair $k: the summaries differ beyond the timings" >&2; exit 1; }
done
python3 - "$work/walls" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
r = [float(w[0]) / float(w[1]) for w in rows]
print(f"speed-up on two threads: median {statistics.median(r):.3f} of {len(r)} pairs (min {min(r):.3f}, max {max(r):.3f})")
if all(w[2] != "-" for w in rows):
    c = [2 * float(w[0]) / ((float(w[2]) + float(w[3])) / 2) for w in rows]
    e = [a / b for a, b in zip(r, c)]
    print(f"the two cores' ceiling (two one-thread runs at once): median {statistics.median(c):.3f} (min {min(c):.3f}, max {max(c):.3f}); "
          f"speed-up / ceiling per pair: median {statistics.median(e):.3f}")
PY
echo "(runs in $work)"
