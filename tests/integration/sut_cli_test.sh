#!/usr/bin/env bash
# --decider, --light-judge and --sut-timeout on the command line (docs/decider.md), with no system under
# test needed: a bad value is one line naming the flag (or the sweep file and line), exit 2, for every
# command that takes them; run --driver sumo with a SUT is refused; a sweep that sweeps decider refuses
# --decider; and naming the reference changes nothing: the outputs are byte-identical to a run without.
# usage: sut_cli_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
scenario=$src/scenarios/intersection_left.yaml

# bad NAME PATTERN COMMAND...: exit 2, one stderr line containing PATTERN.
bad() {
  local name=$1 pattern=$2
  shift 2
  "$@" >"$work/$name.stdout" 2>"$work/$name.stderr"
  local code=$? lines
  lines=$(wc -l <"$work/$name.stderr")
  if [ "$code" -eq 2 ] && [ "$lines" -eq 1 ] && grep -qF -- "$pattern" "$work/$name.stderr"; then
    echo "ok   $name: $(cat "$work/$name.stderr")"
  else
    echo "FAIL $name: exit $code, $lines stderr lines, want 2 and 1 line with '$pattern':"
    cat "$work/$name.stderr"
    failures=$((failures + 1))
  fi
}

for cmd in run batch check compare; do
  extra=()
  [ "$cmd" = check ] && extra=(--golden "$work/golden")
  bad "${cmd}_decider" "--decider: 'magic' is not a decider" "$bin" $cmd "$scenario" "${extra[@]}" --out "$work/o" --decider magic
  bad "${cmd}_decider_empty_lib" "--decider: lib: needs the shared library's path" "$bin" $cmd "$scenario" "${extra[@]}" --out "$work/o" --decider lib:
  bad "${cmd}_judge" "--light-judge: autoware_core is a decider" "$bin" $cmd "$scenario" "${extra[@]}" --out "$work/o" --light-judge autoware_core
  bad "${cmd}_judge_exec" "--light-judge: exec: needs a command" "$bin" $cmd "$scenario" "${extra[@]}" --out "$work/o" --light-judge "exec: "
  bad "${cmd}_timeout" "--sut-timeout: 0 is out of range" "$bin" $cmd "$scenario" "${extra[@]}" --out "$work/o" --sut-timeout 0
done
bad sweep_flag "--decider: 'magic' is not a decider" "$bin" sweep "$src/tests/batch/data/sweep_3x3x2.yaml" --out "$work/o" --decider magic

# SUMO driving leaves nothing to decide: refused whether the flag or the scenario names the SUT.
bad driver_sumo_flag "--driver: --driver sumo lets SUMO decide, so the decider under test 'lib:my.so'" \
  "$bin" run "$scenario" --out "$work/o" --driver sumo --decider lib:my.so
bad driver_sumo_key "--driver: --driver sumo lets SUMO decide, so the light_judge under test 'exec:./judge'" \
  "$bin" run "$scenario" --out "$work/o" --driver sumo --set "light_judge=exec:./judge"

# Sweep files: a swept decider is checked at its line; --decider cannot replace a swept one.
cat >"$work/sweep_bad.yaml" <<YAML
scenarios: $scenario
grid:
  country: [jp, de]
  decider:
    - reference
    - "lib:"
YAML
bad sweep_bad_value "sweep_bad.yaml:6: grid.decider: lib: needs the shared library's path" \
  "$bin" sweep "$work/sweep_bad.yaml" --out "$work/o"
cat >"$work/sweep_deciders.yaml" <<YAML
scenarios: $scenario
grid:
  decider: [reference, autoware_core]
YAML
bad sweep_and_flag "--decider: the sweep file $work/sweep_deciders.yaml sweeps decider itself" \
  "$bin" sweep "$work/sweep_deciders.yaml" --out "$work/o" --decider reference
"$bin" sweep "$work/sweep_deciders.yaml" --list >"$work/list.txt" 2>&1
if grep -q "decider=autoware_core" "$work/list.txt" && [ "$(wc -l <"$work/list.txt")" -eq 2 ]; then
  echo "ok   sweep_list: $(tr '\n' '|' <"$work/list.txt")"
else
  echo "FAIL sweep_list:"; cat "$work/list.txt"; failures=$((failures + 1))
fi

# Naming the reference is no SUT: the same files, byte for byte, and no decider column.
"$bin" run "$scenario" --out "$work/plain" --quiet || { echo "FAIL plain run"; failures=$((failures + 1)); }
"$bin" run "$scenario" --out "$work/named" --quiet --decider reference --light-judge reference --sut-timeout 2 ||
  { echo "FAIL named run"; failures=$((failures + 1)); }
for f in timeline.csv events.csv summary.json; do
  if cmp -s "$work/plain/$f" "$work/named/$f"; then echo "ok   reference_named_$f: identical"
  else echo "FAIL reference_named_$f differs"; failures=$((failures + 1)); fi
done
"$bin" batch "$scenario" --out "$work/batch" --quiet --decider reference >/dev/null 2>&1
if head -1 "$work/batch/results.csv" | grep -q decider; then
  echo "FAIL batch_reference: results.csv has a decider column"; failures=$((failures + 1))
else
  echo "ok   batch_reference: no decider column"
fi

if [ $failures -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "all passed"
