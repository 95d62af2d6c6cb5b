#!/usr/bin/env bash
# Defect 2: text that is not UTF-8 (a Latin-1 byte 0xE9) is refused when its file is loaded, with
# the file and line - scenario files, parameter files, sweep files and --set values - and the run
# directory holds no output that passes for a finished run. It used to fail only after the whole
# run, at summary.json, with a JSON library message and no line, leaving --out empty.
set -u
source "$(dirname "$0")/lib.sh" "$@"

scenario_copy close_turns "$work/name.yaml"
sed -i 's/^name: close_turns$/name: "caf\xe9"/' "$work/name.yaml"
grep -q $'caf\xe9' "$work/name.yaml" || fail "test setup: no 0xE9 byte in the scenario"
bad_input scenario_name "name.yaml:10: invalid UTF-8 \(byte 0xE9 at column 11\); save the file as UTF-8" -- run "$work/name.yaml"
python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$work/scenario_name/summary.json" 2>/dev/null ||
  fail "scenario_name: the error summary.json is not valid JSON"

scenario_copy close_turns "$work/desc.yaml"
printf 'description: "Stra\xdfe"\n' >> "$work/desc.yaml"
n=$(wc -l < "$work/desc.yaml")
bad_input scenario_description "desc.yaml:$n: invalid UTF-8 \(byte 0xDF" -- run "$work/desc.yaml"

printf '/**:\n  ros__parameters:\n    turn_signal_search_time: 3.0  # caf\xe9\n' > "$work/params.yaml"
scenario_copy close_turns "$work/with_params.yaml"
sed -i "s#^  files: \[.*\]#  files: [$work/params.yaml]#" "$work/with_params.yaml"
bad_input parameter_file "params.yaml:3: invalid UTF-8 \(byte 0xE9" -- run "$work/with_params.yaml"

printf 'scenarios: [%s]\ngrid:\n  seed: [1, 2]\ndescription: "\xe9t\xe9"\n' "$src/scenarios/close_turns.yaml" > "$work/sweep.yaml"
bad_input sweep_file "sweep.yaml:4: invalid UTF-8 \(byte 0xE9" -- sweep "$work/sweep.yaml"

bad_input set_value "--set: an override is not UTF-8 text: invalid UTF-8 \(byte 0xE9" -- \
  run "$src/scenarios/close_turns.yaml" --set $'name=caf\xe9'

# Valid UTF-8 (2-, 3- and 4-byte sequences) is accepted and written as it is.
scenario_copy close_turns "$work/utf8.yaml"
sed -i 's/^name: close_turns$/name: "café 交差点 🚦"/' "$work/utf8.yaml"
"$bin" run "$work/utf8.yaml" --out "$work/utf8" --quiet 2>"$work/utf8.err" || fail "valid UTF-8: exit code $? ($(cat "$work/utf8.err"))"
grep -q '"scenario": "café 交差点 🚦"' "$work/utf8/summary.json" || fail "valid UTF-8: the name is not in summary.json"
ok "valid UTF-8 runs and is written as it is"
finish
