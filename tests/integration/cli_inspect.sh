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
echo "ok   an unknown edge is exit 2 with one line"
echo "cli_inspect passed"
