#!/usr/bin/env bash
# lib: systems under test that cannot be used or fail (docs/decider.md "Faults"), on real libsumo: a
# library not found, not a library, without a required function, of another ABI version (bad input
# before SUMO starts); a create that fails, a step that returns an error (the run ends as an error at
# that step); each exits 2 with one stderr line naming the SUT (and the step), summary.json status
# "error". A plugin that crashes (SIGSEGV) inside `batch --jobs 2`: that run is an error row whose
# message names the SUT and the step, the other runs pass, the batch exits 4 (docs/batch.md).
# usage: sut_library_faults_test.sh SIGNALSIM_BINARY SOURCE_DIR PLUGIN_DIR
set -u
bin=$1
src=$2
plugins=$(cd "$3" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
scenario=$src/scenarios/intersection_left.yaml

# check NAME DECIDER PATTERN...: exit 2, one stderr line with every pattern, summary status error.
check() {
  local name=$1 decider=$2; shift 2
  "$bin" run "$scenario" --out "$work/$name" --set "decider=$decider" >/dev/null 2>"$work/$name.err"
  local code=$? ok=1
  [ "$code" -eq 2 ] || { echo "FAIL $name: exit code $code, want 2"; ok=0; }
  [ "$(wc -l <"$work/$name.err")" -eq 1 ] || { echo "FAIL $name: not one stderr line:"; cat "$work/$name.err"; ok=0; }
  for p in "$@"; do
    grep -qF -- "$p" "$work/$name.err" || { echo "FAIL $name: stderr lacks '$p': $(cat "$work/$name.err")"; ok=0; }
  done
  grep -q '"status": "error"' "$work/$name/summary.json" 2>/dev/null || { echo "FAIL $name: summary.json is not an error"; ok=0; }
  [ "$ok" -eq 1 ] || failures=$((failures + 1))
}

echo "not a library" >"$work/text.so"
check not_found "lib:$work/missing.so" "--set decider=lib:$work/missing.so: decider 'lib:$work/missing.so'" "cannot open shared object file"
check not_a_library "lib:$work/text.so" "decider 'lib:$work/text.so'" "text.so"
check missing_symbol "lib:$plugins/libsignalsim_faulty_missing_step.so" "decider 'lib:" "does not export signalsim_decider_step"
check wrong_abi "lib:$plugins/libsignalsim_faulty_wrong_abi.so" "decider 'lib:" "ABI version 42, signalsim speaks version 1"
check create_fails "lib:$plugins/libsignalsim_faulty_create_fails.so" "decider lib:$plugins/libsignalsim_faulty_create_fails.so at the start: cannot decide on a route of"
check step_fails "lib:$plugins/libsignalsim_faulty_step_fails.so" "decider lib:$plugins/libsignalsim_faulty_step_fails.so at t=5.00 s: lost the ego at s="
# Bad libraries are found before SUMO starts: no SUMO log in the run directory.
for name in not_found not_a_library missing_symbol wrong_abi; do
  [ ! -e "$work/$name/sumo.log" ] || { echo "FAIL $name: SUMO started"; failures=$((failures + 1)); }
done
# The light-judge role of a decider-only plugin: the light_judge key is named.
"$bin" run "$scenario" --out "$work/judge" --set "light_judge=lib:$plugins/libsignalsim_faulty_step_fails.so" >/dev/null 2>"$work/judge.err"
[ $? -eq 2 ] && grep -qF "light_judge 'lib:" "$work/judge.err" && grep -qF "does not export signalsim_light_judge_create" "$work/judge.err" ||
  { echo "FAIL judge role: $(cat "$work/judge.err")"; failures=$((failures + 1)); }

# A crash inside the plugin, in a batch of three with two workers.
mkdir -p "$work/suite"
for s in intersection_left intersection_right intersection_straight; do
  sed -e "s#\.\./sumo_nets#$src/sumo_nets#; s#\.\./config#$src/config#" "$src/scenarios/$s.yaml" >"$work/suite/$s.yaml"
done
echo "decider: lib:$plugins/libsignalsim_faulty_segv.so" >>"$work/suite/intersection_right.yaml"
# Under AddressSanitizer (tools/test_sanitized) ASan's own SIGSEGV handler would turn the crash into
# its report and exit status 1; handle_segv=0 lets the signal reach signalsim's crash note as it does
# in an uninstrumented build (the option is ignored there).
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}handle_segv=0" \
  "$bin" batch "$work/suite" --out "$work/batch" --jobs 2 --quiet >/dev/null 2>"$work/batch.err"
code=$?
[ "$code" -eq 4 ] || { echo "FAIL batch: exit code $code, want 4"; failures=$((failures + 1)); }
results=$work/batch/results.csv
grep -q "^.*intersection_left.*,passed," "$results" && grep -q "intersection_straight.*,passed," "$results" ||
  { echo "FAIL batch: the other runs did not pass:"; cat "$results"; failures=$((failures + 1)); }
grep "intersection_right" "$results" | grep -q ",error," ||
  { echo "FAIL batch: the crashed run is not an error row"; cat "$results"; failures=$((failures + 1)); }
grep "intersection_right" "$results" | grep -qF "decider lib:$plugins/libsignalsim_faulty_segv.so crashed (SIGSEGV) at t=3.00 s" ||
  { echo "FAIL batch: the error row does not name the SUT and the step:"; grep intersection_right "$results"; failures=$((failures + 1)); }

if [ "$failures" -ne 0 ]; then echo "$failures failures"; exit 1; fi
echo "ok: every fault is one line naming the SUT; a crash in a batch is one error row"
