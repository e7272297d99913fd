#!/usr/bin/env bash
# demsweep's speed, one table per item of [6/6] (medians of REPEATS runs, default 3):
#   1. the kernel: `demsweep bench` (bonded block and the impact workload, 1 and 2 threads), then
#      `demsweep bench --laws`: the block with each optional law on and off beside the simple
#      kernel (linear springs, central differences), and the bytes per element and per contact;
#      and the block on one thread at five sizes, 312 to 191 800 elements (`--size`): the cost
#      per contact-step against the problem's size, from the first level of cache to past the last;
#   2. one full-resolution penetration event (sweeps/penetration.toml, 500 ft/s, until settled,
#      one thread): steps, Δt, wall, element-steps per second, peak RSS; each run followed by two
#      at once (one per core), whose slowdown bounds any two-thread sweep's efficiency;
#   2b. one large run (the level-2 event) on one thread and on two: speed-up per pair, the cores'
#      busy share, the summaries bitwise the same, and the two cores' ceiling (two one-thread
#      runs at once) (scripts/large_run.sh; about 80 s a pair);
#   3. the parallel efficiency of a ballistic sweep from 1 to 2 threads and its parts (the
#      machine's, the scheduler's; scripts/sweep_efficiency.sh): the CI scene's sweep, REPEATS
#      pairs (about 2 minutes each); with FULL=1 also the default sweep, one pair (about 15
#      minutes on this machine: 550-610 s on one thread, 295-320 s on two);
#   4. with FULL=1: `converge --mesh 3 --case penetration --threads 1` cost per level and the
#      exponents of cost against element count N: per step (expected 1) and per simulated
#      millisecond (expected 1.5, with Δt ∝ R ∝ N^-1/2). One thread, levels one after another:
#      in parallel the finest level borrows the core the coarse ones free, and its wall_s is then
#      not one core's. Per event is printed too but is not an exponent of the kernel: the levels'
#      events end at different simulated times (level 0 scabs and runs to the time cap, the
#      others rebound);
#   5. with FULL=1 or PEERS_BENCH=1: the peers side by side (scripts/bench_peers.sh: LAMMPS 2025
#      bpm/rotational and bpm/spring, LAMMPS 2022, ESyS-Particle and YADE on the peers' beam,
#      alternating with demsweep; installs what is missing; about 5 minutes a round).
# Timings on this machine vary by ±20 % from minute to minute: compare ratios from one run.
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${REPEATS:-3}
. scripts/demsweep_bin.sh
[ -x /usr/bin/time ] || { apt-get update -qq && apt-get install -y -qq time; }
work=$(mktemp -d /tmp/demsweep-bench.XXXXXX)
col() { awk -F, -v name="$2" 'NR==1 {for (i=1;i<=NF;i++) if ($i==name) c=i} NR==2 {print $c}' "$1"; }

echo "== 1. kernel (demsweep bench --workload impact --threads 1,2 --repeats $repeats)"
"$bin" bench --workload impact --threads 1,2 --repeats "$repeats"
echo
"$bin" bench --laws --steps 300 --repeats "$((repeats > 5 ? repeats : 5))"
echo
"$bin" bench --threads 1 --repeats "$repeats" --size 20x16,40x32,120x100,240x200,480x400

echo
echo "== 2. one full-resolution penetration event at 500 ft/s, one thread, each run followed by two"
echo "      such runs at once, one per core (interleaved: what a sweep on two threads asks of the machine)"
printf '%-4s %8s %12s %9s %16s %12s %16s\n' run steps dt_s wall_s elem_steps_per_s peak_rss_mb paired_wall_s
for k in $(seq 1 "$repeats"); do
    RAYON_NUM_THREADS=1 /usr/bin/time -f '%M' -o "$work/rss-$k" "$bin" run sweeps/penetration.toml --quiet --out "$work/event-$k" > /dev/null 2>&1
    RAYON_NUM_THREADS=1 "$bin" run sweeps/penetration.toml --quiet --out "$work/pair-a-$k" > /dev/null 2>&1 &
    RAYON_NUM_THREADS=1 "$bin" run sweeps/penetration.toml --quiet --out "$work/pair-b-$k" > /dev/null 2>&1
    wait
    s="$work/event-$k/penetration/summary.csv"
    col "$s" wall_s >> "$work/alone-walls"
    for x in a b; do col "$work/pair-$x-$k/penetration/summary.csv" wall_s >> "$work/pair-walls"; done
    printf '%-4s %8s %12.4e %9.2f %16.3e %12.1f %16s\n' "$k" "$(col "$s" steps)" "$(col "$s" dt_s)" "$(col "$s" wall_s)" "$(col "$s" element_steps_per_s)" \
        "$(echo "$(cat "$work/rss-$k") / 1024" | bc -l)" "$(tail -n 2 "$work/pair-walls" | paste -sd/)"
done
python3 - "$work/alone-walls" "$work/pair-walls" <<'PY'
import statistics, sys
alone = [float(x) for x in open(sys.argv[1])]
pair = [float(x) for x in open(sys.argv[2])]
a, p = statistics.median(alone), statistics.median(pair)
print(f"alone: median {a:.2f} s of {len(alone)}; two at once: median {p:.2f} s of {len(pair)}; slowdown {p / a:.3f}")
print(f"=> ceiling the machine puts on the parallel efficiency of a two-thread sweep of such runs: {min(100.0, 100 * a / p):.0f} %")
PY

echo
echo "== 2b. one large run (the level-2 event, 54 253 elements) on one thread and on two, $repeats pairs (scripts/large_run.sh)"
DEMSWEEP_BIN="$bin" PAIRS="$repeats" bash scripts/large_run.sh

echo
echo "== 3. parallel efficiency of a ballistic sweep, 1 -> 2 threads, taken apart (scripts/sweep_efficiency.sh):"
echo "      the CI scene's sweep, $repeats pairs"
DEMSWEEP_BIN="$bin" PAIRS="$repeats" bash scripts/sweep_efficiency.sh
if [ "${FULL:-0}" = 1 ]; then
    echo
    echo "== 3b. the default ballistic sweep (500..1500 by 50, both bisections to 5 ft/s), one pair"
    DEMSWEEP_BIN="$bin" PAIRS=1 bash scripts/sweep_efficiency.sh --scene sweeps/penetration.toml
    echo
    echo "== 4. converge --mesh 3 --case penetration --threads 1 (levels one after another, one thread)"
    "$bin" converge --mesh 3 --case penetration --threads 1 --quiet --out "$work/converge" > /dev/null
    python3 - "$work/converge/penetration.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print(f"{'level':>5} {'elements':>9} {'steps':>7} {'dt_s':>11} {'sim_ms':>7} {'wall_s':>8} {'ns/element-step':>16} {'s/sim_ms':>9}")
n, per_step, per_ms, per_event = [], [], [], []
for r in rows:
    e, s, dt, w = int(r["elements"]), int(r["steps"]), float(r["dt_s"]), float(r["wall_s"])
    sim_ms = s * dt * 1e3
    print(f"{r['level']:>5} {e:>9} {s:>7} {dt:>11.4e} {sim_ms:>7.3f} {w:>8.2f} {w / (e * s) * 1e9:>16.1f} {w / sim_ms:>9.3f}")
    n.append(math.log(e)); per_step.append(math.log(w / s)); per_ms.append(math.log(w / sim_ms)); per_event.append(math.log(w))
def slope(x, y):
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)
print(f"cost per step ~ N^{slope(n, per_step):.2f} (expected 1), per simulated ms ~ N^{slope(n, per_ms):.2f} (expected 1.5);"
      f" per event ~ N^{slope(n, per_event):.2f} (events of different length: not the kernel's exponent)")
PY
fi
if [ "${FULL:-0}" = 1 ] || [ "${PEERS_BENCH:-0}" = 1 ]; then
    echo
    echo "== 5. the peers on their beam-impact workload, one core each, $repeats rounds (scripts/bench_peers.sh)"
    DEMSWEEP_BIN="$bin" REPEATS="$repeats" bash scripts/bench_peers.sh
fi
echo "(runs in $work)"
