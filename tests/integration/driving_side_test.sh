#!/usr/bin/env bash
# A country preset for the other driving side than the net's, on the real libsumo with bundled nets:
# jp (left-hand traffic) on the right-hand roundabout and de on the left-hand one give one warning line
# on stderr and the same sentence in summary.json `notes`; jp on the left-hand net gives none (and no
# `notes`); --quiet prints nothing but the summary keeps it; a batch warns once per scenario.
# usage: driving_side_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
suffix="the exit blinker is then on the wrong side for that traffic"

notes_of() { /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get('notes'))" "$1/summary.json"; }

jp_right="country jp drives on the left, but the net $src/sumo_nets/roundabout/roundabout.net.xml is \
right-hand traffic (no lefthand=\"true\"): $suffix"
"$bin" run "$src/scenarios/roundabout_jp_exit2.yaml" --out "$work/jp" >/dev/null 2>"$work/jp.stderr" || fail "jp: exit $?"
[ "$(cat "$work/jp.stderr")" = "signalsim: warning: $jp_right" ] || fail "jp on a right-hand net: $(cat "$work/jp.stderr")"
[ "$(notes_of "$work/jp")" = "['$jp_right']" ] || fail "jp summary notes: $(notes_of "$work/jp")"

"$bin" run "$src/scenarios/roundabout_jp_exit2.yaml" --out "$work/jp_quiet" --quiet 2>"$work/quiet.stderr" ||
  fail "jp --quiet: exit $?"
[ -s "$work/quiet.stderr" ] && fail "--quiet printed: $(cat "$work/quiet.stderr")"
[ "$(notes_of "$work/jp_quiet")" = "['$jp_right']" ] || fail "--quiet summary notes: $(notes_of "$work/jp_quiet")"

de_left="country de drives on the right, but the net $src/sumo_nets/roundabout_lefthand/roundabout_lefthand.net.xml \
is left-hand traffic (lefthand=\"true\"): $suffix"
"$bin" run "$src/scenarios/roundabout_lefthand_jp_exit2.yaml" --set country=de --out "$work/de" >/dev/null 2>"$work/de.stderr"
[ "$(grep -c 'warning' "$work/de.stderr")" -eq 1 ] && grep -qxF "signalsim: warning: $de_left" "$work/de.stderr" ||
  fail "de on a left-hand net: $(cat "$work/de.stderr")"
[ "$(notes_of "$work/de")" = "['$de_left']" ] || fail "de summary notes: $(notes_of "$work/de")"

"$bin" run "$src/scenarios/roundabout_lefthand_jp_exit2.yaml" --out "$work/same" >/dev/null 2>"$work/same.stderr" ||
  fail "jp on a left-hand net: exit $?"
[ -s "$work/same.stderr" ] && fail "jp on a left-hand net printed: $(cat "$work/same.stderr")"
[ "$(notes_of "$work/same")" = "None" ] || fail "jp on a left-hand net has notes: $(notes_of "$work/same")"

"$bin" batch "$src/scenarios/roundabout_jp_exit2.yaml" "$src/scenarios/roundabout_jp_exit2.yaml" \
  "$src/scenarios/roundabout_lefthand_jp_exit2.yaml" --out "$work/batch" --jobs 2 >/dev/null 2>"$work/batch.stderr"
[ "$(grep -c "^signalsim: warning: " "$work/batch.stderr")" -eq 1 ] || fail "batch warnings: $(cat "$work/batch.stderr")"

if [ "$failures" -eq 0 ]; then echo "driving side: all checks passed"; else echo "$failures failure(s)"; fi
[ "$failures" -eq 0 ]
