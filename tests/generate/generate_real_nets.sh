#!/usr/bin/env bash
# Routes generated on every bundled net and on the real net bologna_acosta (no country, jp,
# de, kr) and run as they are with `signalsim batch`: every run passes, i.e. arrives, crosses no stop
# line on red and shows the blinkers the rules give (each file's expectations). Then the same files
# with broken rules (--set) must fail, so the expectations have teeth; and `check --update` accepts
# the folder as a golden suite.
# usage: generate_real_nets.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cd "$work" || exit 1

# every_run_passes OUT: every row of OUT/results.csv passed, and every summary says arrived, no red
# crossing, every expectation held.
every_run_passes() {
  python3 "$src/tests/generate/every_run_passes.py" "$1" || exit 1
}

# 1. The bundled nets: as many distinct routes as each has (up to 8), with a country each.
mkdir suite
for spec in cross: cross_feeder:kr t_junction: t_junction_tsd:de close_turns:jp two_lights: signal_cross:de \
            roundabout:jp roundabout_lefthand:jp roundabout_exit_tags:de roundabout_after_junction:kr \
            roundabout_two_lane:de; do
  net=${spec%%:*}
  country=${spec#*:}
  args=(--count 8 --seed 3 --out "suite/$net" --quiet)
  [ -n "$country" ] && args+=(--country "$country")
  "$bin" generate "$src/sumo_nets/$net/$net.net.xml" "${args[@]}" 2> "$net.err" || fail "generate $net: $(cat "$net.err")"
done
# 2. bologna_acosta: 40 routes with Autoware's defaults, 12 for each country preset.
acosta=$src/sumo_nets/bologna_acosta/acosta_buslanes.net.xml
"$bin" generate "$acosta" --count 40 --seed 1 --out suite/acosta --quiet || fail "generate acosta"
for country in jp de kr; do
  "$bin" generate "$acosta" --count 12 --seed 2 --country $country --out "suite/acosta_$country" --quiet \
    || fail "generate acosta $country"
done
# Roundabouts on the real net too: every route through one of its two roundabouts.
"$bin" generate "$acosta" --count 6 --seed 4 --country kr --through roundabouts --out suite/acosta_rb --quiet \
  || fail "generate acosta roundabouts"
total=$(ls suite/*/*.yaml | wc -l)
[ "$total" -ge 150 ] || fail "only $total scenarios generated"
grep -l "roundabout_exit" suite/acosta_rb/*.yaml > /dev/null || fail "no roundabout exit on acosta's roundabout routes"

"$bin" batch suite/* --out runs --jobs 2 --quiet > batch.out 2>&1
code=$?
every_run_passes runs || fail "generated scenarios failed (batch exit $code)"
[ "$code" = 0 ] || fail "batch exit $code"
echo "ok   $total generated scenarios on 13 nets pass in SUMO"

# 3. Teeth: the same files with the rules broken fail where they should.
# No search distance: the blinker comes on at the junction itself, every lead > 0 fails.
"$bin" batch suite/acosta --out broken_search --jobs 2 --quiet \
  --set turn_signal_intersection_search_distance=0 --set turn_signal_search_time=0 > /dev/null 2>&1
python3 - broken_search <<'PY' || fail "with no search distance the turn leads still held"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/results.csv")))
failed = [r for r in rows if r["status"] == "failed" and "blinker_through_junction" in r["failed_expectations"]]
print(f"no search distance: {len(failed)} of {len(rows)} runs fail a turn's lead")
sys.exit(0 if len(failed) >= len(rows) * 0.8 else 1)
PY
# A longer search distance: the blinker comes on inside the stretches stated quiet.
"$bin" batch suite/acosta --out broken_quiet --jobs 2 --quiet --set turn_signal_intersection_search_distance=150 \
  > /dev/null 2>&1
python3 - broken_quiet <<'PY' || fail "with a 150 m search distance the no_blinker stretches still held"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/results.csv")))
failed = [r for r in rows if "no_blinker" in r["failed_expectations"]]
print(f"150 m search distance: {len(failed)} of {len(rows)} runs fail a no_blinker stretch")
sys.exit(0 if len(failed) >= len(rows) * 0.5 else 1)
PY
# No exit signal (kr's Right off): the roundabout exits' blinkers fail (not all: a turn of the same
# side just after an exit may keep the blinker on there).
"$bin" batch suite/roundabout_after_junction suite/acosta_rb --out broken_exit --jobs 2 --quiet \
  --set turn_signal_roundabout_on_exit=None > /dev/null 2>&1
python3 - broken_exit <<'PY' || fail "with no exit signal the exit blinkers still held"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/results.csv")))
exits = [r for r in rows if r.get("roundabout_exit1.id")]
failed = [r for r in exits if r["status"] == "failed"]
print(f"no exit signal: {len(failed)} of {len(exits)} runs through a roundabout exit fail")
sys.exit(0 if exits and len(failed) >= len(exits) * 0.8 else 1)
PY
echo "ok   with broken rules the generated expectations fail"

# 4. A generated folder is a golden suite as it is.
"$bin" check suite/acosta_de --golden golden --update --out check --quiet > check.out 2>&1 || fail "check --update: $(tail -3 check.out)"
[ "$(ls golden/*.events.csv | wc -l)" = 12 ] || fail "golden files: $(ls golden)"
"$bin" check suite/acosta_de --golden golden --out check2 --quiet > check2.out 2>&1 || fail "check against its goldens: $(tail -3 check2.out)"
echo "ok   check --update accepts a generated folder, and check passes against it"
