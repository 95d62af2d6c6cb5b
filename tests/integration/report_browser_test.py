"""The HTML report in a real browser: `signalsim batch` of the bundled suite plus one scenario whose
expectation fails (tests/data/report/intersection_left_lead_90.yaml) with --report, then report.html
opened from the folder (file://, no server) in headless Chromium over the DevTools protocol
(tests/support/cdp.py): no console error, exception or failed load; one table row per run of
results.csv; the status filter "failed" (the page's own JavaScript) leaves exactly the failing run;
a heat-map cell's link (#cell=...) leaves the runs of that cell; the failed run's page shows the
failed expectation with a FAIL line, and its pictures load (naturalWidth > 0).

  report_browser_test.py SIGNALSIM SOURCE_DIR [--screenshot PNG] [--keep DIR]

--screenshot writes the first page (filtered to the failed run) as a PNG (docs/img/report.png).
Exit 77 (skipped) without chromium."""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import cdp  # noqa: E402

FAILING = "intersection_left_lead_90"


def check(condition, message):
    if not condition:
        print(f"FAIL: {message}", file=sys.stderr)
        sys.exit(1)


def run_suite(signalsim, source, out):
    fixture = os.path.join(source, "tests", "data", "report", f"{FAILING}.yaml")
    command = [signalsim, "batch", os.path.join(source, "scenarios"), fixture, "--out", out, "--jobs", "2",
               "--quiet", "--report"]
    done = subprocess.run(command, capture_output=True, text=True, timeout=600)
    # exit 1: a run failed (the fixture); anything else is a problem of the suite, not of the report
    check(done.returncode == 1, f"batch exit code {done.returncode}, expected 1\n{done.stdout}\n{done.stderr}")
    check(os.path.isfile(os.path.join(out, "report.html")), "no report.html")
    with open(os.path.join(out, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    failed = [r for r in rows if r["status"] == "failed"]
    check([r["scenario"] for r in failed] == [FAILING], f"failed runs {[r['scenario'] for r in failed]}")
    return rows


def first_page(browser, out, rows, screenshot):
    browser.navigate("file://" + os.path.abspath(os.path.join(out, "report.html")))
    check(browser.evaluate("document.body.dataset.rendered") == "yes", "the table was not built")
    shown = browser.evaluate("document.querySelectorAll('#runs tbody tr').length")
    check(shown == len(rows), f"{shown} table rows for {len(rows)} runs")
    check(browser.evaluate("document.getElementById('count-failed').querySelector('b').textContent") == "1",
          "the failed count is not 1")
    browser.evaluate("(() => { const s = document.getElementById('status-filter'); s.value = 'failed';"
                     " s.dispatchEvent(new Event('change')); })()")
    left = browser.evaluate("[...document.querySelectorAll('#runs tbody tr')].map(tr => tr.cells[2].textContent)")
    check(left == [FAILING], f"the 'failed' filter leaves {left}")
    if screenshot:
        browser.screenshot(screenshot)
    href = browser.evaluate("document.querySelector('#runs tbody tr a').href")
    # a heat-map cell's link: #cell={column: value} keeps the rows with those values (all statuses)
    browser.evaluate("(() => { const s = document.getElementById('status-filter'); s.value = '';"
                     " s.dispatchEvent(new Event('change'));"
                     " location.hash = 'cell=' + encodeURIComponent(JSON.stringify({scenario: 'intersection_right'})); })()")
    left = browser.evaluate(  # hashchange is dispatched later: wait until the page says the cell (at most 10 s)
        "new Promise(r => { const end = Date.now() + 10000; (function poll() {"
        " if (document.getElementById('cell-filter').textContent || Date.now() > end)"
        "  r([...document.querySelectorAll('#runs tbody tr')].map(tr => tr.cells[2].textContent));"
        " else setTimeout(poll, 20); })(); })")
    check(left == ["intersection_right"], f"the cell filter scenario=intersection_right leaves {left}")
    return href


def run_page(browser, href):
    browser.navigate(href)
    text = browser.evaluate("document.body.innerText")
    check(f"{FAILING}: failed" in text, "the run page does not name the failed run")
    fail_lines = browser.evaluate("[...document.querySelectorAll('ul.expectations li')]"
                                  ".filter(li => li.querySelector('.fail')).map(li => li.textContent)")
    check(len(fail_lines) == 1 and "blinker_through_junction C left lead 90" in fail_lines[0],
          f"FAIL lines of the run page: {fail_lines}")
    images = browser.evaluate(
        "Promise.all([...document.images].map(i => i.complete ? i : new Promise(r => { i.onload = i.onerror = () => r(i); })))"
        ".then(list => list.map(i => [i.getAttribute('src'), i.naturalWidth]))")
    names = sorted(os.path.basename(src) for src, _ in images)
    check("blinker.png" in names and "speed.png" in names, f"pictures on the run page: {names}")
    check(all(width > 0 for _, width in images), f"a picture did not load: {images}")
    for name in ("timeline.csv", "events.csv", "summary.json", "sumo.log"):
        check(browser.evaluate(f"[...document.links].some(a => a.textContent === '{name}')"), f"no link to {name}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("signalsim")
    parser.add_argument("source")
    parser.add_argument("--screenshot")
    parser.add_argument("--keep")
    args = parser.parse_args()
    if not cdp.find_chromium():
        print("chromium not installed (tools/setup installs it): skipped")
        return 77
    out = args.keep or tempfile.mkdtemp(prefix="signalsim-report-")
    browser = None
    try:
        rows = run_suite(args.signalsim, args.source, out)
        browser = cdp.Browser()
        href = first_page(browser, out, rows, args.screenshot)
        run_page(browser, href)
        check(not browser.problems, "the browser reported:\n  " + "\n  ".join(browser.problems))
    finally:
        if browser:
            browser.close()
        if not args.keep:
            shutil.rmtree(out, ignore_errors=True)
    print(f"report: {len(rows)} rows, the failed filter leaves {FAILING}, its page and pictures load")
    return 0


if __name__ == "__main__":
    sys.exit(main())
