#!/usr/bin/env bash
# The traci systems under test (docs/decider.md "Another TraCI client") on the real sumo and libtraci:
# a sumo started here as a server on 127.0.0.1 (a free port, --num-clients 2), the example Python
# controllers of examples/traci_controller as client 1, signalsim --connect as client 2.
#  1. decider: each row's blinker (and sumo_signals) is the mask the controller set at the row's time
#     (the same step's round); ref_blinker is the reference's (an embedded reference run's blinker);
#     the blinker events lie where the controller's rule switches.
#  2. light judge: the controller says stop while C shows green: the ego comes to rest before the
#     line; then go: it passes. tl_decision follows the controller's answers row by row.
#  3. faults: traci without --connect is refused before SUMO starts (one line naming the key); an
#     answer that is not stop or go ends the run as an error naming the parameter; a controller that
#     dies ends the run as an error (SUMO quits), never a hang.
# Every process started here is stopped by its PID; each runs under `timeout`.
# usage: traci_sut_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
py=/usr/bin/python3  # Debian's, with SUMO's traci (sumo-tools)
export SUMO_HOME=${SUMO_HOME:-/usr/share/sumo}
work=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
limit=120  # [s] the most any process here may take

source "$src/tests/support/traci_server.sh"  # free_port, wait_listening PORT

data=$src/tests/data/traci_sut
net=$src/sumo_nets/cross/cross.net.xml
# cosim NAME SCENARIO CONTROLLER ARGS...: sumo, the controller as client 1, signalsim as client 2.
# signalsim's exit code in $work/NAME.code, its stderr in $work/NAME.err.
cosim() {
  local name=$1 scenario=$2 controller=$3; shift 3
  local port; port=$(free_port)
  timeout $limit sumo -n "$net" --step-length 0.1 --seed 1 --no-step-log true --remote-port "$port" \
    --num-clients 2 >"$work/$name.server.log" 2>&1 &
  local server=$!; pids+=($server)
  wait_listening "$port"
  timeout $limit "$py" "$controller" "$port" --order 1 "$@" >"$work/$name.client.log" 2>&1 &
  local client=$!; pids+=($client)
  timeout $limit "$bin" run "$scenario" --out "$work/$name" --connect "127.0.0.1:$port" --client-order 2 --quiet \
    2>"$work/$name.err"
  echo $? >"$work/$name.code"
  wait "$client"; echo $? >"$work/$name.client.code"
  wait "$server"
}

# 1. The decider.
"$bin" run "$src/scenarios/intersection_left.yaml" --out "$work/reference" --quiet || fail "reference run: exit code $?"
cosim decider "$data/left_traci_decider.yaml" "$src/examples/traci_controller/blinker_controller.py" \
  --log "$work/decider.set.csv"
# Exit 1 is allowed: the controller's blinker rule is not the law's, and the law verdicts say so.
[ "$(cat "$work/decider.code")" -le 1 ] || fail "decider: exit code $(cat "$work/decider.code"): $(cat "$work/decider.err")"
"$py" - "$work/decider" "$work/decider.set.csv" "$work/reference" <<'PY' || fail "decider: the timeline is not the controller's"
import csv, sys
out, log, ref = sys.argv[1:]
names = {0: "none", 1: "right", 2: "left", 4: "hazard"}
set_at = dict(line.strip().split(",") for line in open(log))
rows = list(csv.DictReader(open(out + "/timeline.csv")))
ref_rows = list(csv.DictReader(open(ref + "/timeline.csv")))
assert len(rows) > 250, len(rows)
for r in rows:
    mask = int(set_at["%.2f" % float(r["time"])])  # what the controller set at the row's time
    assert r["blinker"] == names[mask], (r["time"], r["blinker"], mask)
    assert r["blinker_source"] == ("sut" if mask else "none"), r
    if r["sumo_signals"]:  # empty once the ego arrived
        assert int(r["sumo_signals"]) & 7 == mask, (r["time"], r["sumo_signals"], mask)
# The reference in shadow: the blinker of the reference's own run, row by row.
assert [(r["time"], r["ref_blinker"]) for r in rows] == [(r["time"], r["blinker"]) for r in ref_rows]
# The rule: left within 70 m of the end of in_S (189.60 m long), kept through the junction, off on out_W.
events = [e for e in csv.DictReader(open(out + "/events.csv")) if e["kind"] == "blinker"]
assert [(e["from"], e["to"], e["source"]) for e in events] == [("none", "left", "sut"), ("left", "none", "none")], events
on, off = float(events[0]["s_front"]), float(events[1]["s_front"])
assert 119.60 <= on <= 119.60 + 1.5, on   # the first row within 70 m (13.9 m/s: < 1.4 m a step)
assert 208.95 <= off <= 208.95 + 1.5, off  # the first row on out_W
PY

# 2. The light judge: stop while green until 26 s, then go.
cosim light "$data/left_traci_light_judge.yaml" "$src/examples/traci_controller/light_controller.py" \
  --hold-until 26 --log "$work/light.set.csv"
[ "$(cat "$work/light.code")" = 0 ] || fail "light: exit code $(cat "$work/light.code"): $(cat "$work/light.err")"
"$py" - "$work/light" "$work/light.set.csv" <<'PY' || fail "light: the ego did not follow the controller"
import csv, sys
out, log = sys.argv[1:]
said = []  # (time, answer) for C, in time order
for line in open(log):
    t, tls, answer = line.strip().split(",", 2)
    if tls == "C":
        said.append((float(t), answer))
def answer_at(t):  # SUMO keeps a parameter until it is set again: the last answer at or before t
    return [a for when, a in said if when <= t + 1e-6][-1]
rows = list(csv.DictReader(open(out + "/timeline.csv")))
line = 189.60  # C's stop line on in_S, route s
# Rows before C's stop line: behind it the light is passed and the judge is not asked (docs/decider.md).
judged = [r for r in rows if r["tl_id"] == "C" and r["tl_decision"] and float(r["s_front"]) < line]
assert len(judged) > 100, len(judged)
for r in judged:
    answer = answer_at(float(r["time"]))  # the controller's answer at the row's time
    word, reason = answer.split(":", 1)
    assert r["tl_decision"] == {"stop": "stop", "go": "pass"}[word], (r["time"], r["tl_decision"], answer)
    assert r["tl_reason"] == reason, (r["time"], r["tl_reason"], answer)
    if float(r["time"]) < 26:
        assert r["tl_state"] == "g" and r["ref_tl_decision"] == "pass", r  # green: the reference passes
held = [r for r in rows if float(r["time"]) < 26]
assert max(float(r["s_front"]) for r in held) <= line, "crossed the line while told to stop"
rest = [r for r in held if float(r["speed"]) < 0.1 and float(r["s_front"]) > line - 3]
assert rest, "never at rest before the line"
assert float(rows[-1]["s_front"]) > 390, rows[-1]  # went on once told go: reached the end of out_W
events = [e for e in csv.DictReader(open(out + "/events.csv")) if e["kind"] == "light"]
assert [(e["from"], e["to"]) for e in events][:2] == [("none", "stop"), ("stop", "pass")], events
assert abs(float(events[1]["time"]) - 26.0) < 0.15 and float(events[1]["s_front"]) <= line, events[1]
PY

# 3a. traci without --connect: refused before SUMO starts, one line naming the key.
for role in decider light_judge; do
  timeout $limit "$bin" run "$data/left_traci_$role.yaml" --out "$work/alone_$role" >/dev/null 2>"$work/alone.err"
  code=$?
  [ $code -eq 2 ] || fail "$role without --connect: exit code $code, want 2"
  [ "$(wc -l <"$work/alone.err")" -eq 1 ] && grep -q "$role traci .* needs --connect" "$work/alone.err" ||
    fail "$role without --connect: $(cat "$work/alone.err")"
  [ ! -e "$work/alone_$role/timeline.csv" ] || fail "$role without --connect: SUMO ran"
done

# 3b. An answer that is not stop or go: the run ends as an error naming the parameter.
cat >"$work/halt.py" <<'PY'
import sys
sys.path.insert(0, "/usr/share/sumo/tools")
import traci
traci.init(int(sys.argv[1]), host="127.0.0.1")
traci.setOrder(int(sys.argv[3]))
while traci.simulation.getMinExpectedNumber() > 0 or traci.simulation.getTime() < 1:
    if "ego" in traci.vehicle.getIDList():
        traci.vehicle.setParameter("ego", "signalsim.light.C", "halt")
    traci.simulationStep()
traci.close()
PY
cosim halt "$data/left_traci_light_judge.yaml" "$work/halt.py"
[ "$(cat "$work/halt.code")" != 0 ] || fail "halt: exit code 0"
[ "$(wc -l <"$work/halt.err")" -eq 1 ] && grep -q "light_judge traci at t=.* s: the ego's parameter signalsim.light.C is 'halt'" \
  "$work/halt.err" || fail "halt: $(cat "$work/halt.err")"

# 3c. A controller that dies without closing: SUMO quits, the run ends as an error (no hang).
cat >"$work/die.py" <<'PY'
import os, sys
sys.path.insert(0, "/usr/share/sumo/tools")
import traci
traci.init(int(sys.argv[1]), host="127.0.0.1")
traci.setOrder(int(sys.argv[3]))
while traci.simulation.getTime() < 5.0:
    if "ego" in traci.vehicle.getIDList():
        traci.vehicle.setSignals("ego", 1)
    traci.simulationStep()
os._exit(3)
PY
cosim die "$data/left_traci_decider.yaml" "$work/die.py"
code=$(cat "$work/die.code")
[ "$code" != 0 ] && [ "$code" != 124 ] || fail "controller died: exit code $code (124: timed out)"
[ "$(wc -l <"$work/die.err")" -eq 1 ] && grep -q "failed or was lost" "$work/die.err" || fail "die: $(cat "$work/die.err")"

[ $failures -eq 0 ] && echo "traci systems under test: all checks passed"
exit $((failures > 0))
