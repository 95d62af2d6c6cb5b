"""Builds the report of an output folder: the pictures wanted (pictures.py), one page per run
(run_page.py), then OUT/report.html (index_page.py). The run pages are written into a new folder that
replaces OUT/report/runs once complete (one rename, not one a page: renames cost milliseconds each on
some file systems), then the first page (.tmp, renamed); so no page of an earlier report is left."""
import os
import shutil

from signalsim_plot.report import pictures
from signalsim_plot.report.folder import Folder
from signalsim_plot.report.index_page import index_page
from signalsim_plot.report.run_page import run_page
from signalsim_plot.report.runs import CHECK_STATUS, Run

INDEX = "report.html"
PAGES = os.path.join("report", "runs")


def write_whole(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def replace_folder(new, path):
    """Puts the folder `new` at `path`, removing what was there."""
    old = path + ".old"
    shutil.rmtree(old, ignore_errors=True)
    if os.path.exists(path):
        os.rename(path, old)
    os.rename(new, path)
    shutil.rmtree(old, ignore_errors=True)


def row_status(folder, row):
    case = folder.checks.get(row.get("file", ""))
    if case:
        return CHECK_STATUS.get(case.get("status", ""), row.get("status", ""))
    return row.get("status", "") or ("" if folder.kind == "compare" else "error")


def build(out_dir, all_pictures=False, jobs=0):
    """Writes OUT/report.html and OUT/report/runs/*.html; returns (index path, {run_dir: picture error})."""
    folder = Folder(out_dir)
    wanted = {}
    for row in folder.rows:
        run_dir = folder.run_dir(row)
        status = row_status(folder, row)
        if folder.kind == "compare" and run_dir:  # no results.csv: the status is the summary's
            from signalsim_plot.report.runs import read_summary
            status = read_summary(os.path.join(out_dir, run_dir)).get("status", "error")
        wanted[run_dir] = bool(run_dir) and pictures.wants_pictures(status, all_pictures)
    failures = pictures.draw([os.path.join(out_dir, d) for d, w in wanted.items() if w], jobs)
    pages_new = os.path.join(out_dir, PAGES + ".new")
    shutil.rmtree(pages_new, ignore_errors=True)
    try:
        runs = write_run_pages(out_dir, folder, pages_new, wanted, failures)
    finally:
        shutil.rmtree(pages_new, ignore_errors=True)  # left only when writing failed
    index_path = os.path.join(out_dir, INDEX)
    write_whole(index_path, index_page(folder, runs))
    return index_path, failures


def write_run_pages(out_dir, folder, pages_new, wanted, failures):
    """Writes one page per run into pages_new, then puts it at OUT/report/runs; returns the runs."""
    os.makedirs(pages_new)
    runs = []
    for i, row in enumerate(folder.rows):
        run_dir = folder.run_dir(row)
        index = int(row["run"]) if str(row.get("run", "")).isdigit() else i
        run = Run(out_dir, index, run_dir, row, keep_summary=True)
        case = folder.checks.get(run.file)
        if case:
            run.apply_check(case)
        with open(os.path.join(pages_new, os.path.basename(run.page())), "w", encoding="utf-8") as f:
            f.write(run_page(out_dir, run, run.summary, folder.swept, failures.get(os.path.join(out_dir, run_dir)),
                             wanted.get(run_dir, False)))
        run.summary = None  # a sweep of thousands of runs holds one summary at a time
        runs.append(run)
    replace_folder(pages_new, os.path.join(out_dir, PAGES))
    return runs
