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
total=0

# case NAME ARGS... ; expects exit 2, one stderr line matching every PATTERN given after "--".
check() {
  local name=$1; shift
  total=$((total + 1))
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
check broken_net run "$bad/broken_net.yaml" -- "not_a_net.net.xml:1: not XML"
check unknown_parameter run "$bad/unknown_parameter.yaml" -- "unknown_parameter.yaml:6" "unknown parameter 'turn_signal_serch_time'"
check out_of_range_parameter run "$bad/out_of_range_parameter.yaml" -- "out_of_range_parameter.yaml:6" "turn_signal_search_time" "out of range"
check unknown_avoidance_policy run "$bad/unknown_avoidance_policy.yaml" -- "unknown_avoidance_policy.yaml:7" "candidate_path_turn_signal" "'when_stopped' is not one of none, stopped_candidate, all_candidate, stop_on_approval"
check negative_hold_duration run "$bad/negative_hold_duration.yaml" -- "negative_hold_duration.yaml:7" "turn_signal_on_approval_hold_duration" "out of range \[0, 60\]"
check negative_approval_delay run "$bad/negative_approval_delay.yaml" -- "negative_approval_delay.yaml:8" "approval_delay"
check pull_out_wait_while_moving run "$bad/pull_out_wait_while_moving.yaml" -- "pull_out_wait_while_moving.yaml:8: maneuvers: pull_out waits at its start" "needs ego.depart_speed 0"
check pull_out_wait_behind_departure run "$bad/pull_out_wait_behind_departure.yaml" -- "pull_out_wait_behind_departure.yaml:8: maneuvers: pull_out waits at its start, but its shift ends at s 5 m, behind the ego's base_link at departure (6.3 m)"
check bad_param_file run "$bad/bad_param_file.yaml" -- "bad_params.yaml:2" "turn_signal_on_swerving" "true or false"
check unknown_key run "$bad/unknown_key.yaml" -- "unknown_key.yaml:5" "unknown key 'ego.colour'"
check unknown_edge run "$bad/unknown_edge.yaml" -- "unknown_edge.yaml:4: ego.route: " "out_Q" "not in the net"
check unconnected_route run "$bad/unconnected_route.yaml" -- "unconnected_route.yaml:4: ego.route: " "in_S" "in_W" "not connected"
check junction_not_on_route run "$bad/junction_not_on_route.yaml" -- "junction_not_on_route.yaml" "junction 'Z'" "not on the ego's route"
check no_subcommand -- "signalsim"
check duplicate_key run "$bad/duplicate_key.yaml" -- "duplicate_key.yaml:7" "duplicate key 'ego.max_speed'"
check depart_beyond_edge run "$bad/depart_beyond_edge.yaml" -- "depart_beyond_edge.yaml" "ego.depart_pos" "beyond"
check bidi_two_lane_route run "$bad/bidi_two_lane_route.yaml" -- "bidi_two_lane_route.yaml:[0-9]*: ego.route: " "edge 'ab' (2 lanes) is bidirectional with 'ba'" "SUMO 1.15 aborts"
check omission_key_misspelt run "$bad/omission_key_misspelt.yaml" -- "omission_key_misspelt.yaml:6" "unknown key 'perception.omision_probability'"
check omission_out_of_range run "$bad/omission_out_of_range.yaml" -- "omission_out_of_range.yaml:6" "key 'perception.omission_probability'" "out of range"
check omission_interval_reversed run "$bad/omission_interval_reversed.yaml" -- "omission_interval_reversed.yaml:6" "key 'perception.omissions'" "start <= end"
check unknown_light_offset run "$bad/unknown_light_offset.yaml" -- "unknown_light_offset.yaml:3: light_offsets: 'ZZ' is not a traffic light of the net"
# A SUMO error mid-run, into a directory that holds a finished run: the old files must not survive.
"$bin" run "$src/scenarios/intersection_left.yaml" --out "$work/mid_run_sumo_error" --quiet >/dev/null
check mid_run_sumo_error run "$bad/mid_run_sumo_error.yaml" -- "mid_run_sumo_error.yaml" "Vehicle 'bad' has no valid route"
[ -f "$work/mid_run_sumo_error/events.csv" ] && { echo "FAIL mid_run_sumo_error: the old events.csv survived"; failures=$((failures + 1)); }

# What yaml-cpp reads but a scenario file may not hold: a second document, an unterminated quote,
# control characters (raw or as an escape).
check second_document run "$bad/second_document.yaml" -- "second_document.yaml:5: a second YAML document starts here; a scenario file holds one document"
check unterminated_quote run "$bad/unterminated_quote.yaml" -- "unterminated_quote.yaml:5: malformed YAML: the quoted text opened here has no closing \""
check unterminated_quote_first_line run "$bad/unterminated_quote_first_line.yaml" -- "unterminated_quote_first_line.yaml:1: malformed YAML: the quoted text opened here has no closing \""
check escaped_control_character run "$bad/escaped_control_character.yaml" -- "escaped_control_character.yaml:1: a text holds a control character (U+001B)"
check raw_control_character run "$bad/raw_control_character.yaml" -- "raw_control_character.yaml:1: a control character (U+001B at column 10)"

# The number rule (finite, no subnormal) wherever a number is read: light_offsets, parameter values
# (params.set, --set), perception intervals.
check subnormal_light_offset run "$bad/subnormal_light_offset.yaml" -- "subnormal_light_offset.yaml:3: key 'light_offsets.C': value 1e-310 is too small to be a number SUMO can read (below 2.2e-308); write 0"
check subnormal_parameter run "$bad/subnormal_parameter.yaml" -- "subnormal_parameter.yaml:7: parameter 'turn_signal_search_time': value 1e-310 is too small"
check subnormal_parameter_set run "$bad/unknown_edge.yaml" --set turn_signal_search_time=4e-320 -- "--set: parameter 'turn_signal_search_time': value 4e-320 is too small"
check subnormal_blackout run "$bad/subnormal_blackout.yaml" -- "subnormal_blackout.yaml:8: key 'perception.blackouts': value 1e-320 is too small"
check infinite_v2i_blackout run "$bad/infinite_v2i_blackout.yaml" -- "infinite_v2i_blackout.yaml:6: key 'perception.v2i.blackouts': expected a number, got '.inf'"

# Names: a scenario's may not be empty, a sweep's is one folder name (its output stays in out/);
# generate writes into no folder that holds what it did not write (left as it was).
check empty_name run "$bad/empty_name.yaml" -- "empty_name.yaml:1: key 'name': the name is empty"
check sweep_name_escapes sweep "$bad/sweep_name_escapes.yaml" -- "sweep_name_escapes.yaml:1: key 'name': '../../x' is not a folder name"
mkdir -p "$work/generate_foreign/notes" && echo mine > "$work/generate_foreign/notes.txt"
check generate_foreign generate "$src/sumo_nets/cross/cross.net.xml" --count 2 -- "generate_foreign/notes[.a-z]*: not written by signalsim generate"
[ "$(ls "$work/generate_foreign")" = "$(printf 'notes\nnotes.txt')" ] ||
  { echo "FAIL generate_foreign: the folder changed: $(ls "$work/generate_foreign")"; failures=$((failures + 1)); }

# The checks made against the net, at the line of the key at fault: obstacles, maneuvers, the depart
# lane, an option SUMO refuses, a parameter or vehicle_info file that is not there; a net defect at
# the net's line.
check obstacle_unknown_edge run "$bad/obstacle_unknown_edge.yaml" -- "obstacle_unknown_edge.yaml:7: obstacles: 'other': no edge 'nowhere'"
check avoid_unknown_obstacle run "$bad/avoid_unknown_obstacle.yaml" -- "avoid_unknown_obstacle.yaml:6: maneuvers: avoid 'nobody': no such obstacle"
check pull_over_off_route run "$bad/pull_over_off_route.yaml" -- "pull_over_off_route.yaml:7: maneuvers: pull_over: edge 'out_N' is not on the ego's route"
check depart_lane_missing run "$bad/depart_lane_missing.yaml" -- "depart_lane_missing.yaml:5: ego.depart_lane: edge 'in_S' has no lane 5"
check sumo_rejects_option run "$bad/sumo_rejects_option.yaml" -- "sumo_rejects_option.yaml:8: key 'sumo_args': --lateral-resolution wide: SUMO could not load the simulation: While processing option 'lateral-resolution': 'wide' is not a valid float"
check missing_parameter_file run "$bad/missing_parameter_file.yaml" -- "missing_parameter_file.yaml:6: key 'params.files': parameter file '.*nowhere.param.yaml' not found"
check missing_vehicle_info run "$bad/missing_vehicle_info.yaml" -- "missing_vehicle_info.yaml:5: key 'ego.vehicle_info': vehicle_info file '.*nowhere/vehicle_info.param.yaml' not found"
check blinker_never_bad run "$bad/blinker_never_bad.yaml" -- "blinker_never_bad.yaml:6: key 'expect\[0\].blinker_never.blinker': 'sideways' is not one of"
check edge_without_lanes run "$bad/edge_without_lanes.yaml" -- "edge_without_lanes.net.xml:37: edge 'ab': the edge has no <lane> (a route edge) in ego.route of"

# Input files that are folders, named pipes or devices say what they are (and a pipe never blocks);
# a gzip net that inflates beyond the limit (a bomb: 600 MiB of zeros in 0.6 MB) stops at the limit.
mkfifo "$work/pipe.yaml"
check scenario_fifo run "$work/pipe.yaml" -- "pipe.yaml: scenario file is a named pipe (FIFO), not a file"
check net_folder run "$bad/unknown_edge.yaml" --set "net=$src/sumo_nets" -- "key 'net': net file '$src/sumo_nets' is a folder, not a file"
check params_device run "$bad/unknown_edge.yaml" --params /dev/zero -- "^signalsim: /dev/zero: parameter file is a device, not a file$"
head -c 600M /dev/zero | gzip -1 > "$work/bomb.net.xml.gz"
printf 'name: bomb\nnet: bomb.net.xml.gz\nego:\n  route: [a]\n' > "$work/bomb.yaml"
check net_gzip_bomb run "$work/bomb.yaml" -- "bomb.net.xml.gz: inflates to more than 512 MiB, the most a net"
rm -f "$work/bomb.net.xml.gz"

# A value --set gave is named as the command line's, not as a line of the scenario file.
check set_net_missing run "$bad/unknown_edge.yaml" --set net=nowhere.net.xml -- "^signalsim: --set net=nowhere.net.xml: key 'net': net file '.*nowhere.net.xml' not found$"
check set_out_of_range run "$bad/unknown_edge.yaml" --set ego.max_speed=500 -- "^signalsim: --set ego.max_speed=500: key 'ego.max_speed': value 500 is out of range"
check set_route_not_in_net run "$bad/unknown_edge.yaml" --set "ego.route=[in_S, nowhere]" -- "^signalsim: --set ego.route=\[in_S, nowhere\]: ego.route: route edge 'nowhere' is not in the net"
check set_blackout_reversed run "$bad/unknown_edge.yaml" --set "perception.blackouts=[[5, 1]]" -- "^signalsim: --set perception.blackouts=\[\[5, 1\]\]: key 'perception.blackouts'"

# check: a --golden folder that is missing, not a folder or holds none of the scenarios' golden files,
# and a folder --update or --junit cannot write into: one line before any run (no results.csv).
left=$src/scenarios/intersection_left.yaml
check golden_missing check "$left" --golden "$work/nowhere" -- "--golden: folder '$work/nowhere' not found"
check golden_not_a_folder check "$left" --golden "$bad/unknown_key.yaml" -- "--golden: '$bad/unknown_key.yaml' is not a folder"
mkdir -p "$work/golden_empty"
check golden_empty check "$left" --golden "$work/golden_empty" -- "--golden: folder '$work/golden_empty' does not hold the scenario's golden file (intersection_left.events.csv)"
check update_unwritable check "$left" --golden "$bad/unknown_key.yaml/golden" --update -- "--update: cannot create the folder '$bad/unknown_key.yaml/golden'"
check junit_unwritable check "$left" --golden "$src/tests/golden" --junit "$bad/unknown_key.yaml/check.xml" -- "--junit: cannot create the folder '$bad/unknown_key.yaml'"
for name in golden_missing golden_not_a_folder golden_empty update_unwritable junit_unwritable; do
  [ -e "$work/$name/results.csv" ] && { echo "FAIL $name: runs were made"; failures=$((failures + 1)); }
done

# The user's SUMO files: a missing or net-less sumocfg, ego ids, contradicting keys, refused options.
check missing_sumocfg run "$bad/missing_sumocfg.yaml" -- "missing_sumocfg.yaml:2" "key 'sumocfg'" "nowhere.sumocfg' not found"
check sumocfg_without_net run "$bad/sumocfg_without_net.yaml" -- "sumocfg_without_net.yaml:2" "no_net.sumocfg' names no net-file"
check unknown_ego_id run "$bad/unknown_ego_id.yaml" -- "unknown_ego_id.yaml:4" "ego.id 'veh99'" "demand.rou.xml"
check trip_as_ego run "$bad/trip_as_ego.yaml" -- "demand.rou.xml:13" "<trip> 'trip7'" "no edges of its own"
check ego_contradicts_vtype run "$bad/ego_contradicts_vtype.yaml" -- "ego_contradicts_vtype.yaml:5" "ego.length 4.5 contradicts vehicle 'veh42'" "demand.rou.xml:10" "vType 'sedan' has 4.8"
check ego_route_contradicts run "$bad/ego_route_contradicts.yaml" -- "ego_route_contradicts.yaml:5" "ego.route \[in_S out_N\] contradicts" "\[in_S out_W\]"
check forbidden_sumo_arg run "$bad/forbidden_sumo_arg.yaml" -- "forbidden_sumo_arg.yaml:3" "SUMO option 'step-length' is set by signalsim"
check route_file_has_ego run "$bad/route_file_has_ego.yaml" -- "ego_id_taken.rou.xml:2" "<vehicle> 'ego' has the id signalsim gives the ego"
# The back-ends: nothing listens on the port (one bound and released here), no display for sumo-gui.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
check refused_port run "$src/scenarios/intersection_left.yaml" --connect "127.0.0.1:$port" -- "cannot connect to SUMO at 127.0.0.1:$port" "connection refused or host unreachable"
check bad_connect_address run "$src/scenarios/intersection_left.yaml" --connect nowhere -- "--connect" "not HOST:PORT"
check empty_connect run "$src/scenarios/intersection_left.yaml" --connect "" -- "signalsim: --connect: '' is not HOST:PORT"
check traci_timeout_without_connect run "$src/scenarios/intersection_left.yaml" --traci-timeout 5 -- "--traci-timeout" "only applies with --connect"
# A peer that is not SUMO (tests/integration/traci_peer.py: four zero bytes), stopped by its PID.
/usr/bin/python3 "$src/tests/integration/traci_peer.py" zeros "$work/peer_port" &
peer=$!
for _ in $(seq 200); do [ -s "$work/peer_port" ] && break; sleep 0.05; done
check not_a_traci_peer run "$src/scenarios/intersection_left.yaml" --connect "127.0.0.1:$(cat "$work/peer_port")" -- \
  "intersection_left.yaml: something at 127.0.0.1:$(cat "$work/peer_port") is not a TraCI server: it sent a message length of 0 bytes"
kill "$peer" 2>/dev/null
wait "$peer" 2>/dev/null
DISPLAY= check gui_without_display run "$src/scenarios/intersection_left.yaml" --gui -- "--gui needs a display" "DISPLAY is not set"

# The line the README promises, of the scenario or of the net (one block).
check light_not_on_route run "$bad/light_not_on_route.yaml" -- "light_not_on_route.yaml:7: expect\[1\]: traffic light 'ZZ' is not on the ego's route"
check depart_beyond_edge_line run "$bad/depart_beyond_edge.yaml" -- "depart_beyond_edge.yaml:5: ego.depart_pos: 500 m is beyond the end of edge"
check turn_signal_distance_abc run "$bad/turn_signal_distance_abc.yaml" -- "turn_signal_distance_abc.net.xml:40: lane 'ab_0': param 'turn_signal_distance' is not a number: 'abc'" "in ego.route of"
total=$((total + 1))
if "$bin" inspect "$bad/turn_signal_distance_abc.net.xml" 2>&1 | grep -q "40.*lane 'ab_0'.*param 'turn_signal_distance' is not a number: 'abc'"; then
  echo "ok   inspect_lists_turn_signal_distance_defect"
else
  echo "FAIL inspect_lists_turn_signal_distance_defect: $("$bin" inspect "$bad/turn_signal_distance_abc.net.xml" 2>&1 | grep -i defect)"
  failures=$((failures + 1))
fi

echo "$((total - failures)) passed, $failures failed"
[ $failures -eq 0 ]
