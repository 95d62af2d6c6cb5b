#!/usr/bin/env bash
# A persistent worker stays as isolated as a process per run: (1) a worker killed by SIGSEGV during
# run 1 (kill from here, on its process id) makes run 1 an error row "worker killed by SIGSEGV" and
# the runs after it finish in a new worker; (2) a run past --timeout is an error row "timed out", its
# worker is killed and replaced, the rest finish; (3) SIGINT or SIGTERM to the sweep: exit 130, the
# finished rows kept, no row for the interrupted run, no worker left; (4) SIGTERM to the worker
# itself (alone, or with the sweep, as Slurm's scancel): exit 130, no row for its run, run 0's row
# and files untouched, --resume completes. Sweep: sweep_crash.yaml (run 1 takes most of a minute,
# the others a fraction of a second).
# usage: workers_isolation_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
# Under AddressSanitizer (tools/test_sanitized) ASan's own SIGSEGV handler would turn the kill -SEGV
# below into a report and exit code 1: the signal must reach the worker as it does in a normal build.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}handle_segv=0"
bin=$1
src=$2
work=$(mktemp -d)
pid=
trap '[ -n "$pid" ] && kill $pid 2>/dev/null; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# The --timeout of the cases that time run 1 out: long enough for any other run of the sweep under
# the sanitizers with --isolate on a loaded machine (3 s was not, at load 8).
limit=8
ulimit -c 0  # the SIGSEGV of (1) leaves no core file
sweep=$src/tests/batch/data/sweep_crash.yaml

workers() { pgrep -P "$pid"; }  # the sweep's children: its workers
pipes_of() { ls -l "/proc/$1/fd" 2>/dev/null | grep -o 'pipe:\[[0-9]*\]' | sort -u; }
# Retries the command "$@" every 0.05 s for at most 30 s; false if it never succeeded.
wait_for() {
  local i
  for i in $(seq 1 600); do "$@" && return 0; sleep 0.05; done
  return 1
}
# Waits until run $2 of output folder $1 has started (its run directory exists).
wait_run() { wait_for compgen -G "$1/runs/000$2-*" > /dev/null; }
# Records every worker process id of the sweep into $1 until the sweep ends. One process that scans
# /proc every millisecond (pgrep and sleep, a fork each, missed a new worker that finished its four
# short runs within 0.15 s on a loaded CI machine). seen_by_watcher waits until it has seen worker $2.
watch_workers() {
  python3 - "$pid" "$1" <<'PY'
import os, sys, time
sweep, seen = sys.argv[1], set()
def parent_of(entry):
    try:
        with open(f"/proc/{entry}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[1]
    except (OSError, IndexError):
        return None
with open(sys.argv[2], "w") as out:
    while os.path.exists(f"/proc/{sweep}"):
        for child in {e for e in os.listdir("/proc") if e.isdigit() and parent_of(e) == sweep} - seen:
            seen.add(child)
            print(child, file=out, flush=True)
        time.sleep(0.001)
PY
}
seen_by_watcher() { wait_for grep -qx "$2" "$1" 2>/dev/null; }

# The rows as "run status error" lines.
rows() {
  python3 - "$1" <<'PY'
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    print(r["run"], r["status"], r["error"])
PY
}

# (1) SIGSEGV of the worker during run 1.
"$bin" sweep "$sweep" --out "$work/crash" --jobs 1 > "$work/crash.log" 2>&1 &
pid=$!
watch_workers "$work/crash.pids" &
watcher=$!
wait_run "$work/crash" 1 || fail "run 1 never started"
w=$(workers)
[ "$(echo "$w" | wc -w)" -eq 1 ] || fail "--jobs 1: workers '$w', not one"
seen_by_watcher "$work/crash.pids" "$w" || fail "the watcher never saw worker $w"
kill -SEGV "$w"
wait "$pid"
code=$?
[ $code -eq 4 ] || fail "crash: exit code $code, not 4 (a run errored) ($(tail -3 "$work/crash.log"))"
rows "$work/crash/results.csv" > "$work/crash.rows"
grep -q "^1 error worker killed by SIGSEGV" "$work/crash.rows" || fail "run 1: $(sed -n 2p "$work/crash.rows")"
[ "$(grep -c " passed $" "$work/crash.rows")" -eq 5 ] || fail "the other runs: $(cat "$work/crash.rows")"
wait "$watcher"
sort -u "$work/crash.pids" | grep -vx "$w" | grep -q . || fail "no new worker after the crash"
kill -0 "$w" 2>/dev/null && fail "the crashed worker $w still runs"
echo "ok   a worker killed by SIGSEGV: its run is an error row, a new worker runs the rest"

# (2) Run 1 past --timeout.
"$bin" sweep "$sweep" --out "$work/slow" --jobs 1 --timeout $limit > "$work/slow.log" 2>&1 &
pid=$!
watch_workers "$work/slow.pids" &
watcher=$!
wait_run "$work/slow" 1 || fail "run 1 never started"
first=$(workers)
wait "$pid"
code=$?
[ $code -eq 4 ] || fail "timeout: exit code $code, not 4 ($(tail -3 "$work/slow.log"))"
rows "$work/slow/results.csv" > "$work/slow.rows"
grep -qx "1 error timed out: still running after the $limit s limit (worker killed)" "$work/slow.rows" ||
  fail "run 1: $(sed -n 2p "$work/slow.rows")"
[ "$(grep -c " passed $" "$work/slow.rows")" -eq 5 ] || fail "the other runs: $(cat "$work/slow.rows")"
wait "$watcher"
sort -u "$work/slow.pids" | grep -vx "$first" | grep -q . || fail "no new worker after the timeout"
echo "ok   a run past --timeout: an error row, its worker killed and replaced, the rest finish"

# (3) SIGINT, then SIGTERM, during run 1 (--jobs 2: the other worker has finished runs 0, 2 to 5).
for sig in INT TERM; do
  out=$work/stop_$sig
  "$bin" sweep "$sweep" --out "$out" --jobs 2 > "$out.log" 2>&1 &
  pid=$!
  wait_run "$out" 1 || fail "$sig: run 1 never started"
  wait_run "$out" 5 || fail "$sig: run 5 never started"
  sleep 0.5
  seen=$(workers)
  if [ "$sig" = INT ]; then
    # The workers are forks of the sweep (not an exec of `signalsim worker`), and neither holds a
    # pipe of the other's (a fork keeps every descriptor the batch has open; exec would close them).
    set -- $seen
    [ $# -eq 2 ] || fail "--jobs 2: workers '$seen', not two"
    for w in "$@"; do
      [ "$(tr '\0' ' ' < /proc/$w/cmdline)" = "$(tr '\0' ' ' < /proc/$pid/cmdline)" ] ||
        fail "worker $w is not a fork of the sweep: $(tr '\0' ' ' < /proc/$w/cmdline)"
    done
    shared=$(comm -12 <(pipes_of "$1") <(pipes_of "$2"))
    [ -z "$shared" ] || fail "workers $1 and $2 share pipes: $shared"
    echo "ok   --jobs 2: two workers forked from the sweep, no pipe shared between them"
  fi
  kill -$sig "$pid"
  wait "$pid"
  code=$?
  [ $code -eq 130 ] || fail "SIG$sig: exit code $code, not 130 ($(tail -3 "$out.log"))"
  for w in $seen; do kill -0 "$w" 2>/dev/null && fail "SIG$sig: worker $w outlived the sweep"; done
  rows "$out/results.csv" > "$out.rows"
  grep -q "^1 " "$out.rows" && fail "SIG$sig: the interrupted run 1 has a row: $(grep "^1 " "$out.rows")"
  grep -q "^0 passed $" "$out.rows" || fail "SIG$sig: run 0 lost: $(cat "$out.rows")"
  grep -qv " passed $" "$out.rows" && fail "SIG$sig: a row that is not passed: $(cat "$out.rows")"
  grep -q "interrupted: finished runs are kept" "$out.log" || fail "SIG$sig: $(tail -2 "$out.log")"
done
pid=
echo "ok   SIGINT and SIGTERM: exit 130, finished rows kept, no row for the stopped run, no worker left"

# (4) SIGTERM that reaches the worker itself during run 1 (a `kill` of it, or Slurm's scancel, which
#     signals every process of a task): alone, and together with the sweep; persistent workers and
#     --isolate. The stopped run is no result - no row, not an error row - and the sweep stops as for
#     its own SIGTERM (exit 130); run 0's row and files stay as they were; --resume completes.
files_of_run0() { (cd "$1"/runs/0000-* && sha1sum ./*); }
for mode in workers isolate; do
  for target in worker both; do
    out=$work/own_${mode}_$target
    flag=; [ $mode = isolate ] && flag=--isolate
    "$bin" sweep "$sweep" --out "$out" --jobs 1 $flag > "$out.log" 2>&1 &
    pid=$!
    wait_run "$out" 1 || fail "$mode, $target: run 1 never started"
    w=$(workers)
    [ "$(echo "$w" | wc -w)" -eq 1 ] || fail "$mode: workers '$w', not one"
    files_of_run0 "$out" > "$out.run0" || fail "$mode, $target: run 0 has no files"
    if [ $target = both ]; then kill -TERM "$w" "$pid"; else kill -TERM "$w"; fi
    wait "$pid"
    code=$?
    [ $code -eq 130 ] || fail "$mode, SIGTERM to $target: exit code $code, not 130 ($(tail -3 "$out.log"))"
    rows "$out/results.csv" > "$out.rows"
    [ "$(cat "$out.rows")" = "0 passed " ] || fail "$mode, SIGTERM to $target: rows: $(cat "$out.rows")"
    files_of_run0 "$out" | cmp -s - "$out.run0" || fail "$mode, SIGTERM to $target: run 0's files changed"
    [ $target = both ] || continue
    "$bin" sweep "$sweep" --out "$out" --jobs 1 $flag --resume --timeout $limit > "$out.resume.log" 2>&1
    rows "$out/results.csv" > "$out.rows"
    grep -q "^resuming: 1 of 6 runs already done, 5 to run" "$out.resume.log" ||
      fail "$mode, $target: --resume: $(head -1 "$out.resume.log")"
    grep -qx "1 error timed out: still running after the $limit s limit (worker killed)" "$out.rows" ||
      fail "$mode, $target: --resume did not run run 1 again: $(sed -n 2p "$out.rows")"
    [ "$(grep -c " passed $" "$out.rows")" -eq 5 ] || fail "$mode, $target: --resume: $(cat "$out.rows")"
  done
done
pid=
echo "ok   SIGTERM to a worker itself (alone, or with the sweep): exit 130, no row for its run, run 0 untouched"
echo "workers_isolation_test passed"
