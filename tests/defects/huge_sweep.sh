#!/usr/bin/env bash
# A sweep of a million runs (a grid of 1000 x 1000 values): `sweep --list` streams its runs without
# loading a scenario per run or holding the runs (it lists them in 256 MiB of address space, where
# holding them took some 500 MB), and SIGTERM or SIGINT while the sweep is still read and checked
# stops it like any interruption: exit 130, one line, nothing ran (no --out folder).
set -u
source "$(dirname "$0")/lib.sh" "$@"
scenario_copy close_turns "$work/close_turns.yaml"
values() { seq -s, 1 1000; }
cat > "$work/huge.yaml" <<YAML
name: huge
scenarios: [$work/close_turns.yaml]
grid:
  seed: [$(values)]
  turn_signal_search_time: [$(seq 1 1000 | awk '{printf "%s%.3f", (NR > 1 ? "," : ""), NR * 0.002}')]
YAML

# The address space is capped unless AddressSanitizer runs it (its shadow memory is terabytes of it).
(
  [ -z "${ASAN_OPTIONS:-}" ] && ulimit -v 262144
  "$bin" sweep "$work/huge.yaml" --list > "$work/list.txt" 2> "$work/list.err"
)
code=$?
[ $code -eq 0 ] || fail "sweep --list: exit code $code ($(head -c 300 "$work/list.err"))"
[ "$(wc -l < "$work/list.txt")" -eq 1000000 ] || fail "sweep --list: $(wc -l < "$work/list.txt") lines, want 1000000"
[ "$(tail -1 "$work/list.txt")" = "999999  $work/close_turns.yaml  seed=1000  turn_signal_search_time=2.000" ] ||
  fail "the last run: $(tail -1 "$work/list.txt")"
ok "sweep --list of a million runs streams them ($(head -1 "$work/list.txt"))"

stop_while_expanding() {  # stop_while_expanding NAME SIGNAL
  local name=$1 sig=$2
  "$bin" sweep "$work/huge.yaml" --out "$work/$name" --quiet > "$work/$name.out" 2> "$work/$name.err" &
  local pid=$! caught
  # Once the command's handlers are in place (SigCgt has SIGINT and SIGTERM): the sweep is being read
  # and checked (2 001 scenario loads), no run has started.
  for _ in $(seq 400); do
    caught=$(awk '/^SigCgt:/ {print $2}' /proc/$pid/status 2>/dev/null)
    [ -n "$caught" ] && [ $(( 0x$caught & 0x4002 )) -eq $(( 0x4002 )) ] && break
    sleep 0.005
  done
  kill -"$sig" $pid
  # A sweep that does not stop (a background job's SIGINT is ignored unless the program handles it)
  # fails here rather than running its million runs.
  for _ in $(seq 600); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
  kill -0 $pid 2>/dev/null && { kill -KILL $pid; fail "$name: still running a minute after SIG$sig"; }
  wait $pid
  local code=$?
  [ $code -eq 130 ] || fail "$name: exit code $code, want 130 ($(cat "$work/$name.err"))"
  [ "$(cat "$work/$name.err")" = "signalsim: interrupted before any run started; nothing ran" ] ||
    fail "$name: stderr: $(cat "$work/$name.err")"
  [ -e "$work/$name" ] && fail "$name: the --out folder was made"
  ok "$name: exit $code, $(cat "$work/$name.err")"
}
stop_while_expanding sigterm_while_expanding TERM
stop_while_expanding sigint_while_expanding INT
finish
