#!/usr/bin/env bash
# Defect 1: a step_length that is not a whole number of milliseconds is refused (exit 2, its line):
# SUMO rounds it to whole ms while the planner integrated the value as written, and with 0.0015 s
# the ego of tl_red_stop_then_go crossed its stop line on red.
set -u
source "$(dirname "$0")/lib.sh" "$@"
red=$src/scenarios/tl_red_stop_then_go.yaml

bad_input set_0_0015 "^signalsim: --set step_length=0.0015: key 'step_length': 0.0015 s is not a whole number of milliseconds" \
  "round it to 0.002 s" -- run "$red" --set step_length=0.0015
scenario_copy tl_red_stop_then_go "$work/in_file.yaml"
sed -i 's/^step_length: 0.1$/step_length: 0.0505/' "$work/in_file.yaml"
bad_input in_file "in_file.yaml:6: key 'step_length': 0.0505 s is not a whole number of milliseconds" -- run "$work/in_file.yaml"
# In a sweep the value's own line is named, and nothing runs.
cat > "$work/sweep.yaml" <<YAML
scenarios: [$red]
grid:
  step_length: [0.1, 0.0015]
YAML
bad_input sweep_value "sweep.yaml:3: grid.step_length: value 0.0015: .*whole number of milliseconds" -- sweep "$work/sweep.yaml"
[ -e "$work/sweep_value/results.csv" ] && fail "the sweep ran although a value is refused"

# Whole milliseconds still run, and the ego stops for the red light (0.002 s and 0.05 s).
for step in 0.002 0.05; do
  "$bin" run "$red" --set step_length=$step --out "$work/ok_$step" --quiet 2>"$work/ok_$step.err"
  code=$?
  [ $code -eq 0 ] || fail "step_length $step: exit code $code ($(cat "$work/ok_$step.err"))"
  grep -q '"red_light_violations": 0' "$work/ok_$step/summary.json" || fail "step_length $step: a red-light violation"
done
ok "whole milliseconds (0.002 s, 0.05 s) run and stop at the red light"
finish
