#!/bin/sh
# Rebuilds the test nets from their plain-XML sources with SUMO 1.15's netconvert.
# Usage: tests/data/nets/build.sh   (the built .net.xml files are committed; run after editing a source)
set -eu
cd "$(dirname "$0")"
export SUMO_HOME="${SUMO_HOME:-/usr/share/sumo}"
nc() { netconvert --no-warnings true --output.street-names false "$@"; }
nc -n crossing.nod.xml -e crossing.edg.xml -x crossing.con.xml -o crossing.net.xml
nc -n roundabout.nod.xml -e roundabout.edg.xml -o roundabout.net.xml
nc -n line.nod.xml -e line.edg.xml -o line.net.xml
nc -n line.nod.xml -e line.edg.xml --lefthand true -o line_lefthand.net.xml
nc -n line.nod.xml -e line.edg.xml --no-internal-links true -o line_nointernal.net.xml
nc -n bend_then_light.nod.xml -e bend_then_light.edg.xml -o bend_then_light.net.xml
# ab/ba as a two-lane bidirectional pair (netconvert writes bidi= only for rail): SUMO 1.15 loads it and
# aborts on a vehicle there (MSLane::getBidiLane assertion), the case of DLR's Doerpfeldstr net.
nc -n bidi_two_lane.nod.xml -e bidi_two_lane.edg.xml -o bidi_two_lane.net.xml
sed -i -e 's|<edge id="ab" from="A" to="B" priority="-1"|& bidi="ba"|' \
       -e 's|<edge id="ba" from="B" to="A" priority="-1"|& bidi="ab"|' bidi_two_lane.net.xml
nc -n truck_lanes.nod.xml -e truck_lanes.edg.xml -o truck_lanes.net.xml
