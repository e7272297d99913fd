#!/usr/bin/env bash
# Is the penetration scene's step small enough? ([6/6]) The calibrated scene at its default step
# (safety 0.9 of the rigorous bound) and at smaller ones, on what the tool reports:
#   1. the outcome at 500 ft/s, each step at five impact speeds 0.1 ft/s apart (500 ± 0.2): the
#      spread within one step is the response's own sensitivity, against which the difference
#      between steps is judged. 500 ft/s sits near the model's hold/plug bifurcation, so each
#      step gets the number of runs that punched a plug, and the mean depth of those that held;
#   2. the outcome classification of the CI scene at every velocity of its sweep, default step
#      against a conservative one.
# Prints both tables; writes nothing into the repository. About 15 minutes on two cores (a run
# that plugs at the smallest step runs to the 40 ms cap: 90 000 steps).
#
#   SAFETIES="0.9 0.45 0.3 0.2" CONSERVATIVE=0.45 JOBS=2 [WORK=dir] scripts/timestep_study.sh
# (WORK: a folder of an earlier study; the runs it holds are not made again.)
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/demsweep_bin.sh
work=${WORK:-$(mktemp -d /tmp/demsweep-dt.XXXXXX)}
mkdir -p "$work"
export bin work
safeties=${SAFETIES:-0.9 0.45 0.3 0.2}
default=${safeties%% *}
coarse=${CONSERVATIVE:-0.45}
jobs=()
for s in $safeties; do
    for v in 499.8 499.9 500 500.1 500.2; do jobs+=("sweeps/penetration.toml $s $v full"); done
done
for s in "$default" "$coarse"; do
    for v in 500 800 1100 1500; do jobs+=("sweeps/penetration_ci.toml $s $v ci"); done
done
printf '%s\n' "${jobs[@]}" | xargs -P "${JOBS:-2}" -L 1 sh -c \
    'ls "$work/$3-$1-$2"/*/summary.csv > /dev/null 2>&1 || RAYON_NUM_THREADS=1 "$bin" run "$0" --quiet --set penetration.safety="$1" --set projectile.v0_fps="$2" --out "$work/$3-$1-$2" > /dev/null 2> "$work/$3-$1-$2.log" || { cat "$work/$3-$1-$2.log" >&2; exit 1; }'
python3 - "$work" "$default" "$coarse" $safeties <<'PY'
import csv, glob, statistics, sys
work, default, coarse, *safeties = sys.argv[1:]
speeds = ["499.8", "499.9", "500", "500.1", "500.2"]
def row(kind, s, v):
    return next(csv.DictReader(open(glob.glob(f"{work}/{kind}-{s}-{v}/*/summary.csv")[0])))
def label(r):
    return "perforated" if r["perforated"] == "true" else "scabbed" if r["scabbed"] == "true" else "held"
def plug(r):
    # A plug: a scab fragment of more than a pound (the cone the lattice punches weighs 15-30
    # lb per slice; a spalled back-face element weighs a few hundredths).
    return float(r["scab_mass_lb"]) > 1.0
print("1. full scene at 500 ft/s: depth (in) at five impact speeds 0.1 ft/s apart; * = punched a plug")
print(f"{'safety':>7} {'dt_s':>10} " + " ".join(f"{v:>8}" for v in speeds) + f" {'plugs':>6} {'held: mean':>11} {'sd':>6} {'n':>3}")
held = {}
for s in safeties:
    rows = [row("full", s, v) for v in speeds]
    cells = " ".join(f"{float(r['depth_in']):7.2f}{'*' if plug(r) else ' '}" for r in rows)
    d = [float(r["depth_in"]) for r in rows if not plug(r)]
    held[s] = d
    sd = statistics.stdev(d) if len(d) > 1 else float("nan")
    mean = statistics.mean(d) if d else float("nan")
    print(f"{s:>7} {float(rows[0]['dt_s']):10.3e} {cells} {sum(map(plug, rows)):>4}/5 {mean:11.3f} {sd:6.3f} {len(d):>3}")
fine = [x for s in safeties[1:] if float(s) < float(coarse) for x in held[s]]
for name, ref in [(f"safety {coarse}", held[coarse]), ("the steps below " + coarse + " pooled", fine)]:
    if len(ref) > 1 and len(held[default]) > 1:
        a, b = held[default], ref
        se = (statistics.variance(a) / len(a) + statistics.variance(b) / len(b)) ** 0.5
        print(f"held depth at {default} against {name}: {100 * (statistics.mean(a) / statistics.mean(b) - 1):+.1f} % (standard error {100 * se / statistics.mean(b):.1f} %)")
print()
print("2. CI scene, outcome per velocity")
print(f"{'v0_fps':>7} {'safety ' + default:>22} {'safety ' + coarse:>22}  same")
same = True
for v in ["500", "800", "1100", "1500"]:
    a, b = row("ci", default, v), row("ci", coarse, v)
    fa = f"{label(a)} {float(a['depth_in']):.2f} in"
    fb = f"{label(b)} {float(b['depth_in']):.2f} in"
    same &= label(a) == label(b)
    print(f"{v:>7} {fa:>22} {fb:>22}  {label(a) == label(b)}")
print("same classification at every velocity:", same)
PY
echo "(runs in $work)"
