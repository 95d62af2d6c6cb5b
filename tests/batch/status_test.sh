#!/usr/bin/env bash
# A scenario without expectations has its own status, no_expectations, everywhere a status shows:
# `run` (exit 0), summary.json, batch results.csv and summary line, --resume (kept as done), `check`
# (noted, not a failure) and tools/suite_table.py. A sweep file whose plot: or zip: is bad is refused
# before any run starts (exit 2, one line naming file, line and key; no output directory).
# usage: status_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
data=$src/tests/batch/data

# turns.yaml without its expect: list (paths made absolute).
sed -e "s#\.\./\.\./\.\.#$src#" -e '/^expect:/,$d' -e 's/^name: turns$/name: turns_unchecked/' \
  "$data/turns.yaml" > "$work/unchecked.yaml"
grep -q "^expect" "$work/unchecked.yaml" && fail "the test scenario still has expectations"

"$bin" run "$work/unchecked.yaml" --out "$work/run" > "$work/run.log"
code=$?
[ $code -eq 0 ] || fail "run: exit code $code, not 0 ($(cat "$work/run.log"))"
head -1 "$work/run.log" | grep -q "^turns_unchecked: no_expectations (" || fail "run: $(head -1 "$work/run.log")"
grep -q "no expectations (expect:): nothing was checked" "$work/run.log" || fail "run does not say nothing was checked"
grep -q '"status": "no_expectations",' "$work/run/summary.json" || fail "summary.json: $(grep status "$work/run/summary.json")"
echo "ok   run: status no_expectations, exit code 0"

"$bin" batch "$data/turns.yaml" "$work/unchecked.yaml" --out "$work/batch" --jobs 2 > "$work/batch.log"
code=$?
[ $code -eq 0 ] || fail "batch: exit code $code, not 0 ($(cat "$work/batch.log"))"
grep -q "^2 runs: 1 passed, 0 failed, 1 without expectations, 0 errors in " "$work/batch.log" ||
  fail "batch summary: $(tail -1 "$work/batch.log")"
python3 - "$work/batch/results.csv" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
got = [(r["scenario"], r["status"], r["expectations_passed"], r["expectations_total"], r["error"]) for r in rows]
assert got == [("turns", "passed", "1", "1", ""), ("turns_unchecked", "no_expectations", "0", "0", "")], got
PY
"$bin" batch "$data/turns.yaml" "$work/unchecked.yaml" --out "$work/batch" --jobs 2 --resume > "$work/resume.log"
code=$?
[ $code -eq 0 ] || fail "batch --resume: exit code $code"
grep -q "resuming: 2 of 2 runs already done, 0 to run" "$work/resume.log" || fail "--resume: $(head -1 "$work/resume.log")"
echo "ok   batch: a no_expectations row, counted apart, exit code 0, kept by --resume"

golden=$work/golden
"$bin" check "$data/turns.yaml" "$work/unchecked.yaml" --golden "$golden" --update --out "$work/c0" > "$work/update.log" ||
  fail "check --update: exit code $? ($(cat "$work/update.log"))"
"$bin" check "$data/turns.yaml" "$work/unchecked.yaml" --golden "$golden" --expectations --out "$work/c1" > "$work/check.log"
code=$?
[ $code -eq 0 ] || fail "check: exit code $code, not 0 ($(cat "$work/check.log"))"
grep -q "^ok    unchecked: 3 events match .*(note: the scenario has no expectations: only its events are checked)$" \
  "$work/check.log" || fail "check line: $(cat "$work/check.log")"
grep -q "^check: 2 scenarios, 2 passed, 0 failed, 0 errors; 1 without expectations$" "$work/check.log" ||
  fail "check summary: $(tail -1 "$work/check.log")"
echo "ok   check: noted as without expectations, not a failure"

# tools/suite_table.py (tools/demo) reads summary.json statuses too.
mkdir -p "$work/suite"
cp -r "$work/run" "$work/suite/unchecked"
cp -r "$work/batch/runs/0000-turns" "$work/suite/turns"
printf 'turns 0 1.0 1.5\nunchecked 0 1.5 2.0\n' > "$work/times"
python3 "$src/tools/suite_table.py" "$work/suite" "$work/times" > "$work/table.log" || fail "suite_table.py: exit code $?"
grep -q "^unchecked  *no_expectations  *0/0 " "$work/table.log" || fail "suite table row: $(cat "$work/table.log")"
grep -q "^1 passed, 0 failed, 1 without expectations, 0 errors; outputs in " "$work/table.log" ||
  fail "suite table summary: $(tail -1 "$work/table.log")"
echo "ok   tools/suite_table.py counts it apart"

# Bad sweep files are refused before any run: exit code 2, one line, no output directory.
refused() {  # refused NAME EXPECTED_MESSAGE (the sweep file is $work/NAME.yaml)
  local out code
  out=$("$bin" sweep "$work/$1.yaml" --out "$work/$1.out" --plot 2>&1)
  code=$?
  [ $code -eq 2 ] || fail "$1: exit code $code, not 2 ($out)"
  [ "$out" = "signalsim: $work/$1.yaml:$2" ] || fail "$1: $out"
  [ -e "$work/$1.out" ] && fail "$1: runs were started (the output directory exists)"
  return 0
}
printf 'scenarios: [%s]\ngrid:\n  country: [jp, de]\nplot: {metric: turn1.lead_distance, x: ego.max_speed}\n' \
  "$data/turns.yaml" > "$work/plot_x.yaml"
refused plot_x "4: plot.x: 'ego.max_speed' is not a swept key (swept: country; or scenario)"
printf 'scenarios: [%s]\ngrid:\n  country: [jp, de]\nplot:\n  metric: roundabout_exit1.lead_distance\n' \
  "$data/turns.yaml" > "$work/plot_metric.yaml"
refused plot_metric "5: plot.metric: no run's route has a roundabout_exit1, so no run can give 'roundabout_exit1.lead_distance' (the most any route has: 2 turn, 0 light)"
printf 'scenarios: [%s]\nzip: []\n' "$data/turns.yaml" > "$work/zip.yaml"
refused zip "2: key 'zip': the list is empty: it sweeps nothing (give mappings of key: [values], or leave zip out)"
printf 'scenarios: [%s]\ngrid: {}\n' "$data/turns.yaml" > "$work/grid.yaml"
refused grid "2: key 'grid': the mapping is empty: it sweeps nothing (give key: [values], or leave grid out)"
echo "ok   a bad plot:, zip: [] and grid: {} are refused before any run"
echo "status_test passed"
