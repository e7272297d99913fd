#!/usr/bin/env bash
# Is the penetration scene's step small enough? ([6/6]) The calibrated scene at its step (safety
# 0.98 of the rigorous bound) against a conservative one (0.45), on what the tool reports:
#   1. the depth at 500 ft/s, each step at five impact speeds 0.1 ft/s apart (500 ± 0.2): the
#      spread within one step is the response's own sensitivity, against which the difference
#      between steps is judged;
#   2. the outcome classification of the CI scene at every velocity of its sweep.
# Prints both tables; writes nothing into the repository. About 5 minutes on two cores.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/demsweep_bin.sh
work=$(mktemp -d /tmp/demsweep-dt.XXXXXX)
export bin work
fine=${SAFETY:-0.98}
coarse=${CONSERVATIVE:-0.45}
jobs=()
for s in "$fine" "$coarse"; do
    for v in 499.8 499.9 500 500.1 500.2; do jobs+=("sweeps/penetration.toml $s $v full"); done
    for v in 500 800 1100 1500; do jobs+=("sweeps/penetration_ci.toml $s $v ci"); done
done
printf '%s\n' "${jobs[@]}" | xargs -P "${JOBS:-2}" -L 1 sh -c \
    'RAYON_NUM_THREADS=1 "$bin" run "$0" --quiet --set penetration.safety="$1" --set projectile.v0_fps="$2" --out "$work/$3-$1-$2" > /dev/null 2> "$work/$3-$1-$2.log" || { cat "$work/$3-$1-$2.log" >&2; exit 1; }'
python3 - "$work" "$fine" "$coarse" <<'PY'
import csv, glob, statistics, sys
work, fine, coarse = sys.argv[1:]
def row(kind, s, v):
    return next(csv.DictReader(open(glob.glob(f"{work}/{kind}-{s}-{v}/*/summary.csv")[0])))
def label(r):
    return "perforated" if r["perforated"] == "true" else "scabbed" if r["scabbed"] == "true" else "held"
print("1. full scene, depth at 500 ft/s (in), impact speed perturbed by 0.1 ft/s steps")
print(f"{'safety':>7} {'dt_s':>10} " + " ".join(f"{v:>8}" for v in ["499.8", "499.9", "500", "500.1", "500.2"]) + f" {'mean':>7} {'sd':>6} {'outcomes':>10}")
means = {}
for s in (fine, coarse):
    rows = [row("full", s, v) for v in ["499.8", "499.9", "500", "500.1", "500.2"]]
    d = [float(r["depth_in"]) for r in rows]
    means[s] = (statistics.mean(d), statistics.stdev(d))
    print(f"{s:>7} {float(rows[0]['dt_s']):10.3e} " + " ".join(f"{x:8.3f}" for x in d) + f" {means[s][0]:7.3f} {means[s][1]:6.3f} {'/'.join(sorted(set(label(r) for r in rows))):>10}")
(mf, sf), (mc, sc) = means[fine], means[coarse]
se = (sf ** 2 / 5 + sc ** 2 / 5) ** 0.5
print(f"mean depth: {mf:.3f} in at {fine}, {mc:.3f} in at {coarse}: {100 * (mf / mc - 1):+.2f} % (standard error of the difference {100 * se / mc:.2f} %)")
print(f"the 500 ft/s run alone: {100 * (float(row('full', fine, '500')['depth_in']) / float(row('full', coarse, '500')['depth_in']) - 1):+.2f} %")
print()
print("2. CI scene, outcome per velocity")
print(f"{'v0_fps':>7} {'safety ' + fine:>22} {'safety ' + coarse:>22}  same")
same = True
for v in ["500", "800", "1100", "1500"]:
    a, b = row("ci", fine, v), row("ci", coarse, v)
    fa = f"{label(a)} {float(a['depth_in']):.2f} in"
    fb = f"{label(b)} {float(b['depth_in']):.2f} in"
    same &= label(a) == label(b)
    print(f"{v:>7} {fa:>22} {fb:>22}  {label(a) == label(b)}")
print("same classification at every velocity:", same)
PY
