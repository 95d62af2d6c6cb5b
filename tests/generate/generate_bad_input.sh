#!/usr/bin/env bash
# signalsim generate on bad arguments: exit code 2, exactly one stderr line "signalsim: ..." naming
# what is wrong, nothing on stdout and no --out folder made.
# usage: generate_bad_input.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cross=$src/sumo_nets/cross/cross.net.xml
n=0

# expect_bad NAME PATTERN ARGS...: exit 2, one line matching PATTERN, no output, no folder.
expect_bad() {
  local name=$1 pattern=$2
  shift 2
  n=$((n + 1))
  local out=$work/out$n
  "$bin" generate "$@" > "$work/stdout" 2> "$work/stderr"
  local code=$?
  [ "$code" = 2 ] || fail "$name: exit code $code, expected 2: $(cat "$work/stderr")"
  [ "$(wc -l < "$work/stderr")" = 1 ] || fail "$name: expected one stderr line, got: $(cat "$work/stderr")"
  grep -Eq "^signalsim: .*$pattern" "$work/stderr" || fail "$name: message: $(cat "$work/stderr")"
  [ ! -s "$work/stdout" ] || fail "$name: printed: $(cat "$work/stdout")"
  echo "ok   $name: $(cat "$work/stderr")"
}

expect_bad "missing net" "no_such.net.xml" "$work/no_such.net.xml" --count 3 --out "$work/o1"
printf 'not xml at all\n' > "$work/text.net.xml"
expect_bad "not a net" "text.net.xml" "$work/text.net.xml" --count 3 --out "$work/o2"
expect_bad "count 0" "--count 0: out of range 1..10000" "$cross" --count 0 --out "$work/o3"
expect_bad "count missing" "count" "$cross" --out "$work/o4"
expect_bad "unknown --through value" "--through: 'bridges' is not one of turns, lights, roundabouts" \
  "$cross" --count 3 --through turns,bridges --out "$work/o5"
expect_bad "unknown country" "unknown country 'xx' \(known: de, jp, kr\)" "$cross" --count 3 --country xx --out "$work/o6"
expect_bad "lengths the wrong way round" "--min-length 900 and --max-length 300" \
  "$cross" --count 3 --min-length 900 --max-length 300 --out "$work/o7"
# A net with nothing to generate: a 100 m line (too short), or no route through a roundabout.
line=$src/tests/data/nets/line.net.xml
expect_bad "nothing to generate (too short)" "line.net.xml: no route of 300-1500 m .* nothing to generate" \
  "$line" --count 3 --out "$work/o8"
expect_bad "nothing to generate (no roundabout)" "cross.net.xml: no route of 300-1500 m a passenger car can drive through roundabouts" \
  "$cross" --count 3 --through roundabouts --out "$work/o9"
expect_bad "nothing to generate (no internal lanes)" "no edge a passenger car may drive on to another" \
  "$src/tests/data/nets/line_nointernal.net.xml" --count 3 --min-length 10 --out "$work/o10"
# --count and --seed are whole numbers in range (CLI11 wrapped -3 to 2^64-3
# and generate ran for ever), every number option is finite (CLI::Range let NaN through).
expect_bad "count negative" "--count '-3': not a whole number in 1..10000" "$cross" --count -3 --out "$work/o11"
expect_bad "count huge" "--count 100000000000: out of range 1..10000" "$cross" --count 100000000000 --out "$work/o12"
expect_bad "seed negative" "--seed '-1': not a whole number" "$cross" --count 3 --seed -1 --out "$work/o13"
expect_bad "seed beyond 2^64-1" "--seed 18446744073709551616: out of range 0\.\.2.64-1" \
  "$cross" --count 3 --seed 18446744073709551616 --out "$work/o14"
expect_bad "max-speed nan" "--max-speed: 'nan' is not a finite number" "$cross" --count 3 --max-speed nan --out "$work/o15"
expect_bad "max-length inf" "--max-length: 'inf' is not a finite number" "$cross" --count 3 --max-length inf --out "$work/o16"
expect_bad "min-length nan" "--min-length: 'nan' is not a finite number" "$cross" --count 3 --min-length nan --out "$work/o17"
expect_bad "straight -inf" "--straight: '-inf' is not a finite number" "$cross" --count 3 --straight -inf --out "$work/o18"
# A net signalsim reads but SUMO 1.15 does not load (a newer netconvert's vClass,
# as DLR's port_brunswick and port_cologne nets): refused, since no scenario on it could run.
sed -e '0,/<lane id="in_S_0"/s|<lane id="in_S_0"|<lane id="in_S_0" disallow="cable_car"|' "$cross" > "$work/cable_car.net.xml"
grep -q 'disallow="cable_car"' "$work/cable_car.net.xml" || fail "the cable_car net was not made"
expect_bad "net SUMO cannot load" "cable_car.net.xml: SUMO cannot load this net.*Unknown vehicle class 'cable_car'" \
  "$work/cable_car.net.xml" --count 3 --out "$work/o19"
for i in $(seq 1 19); do [ ! -e "$work/o$i" ] || fail "bad input made the folder o$i"; done

# An --out folder holding a scenario generate did not write is refused, and left as it was.
mkdir "$work/mine"
printf 'name: mine\n' > "$work/mine/mine.yaml"
n=0
"$bin" generate "$cross" --count 3 --out "$work/mine" > "$work/stdout" 2> "$work/stderr"
[ $? = 2 ] || fail "foreign yaml in --out: not exit 2"
grep -q "^signalsim: .*mine.yaml: not written by signalsim generate" "$work/stderr" || fail "foreign yaml: $(cat "$work/stderr")"
[ "$(ls "$work/mine")" = "mine.yaml" ] || fail "foreign folder changed: $(ls "$work/mine")"
echo "ok   a folder with someone else's scenario is refused and left alone"
