#!/usr/bin/env bash
# Persistent workers give the same results as one process per run (--isolate), for --jobs 1 and 2:
# results.csv byte for byte (wall_time aside) and every file of every run directory (what differs
# between any two SUMO runs masked: same_outputs.py). The batch is the bundled suite followed by
# scenarios that use SUMO's own options, files and randomness (tests/data/user_sumo), a run whose
# SUMO fails to start and one that fails mid-run, so that runs follow errors in the same worker;
# then the bundled 18-run sweep both ways.
# usage: workers_same_outputs_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
data=$src/tests/batch/data
user=$src/tests/data/user_sumo
cd "$src" || exit 1  # relative scenario paths, as a user types them

suite=(scenarios "$data/sumo_load_error.yaml" "$user/fcd_signals.yaml" "$user/take_over.yaml"
       tests/data/bad/mid_run_sumo_error.yaml "$user/take_over_flow.yaml" "$data/sumo_load_error.yaml"
       "$user/sumo_warnings.yaml" scenarios/intersection_left.yaml)
"$bin" batch "${suite[@]}" --out "$work/isolated" --jobs 2 --isolate --quiet
code=$?
[ $code -eq 4 ] || fail "--isolate: exit code $code, not 4 (the two SUMO errors)"
rows=$(($(wc -l < "$work/isolated/results.csv") - 1))
[ "$rows" -eq 80 ] || fail "--isolate: $rows rows, not 80 (the 72 bundled scenarios and 8 more)"
[ "$(grep -c ',error,' "$work/isolated/results.csv")" -eq 3 ] || fail "--isolate: not 3 error rows"
grep -q "SUMO could not load the simulation: The lane nowhere_0 to use within the busStop 'stop' is not known." \
  "$work/isolated/results.csv" || fail "no SUMO load error row"
for jobs in 1 2; do
  "$bin" batch "${suite[@]}" --out "$work/workers$jobs" --jobs $jobs --quiet
  code=$?
  [ $code -eq 4 ] || fail "workers, --jobs $jobs: exit code $code, not 4"
  python3 "$src/tests/batch/same_outputs.py" "$work/isolated" "$work/workers$jobs" ||
    fail "persistent workers (--jobs $jobs) differ from one process per run"
  echo "ok   the suite and the user_sumo runs, --jobs $jobs: the same as --isolate"
done

sweep=$data/sweep_3x3x2.yaml
"$bin" sweep "$sweep" --out "$work/sweep_isolated" --jobs 2 --isolate --quiet || fail "sweep --isolate: exit code $?"
"$bin" sweep "$sweep" --out "$work/sweep_workers" --jobs 2 --quiet || fail "sweep: exit code $?"
python3 "$src/tests/batch/same_outputs.py" "$work/sweep_isolated" "$work/sweep_workers" ||
  fail "the sweep in persistent workers differs from one process per run"
echo "ok   the 18-run sweep: the same as --isolate"
echo "workers_same_outputs_test passed"
