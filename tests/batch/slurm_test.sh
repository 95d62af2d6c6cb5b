#!/usr/bin/env bash
# The Slurm back-end against a real single-node Slurm (tools/slurm-local: munged, slurmctld and
# slurmd on 127.0.0.1, started here and stopped by their PIDs at the end):
#   - the 18-run sweep through `--backend slurm` gives the local run's results.csv (wall_time aside),
#     into an --out with a space and '%' (the task logs land in OUT/slurm/logs)
#   - --no-wait, one pending task cancelled (scancel JOB_5): --collect names it in error rows,
#     --resume (with --isolate, which the task honours) submits exactly those runs and the
#     results.csv equals the local one; while the job
#     runs, a new submission or a local batch into the same --out is refused
#   - a running task cancelled: its unfinished runs are error rows saying CANCELLED, the finished
#     one is kept
#   - Ctrl-C while waiting cancels the job (exit 130)
#   - no sbatch on PATH, a rejected submission (a bad --partition), a '\' in --out: one line,
#     exit 2, no --out
# Skips (exit 77) where Slurm cannot start: not root, the packages missing (tools/setup --slurm), a
# port taken between choosing it and starting, the machine's name not on loopback. Its ports are
# chosen free for each run, so that two runs at once do not collide.
# usage: slurm_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$(realpath "$1")
src=$(realpath "$2")
work=$(mktemp -d)
cluster=$work/cluster
# Ports of its own, free now (the system picks them): a tools/slurm-local started by hand (16817),
# or another run of this test, may be running beside it.
read -r ctld_port slurmd_port < <(python3 -c "
import socket
held = [socket.socket() for _ in range(2)]
for s in held: s.bind(('127.0.0.1', 0))
print(*(s.getsockname()[1] for s in held))")
export SIGNALSIM_SLURM_PORT=$ctld_port SIGNALSIM_SLURMD_PORT=$slurmd_port
cleanup() {
  "$src/tools/slurm-local" stop "$cluster" > /dev/null 2>&1
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }
sweep=$src/tests/batch/data/sweep_3x3x2.yaml

"$src/tools/slurm-local" start "$cluster" > "$work/start.log" 2>&1
code=$?
if [ $code -eq 3 ]; then
  echo "skipped: Slurm cannot start here: $(cat "$work/start.log")"
  exit 77
fi
[ $code -eq 0 ] || fail "tools/slurm-local start: exit code $code: $(cat "$work/start.log")"
export SLURM_CONF=$cluster/slurm.conf
daemons=$(cat "$cluster"/munged.pid "$cluster"/slurmctld.pid "$cluster"/slurmd.pid | tr '\n' ' ')
echo "ok   single-node Slurm up (PIDs $daemons, ports $ctld_port and $slurmd_port)"
cd "$work" || exit 1

strip() { python3 -c "
import csv, sys
for r in csv.reader(open(sys.argv[1])):
    print(','.join(r[:-2] + r[-1:]))" "$1"; }
same_as_local() {
  cmp -s <(strip "$work/local/results.csv") <(strip "$1/results.csv") || {
    diff <(strip "$work/local/results.csv") <(strip "$1/results.csv") | head -20
    fail "$2: results.csv differs from the local run's"
  }
}
job_of() { python3 -c "import json, sys; print(json.load(open(sys.argv[1] + '/slurm/job.json'))['job'])" "$1"; }
active_tasks() { squeue --noheader --jobs="$1" --format=%T 2> /dev/null | grep -cE 'PENDING|RUNNING|COMPLETING|CONFIGURING'; }

"$bin" sweep "$sweep" --out "$work/local" --jobs 2 --quiet || fail "the local sweep: exit code $?"

# 1. The whole sweep through Slurm: 5 tasks of up to 4 runs, into an --out with a space and a '%j'
#    (sbatch's --output is a filename pattern: the path's '%' must not be one).
s1="$work/s 1%j"
"$bin" sweep "$sweep" --backend slurm --chunk 4 --out "$s1" > "$work/s1.log" 2>&1 ||
  fail "--backend slurm: exit code $? ($(tail -3 "$work/s1.log"))"
grep -q "^submitted Slurm job [0-9]*: 18 runs in 5 array tasks of up to 4, 1 CPU each" "$work/s1.log" ||
  fail "submission line: $(head -1 "$work/s1.log")"
grep -q "^18 runs: 18 passed, 0 failed, 0 without expectations, 0 errors" "$work/s1.log" ||
  fail "summary line: $(tail -1 "$work/s1.log")"
same_as_local "$s1" "--backend slurm"
[ "$(ls "$s1"/runs/*/row.csv | wc -l)" -eq 18 ] || fail "not every run directory has its row.csv"
s1job=$(job_of "$s1")
[ "$(ls "$s1"/slurm/logs/task-"${s1job}"_*.log | wc -l)" -eq 5 ] || fail "the task logs are not in $s1/slurm/logs"
echo "ok   18 runs through Slurm into an --out with ' ' and '%': results.csv == the local run's, logs in place"

# 2. --no-wait; task 5 (runs 15-17) cancelled while pending; --collect; --resume.
"$bin" sweep "$sweep" --backend slurm --chunk 3 --max-parallel 1 --no-wait --out "$work/nw" > "$work/nw.log" 2>&1 ||
  fail "--no-wait: exit code $? ($(cat "$work/nw.log"))"
job=$(job_of "$work/nw")
scancel "${job}_5" || fail "scancel ${job}_5"
grep -q "^submitted Slurm job $job: 18 runs in 6 array tasks of up to 3, 1 CPU each, at most 1 at a time" "$work/nw.log" ||
  fail "--no-wait output: $(cat "$work/nw.log")"
[ "$(wc -l < "$work/nw/results.csv")" -eq 1 ] || fail "--no-wait merged rows already"
# While the job runs (6 tasks one at a time: seconds), its --out is not another batch's.
"$bin" sweep "$sweep" --backend slurm --out "$work/nw" > /dev/null 2> "$work/again.err"
code=$?
[ $code -eq 2 ] && grep -q "Slurm job $job still has .* writing there" "$work/again.err" ||
  fail "a second submission into a running job's --out: exit code $code, $(cat "$work/again.err")"
"$bin" sweep "$sweep" --out "$work/nw" > /dev/null 2> "$work/local_again.err"
code=$?
[ $code -eq 2 ] && grep -q "Slurm job $job still has" "$work/local_again.err" ||
  fail "a local batch into a running job's --out: exit code $code, $(cat "$work/local_again.err")"
echo "ok   --no-wait submitted job $job; its --out is refused to others while it runs"

"$bin" sweep "$sweep" --out "$work/nw" --collect > "$work/collect.log" 2>&1
code=$?
[ $code -eq 4 ] || fail "--collect after a cancelled task: exit code $code, not 4 ($(tail -3 "$work/collect.log"))"
python3 - "$work/nw/results.csv" "${job}_5" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [r["run"] for r in rows] == [str(i) for i in range(18)], [r["run"] for r in rows]
for r in rows[:15]:
    assert r["status"] == "passed", r
for r in rows[15:]:
    assert r["status"] == "error", r
    assert r["error"].startswith("Slurm task %s ended without a row for this run" % sys.argv[2]), r["error"]
print("ok   --collect: 15 runs merged, the 3 of the cancelled pending task are error rows naming it")
PY
active=$(active_tasks "$job")
[ "$active" -eq 0 ] || fail "--collect returned with $active tasks of job $job still active"

"$bin" sweep "$sweep" --backend slurm --out "$work/nw" --resume --isolate > "$work/resume.log" 2>&1 ||
  fail "--resume: exit code $? ($(tail -3 "$work/resume.log"))"
grep -q "^resuming: 15 of 18 runs already done, 3 to run" "$work/resume.log" || fail "resume: $(head -1 "$work/resume.log")"
grep -q "^submitted Slurm job [0-9]*: 3 runs in 1 array task" "$work/resume.log" || fail "resume: $(sed -n 2p "$work/resume.log")"
same_as_local "$work/nw" "--resume after a cancelled task"
rjob=$(job_of "$work/nw")
grep -q "^chunk 0: 3 runs (0 already done), 1 at a time, one process per run (--isolate)" "$work/nw/slurm/logs/task-${rjob}_0.log" ||
  fail "--isolate did not reach the task: $(head -1 "$work/nw/slurm/logs/task-${rjob}_0.log")"
echo "ok   --resume --isolate submitted exactly the 3 lost runs, one process each: results.csv == the local run's"

# 3. A running task cancelled: sweep_slow's runs 1 and 2 take about a second each; the task is
#    cancelled once run 0's row is there.
slow=$src/tests/batch/data/sweep_slow.yaml
"$bin" sweep "$slow" --backend slurm --chunk 5 --no-wait --out "$work/slow" > "$work/slow.log" 2>&1 ||
  fail "sweep_slow --no-wait: exit code $? ($(cat "$work/slow.log"))"
sjob=$(job_of "$work/slow")
# scancel signals every process of the task (proctrack/linuxproc): run-chunk and its worker, in
# either order; the run the worker was doing must end without a row, not as an "interrupted" error.
for i in $(seq 1 2400); do
  ls "$work"/slow/runs/0000-*/row.csv > /dev/null 2>&1 && break
  sleep 0.05
done
ls "$work"/slow/runs/0000-*/row.csv > /dev/null 2>&1 || fail "run 0 of job $sjob left no row.csv in 2 minutes"
scancel "$sjob" || fail "scancel $sjob"
"$bin" sweep "$slow" --out "$work/slow" --collect > "$work/slow_collect.log" 2>&1
code=$?
[ $code -eq 4 ] || fail "--collect after scancel of a running task: exit code $code ($(tail -3 "$work/slow_collect.log"))"
python3 - "$work/slow/results.csv" "${sjob}_0" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert rows[0]["status"] != "error", rows[0]
lost = [r for r in rows if r["status"] == "error"]
assert [r["run"] for r in lost] == ["1", "2", "3", "4"], [(r["run"], r["status"]) for r in rows]
for r in lost:
    assert r["error"].startswith("Slurm task %s ended CANCELLED before this run finished" % sys.argv[2]), r["error"]
print("ok   a running task cancelled: its finished run kept, the others error rows saying CANCELLED")
PY

# 4. Ctrl-C while waiting cancels the job.
"$bin" sweep "$sweep" --backend slurm --chunk 3 --max-parallel 1 --out "$work/cc" > "$work/cc.log" 2>&1 &
pid=$!
for i in $(seq 1 200); do
  grep -q "^submitted Slurm job" "$work/cc.log" && break
  sleep 0.05
done
sleep 0.5
kill -INT "$pid"
wait "$pid"
code=$?
[ $code -eq 130 ] || fail "Ctrl-C: exit code $code, not 130 ($(tail -3 "$work/cc.log"))"
cjob=$(job_of "$work/cc")
grep -q "interrupted: Slurm job $cjob cancelled" "$work/cc.log" || fail "Ctrl-C: $(tail -3 "$work/cc.log")"
for i in $(seq 1 100); do
  [ "$(active_tasks "$cjob")" -eq 0 ] && break
  sleep 0.1
done
[ "$(active_tasks "$cjob")" -eq 0 ] || fail "Ctrl-C left job $cjob with tasks pending or running"
echo "ok   Ctrl-C while waiting: exit 130, job $cjob cancelled"

# 5. Errors: one line, exit 2, nothing written.
env PATH=/nonexistent "$bin" sweep "$sweep" --backend slurm --out "$work/e1" > /dev/null 2> "$work/e1.err"
code=$?
[ $code -eq 2 ] && [ "$(wc -l < "$work/e1.err")" -eq 1 ] && grep -q "sbatch is not on PATH" "$work/e1.err" ||
  fail "no sbatch on PATH: exit code $code, stderr: $(cat "$work/e1.err")"
[ -e "$work/e1" ] && fail "no sbatch on PATH: --out was created"
"$bin" sweep "$sweep" --backend slurm --partition nosuch --out "$work/e2" > /dev/null 2> "$work/e2.err"
code=$?
[ $code -eq 2 ] && [ "$(wc -l < "$work/e2.err")" -eq 1 ] && grep -q "sbatch refused the job: invalid partition specified: nosuch" "$work/e2.err" ||
  fail "a bad --partition: exit code $code, stderr: $(cat "$work/e2.err")"
[ -e "$work/e2" ] && fail "a bad --partition: --out was created"
"$bin" sweep "$sweep" --backend slurm --out "$work/e\\4" > /dev/null 2> "$work/e4.err"
code=$?
[ $code -eq 2 ] && [ "$(wc -l < "$work/e4.err")" -eq 1 ] && grep -q "holds a '\\\\'" "$work/e4.err" ||
  fail "an --out with a backslash: exit code $code, stderr: $(cat "$work/e4.err")"
[ -e "$work/e\\4" ] && fail "an --out with a backslash: --out was created"
"$bin" sweep "$sweep" --out "$work/local" --collect > /dev/null 2> "$work/e3.err"
code=$?
[ $code -eq 2 ] && grep -q "no Slurm job was submitted there" "$work/e3.err" ||
  fail "--collect without a job: exit code $code, stderr: $(cat "$work/e3.err")"
echo "ok   no sbatch, a rejected submission, a '\\' in --out, nothing to collect: one line each, exit 2"

# The daemons stop by their PIDs.
"$src/tools/slurm-local" stop "$cluster" || fail "tools/slurm-local stop"
for p in $daemons; do kill -0 "$p" 2> /dev/null && fail "daemon $p still runs after stop"; done
echo "ok   every daemon stopped"
echo "slurm_test passed"
