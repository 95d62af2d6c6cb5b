#!/usr/bin/env bash
# The three ways to run give the same run: embedded libsumo, --gui in sumo-gui under Xvfb,
# and --connect to a sumo started here with --remote-port on 127.0.0.1 that a second TraCI client
# (SUMO's Python traci, sumo-tools) steps as client 1. Blinker events equal within 0.5 m (they are
# identical), timelines and summaries (but for the `sumo` block) identical; the gui screenshot shows
# the ego with its left blinker, framed on the junction ahead, captioned from its timeline row; the
# other client's simulation goes on after the ego arrived.
# Every service started here (Xvfb, sumo, the Python client) is stopped by its PID.
# usage: backends_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
py=/usr/bin/python3  # Debian's: matplotlib (python3-matplotlib) and SUMO's traci (sumo-tools)
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

# signalsim's --connect tries once: a SUMO that has not bound its port yet is a refused connection.
source "$src/tests/support/traci_server.sh"  # free_port, wait_listening PORT

# Xvfb on a display it picks itself (-displayfd), local connections only.
exec 3<> "$work/display"
Xvfb -displayfd 3 -nolisten tcp -screen 0 1280x1024x24 >"$work/xvfb.log" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -s "$work/display" ] && break; sleep 0.1; done
display=":$(head -1 "$work/display")"
[ "$display" != ":" ] || { echo "FAIL: Xvfb did not start: $(cat "$work/xvfb.log")"; exit 1; }

# The other TraCI client: steps as client `order` until `until` s (pausing `pause` s a step), then leaves.
cat >"$work/other_client.py" <<'PY'
import sys, time
sys.path.insert(0, "/usr/share/sumo/tools")
import traci
port, order, until = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
pause = float(sys.argv[4]) if len(sys.argv) > 4 else 0.0
mark = float(sys.argv[5]) if len(sys.argv) > 5 else None  # print "mark" once this time is reached
traci.init(port, host="127.0.0.1")
traci.setOrder(order)
while traci.simulation.getTime() < until:
    traci.simulationStep()
    if mark is not None and traci.simulation.getTime() >= mark:
        print("mark", flush=True)
        mark = None
    time.sleep(pause)
print("other client reached", traci.simulation.getTime())
traci.close()
PY

# same_run NAME DIR_A DIR_B: events within 0.5 m (same count and kinds), timeline and summary equal.
same_run() {
  "$py" - "$2" "$3" <<'PY' || fail "$1: runs differ"
import csv, json, sys
a, b = sys.argv[1], sys.argv[2]
ea, eb = list(csv.DictReader(open(a + "/events.csv"))), list(csv.DictReader(open(b + "/events.csv")))
assert len(ea) == len(eb), (len(ea), len(eb))
for x, y in zip(ea, eb):
    assert (x["kind"], x["from"], x["to"], x["source"]) == (y["kind"], y["from"], y["to"], y["source"]), (x, y)
    assert abs(float(x["s_front"]) - float(y["s_front"])) <= 0.5, (x, y)
assert open(a + "/timeline.csv").read() == open(b + "/timeline.csv").read(), "timelines differ"
sa, sb = json.load(open(a + "/summary.json")), json.load(open(b + "/summary.json"))
sa.pop("sumo"); sb.pop("sumo")
assert sa == sb, "summaries differ"
PY
}

# connect NAME SCENARIO SERVER_ARGS...: signalsim as client 2 beside the Python client 1.
connect() {
  local name=$1 scenario=$2; shift 2
  local port; port=$(free_port)
  sumo "$@" --remote-port "$port" --num-clients 2 >"$work/$name.server.log" 2>&1 &
  local server=$!; pids+=($server)
  wait_listening "$port"
  "$py" "$work/other_client.py" "$port" 1 100 >"$work/$name.other.log" 2>&1 &
  local other=$!; pids+=($other)
  "$bin" run "$scenario" --out "$work/$name" --connect "127.0.0.1:$port" --client-order 2 --quiet \
    || fail "$name: --connect exit code $?"
  wait "$other" || fail "$name: the other client failed: $(cat "$work/$name.other.log")"
  grep -q "other client reached 100" "$work/$name.other.log" ||
    fail "$name: the simulation did not go on for the other client: $(cat "$work/$name.other.log")"
  wait "$server" || fail "$name: sumo exit code $?: $(tail -2 "$work/$name.server.log")"
}

gui() {
  local name=$1 scenario=$2
  DISPLAY=$display "$bin" run "$scenario" --out "$work/$name" --gui --quiet || fail "$name: --gui exit code $?"
  "$py" - "$work/$name" "$src" <<'PY' || fail "$name: the screenshot is not framed on the junction ahead or its caption is not the run's"
# The caption: the timeline row whose command the kept picture follows (the second of the two shots
# from the first row with a blinker bit in sumo_signals and the junction ahead within 40 m of the
# ego), its blinker, source and the judge's decision; the view framed on that junction: its shape
# (from the net, sumolib) and the ego inside the view.
import csv, json, sys
sys.path.insert(0, "/usr/share/sumo/tools")
import sumolib
from PIL import Image
run = sys.argv[1]
rows = list(csv.DictReader(open(run + "/timeline.csv")))
im = Image.open(run + "/gui.png")
info = im.info
junction = info["signalsim:junction"]
assert junction, info
summary = json.load(open(run + "/summary.json"))
net = sumolib.net.readNet(summary["net"] if summary["net"].startswith("/") else sys.argv[2] + "/" + summary["net"])
cx, cy = net.getNode(junction).getCoord()
first = next(k for k, r in enumerate(rows) if r["sumo_signals"] and int(r["sumo_signals"]) & 7
             and ((float(r["x"]) - cx) ** 2 + (float(r["y"]) - cy) ** 2) ** 0.5 <= 40.0)
row = rows[first + 1]
assert info.get("signalsim:time") == row["time"], (info.get("signalsim:time"), row["time"])
caption = info["Description"]
for fact in (f"t = {row['time']} s", f"blinker: {row['blinker']} (source: {row['blinker_source']})",
             f"light {row['tl_id']}: state {row['tl_state']}", f"decided {row['tl_decision']}"):
    assert fact in caption, (fact, caption)
x0, y0, x1, y1 = (float(v) for v in info["signalsim:view"].split(","))
for x, y in net.getNode(junction).getShape() + [(float(row["x"]), float(row["y"]))]:
    assert x0 - 0.5 <= x <= x1 + 0.5 and y0 - 0.5 <= y <= y1 + 0.5, ((x, y), (x0, y0, x1, y1))
assert min(x1 - x0, y1 - y0) < 150, ("the view is not close on the junction", info["signalsim:view"])
width, height = im.size
strip = im.convert("RGB").crop((0, height - 64, width, height))
assert sum(1 for p in strip.getdata() if p == (255, 255, 255)) > 0.8 * width * 64, "no caption strip"
PY
  "$py" - "$work/$name/gui.png" <<'PY' || fail "$name: the screenshot does not show the ego with its left blinker"
import sys
import matplotlib.image as image
a = image.imread(sys.argv[1])[:-64]  # the picture above the caption strip
r, g, b = a[..., 0], a[..., 1], a[..., 2]
ego = (r > 0.8) & (g < 0.3) & (b > 0.8)                  # signalsim colours the ego magenta in the gui
blinker = (r > 0.8) & (g > 0.5) & (g < 0.9) & (b < 0.3)  # sumo-gui's orange blinker lights
# framed on the junction the ego is about 5 px a metre: some 90 magenta pixels, a blinker lamp some 10
assert ego.sum() > 40, ("ego pixels", int(ego.sum()))
assert blinker.sum() > 8, ("blinker pixels", int(blinker.sum()))
# heading north on in_S, the left blinker is left of the car's centre
assert blinker.nonzero()[1].mean() < ego.nonzero()[1].mean(), "the blinker is not on the left"
PY
}

# 1. An ego signalsim adds, on a bundled net.
s1=$src/scenarios/intersection_left.yaml
"$bin" run "$s1" --out "$work/added_embedded" --quiet || fail "added: embedded exit code $?"
gui added_gui "$s1"
connect added_connect "$s1" -n "$src/sumo_nets/cross/cross.net.xml" --step-length 0.1 --seed 1 --no-step-log true
same_run added_gui "$work/added_embedded" "$work/added_gui"
same_run added_connect "$work/added_embedded" "$work/added_connect"

# 2. The user's own .sumocfg and a vehicle of their route file taken over (the server: sumo -c).
s2=$src/tests/data/user_sumo/take_over.yaml
"$bin" run "$s2" --out "$work/taken_embedded" --quiet || fail "taken: embedded exit code $?"
gui taken_gui "$s2"
# (the configuration's own output and log files, relative to it, are redirected into the scratch folder)
connect taken_connect "$s2" -c "$src/tests/data/user_sumo/cross.sumocfg" --collision.action warn \
  --tripinfo-output "$work/server_tripinfo.xml" --log "$work/server_sumo.log"
same_run taken_gui "$work/taken_embedded" "$work/taken_gui"
same_run taken_connect "$work/taken_embedded" "$work/taken_connect"

# 3. A server whose step length is not the scenario's: exit 2, one line naming both.
port=$(free_port)
sumo -n "$src/sumo_nets/cross/cross.net.xml" --remote-port "$port" --step-length 0.5 --no-step-log true \
  >"$work/mismatch.server.log" 2>&1 &
server=$!; pids+=($server)
wait_listening "$port"
"$bin" run "$s1" --out "$work/mismatch" --connect "127.0.0.1:$port" >/dev/null 2>"$work/mismatch.err"
code=$?
[ $code -eq 2 ] || fail "step-length mismatch: exit code $code, want 2"
[ "$(wc -l <"$work/mismatch.err")" -eq 1 ] || fail "step-length mismatch: not one line: $(cat "$work/mismatch.err")"
grep -q "step_length 0.1 s differs from the step length of SUMO at 127.0.0.1:$port, 0.5 s" "$work/mismatch.err" ||
  fail "step-length mismatch: $(cat "$work/mismatch.err")"
grep -q '"status": "error"' "$work/mismatch/summary.json" || fail "step-length mismatch: no error summary"
wait "$server"  # signalsim left politely: the server ends by itself

# 4. A server whose route files give the taken-over vehicle another route: exit 2, both routes named.
port=$(free_port)
sumo -n "$src/sumo_nets/cross/cross.net.xml" -r "$src/tests/data/user_sumo/other_demand.rou.xml" \
  -a "$src/tests/data/user_sumo/vtypes.add.xml" --remote-port "$port" --step-length 0.1 --no-step-log true \
  >"$work/other.server.log" 2>&1 &
server=$!; pids+=($server)
wait_listening "$port"
"$bin" run "$s2" --out "$work/other" --connect "127.0.0.1:$port" >/dev/null 2>"$work/other.err"
code=$?
[ $code -eq 2 ] || fail "other route: exit code $code, want 2"
grep -q "vehicle 'veh42' drives \[in_S out_N\] in SUMO, not the route \[in_S out_W\] of its route file" "$work/other.err" ||
  fail "other route: $(cat "$work/other.err")"
wait "$server"

# 5. The server dies mid-run (kill -9 once the run has reached 5 s, both clients stepping, while the
# other client paces the run): one line,
# exit 2, an error summary, and no timeline passed off as a finished run.
port=$(free_port)
sumo -n "$src/sumo_nets/cross/cross.net.xml" --remote-port "$port" --num-clients 2 --step-length 0.1 \
  --no-step-log true >"$work/lost.server.log" 2>&1 &
server=$!; pids+=($server)
wait_listening "$port"
"$py" "$work/other_client.py" "$port" 1 100 0.01 5 >"$work/lost.other.log" 2>&1 &
pids+=($!)
(for _ in $(seq 1200); do grep -q "^mark" "$work/lost.other.log" && break; sleep 0.05; done; kill -9 "$server") &
"$bin" run "$s1" --out "$work/lost" --connect "127.0.0.1:$port" --client-order 2 >/dev/null 2>"$work/lost.err"
code=$?
[ $code -eq 2 ] || fail "lost connection: exit code $code, want 2"
[ "$(wc -l <"$work/lost.err")" -eq 1 ] || fail "lost connection: not one line: $(cat "$work/lost.err")"
grep -q "the connection to SUMO at 127.0.0.1:$port failed or was lost" "$work/lost.err" ||
  fail "lost connection: $(cat "$work/lost.err")"
grep -q '"status": "error"' "$work/lost/summary.json" || fail "lost connection: no error summary"
[ -e "$work/lost/timeline.csv" ] && fail "lost connection: a timeline was written"

echo "backends: $failures failures"
[ $failures -eq 0 ]
