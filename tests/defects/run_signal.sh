#!/usr/bin/env bash
# Defect 8: `signalsim run` stopped by a real SIGINT or SIGTERM while SUMO runs, in an --out that
# holds a finished run: exit 130 (SIGINT) or 143 (SIGTERM), one line, and the directory keeps none of
# the earlier run's files: its summary.json says "interrupted" (no "passed" left over), no timeline
# or events. Also a signal sent as soon as the handlers are in place (while the scenario and the net
# load, before SUMO starts).
set -u
source "$(dirname "$0")/lib.sh" "$@"
s=$src/scenarios/close_turns.yaml
# About 400 000 steps at 1 cm/s: the run is still going when the signal comes, whatever the machine.
slow=(--set ego.max_speed=0.1 --set ego.depart_speed=0.1 --set duration=4000 --set step_length=0.01)

interrupt() {  # interrupt NAME SIGNAL WANT_CODE WAIT_FOR_SUMO
  local name=$1 sig=$2 want=$3 wait_sumo=$4
  local out=$work/$name before=$failures
  "$bin" run "$s" --out "$out" --quiet >/dev/null 2>&1
  grep -q '"status": "passed"' "$out/summary.json" || { fail "$name: the first run did not pass"; return; }
  "$bin" run "$s" --out "$out" --quiet "${slow[@]}" >"$work/$name.out" 2>"$work/$name.err" &
  local pid=$!
  if [ "$wait_sumo" = yes ]; then
    # SUMO is running once the old summary is gone and SUMO has opened its log.
    for _ in $(seq 400); do
      [ ! -e "$out/summary.json" ] && [ -e "$out/sumo.log" ] && break
      kill -0 $pid 2>/dev/null || break
      sleep 0.05
    done
    sleep 0.3
  else
    # As soon as the handlers are installed (SigCgt has SIGINT and SIGTERM): the scenario and the net
    # are loading, SUMO has not started. (Before main, during dynamic loading, no program can handle
    # a signal: the default action ends it.)
    for _ in $(seq 400); do
      local caught
      caught=$(awk '/^SigCgt:/ {print $2}' /proc/$pid/status 2>/dev/null)
      [ -n "$caught" ] && [ $(( 0x$caught & 0x4002 )) -eq $(( 0x4002 )) ] && break
      sleep 0.005
    done
  fi
  kill -"$sig" $pid
  wait $pid
  local code=$?
  [ $code -eq "$want" ] || fail "$name: exit code $code, want $want ($(cat "$work/$name.err"))"
  [ "$(wc -l <"$work/$name.err")" -eq 1 ] || fail "$name: stderr is not one line: $(cat "$work/$name.err")"
  grep -q "interrupted by SIG$sig" "$work/$name.err" || fail "$name: stderr: $(cat "$work/$name.err")"
  if [ -e "$out/summary.json" ]; then
    grep -q '"status": "interrupted"' "$out/summary.json" || fail "$name: summary.json: $(head -c 300 "$out/summary.json")"
    grep -q '"passed"' "$out/summary.json" && fail "$name: the earlier run's verdict survived"
  else
    fail "$name: no summary.json"
  fi
  local f
  for f in timeline.csv events.csv timeline.csv.tmp events.csv.tmp summary.json.tmp; do
    [ -e "$out/$f" ] && fail "$name: $f left in --out"
  done
  [ $failures -eq $before ] && echo "ok   $name: exit $code, $(cat "$work/$name.err")"
  return 0
}

interrupt sigint_mid_run INT 130 yes
interrupt sigterm_mid_run TERM 143 yes
interrupt sigint_at_once INT 130 no
interrupt sigterm_at_once TERM 143 no
finish
