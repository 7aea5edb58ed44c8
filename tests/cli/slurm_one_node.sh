#!/usr/bin/env bash
# `granlub slurm CASE --submit` under a real Slurm (issue 76): a one-node cluster of Debian's
# slurm-wlm and munge started here in a temporary folder (its own munge socket and key, its own
# ports, nothing of /etc/slurm), the job arrays of a tiny two-point DEM and warm-started YADE case
# submitted, waited for (at most 400 s), and their results and report checked. The daemons are
# stopped on every way out (the EXIT trap; they are this script's children, not forked away).
# Exit 77 (ctest: skipped) when no Slurm can be started here, saying why.
# Usage: slurm_one_node.sh GRANLUB PRINT_TINY_CELL
#
# What a one-node Slurm needs, measured on Debian 12 (Slurm 22.05, munge 0.5.15) on 2026-12-06:
# munged in the foreground with --force (as root it only warns) on its own socket and key;
# slurmctld -D and slurmd -D with one slurm.conf (SLURM_CONF for the clients); the node is `idle`
# in `sinfo` a few seconds after. Tasks of an array run two at a time on 2 cores.
set -uo pipefail
granlub=$(realpath "${1:?usage: slurm_one_node.sh GRANLUB PRINT_TINY_CELL}")
print_tiny_cell=$(realpath "${2:?usage: slurm_one_node.sh GRANLUB PRINT_TINY_CELL}")

skip() { echo "SKIP: $*"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "not root: slurmd must run as root to start jobs (run the suite as root to test the cluster route)"
missing=()
for c in munged mungekey slurmctld slurmd sbatch squeue sinfo scancel; do
  command -v "$c" >/dev/null 2>&1 || missing+=("$c")
done
[ ${#missing[@]} -eq 0 ] || skip "not installed: ${missing[*]} (apt-get install -y --no-install-recommends slurm-wlm munge; .ci/setup installs them)"

tmp=$(mktemp -d /tmp/granlub_slurm.XXXXXX)
pids=()
cleanup() {
  trap - EXIT INT TERM HUP
  if [ -n "${SLURM_CONF:-}" ]; then
    scancel --quiet --user="$(id -un)" >/dev/null 2>&1
    # the steps end and say so to slurmctld first (a step outliving slurmctld would retry for ever)
    for _ in $(seq 20); do q=$(squeue -h -o %i 2>/dev/null) && [ -z "$q" ] && break; sleep 0.5; done
  fi
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  for p in "${pids[@]}"; do
    for _ in $(seq 20); do kill -0 "$p" 2>/dev/null || break; sleep 0.5; done
    kill -9 "$p" 2>/dev/null
    wait "$p" 2>/dev/null
  done
  # what the daemons forked away (slurmstepd, a task's granlub): every process left working in this
  # test's own folder (the jobs start there)
  cd /
  for d in /proc/[0-9]*; do
    case "$(readlink "$d/cwd" 2>/dev/null)" in
      "$tmp" | "$tmp"/*) [ "${d#/proc/}" != $$ ] && kill -9 "${d#/proc/}" 2>/dev/null ;;
    esac
  done
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP
fail() {
  echo "FAIL: $*"
  for f in "$tmp"/*.log "$tmp"/case/results/slurm/logs/* "$tmp"/submit.out; do
    [ -f "$f" ] && { echo "---- $f"; tail -n 30 "$f"; }
  done
  exit 1
}

# --- munge: its own key and socket (a system munged, if any, is left alone)
chmod 700 "$tmp"
mungekey --create --keyfile="$tmp/munge.key" || fail "mungekey"
munged -F --force --socket="$tmp/munge.sock" --key-file="$tmp/munge.key" --log-file="$tmp/munged.log" \
  --pid-file="$tmp/munged.pid" --seed-file="$tmp/munged.seed" >"$tmp/munged.out" 2>&1 &
pids+=($!)

# --- slurm.conf: one node, this machine, its cores; ports off Slurm's defaults (6817, 6818)
host=$(hostname -s)
mkdir -p "$tmp/ctld" "$tmp/d"
cat >"$tmp/slurm.conf" <<EOF
ClusterName=granlubtest
SlurmctldHost=$host
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$tmp/munge.sock
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
StateSaveLocation=$tmp/ctld
SlurmdSpoolDir=$tmp/d
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
SlurmUser=root
ReturnToService=2
MpiDefault=none
NodeName=$host CPUs=$(nproc) RealMemory=2000 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$tmp/slurm.conf"
for _ in $(seq 50); do [ -S "$tmp/munge.sock" ] && break; sleep 0.2; done
[ -S "$tmp/munge.sock" ] || fail "munged did not start"
slurmctld -D -f "$SLURM_CONF" >"$tmp/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$tmp/slurmd.out" 2>&1 &
pids+=($!)
idle=""
for _ in $(seq 60); do
  idle=$(sinfo -h -o %t 2>/dev/null)
  [ "$idle" = idle ] && break
  sleep 0.5
done
[ "$idle" = idle ] || fail "the node is not idle 30 s after the daemons started (sinfo: '$idle')"

# --- the case: the small shear cell of the particle tests (tests/liggghts/tiny_cell_text.h), two
# speeds, DEM for 0.02 s and YADE warm-started from it for 0.004 s: seconds a task
mkdir -p "$tmp/case"
"$print_tiny_cell" tiny_slurm "" $'time = 0.02\nsample_every = 20\n' $'[yade]\nstart = "warm"\ntime = 0.004\n' |
  sed 's/^speed = \[1\.0\]$/speed = [1.0, 2.0]/' >"$tmp/case/case.toml" || fail "could not write the case"
grep -q '^speed = \[1.0, 2.0\]$' "$tmp/case/case.toml" || fail "the tiny cell has no speed = [1.0] line to widen"

results="$tmp/case/results"
cd "$tmp"  # the jobs start in the folder they were submitted from
"$granlub" slurm "$tmp/case" --solvers dem,yade --time 10 --submit >"$tmp/submit.out" 2>&1 ||
  fail "granlub slurm --submit exited $?"
cat "$tmp/submit.out"
for job in dem yade compare; do
  grep -Eq "^$job [0-9]+$" "$tmp/submit.out" || fail "no '$job <job id>' line from the submission"
done
grep -q -- "--dependency=aftercorr:\$dem" "$results/slurm/submit.sh" || fail "yade's array does not wait for dem's"

# --- wait until the queue is empty (every task and the compare job have ended)
t0=$SECONDS
while :; do
  [ $((SECONDS - t0)) -lt 400 ] || fail "jobs still queued or running after 400 s: $(squeue -h)"
  if queued=$(squeue -h -o %i 2>/dev/null) && [ -z "$queued" ]; then break; fi  # squeue failing is not empty
  sleep 2
done
echo "the jobs ended $((SECONDS - t0)) s after submission"

# --- what they left: each point of each engine complete, YADE's from DEM's final state, the report
for solver in dem yade; do
  for point in U1.0 U2.0; do
    s="$results/$solver/$point/summary.json"
    [ -f "$s" ] || fail "no $s"
  done
  n=$(ls "$results/slurm/logs/$solver"-*.out 2>/dev/null | wc -l)
  [ "$n" -eq 2 ] || fail "$n logs of the $solver array in $results/slurm/logs, not one a task"
done
for point in U1.0 U2.0; do
  grep -q 'warm, from granlub dem' "$results/yade/$point/summary.json" ||
    fail "yade $point did not start from dem's final state"
done
[ -f "$results/report/index.html" ] || fail "no report: $results/report/index.html"
ls "$results/slurm/logs/compare-"*.out >/dev/null 2>&1 || fail "no log of the compare job"
echo "PASS: 2 dem and 2 yade tasks, then compare, under Slurm"
