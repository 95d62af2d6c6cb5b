#!/usr/bin/env bash
# exec: systems under test that misbehave, on the real libsumo (docs/decider.md "JSON lines",
# "Faults"): a command that cannot be found, a reply that is not JSON, lacks 'blinker' or has another
# value, two lines for one step, an early exit, a crash (SIGSEGV), no answer within sut_timeout, SUMO
# failing to load once the SUT has been started. Each
# ends the run with exit 2, summary.json status "error" and one line naming the SUT and the step;
# the SUT's stderr is kept in the run directory; in a batch the other runs still pass.
# usage: sut_exec_faults.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
data=$src/tests/data/sut
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# run NAME EXPECTED_LINE ARGS...: exit 2, one line on stderr equal to EXPECTED_LINE, an error summary.
run_fault() {
  local name=$1 where=$2 expected=$3
  shift 3
  local out=$work/$name
  "$bin" run "$data/good.yaml" --out "$out" --quiet "$@" >"$work/$name.stdout" 2>"$work/$name.stderr"
  local rc=$?
  local said
  said=$(cat "$work/$name.stderr")
  [ "$rc" -eq 2 ] || fail "$name: exit $rc, not 2 ($said)"
  [ "$(wc -l <"$work/$name.stderr")" -eq 1 ] || fail "$name: not one line on stderr: $said"
  [ "$said" = "signalsim: $where: $expected" ] || fail "$name: said '$said', not '$where: $expected'"
  python3 - "$out/summary.json" "$where: $expected" <<'PY' || fail "$name: summary.json"
import json, sys
s = json.load(open(sys.argv[1]))
sys.exit(0 if s["status"] == "error" and s["error"] == sys.argv[2] else 1)
PY
  [ "$rc" -eq 2 ] && echo "ok   $name: $said"
}

sut="exec:sh $data/reply.sh"
at="at t=0.30 s"
# A command that cannot be run is the --set item's (the value came from the command line).
run_fault not_found "--set decider=exec:no_such_program_signalsim" "key 'decider': exec:no_such_program_signalsim: 'no_such_program_signalsim' is not an executable file on PATH" \
  --set "decider=exec:no_such_program_signalsim"
run_fault not_found_relative "--set light_judge=exec:./missing.py x" "key 'light_judge': exec:./missing.py x: './missing.py' is not an executable file (relative to $data)" \
  --set "light_judge=exec:./missing.py x"
run_fault not_json "$data/good.yaml" "decider $sut not_json $at: reply is not JSON: this is not json" --set "decider=$sut not_json"
run_fault no_blinker "$data/good.yaml" "decider $sut no_blinker $at: reply lacks 'blinker': {\"blinkers\": \"left\"}" --set "decider=$sut no_blinker"
run_fault bad_blinker "$data/good.yaml" "decider $sut bad_blinker $at: reply's 'blinker' is \"up\", not \"none\", \"left\", \"right\" or \"hazard\"" \
  --set "decider=$sut bad_blinker"
run_fault two_lines "$data/good.yaml" "decider $sut two_lines $at: wrote more than one line for the step" --set "decider=$sut two_lines"
run_fault exits_early "$data/good.yaml" "decider $sut exit $at: exited with status 3 before replying" --set "decider=$sut exit"
run_fault crashes "$data/good.yaml" "decider $sut segv $at: killed by signal 11 (SIGSEGV) before replying" --set "decider=$sut segv"
run_fault never_answers "$data/good.yaml" "decider $sut silent $at: no reply within 0.5 s" --set "decider=$sut silent" --set sut_timeout=0.5
# The light judge is asked on steps with a light in its window: the first is the run's first step.
run_fault judge_lacks_lights "$data/good.yaml" "light_judge exec:sh $data/judge_reply.sh at t=0.10 s: reply lacks 'lights': {\"decision\": \"go\"}" \
  --set "light_judge=exec:sh $data/judge_reply.sh"
# Whatever went wrong, the SUT's stderr is kept (the crash wrote none) and no process is left.
[ -f "$work/crashes/decider.stderr.txt" ] || fail "crashes: no decider.stderr.txt in the run directory"
if pgrep -f "$data/reply.sh" >/dev/null; then fail "a SUT process is still running"; fi

# The SUT is started before SUMO: when SUMO cannot load the simulation, the one line is SUMO's error
# and the SUT's process (one that writes its pid and would sleep a minute, whatever its stdin) is gone.
"$bin" run "$src/tests/batch/data/sumo_load_error.yaml" --out "$work/sumo_fails" --quiet \
  --set "decider=exec:sh -c 'echo \$\$ > $work/sut.pid; exec sleep 60'" >/dev/null 2>"$work/sumo_fails.stderr"
rc=$?
if [ ! -s "$work/sut.pid" ]; then
  fail "SUMO failing with a SUT launched: the SUT was not started before SUMO"
elif kill -0 "$(cat "$work/sut.pid")" 2>/dev/null; then
  fail "SUMO failed: the SUT process $(cat "$work/sut.pid") is still running"
  kill "$(cat "$work/sut.pid")"
fi
if [ $rc -eq 2 ] && [ "$(wc -l <"$work/sumo_fails.stderr")" -eq 1 ] &&
   grep -q "SUMO could not load the simulation: The lane nowhere_0" "$work/sumo_fails.stderr"; then
  echo "ok   SUMO fails with a SUT launched: $(cat "$work/sumo_fails.stderr")"
else
  fail "SUMO failing with a SUT launched: exit $rc: $(cat "$work/sumo_fails.stderr")"
fi

# A SUT writing to stderr: the run passes, its stderr is in the run directory, not on signalsim's.
"$bin" run "$data/good.yaml" --out "$work/stderr" --quiet >"$work/stderr.stdout" 2>"$work/stderr.stderr"
rc=$?
[ "$rc" -eq 0 ] || fail "stderr: exit $rc"
grep -q "step" "$work/stderr.stderr" "$work/stderr.stdout" && fail "stderr: the SUT's stderr reached signalsim's output"
[ "$(head -1 "$work/stderr/decider.stderr.txt")" = "step 1 seen" ] || fail "stderr: decider.stderr.txt lacks 'step 1 seen'"
[ "$rc" -eq 0 ] && echo "ok   stderr: $(wc -l <"$work/stderr/decider.stderr.txt") lines in decider.stderr.txt"

# A batch: the faulty run is an error row (batch exit 4), the other run still ends as it should.
"$bin" batch "$data/good.yaml" "$data/not_json.yaml" --out "$work/batch" -j 2 -q >"$work/batch.out" 2>&1
rc=$?
[ "$rc" -eq 4 ] || fail "batch: exit $rc, not 4 (a run errored)"
python3 - "$work/batch/results.csv" "$data" <<'PY' || fail "batch: results.csv"
import csv, sys
rows = {r["scenario"]: r for r in csv.DictReader(open(sys.argv[1]))}
good, bad = rows["sut_good"], rows["sut_not_json"]
ok = good["status"] == "no_expectations" and bad["status"] == "error" and \
     bad["error"].endswith("decider exec:sh reply.sh not_json at t=0.30 s: reply is not JSON: this is not json")
print(("ok  " if ok else "FAIL") + " batch: sut_good %s, sut_not_json %s: %s" % (good["status"], bad["status"], bad["error"]))
sys.exit(0 if ok else 1)
PY

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all exec: faults end as errors"
