#!/usr/bin/env bash
# A run does not depend on the size of its net (the net index reads the route's elements on
# demand). netgenerate builds a 5x5 grid and a 26x50 grid with the same options (34 576 edges, as
# many as Bad Hersfeld's 34 801), so the blocks around the route are the same; two laps around the
# block B1 C1 C2 B2 (four lights, a left turn at each) give byte-identical timeline.csv and
# events.csv on both, a summary.json that differs only in the net's path, and the same lanelets in
# `inspect --route`.
# usage: big_net_test.sh SIGNALSIM_BINARY
set -u
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

grid() {  # grid NAME X Y
  netgenerate --grid --grid.x-number "$2" --grid.y-number "$3" --grid.length 100 --default.lanenumber 2 \
    --tls.guess true --no-warnings true -o "$work/$1.net.xml.gz" > "$work/$1.netgenerate.log" 2>&1 \
    || fail "netgenerate $1: $(cat "$work/$1.netgenerate.log")"
}
grid small 5 5
grid big 26 50

lap="B1C1, C1C2, C2B2, B2B1"
cat > "$work/laps.yaml" <<YAML
name: grid_laps
description: two laps around the block B1 C1 C2 B2, a left turn at each light
net: small.net.xml.gz
step_length: 0.1
duration: 600
seed: 1
ego:
  route: [$lap, $lap, B1C1]
  depart_pos: 0
  depart_speed: 8.33
  max_speed: 13.89
  length: 4.5
  base_link_to_front: 3.7
expect:
  - blinker_through_junction: {junction: C1, blinker: left, lead: 30}
  - blinker_never: right
  - arrives: true
YAML

for size in small big; do
  "$bin" run "$work/laps.yaml" --set "net=$work/$size.net.xml.gz" --out "$work/out_$size" --quiet \
    || fail "run on the $size grid: exit $?"
done
for f in timeline.csv events.csv; do
  cmp -s "$work/out_small/$f" "$work/out_big/$f" || fail "$f differs: $(diff "$work/out_small/$f" "$work/out_big/$f" | head -5)"
done
[ "$(wc -l < "$work/out_small/timeline.csv")" -gt 3000 ] || fail "short timeline: $(wc -l < "$work/out_small/timeline.csv") lines"
changed=$(diff "$work/out_small/summary.json" "$work/out_big/summary.json" | grep '^[<>]' | grep -vc '"net":')
[ "$changed" = 0 ] || fail "summary.json differs beyond the net: $(diff "$work/out_small/summary.json" "$work/out_big/summary.json")"
echo "ok   two laps on a 5x5 and a 26x50 grid: the same timeline, events and summary"

for size in small big; do
  "$bin" inspect "$work/$size.net.xml.gz" --route B1C1 C1C2 C2B2 > "$work/inspect_$size.txt" || fail "inspect $size: exit $?"
done
grep -q ": 34576 edges, " "$work/inspect_big.txt" || fail "big grid: $(head -1 "$work/inspect_big.txt")"
cmp -s <(tail -n +2 "$work/inspect_small.txt") <(tail -n +2 "$work/inspect_big.txt") \
  || fail "inspect --route differs: $(diff "$work/inspect_small.txt" "$work/inspect_big.txt" | head -5)"
echo "ok   inspect --route: the same lanelets on both grids"
