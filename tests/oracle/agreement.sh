#!/usr/bin/env bash
# signalsim's blinker at every step equals an independent Python restatement of docs/behaviour.md §T4-§T7
# (tests/oracle/roundabout_oracle.py) on every roundabout and intersection scenario without
# `maneuvers:` (the oracle restates neither the behaviour modules of docs/behaviour.md §T8 nor lane plans with
# requested lane changes; those scenarios are checked by tests/integration/maneuver_scenarios_test.cpp).
# usage: agreement.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0
for scenario in "$src"/scenarios/roundabout_*.yaml "$src"/scenarios/intersection_*.yaml \
                "$src"/scenarios/close_turns.yaml "$src"/scenarios/t_junction_left.yaml \
                "$src"/scenarios/turn_signal_distance_override.yaml; do
  name=$(basename "$scenario" .yaml)
  if grep -q '^maneuvers:' "$scenario"; then echo "skip $name: has maneuvers"; continue; fi
  "$bin" run "$scenario" --out "$work/$name" --quiet >/dev/null 2>&1
  if python3 "$src/tests/oracle/roundabout_oracle.py" "$scenario" --timeline "$work/$name/timeline.csv" \
       >"$work/$name.oracle" 2>&1; then
    passed=$((passed + 1)); echo "ok   $name: $(grep 'rows agree' "$work/$name.oracle" | sed 's/^ *//')"
  else
    failed=$((failed + 1)); echo "FAIL $name"; tail -12 "$work/$name.oracle"
  fi
done
echo "$passed passed, $failed failed"
[ $failed -eq 0 ] && [ $passed -gt 0 ]
