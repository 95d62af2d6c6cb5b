#!/usr/bin/env bash
# Killing a worker mid-run leaves an error row and the sweep goes on; Ctrl-C (SIGINT) stops it
# cleanly with every finished row kept (exit 130); --resume runs the error row and the rest, and again
# a finished run whose folder was deleted.
# The resumed results.csv equals a fresh sweep's (wall_time aside). The first sweep runs one process
# per run (--isolate: its workers are found by their command line); the persistent workers' own
# crashes and interruptions are workers_isolation_test.sh's.
# usage: resume_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'kill $pid 2>/dev/null; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
sweep=$src/tests/batch/data/sweep_slow.yaml   # runs 1 and 2 are slow

# The worker of run N, by its --out argument (a child of the sweep).
worker_of() {
  local run=$1 child
  for child in $(pgrep -P "$pid"); do
    tr '\0' ' ' < /proc/$child/cmdline 2>/dev/null | grep -q "runs/000$run-" && { echo "$child"; return 0; }
  done
  return 1
}
wait_worker() {
  local i
  for i in $(seq 1 200); do worker_of "$1" && return 0; sleep 0.05; done
  return 1
}

"$bin" sweep "$sweep" --out "$work/out" --jobs 1 --isolate > "$work/first.log" 2>&1 &
pid=$!
w=$(wait_worker 1) || fail "run 1 never started"
sleep 0.2
kill -KILL "$w"
wait_worker 2 > /dev/null || fail "the sweep did not go on to run 2 after the kill"
sleep 0.2
kill -INT "$pid"
wait "$pid"
code=$?
[ $code -eq 130 ] || fail "Ctrl-C: exit code $code, not 130 ($(cat "$work/first.log"))"
pgrep -f "$work/out/runs" > /dev/null && fail "a worker outlived the interrupted sweep"

python3 - "$work/out/results.csv" <<'PY' || exit 1
import csv, sys
rows = {r["run"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert set(rows) == {"0", "1"}, sorted(rows)      # run 2 was interrupted: no row, nothing half-written
assert rows["0"]["status"] in ("passed", "failed"), rows["0"]
assert rows["1"]["status"] == "error" and "SIGKILL" in rows["1"]["error"], rows["1"]
print("ok   killed worker -> error row; Ctrl-C -> exit 130 with finished rows kept")
PY

"$bin" sweep "$sweep" --out "$work/out" --jobs 2 --resume > "$work/resume.log" 2>&1 || true
grep -q "resuming: 1 of 5 runs already done, 4 to run" "$work/resume.log" || fail "resume: $(head -3 "$work/resume.log")"
python3 - "$work/out/results.csv" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [r["run"] for r in rows] == ["0", "1", "2", "3", "4"], [r["run"] for r in rows]
assert all(r["status"] != "error" for r in rows), [(r["run"], r["error"]) for r in rows]
print("ok   --resume reran the error row and completed the rest")
PY

"$bin" sweep "$sweep" --out "$work/fresh" --jobs 2 > /dev/null 2>&1 || true
strip() { python3 -c "
import csv, sys
for r in csv.reader(open(sys.argv[1])):
    print(','.join(r[:-2] + r[-1:]))" "$1"; }
cmp -s <(strip "$work/out/results.csv") <(strip "$work/fresh/results.csv") || {
  diff <(strip "$work/out/results.csv") <(strip "$work/fresh/results.csv") | head
  fail "the resumed results.csv differs from a fresh one"
}
echo "ok   resumed results.csv == fresh results.csv"

# A passed row whose run folder was deleted is run again (its files come back), the others kept.
run0=$(ls -d "$work/out/runs/0000-"*) || fail "no run folder of run 0"
rm -rf "$run0"
"$bin" sweep "$sweep" --out "$work/out" --jobs 2 --resume > "$work/again.log" 2>&1 || true
grep -q "resuming: 4 of 5 runs already done, 1 to run" "$work/again.log" || fail "resume after a deleted run folder: $(head -3 "$work/again.log")"
[ -f "$run0/summary.json" ] || fail "run 0 was not run again: no $run0/summary.json"
cmp -s <(strip "$work/out/results.csv") <(strip "$work/fresh/results.csv") || fail "results.csv differs after rerunning run 0"
echo "ok   --resume reruns a finished run whose folder was deleted"
echo "resume_test passed"
