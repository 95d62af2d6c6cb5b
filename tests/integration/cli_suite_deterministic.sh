#!/usr/bin/env bash
# Every bundled scenario passes through the command line, and two runs give byte-identical files.
# usage: cli_suite_deterministic.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0
for scenario in "$src"/scenarios/*.yaml; do
  name=$(basename "$scenario" .yaml)
  ok=1
  for run in a b; do
    "$bin" run "$scenario" --out "$work/$run/$name" --quiet || { echo "FAIL $name: exit code $? (run $run)"; ok=0; }
  done
  for f in timeline.csv events.csv summary.json; do
    cmp -s "$work/a/$name/$f" "$work/b/$name/$f" || { echo "FAIL $name: $f differs between two runs"; ok=0; }
  done
  if [ $ok -eq 1 ]; then passed=$((passed + 1)); echo "ok   $name"; else failed=$((failed + 1)); fi
done
echo "$passed passed, $failed failed"
[ $failed -eq 0 ] && [ $passed -gt 0 ]
