#!/usr/bin/env bash
# Safety under perception faults (stop_release_confirmation_time, README "Safety under perception
# faults"): a cut of the perception_faults sweep, 4 approaches at 5 % misclassification, dropout 0 and
# 10 %. With the filter (0.5 s) no approach crosses on red; the reference (0 s) crosses on at least
# one (else the cut no longer shows the failure the filter is for, and this test says so).
# usage: perception_faults_cut.sh SIGNALSIM_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$bin" sweep "$src/tests/data/sweeps/perception_faults_cut.yaml" --out "$work/out" --jobs 2 --quiet \
  > "$work/log" 2>&1 || fail "sweep: exit code $? ($(tail -3 "$work/log"))"

python3 - "$work/out/results.csv" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 16, f"{len(rows)} rows, expected 16"
crossed = {}
for r in rows:
    assert r["status"] != "error", r["error"]
    assert r["light1.state_at_line"] != "", f"seed {r['seed']}: the ego never reached the light"
    key = (r["perception.dropout_probability"], r["stop_release_confirmation_time"])
    crossed.setdefault(key, []).extend([r["seed"]] if int(r["red_light_violations"]) > 0 else [])
for key, seeds in sorted(crossed.items()):
    print(f"dropout {key[0]}, confirmation {key[1]} s: red crossings on seeds {seeds or 'none'}")
for dropout in ("0", "0.1"):
    assert crossed[(dropout, "0.5")] == [], f"filter on, dropout {dropout}: crossed on red (seeds {crossed[(dropout, '0.5')]})"
reference = crossed[("0", "0")] + crossed[("0.1", "0")]
assert reference, "the reference (0 s) crossed on no seed: the cut no longer shows the failure"
PY
echo "perception_faults_cut: passed"
