#!/usr/bin/env bash
# Slurm end to end on this one machine: install Debian's slurm-wlm (slurmctld + slurmd + munge)
# if missing, start a one-node cluster, submit a small ballistic sweep as a job array of two
# shards plus a merge job that waits for both (afterok) and bisects, then check the merged tables
# equal a local unsharded run's (timing columns aside). Needs root (it installs and starts
# daemons). The sbatch lines are the ones the README shows.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
. scripts/demsweep_bin.sh
if ! command -v sbatch >/dev/null || ! command -v munged >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurm-wlm munge >/dev/null
fi
host=$(hostname -s)
cpus=$(nproc)
# munge: a key, and the daemon (it refuses to run as root without --force).
mkdir -p /etc/munge /var/lib/munge /var/log/munge /run/munge
[ -s /etc/munge/munge.key ] || dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none
chown -R munge: /etc/munge /var/lib/munge /var/log/munge /run/munge
chmod 400 /etc/munge/munge.key
pgrep -x munged >/dev/null || runuser -u munge -- /usr/sbin/munged
# A one-node cluster, no accounting, no cgroups.
conf=/etc/slurm/slurm.conf
mkdir -p /etc/slurm /var/spool/slurmctld /var/spool/slurmd /var/log/slurm
cat > "$conf" <<CONF
ClusterName=demsweep
SlurmctldHost=$host
SlurmUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
# Slurm 22.05 has no "disabled" cgroup plugin; without a cgroup.conf it autodetects (v1 here) and
# only uses it for what the plugins above ask: nothing.
rm -f /etc/slurm/cgroup.conf
pgrep -x slurmctld >/dev/null || slurmctld -c
pgrep -x slurmd >/dev/null || slurmd
for _ in $(seq 1 30); do sinfo -h -o %T 2>/dev/null | grep -q idle && break; sleep 1; done
sinfo
work=$(mktemp -d /tmp/demsweep-slurm.XXXXXX)
sweep=(ballistic --scene "$root/tests/data/tiny_beam.toml" --v0 300..900 --step 100 --tol-fps 5 --quiet --threads 1)
# The README's lines: an array of shards, then the merge with the bisection once all succeed.
array=$(sbatch --parsable --array=1-2 --chdir="$work" --output="$work/shard-%a.log" \
    --wrap "$bin ${sweep[*]} --shard \$SLURM_ARRAY_TASK_ID/\$SLURM_ARRAY_TASK_COUNT --out $work/shard\$SLURM_ARRAY_TASK_ID")
merge=$(sbatch --parsable --dependency=afterok:"$array" --chdir="$work" --output="$work/merge.log" \
    --wrap "$bin merge $work/shard1 $work/shard2 --out $work/merged --bisect --quiet --threads 1")
echo "submitted array $array (2 shards) and merge $merge"
for _ in $(seq 1 600); do
    [ -z "$(squeue -h -j "$array,$merge" 2>/dev/null)" ] && break
    sleep 1
done
sacct_state() { scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z]*' | head -1; }
echo "array: $(sacct_state "$array"), merge: $(sacct_state "$merge")"
cat "$work"/shard-*.log "$work/merge.log"
"$bin" "${sweep[@]}" --out "$work/local"
python3 - "$work/merged" "$work/local" <<'PY'
import csv, sys
timing = {"wall_s", "element_steps_per_s"}
def untimed(path):
    rows = list(csv.reader(open(path)))
    keep = [k for k, h in enumerate(rows[0]) if h not in timing]
    return [[r[k] for k in keep] for r in rows]
a, b = sys.argv[1], sys.argv[2]
runs_equal = untimed(f"{a}/runs.csv") == untimed(f"{b}/runs.csv")
thr_equal = open(f"{a}/thresholds.csv").read() == open(f"{b}/thresholds.csv").read()
n = len(untimed(f"{a}/runs.csv")) - 1
print(f"merged vs local: runs.csv {'equal' if runs_equal else 'DIFFERENT'} ({n} runs), thresholds.csv {'equal' if thr_equal else 'DIFFERENT'}")
sys.exit(0 if runs_equal and thr_equal else 1)
PY
echo "slurm check passed ($work)"
