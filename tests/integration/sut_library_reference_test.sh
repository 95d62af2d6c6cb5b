#!/usr/bin/env bash
# signalsim's own decider behind the C ABI (tests/plugins/reference_decider) in place of the reference,
# on every bundled scenario: at every step of every run the SUT's blinker equals the reference's
# (timeline.csv `blinker` == `ref_blinker`), and each run's events.csv is the reference run's, byte
# for byte, once the blinker events' source (`sut` for a decider under test) is set aside. The proof
# that the ABI carries all the reference decider reads.
# usage: sut_library_reference_test.sh SIGNALSIM_BINARY SOURCE_DIR PLUGIN
set -u
bin=$1
src=$2
plugin=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

"$bin" batch "$src"/scenarios/*.yaml --out "$work/ref" --jobs 2 --quiet >/dev/null 2>"$work/ref.err"
"$bin" batch "$src"/scenarios/*.yaml --out "$work/lib" --jobs 2 --quiet --set "decider=lib:$plugin" >/dev/null 2>"$work/lib.err"
runs=0
for dir in "$work"/ref/runs/*; do
  name=$(basename "$dir")
  lib=$work/lib/runs/$name
  runs=$((runs + 1))
  [ -f "$dir/timeline.csv" ] || { echo "FAIL $name: the reference run has no timeline"; failures=$((failures + 1)); continue; }
  [ -f "$lib/timeline.csv" ] || { echo "FAIL $name: the lib: run has no timeline: $(cat "$lib/summary.json" 2>/dev/null | head -c 300)"; failures=$((failures + 1)); continue; }
  # Every row: blinker == ref_blinker.
  disagree=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "blinker") b = i; if ($i == "ref_blinker") r = i }
                               if (!b || !r) { print "no blinker/ref_blinker column"; exit } next }
                      $b != $r { n++; if (n == 1) first = $1 } END { if (n) print n " rows, first at t=" first }' "$lib/timeline.csv")
  [ -z "$disagree" ] || { echo "FAIL $name: blinker != ref_blinker: $disagree"; failures=$((failures + 1)); }
  # The same rows otherwise: the reference run's columns, blinker_source aside, are the lib: run's.
  ncol=$(head -1 "$dir/timeline.csv" | tr ',' '\n' | wc -l)
  src_col=$(head -1 "$dir/timeline.csv" | tr ',' '\n' | grep -n '^blinker_source$' | cut -d: -f1)
  cut -d, -f1-"$ncol" "$lib/timeline.csv" | cut -d, --complement -f"$src_col" >"$work/lib_rows.csv"
  cut -d, --complement -f"$src_col" "$dir/timeline.csv" >"$work/ref_rows.csv"
  cmp -s "$work/ref_rows.csv" "$work/lib_rows.csv" || { echo "FAIL $name: timeline rows differ"; failures=$((failures + 1)); }
  # Events: the reference's with each blinker event's source replaced by `sut`.
  awk -F, -v OFS=, 'NR > 1 && $3 == "blinker" && $5 != "none" { $NF = "sut" } { print }' "$dir/events.csv" >"$work/ref_events.csv"
  cmp -s "$work/ref_events.csv" "$lib/events.csv" ||
    { echo "FAIL $name: events.csv differs:"; diff "$work/ref_events.csv" "$lib/events.csv" | head -5; failures=$((failures + 1)); }
done
[ "$runs" -ge 60 ] || { echo "FAIL only $runs runs"; failures=$((failures + 1)); }
if [ "$failures" -ne 0 ]; then echo "$failures failures in $runs runs"; exit 1; fi
echo "ok: $runs scenarios, the plugin's blinker is the reference's at every step, events identical"
