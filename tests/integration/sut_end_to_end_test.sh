#!/usr/bin/env bash
# A real system under test through every command, on real libsumo (docs/decider.md): batch, a sweep over
# decider x country, check's golden files per SUT, compare's three drivers.
#   - batch --decider SUT: summary.json "decider" (agreement = agreeing_steps / steps over every row,
#     one entry per metrics section), timeline.csv's ref_blinker, results.csv decider / decider_agreement
#   - sweep: grid decider [reference, SUT] x country [jp, de]: 4 runs, the decider column as written,
#     decider_agreement only for the SUT's runs
#   - check: golden files made with the SUT pass with it and fail the reference; golden files made with
#     the reference fail the SUT, naming both
#   - compare --decider SUT: rows of sut, signalsim and sumo per item, the picture with the SUT's colour
#   - with JUDGE, batch --light-judge JUDGE on a red light: summary.json "light_judge" and its columns
#   - the sweep file names a lib: path relative to itself; for an exec: command its folder links the
#     current folder's files
# usage: sut_end_to_end_test.sh SIGNALSIM_BINARY SOURCE_DIR SUT [JUDGE]   (autoware_core, lib:x.so, ...; a
# relative lib: path is relative to the current directory, as on the command line)
set -u
bin=$1
src=$2
sut=$3
judge=${4:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
py=/usr/bin/python3
scenarios=("$src/scenarios/intersection_left.yaml" "$src/scenarios/roundabout_jp_exit2.yaml")

# batch
"$bin" batch "${scenarios[@]}" --decider "$sut" --out "$work/batch" --quiet --jobs 2 > "$work/batch.log" 2>&1
code=$?
[ $code -le 1 ] || fail "batch --decider $sut: exit $code: $(cat "$work/batch.log")"
$py - "$work/batch" "$sut" <<'PY' || exit 1
import csv, json, os, sys
out, sut = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(os.path.join(out, "results.csv"), newline="")))
header = open(os.path.join(out, "results.csv")).readline().strip().split(",")
assert header.index("decider") < header.index("decider_agreement") < header.index("max_decel"), header
for r in rows:
    assert r["status"] in ("passed", "failed"), r
    assert r["decider"] == sut, r
    s = json.load(open(os.path.join(out, r["run_dir"], "summary.json")))
    d = s["decider"]
    assert d["name"] == sut and d["steps"] == s["counts"]["steps"], d
    assert abs(d["agreement"] - round(d["agreeing_steps"] / d["steps"], 4)) < 1e-12, d
    assert float(r["decider_agreement"]) == d["agreement"], (r, d)
    assert len(d["sections"]) == len(s["metrics"]["sections"]), d
    for sec, met in zip(d["sections"], s["metrics"]["sections"]):
        assert (sec["kind"], sec["id"]) == (met["kind"], met["id"]), (sec, met)
        assert sec["sut"]["lead_distance"] == met["lead_distance"], (sec, met)  # the metrics are the SUT's
        if sec["reference"]["on_s"] is not None:
            assert abs(sec["s_start"] - sec["reference"]["on_s"] - sec["reference"]["lead_distance"]) < 2e-3, sec
    timeline = list(csv.DictReader(open(os.path.join(out, r["run_dir"], "timeline.csv"), newline="")))
    agree = sum(1 for t in timeline if t["blinker"] == t["ref_blinker"])
    assert agree == d["agreeing_steps"] and len(timeline) == d["steps"], (agree, d)
    assert all(t["blinker_source"] == ("none" if t["blinker"] == "none" else "sut") for t in timeline), \
        "a blinker on whose source is not sut"
print("ok   batch --decider:", ", ".join(f'{r["scenario"]} agreement {r["decider_agreement"]}' for r in rows))
PY
# The reference in shadow is the reference: its column equals a reference run's blinker, row by row
# while the ego is where the reference run had it (the same positions: compare on s_front).
"$bin" run "${scenarios[0]}" --out "$work/ref" --quiet > /dev/null 2>&1
$py - "$work/batch/runs/0000-intersection_left/timeline.csv" "$work/ref/timeline.csv" <<'PY' || exit 1
import csv, sys
sut = list(csv.DictReader(open(sys.argv[1], newline="")))
ref = list(csv.DictReader(open(sys.argv[2], newline="")))
# Rows before the SUT first differs from the reference drive the ego identically.
first = next((i for i, (a, b) in enumerate(zip(sut, ref)) if a["blinker"] != a["ref_blinker"]), min(len(sut), len(ref)))
for a, b in zip(sut[:first], ref[:first]):
    assert a["s_front"] == b["s_front"] and a["ref_blinker"] == b["blinker"], (a, b)
print(f"ok   ref_blinker is the reference's: identical to a reference run for the first {first} rows")
PY

# sweep: implementations x countries. A lib: path in a sweep file is relative to the file.
# An exec: command runs in the sweep file's folder: it gets links to the current folder's files.
swept=$sut
case $sut in
  lib:*) swept="lib:$(realpath -m --relative-to="$work" "${sut#lib:}")" ;;
  exec:*) for f in ./*; do [ -e "$work/${f#./}" ] || ln -s "$PWD/${f#./}" "$work/${f#./}"; done ;;
esac
cat > "$work/sweep.yaml" <<YAML
name: deciders
scenarios: ${scenarios[0]}
grid:
  decider: [reference, "$swept"]
  country: [jp, de]
YAML
"$bin" sweep "$work/sweep.yaml" --out "$work/sweep" --quiet --jobs 2 > "$work/sweep.log" 2>&1
code=$?
[ $code -le 1 ] || fail "sweep: exit $code: $(cat "$work/sweep.log")"
$py - "$work/sweep" "$swept" <<'PY' || exit 1
import csv, os, sys
out, sut = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(os.path.join(out, "results.csv"), newline="")))
assert [(r["decider"], r["country"]) for r in rows] == [("reference", "jp"), ("reference", "de"), (sut, "jp"), (sut, "de")], rows
assert all(r["decider_agreement"] == "" for r in rows[:2]) and all(r["decider_agreement"] != "" for r in rows[2:]), rows
print("ok   sweep decider x country:", [(r["decider"], r["country"], r["decider_agreement"]) for r in rows])
PY

# A light judge under test, when the SUT has that role too (JUDGE given): agreement over the judged rows.
if [ -n "$judge" ]; then
  "$bin" batch "$src/scenarios/tl_red_stop_then_go.yaml" --light-judge "$judge" --out "$work/judge" --quiet \
    > "$work/judge.log" 2>&1
  code=$?
  [ $code -le 1 ] || fail "batch --light-judge $judge: exit $code: $(cat "$work/judge.log")"
  $py - "$work/judge" "$judge" <<'PY' || exit 1
import csv, json, os, sys
out, judge = sys.argv[1], sys.argv[2]
r = list(csv.DictReader(open(os.path.join(out, "results.csv"), newline="")))[0]
s = json.load(open(os.path.join(out, r["run_dir"], "summary.json")))
j = s["light_judge"]
assert "decider" not in s and r["light_judge"] == judge == j["name"], (r, j)
timeline = list(csv.DictReader(open(os.path.join(out, r["run_dir"], "timeline.csv"), newline="")))
judged = [t for t in timeline if t["tl_id"] and t["ref_tl_decision"]]
assert j["steps"] == len(judged) > 0, (j["steps"], len(judged))
assert j["agreeing_steps"] == sum(t["tl_decision"] == t["ref_tl_decision"] for t in judged), j
assert float(r["light_judge_agreement"]) == j["agreement"] == round(j["agreeing_steps"] / j["steps"], 4), (r, j)
light = j["lights"][0]
assert light["id"] == "C" and "stop" in light["sut"] and "stop" in light["reference"], light
print(f"ok   batch --light-judge: agreement {j['agreement']} over {j['steps']} judged rows; C: sut {light['sut']}, reference {light['reference']}")
PY
fi

# check: golden files per SUT. A scenario without expectations: --update accepts its runs whatever the
# SUT does (a run whose expectations failed is never accepted).
cat > "$work/left_plain.yaml" <<YAML
name: left_plain
net: $src/sumo_nets/cross/cross.net.xml
ego: {route: [in_S, out_W], depart_speed: 8.33}
YAML
plain=$work/left_plain.yaml
"$bin" check "$plain" --golden "$work/g_sut" --decider "$sut" --update --out "$work/c1" > "$work/c1.log" 2>&1 ||
  fail "check --update --decider: $(cat "$work/c1.log")"
[ -f "$work/g_sut/left_plain.suts.json" ] || fail "no side file beside the golden file"
grep -q "\"decider\": \"$sut\"" "$work/g_sut/left_plain.suts.json" || fail "side file: $(cat "$work/g_sut/left_plain.suts.json")"
"$bin" check "$plain" --golden "$work/g_sut" --decider "$sut" --out "$work/c2" > "$work/c2.log" 2>&1 ||
  fail "check --decider against its own golden files: $(cat "$work/c2.log")"
"$bin" check "$plain" --golden "$work/g_sut" --out "$work/c3" > "$work/c3.log" 2>&1
[ $? -eq 1 ] || fail "the reference passed against the SUT's golden file: $(cat "$work/c3.log")"
grep -q "was made with decider $sut, light_judge reference, this run has decider reference" "$work/c3.log" ||
  fail "check message: $(cat "$work/c3.log")"
"$bin" check "$plain" --golden "$work/g_ref" --update --out "$work/c4" > "$work/c4.log" 2>&1 ||
  fail "check --update: $(cat "$work/c4.log")"
[ -e "$work/g_ref/left_plain.suts.json" ] && fail "a side file for the reference"
"$bin" check "$plain" --golden "$work/g_ref" --decider "$sut" --out "$work/c5" > "$work/c5.log" 2>&1
[ $? -eq 1 ] || fail "the SUT passed against the reference's golden file: $(cat "$work/c5.log")"
grep -q "was made with decider reference, light_judge reference, this run has decider $sut" "$work/c5.log" ||
  fail "check message: $(cat "$work/c5.log")"
echo "ok   check: golden files per SUT ($(head -1 "$work/c5.log"))"

# compare: three drivers
"$bin" compare "${scenarios[0]}" --decider "$sut" --out "$work/cmp" --jobs 2 > "$work/cmp.log" 2>&1
code=$?
[ $code -le 1 ] || fail "compare --decider: exit $code: $(cat "$work/cmp.log")"
grep -q "x 3 drivers (sut, signalsim, sumo)" "$work/cmp.log" || fail "compare: $(cat "$work/cmp.log")"
$py - "$work/cmp" <<'PY' || exit 1
import csv, os, sys
import matplotlib.image as mpimg
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "comparison.csv"), newline="")))
assert [(r["section"], r["driver"]) for r in rows] == [(s, d) for s in ("light1", "turn1") for d in ("sut", "signalsim", "sumo")], rows
assert all(r["status"] != "error" for r in rows), rows
img = (mpimg.imread(os.path.join(out, "comparison.png"))[:, :, :3] * 255).round().astype(int)
def count(hex_colour):
    rgb = [int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)]
    return int(((abs(img - rgb)).sum(axis=2) <= 6).sum())
assert count("#2ca02c") > 100 and count("#1f77b4") > 100 and count("#ff7f0e") > 100, \
    (count("#2ca02c"), count("#1f77b4"), count("#ff7f0e"))
print("ok   compare: sut, signalsim and sumo per item; the picture has all three")
PY
echo "all passed"
