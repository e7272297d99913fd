#!/usr/bin/env bash
# demsweep beside the peer DEM codes on the peers' beam-impact workload (../shared/peers: 13 565
# particles, 40 054 bonds, Δt 8.9e-8 s, 5 000 steps, one core each): LAMMPS 2025 with its BPM
# package (bpm/rotational, bpm/spring), the older Debian LAMMPS (20220106), ESyS-Particle 2.3.5
# and YADE 2023.02a. The codes alternate within each round so the machine's drift hits all
# alike. Prints ms per step, particle-steps per second, ns per bond-step (loop time / (40 054 ×
# steps)) and each peer's time over ours, medians of REPEATS rounds (default 3).
#
#   scripts/bench_peers.sh [PEERS_DIR]     (default ../shared/peers, copied to a scratch folder)
#   PEERS="bpm-rot bpm-spring"             only these peers (default: all five)
#
# Installs what it needs on first use: LAMMPS 2025 from the Python registry (lammps-bpm/run.sh:
# a venv at $LMPVENV, default ~/.cache/lmpbpm); Debian's esys-particle, lammps and yade with
# apt-get (as the peers' README says), when a peer's command is missing.
#
# Where the workloads differ (the same lattice, springs, strengths, step and step count in all):
# - demsweep: 2D discs; bonds with normal and shear (incremental, capped) springs, breaking on
#   normal force; frictional contacts with their own springs after.
# - bpm/rotational: adds bending/torsion algebra (quaternions) per bond (kb = kt = 0 here; the
#   cost is the same); 3D code run on a plane.
# - bpm/spring: central springs only, breaking on |strain| (99 % of bonds break, in compression
#   too): it does less per bond than we do.
# - LAMMPS 2022: bonds are normal springs with no shear stiffness, bonded pairs also carry a
#   granular contact, and fix bond/break rebuilds the neighbour list on every step a bond breaks.
# - ESyS-Particle: 2D rotational bonds breaking in tension, the closest model; one worker plus a
#   master process (two processes on the two cores).
# - YADE: 3D spheres confined to the plane (full 3D contact work for a 2D problem). Its script
#   imports the shared geometry as `geom`, which YADE's own module of that name shadows; the
#   scratch copy loads it by its path instead (the only change made to any peer's input).
# No I/O in any timed loop. demsweep's time is its stepping loop (summary wall_s, setup excluded),
# the peers' their own loop timers.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
peers_src=${1:-$root/../shared/peers}
repeats=${REPEATS:-3}
peers=${PEERS:-bpm-rot bpm-spring lammps2022 esys yade}
. scripts/demsweep_bin.sh
work=$(mktemp -d /tmp/demsweep-peers.XXXXXX)
cp -r "$peers_src"/. "$work/"
nbonds=40054
nsteps=5000

need_apt() { # need_apt COMMAND PACKAGE [apt options]: install PACKAGE when COMMAND is missing
    local cmd=$1 pkg=$2; shift 2
    command -v "$cmd" > /dev/null && return 0
    echo "installing $pkg (Debian) for $cmd" >&2
    { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$@" "$pkg"; } > "$work/apt-$pkg.log" 2>&1 \
        || { echo "could not install $pkg (see $work/apt-$pkg.log)" >&2; return 1; }
}
for p in $peers; do
    case $p in
        lammps2022) need_apt lmp lammps; (cd "$work/lammps" && python3 make_data.py > /dev/null) ;;
        esys) need_apt esysparticle esys-particle ;;
        yade) need_apt yade yade --no-install-recommends
              python3 - "$work/yade/beam_impact.py" <<'PY'
import sys
p = sys.argv[1]; s = open(p).read()
old = "import geom\n"
assert old in s, "the YADE script no longer imports geom as expected"
new = ("import importlib.util  # YADE's own module named geom shadows ours: load ours by its path\n"
       "_spec = importlib.util.spec_from_file_location('beam_geom', os.path.join(os.getcwd(), '..', 'common', 'geom.py'))\n"
       "geom = importlib.util.module_from_spec(_spec); _spec.loader.exec_module(geom)\n")
open(p, "w").write(s.replace(old, new, 1))
PY
              ;;
        bpm-rot|bpm-spring) ;;
        *) echo "unknown peer $p (bpm-rot bpm-spring lammps2022 esys yade)" >&2; exit 2 ;;
    esac
done

results="$work/results.txt"
: > "$results"
run_peer() { # run_peer NAME ROUND -> prints ms per step
    local p=$1 k=$2 line
    case $p in
        bpm-rot|bpm-spring)
            line=$(bash "$work/lammps-bpm/run.sh" "${p#bpm-}" 1 "$nsteps" "$p-$k" | grep '^RESULT')
            echo "$line" | awk '{for (i=1;i<=NF;i++) if ($i=="ms_per_step") print $(i+1)}' ;;
        lammps2022)
            bash "$work/lammps/run.sh" 1 "$nsteps" "r$k" > "$work/lammps-$k.log"
            awk -v n="$nsteps" '/^Loop time of/ {print $4 / n * 1e3}' "$work/lammps/runs/r$k/out.txt" ;;
        esys|yade) # the same run.sh arguments and log line in both peers' folders
            bash "$work/$p/run.sh" 1 "$nsteps" "r$k" > "$work/$p-$k.log"
            grep -o 'us_per_step=[0-9.e+-]*' "$work/$p/runs/r$k/log.txt" | awk -F= '{print $2 / 1e3}' ;;
    esac
}
for k in $(seq 1 "$repeats"); do
    for p in $peers; do
        ms=$(run_peer "$p" "$k")
        [ -n "$ms" ] || { echo "$p gave no loop time in round $k (logs in $work)" >&2; exit 1; }
        echo "$p $ms" >> "$results"
    done
    RAYON_NUM_THREADS=1 "$bin" run "$work/demsweep/beam.toml" --quiet --out "$work/ds-$k" > "$work/ds-$k.log" 2>&1
    wall=$(awk -F, 'NR==1 {for (i=1;i<=NF;i++) if ($i=="wall_s") c=i} NR==2 {print $c}' "$work/ds-$k"/*/summary.csv)
    steps=$(awk -F, 'NR==1 {for (i=1;i<=NF;i++) if ($i=="steps") c=i} NR==2 {print $c}' "$work/ds-$k"/*/summary.csv)
    echo "demsweep $(python3 -c "print(float('$wall') / float('$steps') * 1e3)")" >> "$results"
done
python3 - "$results" "$nbonds" <<'PY'
import statistics, sys
runs, order = {}, []
for line in open(sys.argv[1]):
    name, ms = line.split()
    if name not in runs:
        order.append(name)
    runs.setdefault(name, []).append(float(ms))
nb, particles = int(sys.argv[2]), 13565
ours = statistics.median(runs["demsweep"])
label = {"bpm-rot": "LAMMPS 2025 bpm/rotational", "bpm-spring": "LAMMPS 2025 bpm/spring",
         "lammps2022": "LAMMPS 2022 (Debian)", "esys": "ESyS-Particle 2.3.5", "yade": "YADE 2023.02a"}
# Each round's own ratio shares that round's spell of the machine; its median beside the ratio
# of the medians.
print(f"{'code (1 core)':<28} {'ms/step':>8} {'runs (ms/step)':>26} {'Mparticle-steps/s':>18} "
      f"{'ns/bond-step':>13} {'their/our':>10} {'per round':>10}")
for name in ["demsweep"] + [n for n in order if n != "demsweep"]:
    m = statistics.median(runs[name])
    each = ", ".join(f"{v:.3f}" for v in runs[name])
    own = statistics.median(t / o for t, o in zip(runs[name], runs["demsweep"]))
    print(f"{label.get(name, name):<28} {m:>8.3f} {each:>26} {particles / m / 1e3:>18.2f} "
          f"{m * 1e6 / nb:>13.1f} {m / ours:>9.2f}x {own:>9.2f}x")
PY
echo "(runs and logs in $work)"
