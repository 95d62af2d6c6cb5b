#!/usr/bin/env bash
# signalsim check with --set, --params and --strict-params (as batch and compare take them), against
# the bundled golden files: a candidate parameter that moves a blinker fails the check (by --set and by
# --params alike), autoware_launch's own file passes strictly, and a bad --params file is one line and
# exit 2 before anything runs.
# usage: check_overrides_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
scenario=$src/scenarios/intersection_left.yaml
golden=$src/tests/golden

"$bin" check "$scenario" --golden "$golden" --out "$work/plain" >"$work/plain.log" 2>&1 ||
  fail "check without overrides: exit $? ($(cat "$work/plain.log"))"
grep -q "^check: 1 scenario, 1 passed, 0 failed" "$work/plain.log" || fail "plain: $(tail -1 "$work/plain.log")"

# The left blinker comes on 30 m + 3 s x speed before the junction: 60 m moves it.
"$bin" check "$scenario" --golden "$golden" --out "$work/set" --set turn_signal_intersection_search_distance=60 \
  >"$work/set.log" 2>&1
code=$?
[ "$code" -eq 1 ] || fail "check --set: exit $code, want 1 ($(cat "$work/set.log"))"
grep -q "^FAIL  intersection_left: .*event difference.* against $golden/intersection_left.events.csv" "$work/set.log" ||
  fail "check --set: no FAIL line: $(cat "$work/set.log")"
grep -q "blinker none -> left (intersection)" "$work/set.log" || fail "check --set: the diff does not name the blinker: $(cat "$work/set.log")"

printf 'turn_signal_intersection_search_distance: 60.0\n' >"$work/candidate.yaml"
(cd "$work" && "$bin" check "$scenario" --golden "$golden" --out "$work/params" --params candidate.yaml) \
  >"$work/params.log" 2>&1
code=$?
[ "$code" -eq 1 ] || fail "check --params (relative to the current directory): exit $code, want 1 ($(cat "$work/params.log"))"
grep -q "^FAIL  intersection_left" "$work/params.log" || fail "check --params: $(cat "$work/params.log")"

# autoware_launch's behavior_path_planner.param.yaml keeps the defaults of this turn: it passes, strictly.
"$bin" check "$scenario" --golden "$golden" --out "$work/strict" --strict-params \
  --params "$src/tests/data/autoware_launch/behavior_path_planner.param.yaml" >"$work/strict.log" 2>&1 ||
  fail "check --params autoware_launch's file --strict-params: exit $? ($(cat "$work/strict.log"))"
grep -q "^check: 1 scenario, 1 passed" "$work/strict.log" || fail "strict: $(tail -1 "$work/strict.log")"

# A bad --params file: one line, exit 2, nothing run.
"$bin" check "$scenario" --golden "$golden" --out "$work/missing" --params "$work/nope.yaml" \
  >"$work/missing.out" 2>"$work/missing.err"
code=$?
[ "$code" -eq 2 ] || fail "a missing --params file: exit $code, want 2"
[ "$(wc -l <"$work/missing.err")" -eq 1 ] && grep -q "^signalsim: $work/nope.yaml: parameter file not found" "$work/missing.err" ||
  fail "a missing --params file: $(cat "$work/missing.err")"
[ -s "$work/missing.out" ] && fail "a missing --params file printed: $(cat "$work/missing.out")"
printf 'turn_signal_intersection_search_distance: far\n' >"$work/bad.yaml"
"$bin" check "$scenario" --golden "$golden" --out "$work/bad" --params "$work/bad.yaml" >/dev/null 2>"$work/bad.err"
code=$?
[ "$code" -eq 2 ] || fail "a bad --params value: exit $code, want 2"
[ "$(cat "$work/bad.err")" = "signalsim: $work/bad.yaml:1: parameter 'turn_signal_intersection_search_distance': expected a number, got 'far'" ] ||
  fail "a bad --params value: $(cat "$work/bad.err")"

if [ "$failures" -eq 0 ]; then echo "check overrides: all checks passed"; else echo "$failures failure(s)"; fi
[ "$failures" -eq 0 ]
