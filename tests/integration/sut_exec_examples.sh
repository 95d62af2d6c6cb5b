#!/usr/bin/env bash
# exec: systems under test that work, on the real libsumo (docs/decider.md "JSON lines"):
# - examples/python_decider/decider.py agrees with the reference at every row (timeline `blinker` ==
#   `ref_blinker`) on every bundled scenario whose only signal sections are intersection turns;
# - examples/python_light_judge/judge.py stops the ego before the line at a red light
#   (tl_red_stop_then_go) and lets it pass on green (tl_green_pass);
# - the messages of real runs (both roles) validate against `signalsim schema decider-request`,
#   `light-judge-request`, and the replies against `decider-reply`, `light-judge-reply` (needs
#   python3-jsonschema, which tools/setup installs; that part is skipped without it).
# usage: sut_exec_examples.sh SIGNALSIM_BINARY SOURCE_DIR   (ONLY=GLOB: only the scenarios GLOB.yaml for the decider)
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# Intersection turns only: no roundabout, no maneuver (lane change, avoidance, pull out or over).
decider="exec:python3 $src/examples/python_decider/decider.py"
for path in "$src"/scenarios/${ONLY:-*}.yaml; do
  name=$(basename "$path" .yaml)
  grep -qE 'roundabout|maneuvers:|lane_change|avoid|pull_out|pull_over' "$path" && continue
  "$bin" run "$path" --out "$work/$name" --quiet --set "decider=$decider" >"$work/$name.log" 2>&1
  rc=$?
  [ "$rc" -le 1 ] || { fail "$name: exit $rc: $(cat "$work/$name.log")"; continue; }
  python3 - "$work/$name/timeline.csv" "$name" <<'PY' || fail "$name: the decider differs from the reference"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bad = [r["time"] for r in rows if r["blinker"] != r["ref_blinker"]]
turns = sum(r["ref_blinker"] in ("left", "right") for r in rows)
print("%s %s: %d rows, %d with a turn blinker, %d differ %s" % ("FAIL" if bad else "ok  ", sys.argv[2], len(rows), turns, len(bad), bad[:5]))
sys.exit(1 if bad or not rows else 0)
PY
done

judge="exec:python3 $src/examples/python_light_judge/judge.py"
"$bin" run "$src/scenarios/tl_red_stop_then_go.yaml" --out "$work/red" --quiet --set "light_judge=$judge" >"$work/red.log" 2>&1 ||
  fail "tl_red_stop_then_go: exit $?: $(cat "$work/red.log")"
"$bin" run "$src/scenarios/tl_green_pass.yaml" --out "$work/green" --quiet --set "light_judge=$judge" >"$work/green.log" 2>&1 ||
  fail "tl_green_pass: exit $?: $(cat "$work/green.log")"
python3 - "$work/red" "$work/green" <<'PY' || fail "the Python light judge"
import csv, json, sys
red = list(csv.DictReader(open(sys.argv[1] + "/timeline.csv")))
stops = [r for r in red if float(r["speed"]) == 0.0]
ok = bool(stops) and all(float(r["stop_distance"]) >= 0.0 for r in stops) and stops[0]["tl_decision"] == "stop" \
     and stops[0]["tl_reason"] == "red or amber circle" and not json.load(open(sys.argv[1] + "/summary.json"))["lights"]["red_light_violations"] \
     if stops else False
print("%s red: at rest %s s from t=%s, %s m before the stop line" % (
    "ok  " if ok else "FAIL", len(stops) / 10, stops[0]["time"] if stops else "-", stops[0]["stop_distance"] if stops else "-"))
green = list(csv.DictReader(open(sys.argv[2] + "/timeline.csv")))
passed = min(float(r["speed"]) for r in green) > 10.0 and all(r["tl_decision"] != "stop" for r in green)
print("%s green: never below %.2f m/s, never told to stop" % ("ok  " if passed else "FAIL", min(float(r["speed"]) for r in green)))
sys.exit(0 if ok and passed else 1)
PY

if python3 -c 'import jsonschema' 2>/dev/null; then
  for role in decider light_judge; do
    kind=${role/_/-}
    "$bin" schema "$kind-request" >"$work/$kind-request.json" || fail "schema $kind-request: exit $?"
    "$bin" schema "$kind-reply" >"$work/$kind-reply.json" || fail "schema $kind-reply: exit $?"
  done
  "$bin" run "$src/scenarios/tl_two_lights_close_red.yaml" --out "$work/rec_d" --quiet \
    --set "decider=exec:python3 $src/tests/data/sut/record.py decider $work/decider.log"
  [ $? -le 1 ] || fail "recording the decider's messages"
  "$bin" run "$src/scenarios/tl_two_lights_close_red.yaml" --out "$work/rec_j" --quiet \
    --set "light_judge=exec:python3 $src/tests/data/sut/record.py light_judge $work/judge.log"
  [ $? -le 1 ] || fail "recording the judge's messages"  # it goes at every light: the run may fail
  # A run with planned maneuvers: shift lines in hello, behaviour requests in the steps.
  "$bin" run "$src/scenarios/avoidance_left.yaml" --out "$work/rec_m" --quiet \
    --set "decider=exec:python3 $src/tests/data/sut/record.py decider $work/maneuver.log" >/dev/null
  v=$src/tests/data/sut/validate_messages.py
  python3 "$v" "$work/decider-request.json" "$work/decider.log" "$work/decider-reply.json" \
    '{"blinker": "none"};{"blinker": "hazard"}' '{"blinkers": "left"};{"blinker": "up"};[]' || fail "decider messages"
  python3 "$v" "$work/decider-request.json" "$work/maneuver.log" "$work/decider-reply.json" '' '' || fail "decider messages (maneuver)"
  python3 "$v" "$work/light-judge-request.json" "$work/judge.log" "$work/light-judge-reply.json" \
    '{"lights": []};{"lights": [{"tls_id": "C", "decision": "stop", "reason": "red"}]}' \
    '{"decision": "go"};{"lights": [{"tls_id": "C", "decision": "maybe"}]};{"lights": [{"decision": "go"}]}' || fail "light judge messages"
else
  echo "skipped: the schema part (python3 has no jsonschema module; tools/setup installs python3-jsonschema)"
fi

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "the exec: examples agree with the reference; the messages follow their schemas"
