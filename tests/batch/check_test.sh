#!/usr/bin/env bash
# signalsim check passes on the true golden files and fails on a deliberately shifted one (with a
# readable diff and JUnit XML); a run past its timeout and a run the worker rejects become error rows
# while the batch goes on; a bad sweep file is exit code 2 naming file and line.
# usage: check_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
data=$src/tests/batch/data
golden=$work/golden
scenarios=("$data/turns.yaml" "$data/roundabout_exit.yaml")

"$bin" check "${scenarios[@]}" --golden "$golden" --update --out "$work/c0" > "$work/update.log" ||
  fail "--update: exit code $? ($(cat "$work/update.log"))"
[ -s "$golden/turns.events.csv" ] && [ -s "$golden/roundabout_exit.events.csv" ] || fail "--update wrote no golden files"

"$bin" check "${scenarios[@]}" --golden "$golden" --out "$work/c1" --junit "$work/true.xml" > "$work/true.log" ||
  fail "check on the true goldens: exit code $? ($(cat "$work/true.log"))"
grep -q "check: 2 scenarios, 2 passed, 0 failed" "$work/true.log" || fail "$(tail -1 "$work/true.log")"
grep -q 'failures="0" errors="0"' "$work/true.xml" || fail "JUnit of a passing check: $(head -3 "$work/true.xml")"
echo "ok   check passes on the true goldens"

# Shift the second blinker event of turns by +2 m: a regression with a readable diff.
cp "$golden/turns.events.csv" "$work/turns.true.csv"
shift_event() {  # shift_event METRES
  python3 - "$work/turns.true.csv" "$golden/turns.events.csv" "$1" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
rows[2][1] = "%.3f" % (float(rows[2][1]) + float(sys.argv[3]))
csv.writer(open(sys.argv[2], "w"), lineterminator="\n").writerows(rows)
PY
}
shift_event 2.0
"$bin" check "${scenarios[@]}" --golden "$golden" --out "$work/c2" --junit "$work/shifted.xml" > "$work/shifted.log"
code=$?
[ $code -eq 1 ] || fail "check on a shifted golden: exit code $code, not 1 ($(cat "$work/shifted.log"))"
grep -q "^FAIL  turns: 1 event difference against" "$work/shifted.log" || fail "no FAIL line: $(cat "$work/shifted.log")"
grep -q "ds -2.000 m" "$work/shifted.log" || fail "the diff does not show the shift: $(cat "$work/shifted.log")"
grep -q "^ok    roundabout_exit" "$work/shifted.log" || fail "the other scenario should pass"
grep -q 'tests="2" failures="1" errors="0"' "$work/shifted.xml" || fail "JUnit: $(head -3 "$work/shifted.xml")"
grep -q '<failure message="1 event difference' "$work/shifted.xml" || fail "JUnit has no <failure>"
echo "ok   check fails on a golden shifted by 2 m, with the diff and JUnit XML"
sed -n '/^FAIL/,/^ok/p' "$work/shifted.log" | head -6

shift_event 0.4
"$bin" check "${scenarios[@]}" --golden "$golden" --out "$work/c3" > "$work/within.log" ||
  fail "a shift of 0.4 m is within the default 0.5 m: $(cat "$work/within.log")"
"$bin" check "${scenarios[@]}" --golden "$golden" --out "$work/c4" --tolerance 0.2 > /dev/null &&
  fail "a shift of 0.4 m with --tolerance 0.2 passed"
echo "ok   tolerance: 0.4 m passes at 0.5 m, fails at 0.2 m"

rm "$golden/roundabout_exit.events.csv"
"$bin" check "${scenarios[@]}" --golden "$golden" --out "$work/c5" > "$work/missing.log" && fail "a missing golden passed"
grep -q "no golden file .*roundabout_exit.events.csv (create it with --update)" "$work/missing.log" || fail "$(cat "$work/missing.log")"
echo "ok   a missing golden file fails and says how to make it"

# Error rows: a run past its timeout, a run whose route the worker rejects; the others still run.
"$bin" batch "$data/turns.yaml" --out "$work/slow" --timeout 0.5 --jobs 1 \
  --set step_length=0.002 --set duration=600 --set ego.max_speed=1 --set ego.depart_speed=1 > "$work/slow.log"
code=$?
[ $code -eq 4 ] || fail "timeout: exit code $code, not 4 (a run errored) ($(cat "$work/slow.log"))"
grep -q ',error,.*,timed out: still running after the 0.5 s limit (worker killed)$' "$work/slow/results.csv" ||
  fail "timeout row: $(cat "$work/slow/results.csv")"
"$bin" batch "${scenarios[@]}" --out "$work/bad" --set "ego.route=[in_S, nowhere]" --jobs 2 > "$work/bad.log"
[ $? -eq 4 ] || fail "a rejected run should make the batch exit 4 (a run errored)"
python3 - "$work/bad/results.csv" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 2 and all(r["status"] == "error" for r in rows), rows
assert "nowhere" in rows[0]["error"] and rows[0]["error"].startswith("--set ego.route=[in_S, nowhere]: ego.route: "), rows[0]["error"]
PY
echo "ok   a timed-out run and a rejected run are error rows"

# Bad sweep files: exit code 2, one line naming file and line.
printf 'scenarios: [%s]\ngrid:\n  country: [jp]\ntimeuot: 3\n' "$data/turns.yaml" > "$work/bad1.yaml"
out=$("$bin" sweep "$work/bad1.yaml" --out "$work/b1" 2>&1)
[ $? -eq 2 ] && [ "$out" = "signalsim: $work/bad1.yaml:4: unknown key 'timeuot'" ] || fail "unknown key: $out"
printf 'scenarios: [%s]\ngrid:\n  country: [jp, xx]\n' "$data/turns.yaml" > "$work/bad2.yaml"
out=$("$bin" sweep "$work/bad2.yaml" --out "$work/b2" 2>&1)
[ $? -eq 2 ] && [[ "$out" == "signalsim: $work/bad2.yaml:3: grid.country: value xx: "*"unknown country 'xx'"* ]] ||
  fail "unknown country: $out"
[ -e "$work/b2" ] && fail "a rejected sweep created its output directory"
echo "ok   bad sweep files: exit code 2 with file:line"
echo "check_test passed"
