#!/usr/bin/env bash
# A user's own SUMO files, through the command line on the real libsumo:
#  - a .sumocfg with route files and vehicle types: its net, routes, additional files, step length,
#    end and seed are used, its own log option is ignored (listed), its relative tripinfo output
#    lands in --out; vehicle veh42 of its route file is taken over as the ego (route, vType, departure
#    SUMO's; base_link_to_front from the length) and summary.json says where each value came from;
#  - sumo_args: SUMO's FCD output with signals, whose signals are the timeline's sumo_signals;
#  - SUMO's messages in OUT/sumo.log, its warnings counted in summary.json.
# usage: user_sumo_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
data=$src/tests/data/user_sumo
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

"$bin" run "$data/take_over.yaml" --out "$work/take_over" --quiet || fail "take_over: exit code $?"
python3 - "$work/take_over" <<'PY' || fail "take_over: summary"
import json, os, sys
out = sys.argv[1]
s = json.load(open(os.path.join(out, "summary.json")))
ego = s["ego"]
assert s["status"] == "passed", s["status"]
assert (ego["id"], ego["taken_over"], ego["type"]) == ("veh42", True, "sedan"), ego
assert (ego["length"], ego["width"], ego["max_speed"], ego["accel"], ego["emergency_decel"], ego["type_decel"]) == \
    (4.8, 1.9, 12.5, 2.0, 8.0, 4.0), ego                    # vtypes.add.xml's sedan
assert ego["base_link_to_front"] == round(4.8 * 3.7 / 4.5, 3), ego  # the length rule
assert 5.0 <= ego["depart_time"] <= 5.2 and ego["depart_speed"] == 8.0, ego  # its route file's departure
assert ego["source"]["length"] == "vType 'sedan'" and ego["source"]["route"] == "route file", ego["source"]
assert ego["source"]["base_link_to_front"] == "length x 3.7/4.5", ego["source"]
assert s["route"]["edges"] == ["in_S", "out_W"], s["route"]
cfg = s["sumo"]["sumocfg_used"]
assert "seed 7" in cfg["used"] and "end 120" in cfg["used"], cfg
assert any(i.startswith("log (line 26)") for i in cfg["ignored"]), cfg
assert s["seed"] == 7 and s["duration"] == 120, (s["seed"], s["duration"])
assert os.path.basename(s["sumo"]["route_files"][0]) == "demand.rou.xml", s["sumo"]
# the sumocfg's relative tripinfo output is in --out, with the other vehicles and the ego
trips = open(os.path.join(out, "tripinfo.xml")).read()
assert 'id="veh42"' in trips and 'id="veh40"' in trips, "tripinfo.xml"
assert os.path.isfile(os.path.join(out, "sumo.log"))
PY
[ -e "$data/tripinfo.xml" ] && fail "the sumocfg's output was written beside it, not into --out"
[ -e "$data/user_sumo.log" ] && fail "the sumocfg's own log option was not ignored"

# A flow's vehicle, departLane="best": SUMO chose lane 1 of in_W, which leads on: no lane change.
"$bin" run "$data/take_over_flow.yaml" --out "$work/flow" --quiet || fail "take_over_flow: exit code $?"
python3 - "$work/flow/summary.json" <<'PY' || fail "take_over_flow: summary"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["ego"]["id"] == "east.0" and s["ego"]["depart_lane"] == 1, s["ego"]
assert s["route"]["lane_changes"] == 0 and s["lane_changes"] == [], (s["route"], s["lane_changes"])
assert s["counts"]["arrived"], s["counts"]
PY

"$bin" run "$data/fcd_signals.yaml" --out "$work/fcd" --quiet || fail "fcd_signals: exit code $?"
python3 - "$work/fcd" <<'PY' || fail "fcd_signals: SUMO's FCD signals differ from the timeline's sumo_signals"
import csv, os, sys
import xml.etree.ElementTree as ET
out = sys.argv[1]
fcd = {}
for step in ET.parse(os.path.join(out, "fcd.xml")).getroot().iter("timestep"):
    for v in step.iter("vehicle"):
        if v.get("id") == "ego":
            fcd[round(float(step.get("time")), 3)] = int(v.get("signals"))
rows = list(csv.DictReader(open(os.path.join(out, "timeline.csv"))))
compared = 0
for r in rows:
    if r["sumo_signals"] == "":
        continue
    # SUMO writes FCD timestep t while it executes the step from t, with the commands given at t:
    # the mask the timeline's row t read back after that step.
    t = round(float(r["time"]), 3)
    assert fcd.get(t) == int(r["sumo_signals"]), (r["time"], fcd.get(t), r["sumo_signals"])
    compared += 1
assert compared > 300, compared
assert any(int(r["sumo_signals"] or 0) & 2 for r in rows), "no left blinker in SUMO's signals"
assert os.path.isfile(os.path.join(out, "trips.xml")), "--tripinfo (a synonym) did not land in --out"
PY

"$bin" run "$data/sumo_warnings.yaml" --out "$work/warnings" --quiet || fail "sumo_warnings: exit code $?"
grep -q "^Warning: Route file should be sorted by departure time, ignoring 'early'" "$work/warnings/sumo.log" ||
  fail "sumo_warnings: SUMO's warning is not in sumo.log"
python3 - "$work/warnings/summary.json" <<'PY' || fail "sumo_warnings: the warning is not counted"
import json, sys
m = json.load(open(sys.argv[1]))["sumo"]["messages"]
assert m["warnings"] == 1 and m["errors"] == 0, m
PY

echo "user_sumo: $failures failures"
[ $failures -eq 0 ]
