#!/usr/bin/env bash
# Generate's promise that every generated scenario passes (`batch` exit 0):
#   a red light at departure: on DLR's TAVF-Hamburg net (tests/data/nets/tavf_hamburg) --seed 3 route 3 departed at
#            13.8 m/s 39.7 m before a light red at t=0, closer than the judge's stopping distance
#            (44.7 m): the judge passed and the ego crossed on red. The departure speed now lets a
#            normal stop end before the first light.
#   bidi edges: no route over a multi-lane bidirectional edge, where SUMO 1.15 aborts (SIGABRT).
# usage: generate_regressions.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

tavf=$src/tests/data/nets/tavf_hamburg/network.net.xml.gz
"$bin" generate "$tavf" --count 10 --seed 3 --out "$work/tavf" --quiet || fail "generate on TAVF-Hamburg"
grep -q "before the first light" "$work/tavf/network_0003.yaml" || fail "route 3 does not say why it departs slower"
"$bin" batch "$work/tavf" --out "$work/tavf_runs" -j 2 > "$work/tavf.txt" 2>&1 ||
  fail "generated TAVF-Hamburg scenarios fail: $(grep -v passed "$work/tavf.txt")"
echo "ok   TAVF-Hamburg --seed 3: $(tail -n 1 "$work/tavf.txt")"

bidi=$src/tests/data/nets/bidi_two_lane.net.xml
"$bin" generate "$bidi" --count 5 --seed 1 --out "$work/bidi" > "$work/bidi_gen.txt" 2>&1 ||
  fail "generate on bidi_two_lane: $(cat "$work/bidi_gen.txt")"
if grep -l -E '^  route: .*"(ab|ba)"' "$work"/bidi/*.yaml; then fail "a route over the two-lane bidi edges ab/ba"; fi
"$bin" batch "$work/bidi" --out "$work/bidi_runs" > "$work/bidi.txt" 2>&1 ||
  fail "generated bidi_two_lane scenarios fail: $(cat "$work/bidi.txt")"
echo "ok   bidi_two_lane: no route over ab/ba; $(tail -n 1 "$work/bidi.txt")"
