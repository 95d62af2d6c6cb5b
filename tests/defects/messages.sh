#!/usr/bin/env bash
# Messages: `--set key=` says "empty value"; a country code is checked against the
# presets before it is used as a path (`../countries/jp` used to load config/countries/jp.yaml);
# SUMO's multi-line messages come out as one line; two identical bad runs give identical error
# summaries and batch error rows (no addresses, ports or process ids in them).
set -u
source "$(dirname "$0")/lib.sh" "$@"
s=$src/scenarios/close_turns.yaml
net=$src/sumo_nets/cross/cross.net.xml

bad_input empty_seed "--set: 'seed=': empty value \(write seed=VALUE\)" -- run "$s" --set seed=
bad_input empty_depart_speed "--set: 'ego.depart_speed=': empty value" -- run "$s" --set ego.depart_speed=
scenario_copy close_turns "$work/null_seed.yaml"
sed -i 's/^seed: 1$/seed:/' "$work/null_seed.yaml"
bad_input null_seed_in_file "null_seed.yaml:[0-9]+: key 'seed': empty value \(expected an integer\)" -- run "$work/null_seed.yaml"

# A scenario file that is not a mapping, with --set (found by tests/fuzz/fuzz_scenario: yaml-cpp's
# "operator[] call on a scalar" for a scalar file; a list file was turned into a mapping).
printf 'just a scalar\n' >"$work/scalar.yaml"
printf -- '- a\n- b\n' >"$work/list.yaml"
bad_input set_on_scalar_file "scalar.yaml:1: the file must be a mapping of key: value" -- run "$work/scalar.yaml" --set seed=3
bad_input set_on_list_file "list.yaml:1: the file must be a mapping of key: value" -- run "$work/list.yaml" --set ego.route=x

for code in ../countries/jp jp/../jp /etc/passwd; do
  bad_input "country_${code//\//_}" "^signalsim: --set country=$code: key 'country': unknown country '$code' \(known: de, jp, kr\)" -- \
    run "$s" --set "country=$code"
done
scenario_copy close_turns "$work/country.yaml"
sed -i 's/^seed: 1$/seed: 1\ncountry: ..\/countries\/de/' "$work/country.yaml"
line=$(grep -n '^country:' "$work/country.yaml" | cut -d: -f1)
bad_input country_in_file "country.yaml:$line: key 'country': unknown country '../countries/de'" -- run "$work/country.yaml"
bad_input generate_country "unknown country '../countries/jp' \(known: de, jp, kr\)" -- \
  generate "$net" --count 1 --country ../countries/jp
[ -e "$work/generate_country" ] && fail "generate wrote its folder for an unknown country"
"$bin" inspect "$net" --route in_S out_W --country ../countries/jp >/dev/null 2>"$work/inspect.err"
[ $? -eq 2 ] && grep -q "unknown country '../countries/jp'" "$work/inspect.err" || fail "inspect --country: $(cat "$work/inspect.err")"
ok "country codes are checked against the presets before any path is built"

# A SUMO message of several lines is one line (here: a route file that is not XML).
bad_input sumo_multi_line "SUMO could not load the simulation: invalid document structure In file '$src/README.md'" -- \
  run "$s" --set "routes=[$src/README.md]"

# Identical bad runs, identical error summaries.
for case in mid_run_sumo_error unconnected_route broken_net unknown_key; do
  "$bin" run "$src/tests/data/bad/$case.yaml" --out "$work/same1_$case" >/dev/null 2>&1
  "$bin" run "$src/tests/data/bad/$case.yaml" --out "$work/same2_$case" >/dev/null 2>&1
  cmp -s "$work/same1_$case/summary.json" "$work/same2_$case/summary.json" ||
    fail "$case: the two error summaries differ: $(diff "$work/same1_$case/summary.json" "$work/same2_$case/summary.json")"
  grep -qiE '0x[0-9a-f]{6,}' "$work/same1_$case/summary.json" && fail "$case: an address in $(cat "$work/same1_$case/summary.json")"
done
mkdir -p "$work/suite"
cp "$src/tests/data/bad/mid_run_sumo_error.yaml" "$src/tests/data/bad/unroutable_trip.rou.xml" "$src/tests/data/bad/unknown_key.yaml" "$work/suite/"
sed -i "s#\.\./\.\./\.\./#$src/#g; s#net: \.\./#net: $src/tests/data/#" "$work/suite/"*.yaml
for n in 1 2; do "$bin" batch "$work/suite" --out "$work/batch$n" --quiet >/dev/null 2>&1; done
errors() { python3 -c 'import csv,sys; [print(r["status"], r["error"]) for r in csv.DictReader(open(sys.argv[1]))]' "$1" | sed "s#$work/batch[12]#OUT#g"; }
[ "$(errors "$work/batch1/results.csv")" = "$(errors "$work/batch2/results.csv")" ] || fail "the batches' error rows differ"
errors "$work/batch1/results.csv" | grep -q '^error ' || fail "the batch has no error row: $(errors "$work/batch1/results.csv")"
ok "two identical bad runs (and batches) give identical error summaries (and rows), without addresses"
finish
