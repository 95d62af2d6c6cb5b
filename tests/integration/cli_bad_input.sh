#!/usr/bin/env bash
# Bad input gives exit code 2, exactly one line on stderr naming the file, the key and the reason,
# and no output directory content presented as complete.
# usage: cli_bad_input.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
bad=$src/tests/data/bad
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# case NAME ARGS... ; expects exit 2, one stderr line matching every PATTERN given after "--".
check() {
  local name=$1; shift
  local args=() patterns=()
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do args+=("$1"); shift; done
  shift
  patterns=("$@")
  local out=$work/$name
  "$bin" "${args[@]}" --out "$out" >"$work/$name.stdout" 2>"$work/$name.stderr"
  local code=$?
  local lines
  lines=$(wc -l <"$work/$name.stderr")
  local ok=1
  [ "$code" -eq 2 ] || { echo "FAIL $name: exit code $code, want 2"; ok=0; }
  [ "$lines" -eq 1 ] || { echo "FAIL $name: $lines stderr lines, want 1"; cat "$work/$name.stderr"; ok=0; }
  for p in "${patterns[@]}"; do
    grep -q -- "$p" "$work/$name.stderr" || { echo "FAIL $name: stderr lacks '$p': $(cat "$work/$name.stderr")"; ok=0; }
  done
  if [ -f "$out/summary.json" ] && ! grep -q '"status": "error"' "$out/summary.json"; then
    echo "FAIL $name: a summary.json presents the run as complete"; ok=0
  fi
  [ -f "$out/timeline.csv" ] && { echo "FAIL $name: timeline.csv written"; ok=0; }
  if [ $ok -eq 1 ]; then echo "ok   $name: $(cat "$work/$name.stderr")"; else failures=$((failures + 1)); fi
}

check missing_scenario run "$bad/does_not_exist.yaml" -- "does_not_exist.yaml" "not found"
check malformed_yaml run "$bad/malformed.yaml" -- "malformed.yaml:" "malformed YAML"
check missing_net run "$bad/missing_net.yaml" -- "missing_net.yaml:" "key 'net'" "not found"
check broken_net run "$bad/broken_net.yaml" -- "not_a_net.net.xml"
check unknown_parameter run "$bad/unknown_parameter.yaml" -- "unknown_parameter.yaml:6" "unknown parameter 'turn_signal_serch_time'"
check out_of_range_parameter run "$bad/out_of_range_parameter.yaml" -- "out_of_range_parameter.yaml:6" "turn_signal_search_time" "out of range"
check bad_param_file run "$bad/bad_param_file.yaml" -- "bad_params.yaml:2" "turn_signal_on_swerving" "true or false"
check unknown_key run "$bad/unknown_key.yaml" -- "unknown_key.yaml:5" "unknown key 'ego.colour'"
check unknown_edge run "$bad/unknown_edge.yaml" -- "unknown_edge.yaml" "out_Q" "not in the net"
check unconnected_route run "$bad/unconnected_route.yaml" -- "unconnected_route.yaml" "in_S" "in_W" "not connected"
check junction_not_on_route run "$bad/junction_not_on_route.yaml" -- "junction_not_on_route.yaml" "junction 'Z'" "not on the ego's route"
check no_subcommand -- "signalsim"
check duplicate_key run "$bad/duplicate_key.yaml" -- "duplicate_key.yaml:7" "duplicate key 'ego.max_speed'"
check depart_beyond_edge run "$bad/depart_beyond_edge.yaml" -- "depart_beyond_edge.yaml" "ego.depart_pos" "beyond"
check unknown_light_offset run "$bad/unknown_light_offset.yaml" -- "unknown_light_offset.yaml" "light_offsets" "'ZZ'"
# A SUMO error mid-run, into a directory that holds a finished run: the old files must not survive.
"$bin" run "$src/scenarios/intersection_left.yaml" --out "$work/mid_run_sumo_error" --quiet >/dev/null
check mid_run_sumo_error run "$bad/mid_run_sumo_error.yaml" -- "mid_run_sumo_error.yaml" "Vehicle 'bad' has no valid route"
[ -f "$work/mid_run_sumo_error/events.csv" ] && { echo "FAIL mid_run_sumo_error: the old events.csv survived"; failures=$((failures + 1)); }

echo "$((16 - failures)) passed, $failures failed"
[ $failures -eq 0 ]
