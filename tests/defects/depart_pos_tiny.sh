#!/usr/bin/env bash
# Defect 6: a number SUMO cannot read - a subnormal such as 1e-308, which its strtod-based parser
# refuses as out of range - passed signalsim's checks and then failed in SUMO with its own two-line
# message. It is refused where it is written (file and line), on one line; 0 and the smallest normal
# double still run.
set -u
source "$(dirname "$0")/lib.sh" "$@"
s=$src/scenarios/tl_red_stop_then_go.yaml

bad_input depart_pos_set "^signalsim: --set ego.depart_pos=1e-308: key 'ego.depart_pos': value 1e-308 is too small to be a number SUMO can read" \
  -- run "$s" --set ego.depart_pos=1e-308
bad_input depart_speed_set "^signalsim: --set ego.depart_speed=4.9e-324: key 'ego.depart_speed': value 4.9e-324 is too small" \
  -- run "$s" --set ego.depart_speed=4.9e-324
scenario_copy tl_red_stop_then_go "$work/file.yaml"
sed -i 's/^  depart_pos: 0$/  depart_pos: -1e-310/' "$work/file.yaml"
bad_input depart_pos_file "file.yaml:11: key 'ego.depart_pos': value -1e-310 is too small" -- run "$work/file.yaml"
scenario_copy avoidance_left "$work/obstacle.yaml"
sed -i 's/pos: 120,/pos: 1e-320,/' "$work/obstacle.yaml"
line=$(grep -n "pos: 1e-320" "$work/obstacle.yaml" | cut -d: -f1)
[ -n "$line" ] || fail "test setup: no obstacle pos in avoidance_left"
bad_input obstacle_pos "obstacle.yaml:$line: key 'obstacles\[0\].pos': value 1e-320 is too small" -- run "$work/obstacle.yaml"

for v in 0 2.2250738585072014e-308 1e-300; do
  "$bin" run "$s" --set ego.depart_pos=$v --out "$work/ok" --quiet 2>"$work/ok.err"
  code=$?
  [ $code -eq 0 ] || fail "depart_pos $v: exit code $code ($(cat "$work/ok.err"))"
done
ok "depart_pos 0, 2.2250738585072014e-308 and 1e-300 run"
finish
