#!/usr/bin/env bash
# signalsim inspect: a route's lanelets as the decider sees them. Space- and comma-separated routes
# give the same table; the lane change the route needs is counted; an edge the net does not have is
# exit 2 with one line naming the net, --route and the edge.
# usage: cli_inspect.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

net=$src/sumo_nets/cross_feeder/cross_feeder.net.xml
"$bin" inspect "$net" --route w_far in_W out_N > "$work/spaces.txt" || fail "inspect with spaces: exit $?"
"$bin" inspect "$net" --route w_far,in_W,out_N > "$work/commas.txt" || fail "inspect with commas: exit $?"
cmp -s "$work/spaces.txt" "$work/commas.txt" || fail "comma-separated route differs: $(diff "$work/spaces.txt" "$work/commas.txt")"
grep -q "route: 6 lanelets, 599.36 m, 1 lane change(s) planned" "$work/spaces.txt" \
  || fail "route line: $(grep route: "$work/spaces.txt")"
# The left turn's internal lanes carry the turn direction and the junction.
grep -Eq "^ +[0-9]+ +[0-9.]+ +[0-9.]+ +:C_[0-9]+_0 +left +none +C " "$work/spaces.txt" || fail "no left turn lanelet at C"
echo "ok   space- and comma-separated routes, lane change counted, the left turn at C"

"$bin" inspect "$src/sumo_nets/cross/cross.net.xml" --route in_S,nope > "$work/bad.out" 2> "$work/bad.err"
code=$?
[ "$code" = 2 ] || fail "unknown edge: exit code $code, expected 2"
[ "$(wc -l < "$work/bad.err")" = 1 ] || fail "unknown edge: expected one stderr line, got: $(cat "$work/bad.err")"
grep -q "cross.net.xml: --route: route edge 'nope' is not in the net" "$work/bad.err" || fail "message: $(cat "$work/bad.err")"
[ ! -s "$work/bad.out" ] || fail "unknown edge: output written: $(cat "$work/bad.out")"
echo "ok   an unknown edge is exit 2 with one line"
# A real city net whose netconvert (1.22) wrote two index-0 lanes on an internal edge
# loads (SUMO 1.15 does), the defect is listed with its line, and a route through it is shown.
acosta=$src/sumo_nets/bologna_acosta/acosta_buslanes.net.xml
"$bin" inspect "$acosta" --route 131 117 209 > "$work/acosta.txt" 2> "$work/acosta.err" \
  || fail "bologna acosta: exit $?: $(cat "$work/acosta.err")"
grep -q "acosta_buslanes.net.xml:989: edge ':9_17': lane indices are not 0..1 (lane ':9_17_1' repeats index 0); the file's lane order is used \[no route reads it\]" "$work/acosta.txt" \
  || fail "acosta defect line: $(cat "$work/acosta.txt")"
grep -q "route: 5 lanelets, 874.23 m, 0 lane change(s) planned" "$work/acosta.txt" || fail "acosta route: $(cat "$work/acosta.txt")"
echo "ok   a real net with a defect on no route loads; the defect is listed"

# A defect the route uses: exit 2, one line naming the net's line, the element and the reason.
sed 's|id="bc_1" index="1" speed="13.89" length="48.50"|id="bc_1" index="1" speed="13.89" length="nan"|' \
  "$src/tests/data/nets/line.net.xml" > "$work/nan.net.xml"
line=$(grep -n 'id="bc_1"' "$work/nan.net.xml" | cut -d: -f1)
"$bin" inspect "$work/nan.net.xml" --route ab bc > "$work/nan.out" 2> "$work/nan.err"
code=$?
[ "$code" = 2 ] || fail "defect on the route: exit code $code, expected 2"
[ "$(wc -l < "$work/nan.err")" = 1 ] || fail "defect on the route: expected one stderr line, got: $(cat "$work/nan.err")"
[ "$(cat "$work/nan.err")" = "signalsim: $work/nan.net.xml:$line: lane 'bc_1': attribute 'length' is not a number: 'nan' (a lane the route drives on edge 'bc') in --route" ] \
  || fail "defect message: $(cat "$work/nan.err")"
[ ! -s "$work/nan.out" ] || fail "defect on the route: output written: $(cat "$work/nan.out")"
"$bin" inspect "$work/nan.net.xml" --route cb bc > /dev/null || fail "a route beside the defect: exit $?"
echo "ok   a defect the route uses is exit 2 with one line naming the net's line; a route beside it builds"
# Inspect says where the lane plan put the lane change and the room it has there
# (was: exit 2, the lane change on the 0.54 m edge 204[1][0] did not fit).
"$bin" inspect "$acosta" --route 46 201 201c "204a[0]" "204b[0]" "204[1][0]" 125 > "$work/room.txt" 2> "$work/room.err" \
  || fail "room: exit $?: $(cat "$work/room.err")"
grep -qF "lane change on edge '201': lane 0 -> 1, a 3.20 m shift in 227.67 m of room: fits (at least 19.90 m of lateral motion at 13.89 m/s)" "$work/room.txt" \
  || fail "room: $(grep "lane change" "$work/room.txt")"
echo "ok   the lane change goes on the edge with the most room, and inspect names it"

# A lane change across the bus lane 31_1 is exit 2 with one line.
"$bin" inspect "$acosta" --route 165 31 113 > "$work/bus.out" 2> "$work/bus.err"
code=$?
[ "$code" = 2 ] || fail "bus lane: exit code $code, expected 2"
[ "$(cat "$work/bus.err")" = "signalsim: $acosta: --route: the lane change the route needs on edge '31' (lane 0 -> 2) crosses lane '31_1', which a passenger car may not use; no other lane sequence connects the route edges" ] \
  || fail "bus lane: $(cat "$work/bus.err")"
[ ! -s "$work/bus.out" ] || fail "bus lane: output written"
echo "ok   a lane change across a bus lane is exit 2 naming the edge and the lane"
echo "cli_inspect passed"
