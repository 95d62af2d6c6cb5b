#!/usr/bin/env bash
# The batch command does not read its scenario files; each run's worker reads its own (docs/batch.md
# "The command does not read the scenarios"). A file that does not load among many is that run's
# error row with FILE:LINE: reason (exit code 4) while the others run; run directories are named by
# the files' stems and results.csv's scenario column is the name the run read; --resume keeps the
# finished rows and runs the error row again, and refuses once a file changed. A bad --set is still
# the whole command's bad input (exit 2, nothing run). A sweep of more than 500 runs is checked on its
# first file alone: a broken later file gives its runs' error rows, the rest run.
# usage: large_batch_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# 30 copies of the batch tests' turns.yaml (paths made absolute), one named unlike its file,
# and one with an unknown key at line 4 in the middle (by name order).
mkdir "$work/suite"
for i in $(seq -w 0 29); do
  sed -e "s#\.\./\.\./\.\.#$src#" -e "s/^name: turns$/name: turns$i/" \
    "$src/tests/batch/data/turns.yaml" > "$work/suite/s$i.yaml"
done
sed -i 's/^name: turns03$/name: renamed/' "$work/suite/s03.yaml"
printf 'name: broken\ndescription: a key signalsim does not know\nnet: x.net.xml\nnot_a_key: 1\n' > "$work/suite/s15b.yaml"
total=31

"$bin" batch "$work/suite" --out "$work/out" --jobs 2 --quiet > "$work/batch.log" 2>&1
code=$?
[ $code -eq 4 ] || fail "batch with a broken file: exit code $code, not 4 ($(tail -3 "$work/batch.log"))"
rows=$(($(wc -l < "$work/out/results.csv") - 1))
[ "$rows" -eq $total ] || fail "results.csv has $rows rows, not $total"
row_of() { grep ",$work/suite/$1.yaml," "$work/out/results.csv"; }
row_of s15b | grep -q ",error," || fail "the broken file's row is not an error row: $(row_of s15b)"
row_of s15b | grep -q "$work/suite/s15b.yaml:[0-9]*: " || fail "the error row does not name the file and line: $(row_of s15b)"
[ "$(grep -c ',passed,' "$work/out/results.csv")" -eq 30 ] || fail "not every other run passed"
[ -f "$work/out/runs/0003-s03/summary.json" ] || fail "run directories are not named by the file's stem: $(ls "$work/out/runs" | head -5)"
row_of s03 | grep -q "^3,renamed," || fail "the scenario column is not the name its run read: $(row_of s03)"
echo "ok   a broken file among $total: its error row with file and line, the other 30 passed; names"

"$bin" batch "$work/suite" --out "$work/out" --jobs 2 --resume > "$work/resume.log" 2>&1
code=$?
[ $code -eq 4 ] || fail "--resume: exit code $code, not 4"
grep -q "^resuming: 30 of $total runs already done, 1 to run" "$work/resume.log" || fail "--resume: $(head -2 "$work/resume.log")"
[ "$(($(wc -l < "$work/out/results.csv") - 1))" -eq $total ] || fail "--resume lost rows"
echo "ok   --resume keeps the 30 finished rows and runs the error row again"

echo "# changed" >> "$work/suite/s07.yaml"
"$bin" batch "$work/suite" --out "$work/out" --jobs 2 --resume > "$work/changed.log" 2>&1
code=$?
[ $code -eq 2 ] || fail "--resume after a file changed: exit code $code, not 2"
grep -q "results there were made with other settings.*: run [0-9]* ($work/suite/s07.yaml): the file changed" "$work/changed.log" ||
  fail "--resume after a change: $(cat "$work/changed.log")"
echo "ok   --resume refuses once a scenario file changed, naming the file"

"$bin" batch "$work/suite" --out "$work/badset" --set no_such_parameter=1 > "$work/badset.log" 2>&1
code=$?
[ $code -eq 2 ] || fail "a bad --set: exit code $code, not 2"
grep -q "no_such_parameter" "$work/badset.log" || fail "a bad --set is not named: $(cat "$work/badset.log")"
[ -z "$(ls -A "$work/badset/runs" 2>/dev/null)" ] || fail "a run started despite the bad --set"
echo "ok   a bad --set is the command's bad input: exit 2 before any run"

# 31 files x 17 seeds = 527 runs (> 500): checked on s00.yaml alone; s15b's 17 runs are error rows.
printf 'name: many\nscenarios: [suite]\nset: {duration: 0.5}\ngrid:\n  seed: [%s]\n' "$(seq -s ', ' 1 17)" > "$work/many.yaml"
"$bin" sweep "$work/many.yaml" --out "$work/sweep" --jobs 2 --quiet > "$work/sweep.log" 2>&1
code=$?
[ $code -eq 4 ] || fail "sweep with a broken file: exit code $code, not 4 ($(tail -3 "$work/sweep.log"))"
[ "$(($(wc -l < "$work/sweep/results.csv") - 1))" -eq 527 ] || fail "the sweep's results.csv does not have 527 rows"
[ "$(grep -c ',error,' "$work/sweep/results.csv")" -eq 17 ] || fail "not exactly the broken file's 17 runs are errors"
[ "$(grep -c "s15b.yaml:[0-9]*: " "$work/sweep/results.csv")" -eq 17 ] || fail "the sweep's error rows do not name file and line"
echo "ok   a sweep of 527 runs: the broken file's 17 runs are error rows, the other 510 ran"
