#!/usr/bin/env bash
# Systems under test keep signalsim's determinism (docs/decider.md): the same scenarios with a
# JSON-lines decider (examples/python_decider), the C ABI example's light judge and the bundled
# autoware_core give byte-identical outputs with one worker and with two (tests/batch/same_outputs.py:
# results.csv and every file of every run directory).
# usage: sut_determinism_test.sh SIGNALSIM_BINARY SOURCE_DIR EXAMPLE_PLUGIN
set -u
bin=$1
src=$2
plugin=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scenarios=()
for name in intersection_left tl_red_stop_then_go roundabout_de_exit2 lane_change_right; do
  scenarios+=("$src/scenarios/$name.yaml")
done
failures=0
for suts in "decider=exec:python3 $src/examples/python_decider/decider.py|light_judge=lib:$plugin" \
            "decider=autoware_core|light_judge=reference"; do
  IFS='|' read -r decider judge <<<"$suts"
  for jobs in 1 2; do
    "$bin" batch "${scenarios[@]}" --out "$work/out$jobs" --jobs "$jobs" --quiet --set "$decider" --set "$judge" \
      >"$work/log$jobs" 2>&1
    rc=$?
    [ "$rc" -le 1 ] || { echo "FAIL $decider $judge --jobs $jobs: exit $rc: $(tail -3 "$work/log$jobs")"; failures=$((failures + 1)); }
  done
  grep -q ",error," "$work/out1/results.csv" && { echo "FAIL $decider: an error row"; failures=$((failures + 1)); }
  if python3 "$src/tests/batch/same_outputs.py" "$work/out1" "$work/out2"; then
    echo "ok   $decider $judge: --jobs 1 and --jobs 2 byte-identical"
  else
    echo "FAIL $decider $judge: outputs differ between --jobs 1 and 2"
    failures=$((failures + 1))
  fi
  rm -rf "$work/out1" "$work/out2"
done
exit $((failures > 0))
