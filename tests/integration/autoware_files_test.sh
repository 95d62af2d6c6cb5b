#!/usr/bin/env bash
# Autoware's parameter files as shipped and its vehicle description, end to end in SUMO (libsumo):
# the run takes each value from where the files keep it (the stop 0.5 m earlier for
# traffic_light.stop_margin, the blinker 0.5 s later for turn_signal_search_time 2.5), SUMO's ego has
# the vehicle_info footprint, the keys signalsim does not use are one note line per file (once in a
# batch), summary.json says where each value came from, and --strict-params (every key checked
# against Autoware's own) passes with one warning, for the start planner's key Autoware dropped.
# usage: autoware_files_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
scenario=$src/tests/data/scenarios/autoware_files.yaml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# An events.csv column for the first row of a kind/to: e.g. first_s FILE blinker left -> s_front.
first_s() { awk -F, -v kind="$2" -v to="$3" '$3 == kind && $5 == to { print $2; exit }' "$1"; }
light_rest_s() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['lights']['stops'][0]['rest_s'])" "$1"; }

"$bin" run "$scenario" --out "$work/files" >"$work/files.stdout" 2>"$work/files.stderr" || fail "run with the files: exit $?"
"$bin" run "$scenario" --out "$work/defaults" --quiet --set 'params.files=[]' || fail "run without the files: exit $?"

# One note per file with unused keys: vehicle_info and six parameter files (traffic_light uses all).
notes=$(grep -c '^signalsim: note: .* signalsim does not use' "$work/files.stderr")
[ "$notes" -eq 7 ] || { fail "want 7 note lines, got $notes"; cat "$work/files.stderr"; }
grep -q 'traffic_light.param.yaml: .*does not use' "$work/files.stderr" && fail "traffic_light.param.yaml has no unused key"
grep -q 'lane_change.param.yaml: 20 keys signalsim does not use: lane_change.time_limit' "$work/files.stderr" ||
  fail "lane_change note: $(grep lane_change "$work/files.stderr")"

# Behaviour: the stop point 0.5 m earlier, the blinker 0.5 s x 13.89 m/s later.
python3 - "$work/files" "$work/defaults" <<'PY' || failures=$((failures + 1))
import csv, json, sys
files, defaults = sys.argv[1], sys.argv[2]
def rest(d): return json.load(open(d + "/summary.json"))["lights"]["stops"][0]["rest_s"]
def blinker_on(d):
    for row in csv.DictReader(open(d + "/events.csv")):
        if row["kind"] == "blinker" and row["to"] == "left": return float(row["s_front"])
shift = rest(defaults) - rest(files)
lead = blinker_on(files) - blinker_on(defaults)
ok = abs(shift - 0.5) < 0.05 and 5.5 < lead < 8.5
print(("ok  " if ok else "FAIL") + f" stop {shift:.3f} m earlier (want 0.5), blinker {lead:.2f} m later (want ~6.9)")
s = json.load(open(files + "/summary.json"))
ego, src = s["ego"], s["parameter_sources"]
checks = [
    (s["status"] == "passed", "status " + s["status"]),
    (ego["length"] == 4.89 and abs(ego["width"] - 1.896) < 1e-9 and ego["base_link_to_front"] == 3.79,
     f"footprint {ego['length']} x {ego['width']}, base_link_to_front {ego['base_link_to_front']}"),
    (ego["source"]["width"].startswith("vehicle_info ") and ego["vehicle_info"].endswith("vehicle_info.param.yaml"),
     "ego sources " + str(ego["source"])),
    (src["stop_margin"]["from"].endswith("tests/data/autoware/traffic_light.param.yaml:4") and src["stop_margin"]["value"] == 0.5,
     "stop_margin " + str(src["stop_margin"])),
    (src["max_prepare_duration"]["from"].endswith("lane_change.param.yaml:17") and
     src["max_prepare_duration"]["autoware_key"] == "lane_change.trajectory.max_prepare_duration",
     "max_prepare_duration " + str(src["max_prepare_duration"])),
    (src["lane_change_safety_rear_gap"]["from"] == "default", "a default's origin"),
    (s["parameters"]["stop_margin"] == 0.5, "parameters keeps name -> value"),
    (len(s["parameter_files"]) == 6 and s["parameter_files"][0]["unused_keys"][0] == "traffic_light_signal_timeout",
     "parameter_files " + str([f["file"] for f in s["parameter_files"]])),
]
for good, what in checks:
    if not good: print("FAIL " + what)
sys.exit(0 if ok and all(g for g, _ in checks) else 1)
PY

# --quiet: no notes. --strict-params: every key is Autoware's; the one Autoware dropped is a warning
# (and a summary note), the run passes.
"$bin" run "$scenario" --out "$work/quiet" --quiet 2>"$work/quiet.stderr" || fail "quiet run: exit $?"
[ -s "$work/quiet.stderr" ] && fail "--quiet printed: $(cat "$work/quiet.stderr")"
"$bin" run "$scenario" --out "$work/strict" --strict-params >/dev/null 2>"$work/strict.stderr"
code=$?
[ "$code" -eq 0 ] || fail "--strict-params: exit $code, want 0: $(cat "$work/strict.stderr")"
warnings=$(grep '^signalsim: warning: ' "$work/strict.stderr")
[ "$warnings" = "signalsim: warning: $src/tests/data/autoware/start_planner.param.yaml:10: parameter \
'start_planner.enable_shift_pull_out' was dropped from Autoware's start_planner.param.yaml \
(autowarefoundation/autoware_launch 4aeeff84d0, 2025-08-28): it has no effect" ] || fail "--strict-params warnings: $warnings"
grep -q '"status": "passed"' "$work/strict/summary.json" || fail "--strict-params: not passed"
grep -q '"notes": \[' "$work/strict/summary.json" || fail "--strict-params: no summary notes"

# An explicit ego key wins over vehicle_info, and the note says so.
"$bin" run "$scenario" --out "$work/explicit" --set ego.length=5.2 >/dev/null 2>"$work/explicit.stderr" || fail "explicit length: exit $?"
grep -q "ego.length 5.2 replaces 4.89 from vehicle_info" "$work/explicit.stderr" || fail "no note for ego.length: $(cat "$work/explicit.stderr")"
python3 -c "import json,sys; e=json.load(open(sys.argv[1]))['ego']; sys.exit(0 if e['length']==5.2 and e['source']['length']=='--set' else 1)" \
  "$work/explicit/summary.json" || fail "explicit length not used"

# A batch of the same scenario twice: each note once (the workers run quietly).
"$bin" batch "$scenario" "$scenario" --out "$work/batch" --jobs 2 >/dev/null 2>"$work/batch.stderr"
code=$?
[ "$code" -eq 0 ] || fail "batch: exit $code"
notes=$(grep -c 'lane_change.param.yaml: 20 keys' "$work/batch.stderr")
[ "$notes" -eq 1 ] || fail "batch: lane_change note $notes times, want once"
"$bin" batch "$scenario" --out "$work/batch_quiet" --quiet 2>"$work/batch_quiet.stderr" || fail "quiet batch: exit $?"
[ -s "$work/batch_quiet.stderr" ] && fail "batch --quiet printed: $(head -2 "$work/batch_quiet.stderr")"

if [ "$failures" -eq 0 ]; then echo "autoware files: all checks passed"; else echo "$failures failure(s)"; fi
[ "$failures" -eq 0 ]
