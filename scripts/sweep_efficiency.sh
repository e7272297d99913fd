#!/usr/bin/env bash
# The parallel efficiency of a ballistic sweep from 1 to 2 threads, E = T1 / (2 T2), measured on
# PAIRS pairs of sweeps (one thread, then two, alternating, so that the machine's spells hit both
# alike; default 3), and taken apart into what the machine and what the scheduler cost:
#
#   E = (T1 / S1) · (S1 / S2) · (S2 / 2 T2)
#
# with S1, S2 the sums of the runs' own wall times (runs.csv, wall_s) in each sweep:
#   T1 / S1   the one-thread sweep's time over its runs' (set-up, tables, plot: ≥ 1);
#   S1 / S2   1 / the slowdown of a run when two run at once (memory, caches: the machine's);
#   S2 / 2T2  the share of the two cores' time that runs occupy in the two-thread sweep (the
#             scheduler's: tails of the grid, uneven bisections, serial work). A run that
#             borrows the spare core (`sweep::share`) counts once, so this share is a lower
#             bound on the cores' use.
# Each factor is measured within one sweep or one pair, so the spells cancel in it.
#
#   scripts/sweep_efficiency.sh [BALLISTIC ARGS...]   (default: the CI scene's sweep, as
#                                                     scripts/thresholds_ci.sh runs it)
set -euo pipefail
cd "$(dirname "$0")/.."
pairs=${PAIRS:-3}
. scripts/demsweep_bin.sh
if [ $# -eq 0 ]; then
    set -- --scene sweeps/penetration_ci.toml --v0 300..900 --step 100 --tol-fps 12.5
fi
work=$(mktemp -d /tmp/demsweep-sweep-eff.XXXXXX)
: > "$work/walls"
for k in $(seq 1 "$pairs"); do
    for t in 1 2; do
        start=$(date +%s.%N)
        "$bin" ballistic "$@" --threads "$t" --quiet --out "$work/p$k-t$t" > /dev/null
        end=$(date +%s.%N)
        echo "$k $t $(echo "$end - $start" | bc -l) $work/p$k-t$t/runs.csv" >> "$work/walls"
    done
done
python3 - "$work/walls" <<'PY'
import csv, statistics, sys
pairs = {}
for line in open(sys.argv[1]):
    k, t, wall, runs = line.split()
    rows = list(csv.DictReader(open(runs)))
    pairs.setdefault(k, {})[int(t)] = (float(wall), sum(float(r["wall_s"]) for r in rows), len(rows))
print(f"{'pair':>4} {'runs':>5} {'T1_s':>8} {'T2_s':>8} {'speedup':>8} {'E_%':>6} {'T1/S1':>7} {'S1/S2':>7} {'S2/2T2':>7}")
cols = []
for k, p in sorted(pairs.items()):
    (t1, s1, n), (t2, s2, _) = p[1], p[2]
    c = (t1 / t2, 100 * t1 / (2 * t2), t1 / s1, s1 / s2, s2 / (2 * t2))
    cols.append(c)
    print(f"{k:>4} {n:>5} {t1:>8.1f} {t2:>8.1f} {c[0]:>8.3f} {c[1]:>6.1f} {c[2]:>7.3f} {c[3]:>7.3f} {c[4]:>7.3f}")
med = [statistics.median(c[i] for c in cols) for i in range(5)]
print(f"{'med':>4} {'':>5} {'':>8} {'':>8} {med[0]:>8.3f} {med[1]:>6.1f} {med[2]:>7.3f} {med[3]:>7.3f} {med[4]:>7.3f}")
print(f"=> efficiency 1 -> 2 threads {med[1]:.1f} % (median of {len(cols)} pairs): the cores busy with runs "
      f"{100 * med[4]:.1f} % of the two-thread sweep (the scheduler's part), a run {1 / med[3]:.3f}x slower two at a time "
      f"(the machine's part), the one-thread sweep {med[2]:.3f}x its runs' time")
PY
echo "(sweeps in $work)"
