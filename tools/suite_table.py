#!/usr/bin/env python3
"""Prints the suite summary table from out/<scenario>/summary.json and a times file
(lines: "<scenario> <exit code> <start epoch> <end epoch>")."""
import json
import sys
from pathlib import Path


def main(out_dir: str, times_file: str) -> None:
    rows = []
    for line in Path(times_file).read_text().splitlines():
        name, code, start, end = line.split()
        summary_path = Path(out_dir) / name / "summary.json"
        summary = json.loads(summary_path.read_text()) if summary_path.exists() else {}
        status = summary.get("status", "error") if code in ("0", "1") else "error"
        counts = summary.get("counts", {})
        expectations = summary.get("expectations", [])
        held = sum(1 for e in expectations if e.get("passed"))
        stops = summary.get("lights", {}).get("stops", [])
        stop_text = ",".join(f"{s['error']:+.2f}" for s in stops) or "-"
        rows.append((name, status, f"{held}/{len(expectations)}", str(counts.get("blinker_events", "-")),
                     str(counts.get("light_events", "-")), stop_text, f"{float(end) - float(start):.2f}"))
    header = ("scenario", "result", "expectations", "blinker events", "light events", "stop error [m]", "wall [s]")
    widths = [max(len(r[i]) for r in rows + [header]) for i in range(len(header))]
    fmt = "  ".join("{:<%d}" % w for w in widths)
    print(fmt.format(*header))
    print(fmt.format(*("-" * w for w in widths)))
    for r in rows:
        print(fmt.format(*r))
    # no_expectations: the scenario has none, nothing was checked; neither passed nor failed.
    count = {status: sum(1 for r in rows if r[1] == status) for status in ("passed", "failed", "no_expectations")}
    errors = len(rows) - sum(count.values())
    print(f"\n{count['passed']} passed, {count['failed']} failed, {count['no_expectations']} without expectations, "
          f"{errors} error{'' if errors == 1 else 's'}; outputs in {out_dir}/<scenario>/")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
