#!/usr/bin/env bash
# A sweep over 3 countries x 3 speeds x 2 scenarios finishes with correct rows, and --jobs 1 and
# --jobs 2 give the same results.csv (wall_time aside). With python3-matplotlib, sweep --plot draws
# the heat map of the exit blinker lead by country and speed.
# usage: sweep_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
sweep=$src/tests/batch/data/sweep_3x3x2.yaml

"$bin" sweep "$sweep" --out "$work/j1" --jobs 1 > "$work/j1.log" || fail "jobs 1: exit code $? ($(tail -3 "$work/j1.log"))"
"$bin" sweep "$sweep" --out "$work/j2" --jobs 2 > "$work/j2.log" || fail "jobs 2: exit code $?"
grep -q "^18 runs: 18 passed, 0 failed, 0 without expectations, 0 errors" "$work/j1.log" || fail "summary line: $(tail -1 "$work/j1.log")"

# The rows: one per run, in run order, every country x speed x scenario once, no error.
python3 - "$work/j1/results.csv" "$work/j1" <<'PY' || exit 1
import csv, itertools, os, re, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 18, len(rows)
assert [r["run"] for r in rows] == [str(i) for i in range(18)]
header = list(rows[0].keys())
assert header[:5] == ["run", "scenario", "file", "country", "ego.max_speed"], header[:5]
assert header[5:11] == ["status", "expectations_passed", "expectations_total", "failed_expectations", "law_failed", "run_dir"]
assert header[-2:] == ["wall_time", "error"], header[-2:]
combos = [(r["scenario"], r["country"], r["ego.max_speed"]) for r in rows]
expected = [(s, c, v) for s in ("roundabout_exit", "turns") for c in ("jp", "de", "kr") for v in ("8.33", "11.11", "13.89")]
assert combos == expected, combos
for r in rows:
    assert r["status"] == "passed" and r["error"] == "", r
    assert (r["expectations_passed"], r["expectations_total"]) == ("1", "1"), r
    assert r["law_failed"] == "0", r
    assert os.path.isfile(os.path.join(sys.argv[2], r["run_dir"], "summary.json")), r["run_dir"]
    assert r["max_decel"] != "" and r["collisions"] == "0", r
    # The run's time, as text with two decimals: "0.00" is a valid value (a run in a warm persistent
    # worker takes under 5 ms on an idle machine), and a test asserts no timing (docs/testing.md).
    assert re.fullmatch(r"[0-9]+\.[0-9]{2}", r["wall_time"]), r
for r in rows[:9]:  # the roundabout: an exit blinker that is never missed, with a lead
    assert r["roundabout_exit1.missed"] == "false" and r["roundabout_exit1.lead_distance"] != "", r
    assert r["roundabout_exit1.blinker"] == {"jp": "left", "de": "right", "kr": "right"}[r["country"]], r
for r in rows[9:]:  # the close turns: left at A then right at B, both with a lead that grows with speed
    assert (r["turn1.id"], r["turn1.blinker"], r["turn2.id"], r["turn2.blinker"]) == ("A", "left", "B", "right"), r
    assert r["turn1.missed"] == "false" and r["turn2.missed"] == "false", r
leads = [float(r["turn1.lead_distance"]) for r in rows[9:12]]
assert leads == sorted(leads) and leads[0] < leads[-1], leads
print("ok   18 rows, every combination once, metrics filled")
PY

# Identical whatever --jobs is (wall_time aside).
strip() { python3 -c "
import csv, sys
for r in csv.reader(open(sys.argv[1])):
    print(','.join(r[:-2] + r[-1:]))" "$1"; }
cmp -s <(strip "$work/j1/results.csv") <(strip "$work/j2/results.csv") || {
  diff <(strip "$work/j1/results.csv") <(strip "$work/j2/results.csv") | head -20
  fail "results.csv differs between --jobs 1 and --jobs 2"
}
echo "ok   --jobs 1 and --jobs 2 give the same results.csv"

# --plot: the heat map of the file's plot: section.
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  "$bin" sweep "$sweep" --out "$work/j1" --jobs 2 --resume --plot > "$work/plot.log" || fail "sweep --plot: exit code $?"
  grep -q "resuming: 18 of 18 runs already done, 0 to run" "$work/plot.log" || fail "--resume reran finished runs"
  png=$work/j1/plots/roundabout_exit1.lead_distance_by_country_max_speed.png  # keys by their last dotted part
  [ -s "$png" ] || fail "no heat map $png ($(cat "$work/plot.log"))"
  echo "ok   sweep --plot drew $(basename "$png")"
else
  echo "skip sweep --plot: /usr/bin/python3 has no matplotlib (python3-matplotlib)"
fi
# A picture that cannot be drawn fails the command (exit 3) although every run passed.
SIGNALSIM_PLOT_TOOL=$work/no_such_plot_tool "$bin" sweep "$sweep" --out "$work/j1" --jobs 2 --resume --plot \
  > "$work/noplot.log" 2>&1
code=$?
[ "$code" = 3 ] || fail "sweep --plot with a missing plot tool: exit code $code, expected 3 ($(cat "$work/noplot.log"))"
grep -q "plotting failed" "$work/noplot.log" || fail "no 'plotting failed' message"
echo "ok   sweep --plot fails with exit 3 when the picture cannot be drawn"
echo "sweep_test passed"
