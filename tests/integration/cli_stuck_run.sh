#!/usr/bin/env bash
# signalsim run on a scenario whose ego waits behind a vehicle that never moves: the run
# ends after stuck_rest_time (60 s) at rest, not at its 300 s duration, with exit code 1, status
# failed, arrived false and the reason in summary.json (not_arrived: stuck, the leader and its gap),
# and the built-in check printed.
# usage: cli_stuck_run.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$bin" run "$src/tests/data/scenarios/stuck_behind_obstacle.yaml" --out "$work/run" > "$work/stdout" 2> "$work/stderr"
code=$?
[ "$code" = 1 ] || fail "exit code $code, expected 1 (stderr: $(cat "$work/stderr"))"
grep -q "\[FAIL\] ego arrives (not stuck): at rest for 60.0 s at s_front 245.58 m (edge mid, lane mid_0)" "$work/stdout" \
  || fail "no built-in stuck check in: $(cat "$work/stdout")"
python3 - "$work/run/summary.json" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1]))
def check(ok, what):
    if not ok:
        print("FAIL:", what)
        sys.exit(1)
check(s["status"] == "failed", "status %r" % s["status"])
check(s["counts"]["arrived"] is False, "arrived")
check(s["counts"]["simulated_time"] < 150.0, "ran %s s, expected to end after 60 s at rest (red phases paused)" % s["counts"]["simulated_time"])
n = s.get("not_arrived")
check(isinstance(n, dict), "no not_arrived record")
check(n["reason"] == "stuck", "reason %r" % n["reason"])
check(n["edge"] == "mid" and n["lane"] == "mid_0", "where: %s %s" % (n["edge"], n["lane"]))
check(n["leader"] is not None and n["leader"]["id"] == "parked" and abs(n["leader"]["gap"] - 2.5) < 0.05,
      "leader %r" % n["leader"])
check(n["held_by"] == "", "held_by %r" % n["held_by"])
PY
echo "ok   stuck behind a parked car: exit 1, failed, arrived false, reason and leader in summary.json"
"$bin" run "$src/scenarios/tl_red_stop_then_go.yaml" --out "$work/red" --quiet || fail "red light run: exit $?"
grep -q '"not_arrived": null' "$work/red/summary.json" || fail "an arrived run has a not_arrived record"
echo "ok   an arrived run records not_arrived: null"
echo "cli_stuck_run passed"
