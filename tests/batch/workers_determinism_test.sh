#!/usr/bin/env bash
# Same seed, same outputs, whatever ran before in the same worker: scenarios A (SUMO options that
# write extra files, SUMO's randomness with the sumocfg's seed, the perception model's draws) then B
# in one worker (--jobs 1) give B the row and the run directory B gets alone in its own process.
# B drives with background traffic whose drivers are random (SUMO's sigma, the sumocfg's seed 7,
# tripinfo.xml of every vehicle) and a light approach with random perception faults.
# usage: workers_determinism_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
user=$src/tests/data/user_sumo
approach=$src/tests/data/scenarios/random_approach.yaml

# A: fcd_signals (--fcd-output, --tripinfo), take_over (seed 7, traffic), random_approach (seed 1);
# B: take_over_flow (seed 7, the same traffic), random_approach again.
"$bin" batch "$user/fcd_signals.yaml" "$user/take_over.yaml" "$approach" "$user/take_over_flow.yaml" "$approach" \
  --out "$work/after" --jobs 1 --quiet || fail "A then B: exit code $?"
"$bin" batch "$user/take_over_flow.yaml" --out "$work/alone_flow" --isolate --quiet || fail "B alone: exit code $?"
"$bin" batch "$approach" --out "$work/alone_approach" --isolate --quiet || fail "B alone: exit code $?"
[ -s "$work/after/runs/0003-take_over_flow/tripinfo.xml" ] || fail "take_over_flow wrote no tripinfo.xml"
python3 "$src/tests/batch/same_outputs.py" "$work/after" "$work/alone_flow" --pair 3:0 ||
  fail "take_over_flow after A differs from take_over_flow alone"
python3 "$src/tests/batch/same_outputs.py" "$work/after" "$work/alone_approach" --pair 4:0 --pair 2:0 ||
  fail "random_approach after A differs from random_approach alone"
echo "ok   B after A in one worker == B alone in its own process"
echo "workers_determinism_test passed"
