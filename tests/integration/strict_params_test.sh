#!/usr/bin/env bash
# --strict-params on autoware_launch's files with every key they have (tests/data/autoware_launch),
# end to end in SUMO (libsumo): the run passes, each key Autoware knows but signalsim does not use is
# listed in one note line per file, the one key Autoware dropped is one warning line (and a note in
# summary.json); a typo'd key is one error line naming the file, the line, the key and the nearest
# known key, exit 2 and no output presented as complete.
# usage: strict_params_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
scenario=$src/tests/data/scenarios/autoware_launch_files.yaml
files=$src/tests/data/autoware_launch
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

dropped="signalsim: warning: $src/tests/data/autoware_launch/static_obstacle_avoidance.param.yaml:227: \
parameter 'avoidance.yield.enable_signalling_during_yield' was dropped from Autoware's \
static_obstacle_avoidance.param.yaml (tier4/autoware_universe_planning e4f932aebc, 2026-02-26): it has no effect"

"$bin" run "$scenario" --out "$work/strict" --strict-params >"$work/strict.stdout" 2>"$work/strict.stderr"
code=$?
[ "$code" -eq 0 ] || fail "--strict-params on autoware_launch's files: exit $code: $(cat "$work/strict.stderr")"
grep -q "^autoware_launch_files: passed" "$work/strict.stdout" || fail "not passed: $(head -1 "$work/strict.stdout")"
[ "$(grep -c '^signalsim: warning: ' "$work/strict.stderr")" -eq 1 ] || fail "want one warning: $(cat "$work/strict.stderr")"
grep -qxF "$dropped" "$work/strict.stderr" || fail "the dropped key's warning: $(grep warning "$work/strict.stderr")"
# Known but unused: one note per file with such keys (traffic_light.param.yaml has none).
notes=$(grep -c '^signalsim: note: .* signalsim does not use' "$work/strict.stderr")
[ "$notes" -eq 7 ] || fail "want 7 note lines, got $notes: $(cat "$work/strict.stderr")"
grep -q "^signalsim: note: .*/behavior_path_planner.param.yaml: 13 keys signalsim does not use: traffic_light_signal_timeout, " \
  "$work/strict.stderr" || fail "behavior_path_planner's note: $(grep behavior_path_planner "$work/strict.stderr")"
[ "$(grep -vc '^signalsim: \(note\|warning\): ' "$work/strict.stderr")" -eq 0 ] || fail "other stderr: $(cat "$work/strict.stderr")"
/usr/bin/python3 - "$work/strict/summary.json" "${dropped#signalsim: warning: }" <<'PY' || fail "summary.json notes"
import json, sys
s = json.load(open(sys.argv[1]))
ok = s["status"] == "passed" and s["notes"] == [sys.argv[2]]
print(("ok  " if ok else "FAIL") + " summary.json: status " + s["status"] + ", notes " + str(s.get("notes")))
sys.exit(0 if ok else 1)
PY
# Without --strict-params the dropped key is only one more listed key.
"$bin" run "$scenario" --out "$work/lenient" >/dev/null 2>"$work/lenient.stderr" || fail "lenient run: exit $?"
grep -q 'warning' "$work/lenient.stderr" && fail "a lenient run warned: $(grep warning "$work/lenient.stderr")"

# A typo'd key of one file: one line, exit 2, an error summary and no run outputs.
sed 's/^    backward_path_length:/    backward_path_lenght:/' "$files/behavior_path_planner.param.yaml" \
  >"$work/behavior_path_planner.param.yaml"
"$bin" run "$src/scenarios/intersection_left.yaml" --out "$work/typo" --params "$work/behavior_path_planner.param.yaml" \
  --strict-params >"$work/typo.stdout" 2>"$work/typo.stderr"
code=$?
[ "$code" -eq 2 ] || fail "a typo'd key: exit $code, want 2"
want="signalsim: $work/behavior_path_planner.param.yaml:11: unknown parameter 'backward_path_lenght': not a key of \
Autoware's behavior_path_planner.param.yaml (did you mean 'backward_path_length'?)"
[ "$(cat "$work/typo.stderr")" = "$want" ] || fail "a typo'd key's message: $(cat "$work/typo.stderr")"
[ -s "$work/typo.stdout" ] && fail "a refused run printed: $(cat "$work/typo.stdout")"
grep -q '"status": "error"' "$work/typo/summary.json" || fail "a typo'd key: no error summary"
[ -e "$work/typo/timeline.csv" ] && fail "a refused run left a timeline"
# Lenient, the typo is only a listed key.
"$bin" run "$src/scenarios/intersection_left.yaml" --out "$work/typo_lenient" --quiet \
  --params "$work/behavior_path_planner.param.yaml" || fail "a typo'd key without --strict-params: exit $?"

if [ "$failures" -eq 0 ]; then echo "strict params: all checks passed"; else echo "$failures failure(s)"; fi
[ "$failures" -eq 0 ]
