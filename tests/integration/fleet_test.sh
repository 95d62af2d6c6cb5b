#!/usr/bin/env bash
# Fleet mode end to end on the real libsumo, sumo-gui and sumo (docs/fleet.md):
#   junction     the signalised crossing with turning traffic: every turning vehicle's blinker by the
#                rule at C, straight ones none; SUMO's FCD (--fcd-output.signals) shows it every step
#   observe      signals: observe: SUMO's own blinker measured against the rules
#   egoless      the crossing's traffic without an ego: the junction check on its own, the run ending
#                when no vehicle is left; batch and report on it; an egoless scenario without fleet:,
#                or with an expectation, refused at its line
#   ego          the ego's timeline.csv and events.csv byte-identical with and without --fleet, on
#                the crossing and on bologna/acosta with its own demand; there every vehicle of the
#                traffic at the same place at every step (SUMO's FCD)
#   roundabout   the roundabout under de, kr and jp (entry and exit signals by the preset), with a vehicle
#                a rerouter sends to another exit once it is on the ring
#   sweep        a sweep over countries in fleet mode: results.csv's fleet_* columns per country
#   teleport     a vehicle SUMO teleports past the junction: followed, its blinker off after
#   gui          --gui under Xvfb: fleet_events.csv byte-identical to the embedded run's, and the
#                screenshot shows other vehicles' blinkers
#   connect      --connect beside a Python TraCI client that reads every vehicle's signals each step
#                (they are what fleet_events.csv says), re-routes a vehicle (followed) and removes
#                another (passed over)
# Every service started here (Xvfb, sumo, the Python client) is stopped by its PID.
# usage: fleet_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
py=/usr/bin/python3
export SUMO_HOME=${SUMO_HOME:-/usr/share/sumo}
work=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill -KILL "$p" 2>/dev/null; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null; done
  [ -n "${KEEP_FLEET_WORK:-}" ] || rm -rf "$work"; [ -n "${KEEP_FLEET_WORK:-}" ] && echo "kept $work"
}
trap cleanup EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
check() { "$py" "$src/tests/integration/fleet_check.py" "$@" || fail "check $*"; }
source "$src/tests/support/traci_server.sh"  # free_port, wait_listening PORT
data=$src/tests/data/fleet
cross=$data/cross_traffic.yaml
fcd_args='sumo_args=[--fcd-output, fcd.xml, --fcd-output.signals]'

# junction, ego (crossing)
"$bin" run "$cross" --out "$work/cross_plain" --quiet || fail "cross without fleet: exit code $?"
"$bin" run "$cross" --out "$work/cross_fleet" --quiet --fleet || fail "cross with fleet: exit code $?"
"$bin" run "$cross" --out "$work/cross_fcd" --quiet --fleet --set "$fcd_args" || fail "cross with FCD: exit code $?"
check junction "$work/cross_fcd" "$work/cross_fcd/fcd.xml"
check same "$work/cross_fleet" "$work/cross_fcd"
"$bin" run "$cross" --out "$work/cross_observe" --quiet --set fleet.signals=observe || fail "observe: exit code $?"
check observe "$work/cross_observe"
# --fleet beside --set fleet.signals=observe observes: the --set wins over --fleet's signals=set.
"$bin" run "$cross" --out "$work/cross_fleet_observe" --quiet --fleet --set fleet.signals=observe ||
  fail "--fleet with observe: exit code $?"
grep -q '"mode": "observe"' "$work/cross_fleet_observe/summary.json" || fail "--fleet overrode --set fleet.signals=observe"
for f in timeline.csv events.csv; do
  cmp -s "$work/cross_plain/$f" "$work/cross_fleet/$f" || fail "ego: cross $f differs with --fleet"
done
[ -e "$work/cross_plain/fleet_events.csv" ] && fail "fleet_events.csv written without fleet mode"

# egoless: the crossing's traffic alone, fleet mode from the first step
egoless=$data/cross_traffic_egoless.yaml
"$bin" run "$egoless" --out "$work/egoless" --quiet --set "$fcd_args" || fail "egoless: exit code $?"
check junction "$work/egoless" "$work/egoless/fcd.xml"
"$py" - "$work/egoless" <<'PY' || fail "egoless: summary.json or the empty ego files"
import json, sys
run = sys.argv[1]
s = json.load(open(run + "/summary.json"))
assert s["status"] == "no_expectations" and s["ego"] is None and s["route"] is None, s["status"]
# The last of the 54 vehicles leaves before the 300 s duration: the run ends with no vehicle left.
e = s["egoless"]
assert e["ended"] == "no_vehicles" and e["steps"] == round(e["end_time"] * 10) and 100 < e["end_time"] < 300, e
for name in ("timeline.csv", "events.csv"):
    lines = open(run + "/" + name).read().splitlines()
    assert len(lines) == 1 and lines[0].startswith("time,s_front,"), (name, lines[:2])
PY
"$bin" run "$egoless" --out "$work/egoless_short" --quiet --set duration=30 || fail "egoless 30 s: exit code $?"
"$py" -c 'import json,sys; e=json.load(open(sys.argv[1]))["egoless"]; assert e == {"steps": 300, "end_time": 30.0, "ended": "duration"}, e' \
  "$work/egoless_short/summary.json" || fail "egoless: duration=30 did not end the run at 30 s"
"$bin" batch "$egoless" "$cross" --out "$work/egoless_batch" -j2 --junit "$work/egoless_batch/junit.xml" >/dev/null \
  || fail "egoless batch: exit code $?"
"$py" - "$work/egoless_batch/results.csv" <<'PY' || fail "egoless batch: results.csv"
import csv, sys
rows = {r["scenario"]: r for r in csv.DictReader(open(sys.argv[1]))}
r = rows["fleet_cross_traffic_egoless"]
assert r["status"] == "no_expectations" and r["fleet_followed"] == "54" and r["fleet_signalled"] == "36", r
PY
"$bin" report "$work/egoless_batch" >/dev/null || fail "egoless report: exit code $?"
grep -q fleet_cross_traffic_egoless "$work/egoless_batch/report.html" || fail "egoless report: the run is missing"
printf 'name: no_ego\nnet: %s\nduration: 5\n' "$src/sumo_nets/cross/cross.net.xml" > "$work/no_ego.yaml"
printf 'name: no_ego\nnet: %s\nfleet:\nexpect:\n  - blinker_never: left\n' "$src/sumo_nets/cross/cross.net.xml" \
  > "$work/no_ego_expect.yaml"
refused() {  # FILE TEXT [ARGS...]: the run exits 2 with one line holding TEXT
  local file=$1 want=$2 msg rc
  shift 2
  msg=$("$bin" run "$file" --out "$work/bad_out" --quiet "$@" 2>&1); rc=$?
  [ $rc -eq 2 ] || fail "egoless $file $*: exit code $rc, not 2"
  case $msg in *"$want"*) ;; *) fail "egoless $file $*: message '$msg' lacks '$want'" ;; esac
}
refused "$work/no_ego.yaml" "no_ego.yaml: missing required key 'ego'"
refused "$work/no_ego_expect.yaml" "no_ego_expect.yaml:4: key 'expect': is about the ego, and the scenario has none"
refused "$egoless" "--driver: --driver sumo drives the ego, and the scenario has none" --driver sumo
refused "$egoless" "--plot: the pictures are of the ego's run, and the scenario has no ego" --plot

# ego on bologna/acosta with its demand (hundreds of vehicles), its first 60 s
acosta=$src/tests/data/scenarios/acosta_red_light_right_of_way.yaml
fcd_plain='sumo_args=[--fcd-output, fcd.xml]'
"$bin" run "$acosta" --out "$work/acosta_plain" --quiet --set duration=60 --set "$fcd_plain"
"$bin" run "$acosta" --out "$work/acosta_fleet" --quiet --set duration=60 --set "$fcd_plain" --fleet
for f in timeline.csv events.csv; do
  cmp -s "$work/acosta_plain/$f" "$work/acosta_fleet/$f" || fail "ego: acosta $f differs with --fleet"
done
# SUMO keeps driving the traffic: every vehicle where it was, at every step (signals set, brake
# lights kept by SUMO's rule)
"$py" - "$work/acosta_plain/fcd.xml" "$work/acosta_fleet/fcd.xml" <<'PY' || fail "acosta: the traffic moved differently with --fleet"
import sys
import xml.etree.ElementTree as ET
def states(path):
    return [(s.get("time"), v.get("id"), v.get("x"), v.get("y"), v.get("speed"), v.get("lane"))
            for s in ET.parse(path).getroot().iter("timestep") for v in s.iter("vehicle")]
a, b = states(sys.argv[1]), states(sys.argv[2])
assert len(a) > 20000 and a == b, (len(a), len(b))
PY
"$py" - "$work/acosta_fleet/summary.json" <<'PY' || fail "acosta: fleet mode followed too few vehicles"
import json, sys
v = json.load(open(sys.argv[1]))["fleet"]["vehicles"]
assert v["followed"] > 100 and v["signalled"] > 50, v
PY

# roundabout under two countries, with a rerouted vehicle
for c in de kr jp; do
  "$bin" run "$data/roundabout_traffic.yaml" --out "$work/roundabout_$c" --quiet --set country=$c ||
    fail "roundabout $c: exit code $?"
  check roundabout "$work/roundabout_$c" $c
done

# the country sweep: each country's traffic side by side in results.csv (de: exits only; kr: entries too)
"$bin" sweep "$data/country_sweep.yaml" --out "$work/sweep" --quiet || fail "sweep: exit code $?"
"$py" - "$work/sweep/results.csv" <<'PY' || fail "sweep: results.csv's fleet columns"
import csv, sys
rows = {r["country"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert set(rows) == {"de", "kr"}, rows.keys()
for c, want_left in (("de", 0), ("kr", 28)):
    r = rows[c]
    assert (r["fleet_followed"], r["fleet_signals_right"], r["fleet_signals_left"]) == ("28", "28", str(want_left)), (c, r)
PY

# teleport
"$bin" run "$data/cross_teleport.yaml" --out "$work/teleport" --quiet || fail "teleport: exit code $?"
check teleport "$work/teleport"

# gui: the ego turns left (its first blinker takes the screenshot) amid the traffic
gui_set=(--set 'ego.route=[in_S, out_W]' --set ego.max_speed=13.89 --set duration=40)
"$bin" run "$cross" --out "$work/gui_embedded" --quiet --fleet "${gui_set[@]}" || fail "gui embedded: exit code $?"
exec 3<> "$work/display"
Xvfb -displayfd 3 -nolisten tcp -screen 0 1280x1024x24 >"$work/xvfb.log" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -s "$work/display" ] && break; sleep 0.1; done
display=":$(head -1 "$work/display")"
if [ "$display" = ":" ]; then
  fail "Xvfb did not start: $(cat "$work/xvfb.log")"
else
  DISPLAY=$display "$bin" run "$cross" --out "$work/gui" --quiet --fleet --gui "${gui_set[@]}" || fail "gui: exit code $?"
  check same "$work/gui_embedded" "$work/gui"
  "$py" - "$work/gui/gui.png" <<'PY' || fail "gui: the screenshot shows no other vehicle's blinker"
import sys
import matplotlib.image as image
a = image.imread(sys.argv[1])
r, g, b = a[..., 0], a[..., 1], a[..., 2]
ego = (r > 0.8) & (g < 0.3) & (b > 0.8)                  # signalsim colours the ego magenta
blinker = (r > 0.8) & (g > 0.5) & (g < 0.9) & (b < 0.3)  # sumo-gui's orange blinker lights
ys, xs = ego.nonzero()
assert len(xs) > 10, ("ego pixels", len(xs))
by, bx = blinker.nonzero()
far = (abs(bx - xs.mean()) > 15) | (abs(by - ys.mean()) > 15)  # not the ego's own
assert far.sum() > 4, ("other vehicles' blinker pixels", int(far.sum()))
PY
fi

# connect: a co-simulation client reads every vehicle's signals and re-routes E_straight.0 (to the
# north: a right turn)
port=$(free_port)
sumo -n "$src/sumo_nets/cross/cross.net.xml" -r "$data/cross_traffic.rou.xml" --step-length 0.1 --seed 1 \
  --no-step-log true --remote-port "$port" --num-clients 2 >"$work/server.log" 2>&1 &
server=$!; pids+=($server)
wait_listening "$port"
"$py" "$src/tests/integration/fleet_client.py" "$port" 170 "$work/samples.csv" E_straight.0 out_N N_left.1 \
  >"$work/client.log" 2>&1 &
client=$!; pids+=($client)
"$bin" run "$cross" --out "$work/connect" --quiet --fleet --connect "127.0.0.1:$port" --client-order 2 ||
  fail "connect: exit code $?"
wait "$client" || fail "connect: the client failed: $(tail -3 "$work/client.log")"
grep -q "rerouted removed" "$work/client.log" ||
  fail "connect: the client did not re-route and remove: $(cat "$work/client.log")"
kill "$server" 2>/dev/null
check samples "$work/connect" "$work/samples.csv"
check rerouted "$work/connect" E_straight.0 right

[ $failures -eq 0 ] && echo "fleet: all checks passed"
exit $((failures > 0))
