#!/usr/bin/env python3
"""Whether two batch output folders hold the same results: results.csv and every file of every run
directory, byte for byte, except what differs between any two runs of SUMO itself (tests/batch/
workers_*_test.sh compare persistent workers with one process per run).

Masked: the wall_time column; in the files SUMO writes, its load durations "(12ms)", the date of its
XML outputs' "generated on" comment, and the run directory's own path (SUMO's XML outputs repeat
their options). Exit 0 when the same, else 1 with one line per difference.

usage: same_outputs.py DIR_A DIR_B                      every row and run directory
       same_outputs.py DIR_A DIR_B --pair RUN_A:RUN_B   only these runs (by results.csv run number;
                                                        the run and run_dir columns then differ, and a
                                                        column only one table has counts as empty)
"""
import csv
import os
import re
import sys


def rows(folder):
    with open(os.path.join(folder, "results.csv"), newline="") as f:
        table = list(csv.reader(f))
    header = table[0]
    return header, {r[0]: dict(zip(header, r)) for r in table[1:]}


def run_files(folder, run_dir):
    base = os.path.abspath(os.path.join(folder, run_dir))
    out = {}
    for root, _, names in os.walk(base):
        for name in names:
            path = os.path.join(root, name)
            with open(path, "rb") as f:
                text = f.read()
            text = re.sub(rb"\(\d+ms\)", b"(Nms)", text)
            # SUMO's router statistics at the end of its log are CPU times too: "spent 0.01s answering
            # queries (0.05ms on average)" under load, 0.00 on an idle machine.
            text = re.sub(rb"spent [0-9.]+s answering queries \([0-9.]+ms on average\)",
                          b"spent Ns answering queries (Nms on average)", text)
            text = re.sub(rb"generated on [0-9: -]+ by", b"generated on DATE by", text)
            text = text.replace(base.encode(), b"RUNDIR")
            out[os.path.relpath(path, base)] = text
    return out


def main(argv):
    a, b = argv[1], argv[2]
    pairs = [p.split(":") for p in argv[4::2]] if len(argv) > 3 and argv[3] == "--pair" else None
    header_a, rows_a = rows(a)
    header_b, rows_b = rows(b)
    problems = []
    if pairs is None and header_a != header_b:  # pairs: tables of other runs have other columns
        problems.append(f"results.csv columns differ: {header_a} / {header_b}")
    ignored = {"wall_time"} | ({"run", "run_dir"} if pairs else set())
    if pairs is None:
        if list(rows_a) != list(rows_b):
            problems.append(f"results.csv runs differ: {list(rows_a)} / {list(rows_b)}")
        pairs = [(r, r) for r in rows_a if r in rows_b]
    compared = 0
    for ra, rb in pairs:
        row_a, row_b = rows_a.get(ra), rows_b.get(rb)
        if row_a is None or row_b is None:
            problems.append(f"run {ra} / {rb}: missing in results.csv")
            continue
        for column in header_a + [c for c in header_b if c not in header_a]:
            if column not in ignored and row_a.get(column, "") != row_b.get(column, ""):
                problems.append(f"run {ra} / {rb}: {column}: '{row_a.get(column)}' / '{row_b.get(column)}'")
        if not row_a["run_dir"]:
            continue
        files_a, files_b = run_files(a, row_a["run_dir"]), run_files(b, row_b["run_dir"])
        if set(files_a) != set(files_b):
            problems.append(f"{row_a['run_dir']}: files {sorted(files_a)} / {sorted(files_b)}")
        for name in sorted(set(files_a) & set(files_b)):
            compared += 1
            if files_a[name] != files_b[name]:
                problems.append(f"{row_a['run_dir']}/{name} differs from {row_b['run_dir']}/{name}")
    for p in problems[:40]:
        print("DIFFERENT " + p)
    if not problems and compared == 0:
        print("DIFFERENT: no run directory files were compared")
        return 1
    if not problems:
        print(f"same: {len(pairs)} rows, {compared} files")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
