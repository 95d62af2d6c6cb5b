"""The HTML report of sweep, check, compare and batch folders, read back from the pages it writes
(no browser: the table's inline JSON and the HTML): a sweep's heat-map cells link to exactly the runs
they count; check's golden diff is on the failed run's page and makes its pictures; compare's table,
picture and runs; --report=all draws every run's pictures, the default only failed ones; an error
row's message and page; `signalsim report` on a folder that is not an output folder is one line and
exit 2.

  report_pages_test.py SIGNALSIM SOURCE_DIR"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from urllib.parse import unquote


def check(condition, message):
    if not condition:
        print(f"FAIL: {message}", file=sys.stderr)
        sys.exit(1)


def run(command, expected, cwd):
    done = subprocess.run(command, capture_output=True, text=True, timeout=600, cwd=cwd)
    check(done.returncode == expected, f"{' '.join(command)}: exit {done.returncode}, expected {expected}\n"
                                       f"{done.stdout}\n{done.stderr}")
    return done


def page_data(out):
    with open(os.path.join(out, "report.html")) as f:
        text = f.read()
    data = json.loads(re.search(r'<script type="application/json" id="report-data">(.*?)</script>', text, re.S).group(1))
    keys = [c["key"] for c in data["columns"]]
    return text, [dict(zip(keys + ["page"], row)) for row in data["rows"]]


def results(out):
    with open(os.path.join(out, "results.csv"), newline="") as f:
        return list(csv.DictReader(f))


def sweep_report(signalsim, source, tmp):
    out = os.path.join(tmp, "sweep")
    run([signalsim, "sweep", "tests/batch/data/sweep_3x3x2.yaml", "--out", out, "-j", "2", "-q", "--report"], 0, source)
    facts = json.load(open(os.path.join(out, "command.json")))
    check(facts["command"] == "sweep" and facts["sweep_plots"] == [
        {"metric": "roundabout_exit1.lead_distance", "x": "ego.max_speed", "y": "country"}], f"command.json {facts}")
    text, rows = page_data(out)
    table = results(out)
    check(len(rows) == len(table) == 18, f"{len(rows)} table rows for {len(table)} runs")
    links = [json.loads(unquote(h)) for h in re.findall(r'href="#cell=([^"]+)"', text)]
    counts = [int(n) for n in re.findall(r"n=(\d+)</small>", text)]
    check(len(links) == len(counts) == 18, f"{len(links)} heat-map cells, expected 9 per scenario")
    for cell, n in zip(links, counts):
        matching = [r for r in table if all(r[k] == v for k, v in cell.items())]
        check(len(matching) == n == 1, f"cell {cell} counts {n} runs, links to {len(matching)}")
    # the roundabout exit's cells: a late lead of -0.12 m is tinted red, not the white of 0, and each cell
    # says the blinker at the section start (results.csv roundabout_exit1.blinker_at_start)
    for row in (r for r in table if r["scenario"] == "roundabout_exit"):
        selection = {"ego.max_speed": row["ego.max_speed"], "country": row["country"], "scenario": "roundabout_exit"}
        cell = next(m for m in re.finditer(r'<td[^>]*style="background:#(\w{6})"[^>]*><a href="#cell=([^"]+)">(.*?)</a></td>', text)
                    if json.loads(unquote(m.group(2))) == selection)
        background, shown = cell.group(1), cell.group(3)
        blinker = row["roundabout_exit1.blinker_at_start"]
        check(f"start: {'←' if blinker == 'left' else '→'} {blinker}" in shown, f"cell {selection}: {shown}")
        if float(row["roundabout_exit1.lead_distance"]) < 0:
            check(int(background[2:4], 16) < 230, f"cell {selection} of a late lead is near white: #{background}")
    check(len(os.listdir(os.path.join(out, "report", "runs"))) == 18, "not one page per run")
    check(not any(os.path.isdir(os.path.join(out, r["run_dir"], "plots")) for r in table),
          "pictures of passed runs drawn without --report=all")


def golden_with_moved_blinker(source, tmp):
    golden = os.path.join(tmp, "golden")
    os.makedirs(golden)
    for name in ("intersection_left", "intersection_right"):
        shutil.copy(os.path.join(source, "tests", "golden", f"{name}.events.csv"), golden)
    path = os.path.join(golden, "intersection_left.events.csv")
    with open(path) as f:
        lines = f.read().splitlines()
    moved = []
    for line in lines:  # the left blinker 6 m earlier: one moved event
        cells = line.split(",")
        if len(cells) == 6 and cells[2] == "blinker" and cells[4] == "left":
            cells[1] = f"{float(cells[1]) - 6:.3f}"
        moved.append(",".join(cells))
    with open(path, "w") as f:
        f.write("\n".join(moved) + "\n")
    return golden


def check_report(signalsim, source, tmp):
    out = os.path.join(tmp, "check")
    golden = golden_with_moved_blinker(source, tmp)
    run([signalsim, "check", "scenarios/intersection_left.yaml", "scenarios/intersection_right.yaml", "--golden",
         golden, "--out", out, "-j", "2", "-q", "--report"], 1, source)
    text, rows = page_data(out)
    status = {r["scenario"]: (r["status"], r["problem"]) for r in rows}
    check(status["intersection_left"][0] == "failed" and "1 event difference" in status["intersection_left"][1],
          f"check's verdict in the table: {status}")
    check(status["intersection_right"][0] == "passed", f"check's verdict in the table: {status}")
    left = next(r for r in rows if r["scenario"] == "intersection_left")
    with open(os.path.join(out, left["page"])) as f:
        page = f.read()
    check("check against the golden file" in page and "~ " in page and "golden" in page, "no golden diff on the run page")
    run_dir = next(r["run_dir"] for r in results(out) if r["scenario"] == "intersection_left")
    check(os.path.isfile(os.path.join(out, run_dir, "plots", "blinker.png")), "no pictures of the run check failed")


def compare_report(signalsim, source, tmp):
    out = os.path.join(tmp, "compare")
    run([signalsim, "compare", "scenarios/intersection_left.yaml", "--out", out, "-j", "2", "-q", "--report"], 0, source)
    text, rows = page_data(out)
    check(sorted(r["driver"] for r in rows) == ["signalsim", "sumo"], f"compare's runs: {rows}")
    check('<img src="comparison.png"' in text and "lead_distance" in text, "no comparison picture or table")
    sumo = next(r for r in rows if r["driver"] == "sumo")
    check(sumo["status"] == "failed" and sumo["problem"], f"SUMO's run: {sumo}")


def batch_all_pictures(signalsim, source, tmp):
    out = os.path.join(tmp, "all")
    run([signalsim, "batch", "scenarios/intersection_left.yaml", "scenarios/tl_red_stop_then_go.yaml", "--out", out,
         "-j", "2", "-q", "--report=all"], 0, source)
    for r in results(out):
        check(os.path.isfile(os.path.join(out, r["run_dir"], "plots", "speed.png")), f"--report=all: no pictures of {r['run_dir']}")
    again = run([signalsim, "report", out], 0, source)
    check(again.stdout.strip() == f"report: {out}/report.html", f"signalsim report prints {again.stdout!r}")


def error_rows(signalsim, source, tmp):
    out = os.path.join(tmp, "errors")
    done = run([signalsim, "batch", "tests/batch/data/sumo_load_error.yaml", "scenarios/intersection_left.yaml",
                "--out", out, "-q", "--report"], 4, source)
    check("pictures not drawn" not in done.stderr, f"a run that did not finish warned about: {done.stderr!r}")
    _, rows = page_data(out)
    error = next(r for r in rows if r["scenario"] == "sumo_load_error")
    check(error["status"] == "error" and "SUMO could not load the simulation" in error["problem"], f"error row {error}")
    with open(os.path.join(out, error["page"])) as f:
        check("no pictures: the run did not finish" in f.read(), "the error run's page does not say why it has no pictures")


def bad_folders(signalsim, source, tmp):
    missing = run([signalsim, "report", os.path.join(tmp, "nothing")], 2, source)
    check(missing.stderr.count("\n") == 1 and "not found" in missing.stderr, f"missing folder: {missing.stderr!r}")
    empty = os.path.join(tmp, "empty")
    os.makedirs(empty)
    neither = run([signalsim, "report", empty], 2, source)
    check(neither.stderr.count("\n") == 1 and "results.csv" in neither.stderr, f"empty folder: {neither.stderr!r}")
    check(not os.path.exists(os.path.join(empty, "report.html")), "a report of an empty folder")


def main():
    signalsim, source = os.path.abspath(sys.argv[1]), sys.argv[2]
    tmp = tempfile.mkdtemp(prefix="signalsim-report-pages-")
    try:
        for part in (bad_folders, sweep_report, check_report, compare_report, batch_all_pictures, error_rows):
            part(signalsim, source, tmp)
            print(f"ok {part.__name__}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
