#!/usr/bin/env bash
# signalsim compare through the command line, real SUMO workers: a left turn, a roundabout
# with the Japanese preset and a red light, each driven by signalsim and by SUMO alone.
#   - comparison.csv: one row per section/light and driver in route order, with the values each
#     model gives (SUMO's lead 7 s x 13.89 m/s before the lane end vs the decider's 3 v + 30; the
#     jp exit signal present for signalsim, missed by SUMO, which shows right; SUMO's own stop at
#     the red light short of the line), the run directories and their drivers
#   - comparison.png drawn with both drivers' bars
#   - byte-identical comparison.csv on a second run and with --jobs 1; exit 3 without the picture
#   - a scenario SUMO refuses: error rows for both drivers, exit code 1, the others complete
#   - bad input: exit 2, one line, nothing run, an earlier comparison removed
# usage: compare_test.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
py=/usr/bin/python3  # Debian's, with matplotlib
scenarios=("$src/scenarios/intersection_left.yaml" "$src/scenarios/roundabout_jp_exit2.yaml"
           "$src/scenarios/tl_red_stop_then_go.yaml")

"$bin" compare "${scenarios[@]}" --out "$work/a" --jobs 2 > "$work/a.log" 2> "$work/a.err"
code=$?
[ $code -eq 0 ] || fail "compare: exit code $code ($(cat "$work/a.log" "$work/a.err"))"
# Only the one warning of jp's preset on the right-hand roundabout (docs/parameters.md "Country presets").
[ "$(cat "$work/a.err")" = "signalsim: warning: country jp drives on the left, but the net \
$src/sumo_nets/roundabout/roundabout.net.xml is right-hand traffic (no lefthand=\"true\"): the exit blinker is \
then on the wrong side for that traffic" ] || fail "compare wrote to stderr: $(cat "$work/a.err")"
grep -Eq "^roundabout_jp_exit2 +roundabout_exit1 +RN +left +lead [0-9.]+ m [0-9.]+ s +missed \(right on\)$" \
  "$work/a.log" || fail "summary line of the exit: $(cat "$work/a.log")"
grep -Eq "^tl_red_stop_then_go +light1 +C +- +stop -?0\.[0-9]+ m +stop -[0-9.]+ m$" "$work/a.log" ||
  fail "summary line of the light: $(cat "$work/a.log")"
grep -q "^6 runs, 0 errors in .* s; comparison: $work/a/comparison.csv, $work/a/comparison.png$" "$work/a.log" ||
  fail "closing line: $(tail -1 "$work/a.log")"
[ "$(wc -l < "$work/a.log")" -le 25 ] || fail "the summary is longer than a screen"
echo "ok   compare: exit 0, one line per section with both drivers"

$py - "$work/a" <<'PY' || exit 1
import csv, json, os, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "comparison.csv"), newline="")))
header = open(os.path.join(out, "comparison.csv")).readline().strip().split(",")
assert header == ["scenario", "section", "kind", "id", "s", "blinker", "driver", "status", "expectations",
                  "lead_distance", "lead_time", "time_on", "missed", "blinker_at_start", "state_at_line",
                  "red_light_violation", "stop_position_error", "decision", "notes", "run_dir", "error"], header
keys = [(r["scenario"], r["section"], r["driver"]) for r in rows]
want = []
for sc, items in (("intersection_left", ["light1", "turn1"]),
                  ("roundabout_jp_exit2", ["roundabout_entry1", "roundabout_exit1"]),
                  ("tl_red_stop_then_go", ["light1"])):
    for item in items:
        want += [(sc, item, "signalsim"), (sc, item, "sumo")]
assert keys == want, keys
row = {(r["scenario"], r["section"], r["driver"]): r for r in rows}
num = lambda r, c: float(r[c])

# The left turn: the decider's search distance 3 v + 30 (71.67 m at 13.89 m/s, docs/behaviour.md §T4.3) against
# SUMO's 7 s x 13.89 m/s = 97.23 m before the end of in_S_1 (the turn starts there), within a step.
sig, sumo = row["intersection_left", "turn1", "signalsim"], row["intersection_left", "turn1", "sumo"]
assert sig["s"] == "189.6" and sig["blinker"] == "left" and sig["id"] == "C", sig
assert 70.0 < num(sig, "lead_distance") <= 71.67, sig
assert 97.23 - 1.39 < num(sumo, "lead_distance") <= 97.23, sumo
assert sig["missed"] == sumo["missed"] == "false" and sig["blinker_at_start"] == sumo["blinker_at_start"] == "left"
assert sig["status"] == "passed" and sig["expectations"] == "4/4", sig
assert sumo["status"] == "failed" and sumo["expectations"] == "2/4", sumo  # the law's expectations, SUMO's blinker
light = row["intersection_left", "light1", "sumo"]
assert light["state_at_line"] == "g" and light["red_light_violation"] == "false" and light["decision"] == "", light

# Japan's exit signal (left, from the previous exit): signalsim's is on before the exit lanelet;
# SUMO shows right (the link's dir 'r') on the last ring lane: the left signal is missed.
sig, sumo = row["roundabout_jp_exit2", "roundabout_exit1", "signalsim"], row["roundabout_jp_exit2", "roundabout_exit1", "sumo"]
assert sig["blinker"] == "left" and sig["missed"] == "false" and num(sig, "lead_distance") > 10.0, sig
assert sumo["missed"] == "true" and sumo["lead_distance"] == "" and sumo["time_on"] == "0.0", sumo
assert sumo["blinker_at_start"] == "right", sumo
entry_sig, entry_sumo = row["roundabout_jp_exit2", "roundabout_entry1", "signalsim"], row["roundabout_jp_exit2", "roundabout_entry1", "sumo"]
assert entry_sig["blinker"] == "none" and entry_sig["blinker_at_start"] == "none", entry_sig
assert entry_sumo["blinker_at_start"] == "right" and entry_sumo["lead_distance"] == "", entry_sumo

# The red light: the judge's normal stop within 0.3 m of the stop point; SUMO's own stop short of it.
sig, sumo = row["tl_red_stop_then_go", "light1", "signalsim"], row["tl_red_stop_then_go", "light1", "sumo"]
assert abs(num(sig, "stop_position_error")) <= 0.3 and sig["decision"] == "stop", sig
assert -2.0 < num(sumo, "stop_position_error") < -0.3 and sumo["decision"] == "", sumo
assert sig["red_light_violation"] == sumo["red_light_violation"] == "false", (sig, sumo)
assert sig["state_at_line"] == sumo["state_at_line"] == "G", (sig, sumo)

# The run directories: the two drivers of a scenario, same seed and route.
for sc in ("intersection_left", "roundabout_jp_exit2", "tl_red_stop_then_go"):
    dirs = {r["driver"]: r["run_dir"] for r in rows if r["scenario"] == sc}
    s = {d: json.load(open(os.path.join(out, dirs[d], "summary.json"))) for d in ("signalsim", "sumo")}
    assert s["signalsim"]["driver"] == "signalsim" and s["sumo"]["driver"] == "sumo", sc
    assert s["signalsim"]["seed"] == s["sumo"]["seed"] and s["signalsim"]["route"] == s["sumo"]["route"], sc
    assert s["sumo"]["counts"]["arrived"] and s["signalsim"]["counts"]["arrived"], sc
assert sorted(os.listdir(os.path.join(out, "runs"))) == [
    "0000-intersection_left-signalsim", "0000-intersection_left-sumo", "0001-roundabout_jp_exit2-signalsim",
    "0001-roundabout_jp_exit2-sumo", "0002-tl_red_stop_then_go-signalsim", "0002-tl_red_stop_then_go-sumo"]
PY
echo "ok   comparison.csv: rows, values of both models, run directories"

# The picture: a PNG with bars in both drivers' colours.
$py - "$work/a/comparison.png" <<'PY' || exit 1
import sys
import matplotlib.image as image
png = open(sys.argv[1], "rb").read(8)
assert png == b"\x89PNG\r\n\x1a\n", png
pixels = image.imread(sys.argv[1])[:, :, :3]
def count(hex_colour):
    rgb = [int(hex_colour[i:i + 2], 16) / 255 for i in (1, 3, 5)]
    return int((abs(pixels - rgb).max(axis=2) < 0.02).sum())
signalsim, sumo = count("#1f77b4"), count("#ff7f0e")
assert signalsim > 2000 and sumo > 2000, (signalsim, sumo)
PY
echo "ok   comparison.png drawn with both drivers' bars"

"$bin" compare "${scenarios[@]}" --out "$work/b" --jobs 2 --quiet > "$work/b.log" || fail "second compare: exit $?"
[ -s "$work/b.log" ] && fail "--quiet printed: $(cat "$work/b.log")"
cmp -s "$work/a/comparison.csv" "$work/b/comparison.csv" || fail "comparison.csv differs on a second run"
"$bin" compare "${scenarios[@]}" --out "$work/c" --jobs 1 --quiet || fail "compare --jobs 1: exit $?"
cmp -s "$work/a/comparison.csv" "$work/c/comparison.csv" || fail "comparison.csv differs with --jobs 1"
echo "ok   comparison.csv byte-identical on a second run and with --jobs 1"

# The picture cannot be drawn: the table stands, exit code 3 (as sweep --plot).
SIGNALSIM_PLOT_TOOL=/bin/false "$bin" compare "${scenarios[0]}" --out "$work/p" --quiet 2> "$work/p.err"
code=$?
[ $code -eq 3 ] || fail "a failed picture: exit code $code, not 3"
grep -q "plotting failed" "$work/p.err" || fail "a failed picture is not reported: $(cat "$work/p.err")"
[ -s "$work/p/comparison.csv" ] || fail "a failed picture: no comparison.csv"
[ -e "$work/p/comparison.png" ] && fail "a failed picture: comparison.png exists"
echo "ok   a picture that cannot be drawn: comparison.csv written, exit code 3"

# A scenario SUMO refuses to start: error rows for both drivers, the other scenario complete, exit 1.
"$bin" compare "$src/tests/data/compare/sumo_fails.yaml" "${scenarios[0]}" --out "$work/e" --jobs 2 > "$work/e.log" 2>&1
code=$?
[ $code -eq 1 ] || fail "a failing run: exit code $code, not 1 ($(cat "$work/e.log"))"
grep -q "^4 runs, 2 errors in " "$work/e.log" || fail "closing line: $(tail -1 "$work/e.log")"
$py - "$work/e/comparison.csv" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
bad = [r for r in rows if r["scenario"] == "sumo_fails"]
assert [(r["section"], r["driver"]) for r in bad] == [("light1", "signalsim"), ("light1", "sumo"),
                                                      ("turn1", "signalsim"), ("turn1", "sumo")], bad
assert all(r["status"] == "error" and "default.speeddev" in r["error"] and r["lead_distance"] == "" for r in bad), bad
good = [r for r in rows if r["scenario"] == "intersection_left"]
assert len(good) == 4 and all(r["status"] in ("passed", "failed") and r["error"] == "" for r in good), good
PY
echo "ok   a run that errors gives error rows, never a gap; exit code 1"

# Bad input: exit 2, one line, nothing run; an earlier comparison in --out is removed.
refused() {  # refused NAME PATTERN ARGS...
  local name=$1 pattern=$2; shift 2
  mkdir -p "$work/$name"
  echo stale > "$work/$name/comparison.csv"
  "$bin" compare "$@" --out "$work/$name" > "$work/$name.out" 2> "$work/$name.err"
  local code=$?
  [ $code -eq 2 ] || fail "$name: exit code $code, not 2"
  [ "$(wc -l < "$work/$name.err")" -eq 1 ] || fail "$name: stderr is not one line: $(cat "$work/$name.err")"
  grep -q -- "$pattern" "$work/$name.err" || fail "$name: stderr lacks '$pattern': $(cat "$work/$name.err")"
  [ -e "$work/$name/comparison.csv" ] && fail "$name: an earlier comparison.csv is left"
  [ -e "$work/$name/runs" ] && fail "$name: runs were started"
  echo "ok   $name: $(cat "$work/$name.err")"
}
refused no_scenario "compare: no scenario given"
refused missing_file "does_not_exist.yaml' not found" "${scenarios[0]}" "$work/does_not_exist.yaml"
refused bad_scenario "unknown_key.yaml:" "${scenarios[0]}" "$src/tests/data/bad/unknown_key.yaml"
refused unknown_edge "unknown_edge.yaml" "${scenarios[0]}" "$src/tests/data/bad/unknown_edge.yaml"
refused bad_override "unknown parameter" "${scenarios[0]}" --set no_such_parameter=1
out=$("$bin" run "${scenarios[0]}" --driver bogus --out "$work/bogus" 2>&1)
code=$?
[ $code -eq 2 ] || fail "run --driver bogus: exit code $code"
[ "$(echo "$out" | wc -l)" -eq 1 ] || fail "run --driver bogus: $out"
echo "ok   run --driver bogus: $out"
echo "compare_test passed"
