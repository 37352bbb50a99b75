#!/usr/bin/env bash
# The batch on a real Slurm (docs/cluster.md, "Slurm"): starts a one-node Slurm of the Debian
# packages (munge, slurmctld, slurmd; as root, without systemd, everything under one temporary
# folder), submits the job-array script of docs/cluster.md as 4 tasks over the examples, and checks
# the merged outputs are byte-identical to one batch on this machine; then kills one task of a
# longer array in the middle, submits that task again, and checks that nothing is lost, left over
# or converted twice. It stops the daemons it started, by their process ids, also on failure.
# Every wait is bounded. Usage: slurm_test.sh FAPC SOURCE_DIR
set -euo pipefail
fapc=$(realpath "$1")
source_dir=$(realpath "$2")
fail() { echo "slurm test: $*" >&2; exit 1; }
[ "$(id -u)" = 0 ] || fail "needs root (slurmd runs jobs as their users)"
for program in munged slurmctld slurmd sbatch squeue scontrol scancel python3; do
  command -v "$program" > /dev/null || fail "$program is missing: apt-get install slurm-wlm munge (README command 2)"
done

tmp=$(mktemp -d /tmp/fapc-slurm-XXXXXX)
started_munged=""
stop_daemons() {
  local status=$?
  # Tasks still queued or running (a failure midway) go before the daemons that run them.
  [ -s "$tmp/slurmctld.pid" ] && timeout 20 scancel --quiet --user=root 2> /dev/null && sleep 1 || true
  for pid_file in "$tmp/slurmd.pid" "$tmp/slurmctld.pid"; do
    pid=$(cat "$pid_file" 2> /dev/null) && [ -n "$pid" ] && kill "$pid" 2> /dev/null || true
  done
  [ -n "$started_munged" ] && kill "$started_munged" 2> /dev/null || true
  # The daemons go within a few seconds; their folder goes after them.
  for _ in $(seq 50); do
    alive=0
    for pid_file in "$tmp/slurmd.pid" "$tmp/slurmctld.pid"; do
      # (a daemon removes its pid file as it ends: the file may go between the test and the read)
      pid=$(cat "$pid_file" 2> /dev/null) && [ -n "$pid" ] && kill -0 "$pid" 2> /dev/null && alive=1
    done
    [ "$alive" = 0 ] && break
    sleep 0.2
  done
  if [ "$status" != 0 ]; then
    echo "--- slurmctld.log" >&2; tail -n 30 "$tmp/slurmctld.log" >&2 2> /dev/null || true
    echo "--- slurmd.log" >&2; tail -n 30 "$tmp/slurmd.log" >&2 2> /dev/null || true
  fi
  rm -rf "$tmp"
  exit "$status"
}
trap stop_daemons EXIT
trap 'exit 1' INT TERM

# munge: the package's key; a munged already running is used and left alone.
if ! munge -n 2> /dev/null | unmunge > /dev/null 2>&1; then
  mkdir -p /run/munge /var/log/munge /var/lib/munge
  chown munge:munge /run/munge /var/log/munge /var/lib/munge
  chmod 0755 /run/munge
  rm -f /run/munge/munged.pid  # a stale one would be taken for the new daemon's
  su -s /bin/sh munge -c "/usr/sbin/munged --force"
  for _ in $(seq 50); do [ -s /run/munge/munged.pid ] && break; sleep 0.1; done
  started_munged=$(cat /run/munge/munged.pid)
  munge -n | unmunge | grep -q "STATUS: *Success" || fail "munge does not work"
fi

# Two free ports, one node of this machine's cores and most of its memory.
free_port() {
  local port
  for _ in $(seq 100); do
    port=$((20000 + RANDOM % 20000))
    ss -ltn | awk '{print $4}' | grep -q ":$port\$" || { echo "$port"; return; }
  done
  fail "no free port"
}
ctld_port=$(free_port)
slurmd_port=$(free_port)
[ "$ctld_port" != "$slurmd_port" ] || slurmd_port=$((ctld_port + 1))
host=$(hostname -s)
cpus=$(nproc)
memory=$(( $(awk '/MemTotal/ {print int($2 / 1024)}' /proc/meminfo) * 8 / 10 ))
mkdir -p "$tmp/state" "$tmp/spool"
export SLURM_CONF="$tmp/slurm.conf"
cat > "$SLURM_CONF" << CONF
ClusterName=fapctest
SlurmctldHost=$host
SlurmUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SwitchType=switch/none
MpiDefault=none
ReturnToService=2
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
NodeName=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=batch Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for _ in $(seq 60); do
  sinfo -h -o %T 2> /dev/null | grep -q '^idle' && break
  sleep 0.5
done
sinfo -h -o %T | grep -q '^idle' || fail "the node did not come up"

# Waits (at most $2 seconds) until job $1 has left the queue.
wait_for_job() {
  for _ in $(seq $(($2 * 2))); do
    [ -z "$(squeue -h -j "$1" 2> /dev/null)" ] && return 0
    sleep 0.5
  done
  scancel "$1" 2> /dev/null || true
  fail "job $1 still queued or running after $2 s"
}
# The job-array script, exactly as docs/cluster.md shows it.
awk '/^#!\/bin\/sh$/ && seen {inside=1} /<!-- slurm-script -->/ {seen=1} inside {print} inside && /^```$/ {exit}' \
  "$source_dir/docs/cluster.md" | sed '$d' > "$tmp/fapc-array.sbatch"
grep -q '^fapc batch' "$tmp/fapc-array.sbatch" || fail "no job-array script in docs/cluster.md"
export PATH="$(dirname "$fapc"):$PATH"  # the tasks inherit the submitter's environment
# Submits the script from folder $1 (extra sbatch options after it); prints the job id.
submit() {
  local folder=$1
  shift
  (cd "$folder" && sbatch --parsable --cpus-per-task=1 "$@" "$tmp/fapc-array.sbatch") | cut -d';' -f1
}
same_outputs() {  # the outputs of folders $1 and $2, completion records left out
  diff -r -x .fapc-batch "$1" "$2" > /dev/null || fail "outputs of $1 and $2 differ: $(diff -rq -x .fapc-batch "$1" "$2" | head -5)"
}

# 1. Four tasks over the examples give the outputs of one batch.
mkdir -p "$tmp/one" "$tmp/array"
for folder in one array; do ln -s "$source_dir/corpus/examples" "$tmp/$folder/corpus"; done
(cd "$tmp/one" && sed -n 's/^fapc batch \(.*\) --shards [0-9]* .*/\1/p' "$tmp/fapc-array.sbatch" |
   xargs "$fapc" batch > /dev/null) || fail "the one-machine batch failed"
job=$(submit "$tmp/array")
wait_for_job "$job" 240
for task in 0 1 2 3; do
  [ -s "$tmp/array/reports/shard-$task.json" ] || fail "task $task wrote no report: $(cat "$tmp"/array/fapc-*_"$task".out 2>&1)"
done
(cd "$tmp/array" && "$fapc" batch-report merge reports/shard-*.json > merge.txt) ||
  fail "the merged reports name missing work: $(cat "$tmp/array/merge.txt")"
same_outputs "$tmp/one/out" "$tmp/array/out"  # talk included (docs/cluster.md, "Speech")
echo "slurm test: 4 array tasks = one batch ($(grep -c . "$tmp/array/merge.txt") lines of merge: $(tail -1 "$tmp/array/merge.txt"))"

# 2. A task killed in the middle and submitted again: nothing lost, nothing twice, nothing left over.
mkdir -p "$tmp/long/corpus" "$tmp/long-one/corpus"
for folder in long long-one; do
  cp "$source_dir/corpus/examples/mimic/smile.xpr" "$tmp/$folder/corpus/"
  for i in $(seq 100 299); do cp "$source_dir/corpus/examples/mimic/figure3.mimic" "$tmp/$folder/corpus/s$i.mimic"; done
done
(cd "$tmp/long-one" && sed -n 's/^fapc batch \(.*\) --shards [0-9]* .*/\1/p' "$tmp/fapc-array.sbatch" |
   xargs "$fapc" batch > /dev/null) || fail "the one-machine batch of the long corpus failed"
job=$(submit "$tmp/long")
# Task 2's jobs, from the report it writes as it starts; kill it once it has finished some.
records_of_task2() {
  python3 - "$tmp/long" << 'PY'
import json, os, sys
folder = sys.argv[1]
report = json.load(open(os.path.join(folder, "reports/shard-2.json")))
# A job's completion record: out/.fapc-batch/<its first output, relative to out>.done
done = sum(os.path.exists(os.path.join(folder, "out/.fapc-batch", os.path.relpath(job["outputs"][0], "out") + ".done"))
           for job in report["jobs"])
print(done, len(report["jobs"]))
PY
}
killed=""
for _ in $(seq 600); do
  if [ -s "$tmp/long/reports/shard-2.json" ]; then
    read -r done_count total < <(records_of_task2)
    if [ "$done_count" -ge 3 ]; then
      scancel --signal=KILL "${job}_2"
      killed="$done_count of $total"
      break
    fi
  fi
  sleep 0.2
done
[ -n "$killed" ] || fail "task 2 never got going"
wait_for_job "$job" 300
read -r before total < <(records_of_task2)
[ "$before" -lt "$total" ] || fail "task 2 finished before it was killed ($killed): make the corpus longer"
if (cd "$tmp/long" && "$fapc" batch-report merge reports/shard-*.json > merge.txt); then
  fail "the merge did not see task 2's missing work"
fi
grep -q "^no result: " "$tmp/long/merge.txt" || fail "the merge names no job without result: $(cat "$tmp/long/merge.txt")"
job=$(submit "$tmp/long" --array=2)
wait_for_job "$job" 240
(cd "$tmp/long" && "$fapc" batch-report merge reports/shard-*.json --report-json merged.json > merge.txt) ||
  fail "work is still missing after task 2 ran again: $(cat "$tmp/long/merge.txt")"
python3 - "$tmp/long/reports/shard-2.json" "$before" << 'PY' || fail "task 2 converted finished jobs again"
import json, sys
report = json.load(open(sys.argv[1]))
totals = report["totals"]
# What was finished before the kill is up to date now; the rest converted, each once.
assert totals["up_to_date"] >= int(sys.argv[2]), totals
assert totals["up_to_date"] + totals["converted"] == totals["jobs"], totals
PY
[ -z "$(find "$tmp/long/out" -name '.fapc-tmp-*')" ] || fail "temporary files left over"
same_outputs "$tmp/long-one/out" "$tmp/long/out"
echo "slurm test: task 2 killed after $killed jobs, submitted again: $(tail -1 "$tmp/long/merge.txt")"
