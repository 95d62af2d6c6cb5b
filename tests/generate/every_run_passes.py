#!/usr/bin/env python3
"""every_run_passes.py OUT: every row of OUT/results.csv passed, and every summary says arrived, no
red crossing, every expectation held (generate_real_nets.sh, generate_real_nets_reduced.sh)."""
import csv, json, sys, glob
out = sys.argv[1]
rows = list(csv.DictReader(open(out + "/results.csv")))
bad = [r for r in rows if r["status"] != "passed"]
for r in bad:
    print("FAIL:", r["scenario"], r["status"], r["failed_expectations"], r.get("error", ""))
summaries = sorted(glob.glob(out + "/runs/*/summary.json"))
assert len(summaries) == len(rows), (len(summaries), len(rows))
checked = 0
for f in summaries:
    s = json.load(open(f))
    if not s["counts"]["arrived"]:
        print("FAIL:", f, "did not arrive"); bad.append(f)
    if s["metrics"]["red_light_violations"] != 0:
        print("FAIL:", f, "crossed on red"); bad.append(f)
    checked += len(s["expectations"])
    bad += [e for e in s["expectations"] if not e["passed"]]
print(f"{len(rows)} runs, {checked} expectations, {len(bad)} failures")
sys.exit(1 if bad else 0)
