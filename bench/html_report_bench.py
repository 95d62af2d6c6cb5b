#!/usr/bin/python3
"""The HTML report's cost on a big folder (docs/performance.md "The HTML report"): the wall and CPU
time of `signalsim report OUT`, the size of OUT/report.html, and in headless Chromium (over the
DevTools protocol, tests/support/cdp.py) the time from navigation to DOMContentLoaded, to the load
event and to the table built by report.js, then a status filter, a sort and "show all" done in the page,
each with the layout it causes; medians of --repeat loads.

  bench/html_report_bench.py OUT [--bin build/src/app/signalsim] [--repeat 5]"""
import argparse
import os
import resource
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "support"))
import cdp  # noqa: E402

TIMING = """(() => { const n = performance.getEntriesByType('navigation')[0];
  return [n.domContentLoadedEventEnd, n.loadEventEnd, Number(document.body.dataset.renderedMs),
          document.querySelectorAll('#runs tbody tr').length]; })()"""
# Each action with the layout it causes (offsetHeight forces it): a status filter, a sort, "show all".
ACTIONS = """(() => { const s = document.getElementById('status-filter'); const took = (f) => {
    const t = performance.now(); f(); document.body.offsetHeight; return performance.now() - t; };
  const filter = took(() => { s.value = 'failed'; s.dispatchEvent(new Event('change')); });
  s.value = ''; s.dispatchEvent(new Event('change'));
  const sort = took(() => document.querySelector('#runs thead th:nth-child(3)').click());
  const button = document.getElementById('show-all');
  const all = button ? took(() => button.click()) : 0;
  return [filter, sort, all, document.querySelectorAll('#runs tbody tr').length]; })()"""


def build_report(signalsim, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    subprocess.run([signalsim, "report", out], check=True, stdout=subprocess.DEVNULL)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("out")
    parser.add_argument("--bin", default="build/src/app/signalsim")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    wall, cpu = build_report(args.bin, args.out)
    index = os.path.abspath(os.path.join(args.out, "report.html"))
    print(f"signalsim report: {wall:.2f} s wall, {cpu:.2f} s CPU; report.html {os.path.getsize(index) / 1e6:.2f} MB, "
          f"{len(os.listdir(os.path.join(args.out, 'report', 'runs')))} run pages")
    browser = cdp.Browser()
    try:
        loads, actions = [], []
        for _ in range(args.repeat):
            browser.navigate("file://" + index)
            loads.append(browser.evaluate(TIMING))
            actions.append(browser.evaluate(ACTIONS))
        rows = loads[0][3]
        med = lambda i, xs: statistics.median(x[i] for x in xs)
        print(f"Chromium, median of {args.repeat}: DOMContentLoaded {med(0, loads):.0f} ms, load {med(1, loads):.0f} ms, "
              f"table ({rows} rows drawn) built {med(2, loads):.0f} ms after navigation; with their layout: status filter "
              f"{med(0, actions):.0f} ms, sort {med(1, actions):.0f} ms, show all {med(2, actions):.0f} ms "
              f"({actions[0][3]} rows)")
        if browser.problems:
            print("browser problems:\n  " + "\n  ".join(browser.problems))
            return 1
    finally:
        browser.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
