#!/usr/bin/env bash
# `run --connect` against a peer that is not SUMO or stops answering (docs/sumo.md "Attached to a
# SUMO you started"):
#   - a server sending four zero bytes, ff ff ff ff, random bytes, or the length 7f ff ff f0
#     (traci_peer.py): exit 2, one line naming the peer and what it sent, a summary.json with status
#     "error", no timeline; never SUMO's assertion (exit 134) or a 2 GiB allocation;
#   - a server that accepts but never answers, and a real sumo frozen with SIGSTOP mid-run, both
#     with --traci-timeout 2: the run ends with the timeout's line, exit 2, an error summary;
#   - SIGTERM and SIGINT to a run waiting on a frozen sumo or a silent peer (--traci-timeout 600),
#     and SIGTERM to one waiting on a frozen sumo-gui (under Xvfb): exit 143 / 130, "interrupted by
#     SIG...", a summary with status "interrupted".
# Every server started here is stopped by its PID.
# usage: traci_peer_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
py=/usr/bin/python3  # SUMO's traci (sumo-tools) for the other client
export SUMO_HOME=${SUMO_HOME:-/usr/share/sumo}
work=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill -KILL "$p" 2>/dev/null; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
scenario=$src/scenarios/intersection_left.yaml

# peer MODE: starts traci_peer.py in MODE; sets $peer_pid and $peer_port.
peer() {
  rm -f "$work/port" "$work/port.connected"
  "$py" "$src/tests/integration/traci_peer.py" "$1" "$work/port" &
  peer_pid=$!
  pids+=("$peer_pid")
  for _ in $(seq 200); do [ -s "$work/port" ] && break; sleep 0.05; done
  peer_port=$(cat "$work/port" 2>/dev/null)
  [ -n "$peer_port" ] || fail "$1: traci_peer.py wrote no port"
}

# ended NAME CODE WANT_CODE STATUS PATTERN...: the run NAME ended with WANT_CODE, one stderr line
# holding every PATTERN, a summary.json with STATUS and no timeline.
ended() {
  local name=$1 code=$2 want=$3 status=$4; shift 4
  local err=$work/$name.err out=$work/$name before=$failures
  [ "$code" -eq "$want" ] || fail "$name: exit code $code, want $want: $(head -c 400 "$err")"
  [ "$(wc -l <"$err")" -eq 1 ] || fail "$name: stderr is not one line: $(head -c 600 "$err")"
  for p in "$@"; do grep -q -- "$p" "$err" || fail "$name: stderr lacks '$p': $(cat "$err")"; done
  grep -q "\"status\": \"$status\"" "$out/summary.json" 2>/dev/null || fail "$name: no summary.json with status $status"
  [ -e "$out/timeline.csv" ] && fail "$name: a timeline was written"
  [ $failures -eq $before ] && echo "ok   $name: exit $code, $(cat "$err")"
  return 0
}

# 1. Peers that are not SUMO.
not_sumo() {  # not_sumo MODE PATTERN...
  local mode=$1; shift
  peer "$mode"
  "$bin" run "$scenario" --out "$work/$mode" --connect "127.0.0.1:$peer_port" --traci-timeout 2 --quiet \
    >/dev/null 2>"$work/$mode.err"
  ended "$mode" $? 2 error "something at 127.0.0.1:$peer_port is not a TraCI server: it sent" "$@"
  kill -KILL "$peer_pid" 2>/dev/null
}
not_sumo zeros "a message length of 0 bytes"
not_sumo ones "a message length of -1 bytes"
not_sumo random "is it a SUMO started with --remote-port?"
not_sumo huge "a message length of 2147483632 bytes, more than the 16 MiB signalsim accepts"

# 2. A peer that accepts and never answers: the first exchange's limit.
peer silent
"$bin" run "$scenario" --out "$work/silent" --connect "127.0.0.1:$peer_port" --traci-timeout 2 --quiet \
  >/dev/null 2>"$work/silent.err"
ended silent $? 2 error "something at 127.0.0.1:$peer_port accepted the connection but did not answer TraCI within 2 s"
kill -KILL "$peer_pid" 2>/dev/null

# 3. A real sumo frozen mid-run. The other client (order 1) paces the run and says "mark" once the
# simulation reached 3 s: both clients step in lock-step, so signalsim is mid-run then.
cat >"$work/other_client.py" <<'PY'
import sys
sys.path.insert(0, "/usr/share/sumo/tools")
import traci
traci.init(int(sys.argv[1]), host="127.0.0.1")
traci.setOrder(1)
marked = False
while traci.simulation.getTime() < 1000:
    traci.simulationStep()
    if not marked and traci.simulation.getTime() >= 3:
        print("mark", flush=True)
        marked = True
PY
source "$src/tests/support/traci_server.sh"  # free_port, wait_listening PORT
# frozen NAME SIGNAL TIMEOUT: signalsim as client 2 of a sumo that is stopped (SIGSTOP) once the
# simulation reached 3 s; then SIGNAL (or none) to signalsim. Sets $code.
frozen() {
  local name=$1 sig=$2 timeout=$3
  local port; port=$(free_port)
  sumo -n "$src/sumo_nets/cross/cross.net.xml" --remote-port "$port" --num-clients 2 --step-length 0.1 \
    --no-step-log true >"$work/$name.server.log" 2>&1 &
  local server=$!; pids+=("$server")
  wait_listening "$port"
  "$py" "$work/other_client.py" "$port" >"$work/$name.other.log" 2>&1 &
  pids+=($!)
  "$bin" run "$scenario" --out "$work/$name" --connect "127.0.0.1:$port" --client-order 2 --quiet \
    --set duration=1000 --set ego.max_speed=0.5 --set ego.depart_speed=0.5 --traci-timeout "$timeout" \
    >/dev/null 2>"$work/$name.err" &
  local run=$!
  for _ in $(seq 600); do grep -q "^mark" "$work/$name.other.log" && break; sleep 0.05; done
  grep -q "^mark" "$work/$name.other.log" || fail "$name: the simulation did not reach 3 s: $(cat "$work/$name.err")"
  kill -STOP "$server"
  if [ "$sig" != none ]; then
    sleep 1  # signalsim is waiting for the frozen server's answer now
    kill -"$sig" "$run"
  fi
  wait "$run"
  code=$?
  kill -KILL "$server" 2>/dev/null
}
frozen frozen_sumo none 2
ended frozen_sumo "$code" 2 error "SUMO at 127.0.0.1:[0-9]* did not answer within 2 s (is it stopped or frozen?"
frozen frozen_sumo_sigterm TERM 600
ended frozen_sumo_sigterm "$code" 143 interrupted "interrupted by SIGTERM"

# 4. SIGINT while the handshake waits on a silent peer.
peer silent
"$bin" run "$scenario" --out "$work/silent_sigint" --connect "127.0.0.1:$peer_port" --traci-timeout 600 --quiet \
  >/dev/null 2>"$work/silent_sigint.err" &
run=$!
for _ in $(seq 400); do [ -e "$work/port.connected" ] && break; sleep 0.05; done
[ -e "$work/port.connected" ] || fail "silent_sigint: signalsim did not connect"
sleep 0.5  # signalsim is waiting for the answer to its first request now
kill -INT "$run"
wait "$run"
ended silent_sigint $? 130 interrupted "interrupted by SIGINT"
kill -KILL "$peer_pid" 2>/dev/null

# 5. SIGTERM to a run waiting on a frozen sumo-gui (no time limit with --gui: a user may pause it),
# under an Xvfb started here on a display it picks itself.
exec 3<>"$work/display"
Xvfb -displayfd 3 -nolisten tcp -screen 0 1280x1024x24 >"$work/xvfb.log" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -s "$work/display" ] && break; sleep 0.1; done
DISPLAY=":$(head -1 "$work/display")" "$bin" run "$scenario" --out "$work/gui_sigterm" --gui --quiet \
  --set duration=10000 --set ego.max_speed=0.1 --set ego.depart_speed=0.1 --set step_length=0.01 \
  >/dev/null 2>"$work/gui_sigterm.err" &
run=$!
for _ in $(seq 600); do [ -s "$work/gui_sigterm/gui.png" ] && break; sleep 0.05; done  # the ego has departed
gui=$(pgrep -P "$run" -x sumo-gui)
if [ -n "$gui" ]; then
  pids+=("$gui")
  kill -STOP "$gui"
  sleep 0.5
  kill -TERM "$run"
  wait "$run"
  ended gui_sigterm $? 143 interrupted "interrupted by SIGTERM"
else
  fail "gui_sigterm: no sumo-gui running under signalsim: $(cat "$work/gui_sigterm.err")"
  kill -KILL "$run" 2>/dev/null
fi

echo "traci_peer: $failures failures"
[ $failures -eq 0 ]
