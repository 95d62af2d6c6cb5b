#!/usr/bin/env bash
# The bundled autoware_core decider on the real libsumo (docs/autoware_core.md): three bundled
# scenarios with decider=autoware_core; its blinker sections (front s on..off [m], timeline.csv's
# `blinker`, listed by tools/sut_blinker_diff) are path_generator's, the reference's in shadow
# (`ref_blinker`) its own:
#   close_turns: left on 71 m before :A_3_0, handed to the right turn :B_2_0 at the left lanelet's
#     required end (base_link 203.60), 1.6 m later than the reference; right to :B_2_0's end
#   roundabout_de_exit2: the entry :RS_0_0 right until its required end, the ring-internal :RE_2_0
#     (straight) off, the exit :RN_1_0 right from :RE_2_0's required end to the exit lanelet's end;
#     the reference (de preset) only the exit signal
#   lane_change_right: no blinker (path_generator has no lane-change module)
# usage: autoware_core_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$bin" batch "$src/scenarios/close_turns.yaml" "$src/scenarios/roundabout_de_exit2.yaml" \
  "$src/scenarios/lane_change_right.yaml" --out "$work/out" --jobs 2 --set decider=autoware_core \
  > "$work/log" 2>&1
code=$?
[ $code -eq 0 ] || [ $code -eq 1 ] || fail "batch: exit code $code ($(cat "$work/log"))"
grep -q "0 errors" "$work/log" || fail "a run ended as an error: $(cat "$work/log")"
python3 "$src/tools/sut_blinker_diff" "$work/out" --all > "$work/diff" || fail "sut_blinker_diff: $(cat "$work/diff")"

expect() {  # run name, the line expected after it
  grep -A2 "^$1: " "$work/diff" | grep -qxF "  $2" || fail "$1: expected '$2' in: $(cat "$work/diff")"
}
expect 0000-close_turns "sut: left 122.203..207.319 right 207.319..260.421"
expect 0000-close_turns "ref: left 122.203..205.719 right 205.719..260.421"
expect 0001-roundabout_de_exit2 "sut: right 146.853..225.719 right 255.567..283.987"
expect 0001-roundabout_de_exit2 "ref: right 272.311..283.987"
expect 0002-lane_change_right "sut: none"
expect 0002-lane_change_right "ref: right 13.523..106.493"

# Deterministic: a second run gives byte-identical timelines.
"$bin" batch "$src/scenarios/close_turns.yaml" --out "$work/again" --set decider=autoware_core > /dev/null 2>&1
cmp -s "$work/out/runs/0000-close_turns/timeline.csv" "$work/again/runs/0000-close_turns/timeline.csv" ||
  fail "close_turns: timeline.csv differs between two runs"
echo "autoware_core: path_generator's blinker on close_turns, roundabout_de_exit2, lane_change_right"
