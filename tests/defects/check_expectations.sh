#!/usr/bin/env bash
# Defect 10: `check` fails a scenario whose expectations fail even when its events match the golden
# file (a never_runs_red failure used to leave CI green unless --expectations was given);
# --ignore-expectations makes them a note. JUnit carries the failed expectations (<failure>, and the
# details in <system-out>) and marks a scenario without expectations <skipped>. Exit codes: 0 all
# passed, 1 a failure, 4 an error (a run or a file that does not load; it wins over 1).
set -u
source "$(dirname "$0")/lib.sh" "$@"
golden=$src/tests/golden
dir=$work/suite
mkdir -p "$dir"
# The light is never seen (detection range 0): the ego crosses on red, as its golden events say.
scenario_copy tl_light_out_of_range "$dir/tl_light_out_of_range.yaml"
echo "  - never_runs_red: true" >> "$dir/tl_light_out_of_range.yaml"

"$bin" check "$dir/tl_light_out_of_range.yaml" --golden "$golden" --out "$work/c1" --junit "$work/c1.xml" >"$work/c1.out" 2>&1
code=$?
[ $code -eq 1 ] || fail "check by default: exit code $code, want 1 ($(cat "$work/c1.out"))"
grep -q "^FAIL  tl_light_out_of_range: expectations failed: never_runs_red; [0-9]* events match" "$work/c1.out" ||
  fail "check line: $(cat "$work/c1.out")"
grep -q "expectation failed: never_runs_red: " "$work/c1.out" || fail "no detail of the failed expectation: $(cat "$work/c1.out")"
grep -q "^check: 1 scenario, 0 passed, 1 failed, 0 errors" "$work/c1.out" || fail "summary: $(tail -1 "$work/c1.out")"
python3 - "$work/c1.xml" <<'PY' || fail "JUnit of a failed expectation (above)"
import sys, xml.etree.ElementTree as ET
suite = ET.parse(sys.argv[1]).getroot().find("testsuite")
assert suite.get("failures") == "1" and suite.get("errors") == "0" and suite.get("skipped") == "0", suite.attrib
case = suite.find("testcase")
failure = case.find("failure")
assert failure is not None and "expectations failed: never_runs_red" in failure.get("message"), ET.tostring(case)
out = case.find("system-out")
assert out is not None and "expectation failed: never_runs_red: " in out.text and "red" in out.text, ET.tostring(case)
PY
ok "check fails a matching run whose never_runs_red fails (exit 1, JUnit <failure> and <system-out>)"

"$bin" check "$dir/tl_light_out_of_range.yaml" --golden "$golden" --out "$work/c2" --expectations >"$work/c2.out" 2>&1
[ $? -eq 1 ] || fail "--expectations (the default): not exit 1"
"$bin" check "$dir/tl_light_out_of_range.yaml" --golden "$golden" --out "$work/c3" --ignore-expectations >"$work/c3.out" 2>&1
code=$?
[ $code -eq 0 ] || fail "--ignore-expectations: exit code $code, want 0 ($(cat "$work/c3.out"))"
grep -q "(note: expectations failed: never_runs_red, ignored: --ignore-expectations)" "$work/c3.out" ||
  fail "--ignore-expectations note: $(cat "$work/c3.out")"
"$bin" check "$dir/tl_light_out_of_range.yaml" --golden "$golden" --out "$work/c4" --expectations --ignore-expectations \
  >/dev/null 2>&1
[ $? -eq 2 ] || fail "--expectations with --ignore-expectations: not exit 2"
ok "--expectations is the default, --ignore-expectations the opt-out"

# A scenario without expectations whose events match: passes, JUnit <skipped>; with a failure: 1;
# with a file that does not load as well: 4.
scenario_copy close_turns "$dir/close_turns.yaml"
python3 - "$dir/close_turns.yaml" <<'PY'
import sys
text = open(sys.argv[1]).read()
open(sys.argv[1], "w").write(text[:text.index("expect:")])
PY
"$bin" check "$dir/close_turns.yaml" --golden "$golden" --out "$work/c5" --junit "$work/c5.xml" >"$work/c5.out" 2>&1
code=$?
[ $code -eq 0 ] || fail "no expectations: exit code $code, want 0 ($(cat "$work/c5.out"))"
grep -q 'tests="1" failures="0" errors="0" skipped="1"' "$work/c5.xml" || fail "JUnit skipped count: $(head -3 "$work/c5.xml")"
grep -q '<skipped message="[0-9]* events match .*the scenario has no expectations' "$work/c5.xml" ||
  fail "JUnit <skipped>: $(cat "$work/c5.xml")"
"$bin" check "$dir/close_turns.yaml" "$dir/tl_light_out_of_range.yaml" --golden "$golden" --out "$work/c6" >/dev/null 2>&1
[ $? -eq 1 ] || fail "a skipped and a failed scenario: not exit 1"
printf 'name: x\nnet: [\n' > "$dir/zz_broken.yaml"
"$bin" check "$dir" --golden "$golden" --out "$work/c7" --junit "$work/c7.xml" >"$work/c7.out" 2>&1
code=$?
[ $code -eq 4 ] || fail "an error and a failure: exit code $code, want 4 ($(tail -2 "$work/c7.out"))"
grep -q 'tests="3" failures="1" errors="1" skipped="1"' "$work/c7.xml" || fail "JUnit counts: $(head -3 "$work/c7.xml")"
ok "no expectations: JUnit <skipped>; exit 1 for a failure, 4 when there is an error too"
finish
