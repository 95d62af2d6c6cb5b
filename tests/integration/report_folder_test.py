"""The HTML report and the files it reads in folders a user reuses or cannot write: an earlier check's
verdicts (check.json) are not read as a later batch's; an earlier compare's run folders are not rows
of a later compare's report; an interrupted check leaves no report or verdicts of the check before
it; a folder the report cannot be written into is one line and exit 3; a results.csv that is not
signalsim's is one line and exit 2; a scenario file whose name is not UTF-8 (Latin-1) gives a batch
exit 4 (its run error), well-formed JUnit XML and a report, and an error row with --junit draws no
pictures.

  report_folder_test.py SIGNALSIM SOURCE_DIR"""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_pages_test import check, page_data as table_rows  # noqa: E402


def run(command, expected, cwd):
    """As report_pages_test.run, with output that may not be UTF-8 (a Latin-1 file name)."""
    done = subprocess.run(command, capture_output=True, timeout=600, cwd=cwd)
    stdout, stderr = done.stdout.decode(errors="replace"), done.stderr.decode(errors="replace")
    check(done.returncode == expected, f"{command}: exit {done.returncode}, expected {expected}\n{stdout}\n{stderr}")
    return stdout, stderr


def golden_with_right_blinker(source, tmp):
    """intersection_left's golden events with its left blinker written as right: check fails it."""
    golden = os.path.join(tmp, "golden")
    os.makedirs(golden)
    with open(os.path.join(source, "tests", "golden", "intersection_left.events.csv")) as f:
        text = f.read()
    with open(os.path.join(golden, "intersection_left.events.csv"), "w") as f:
        f.write(text.replace(",none,left,", ",none,right,"))
    return golden


def earlier_check_verdicts(signalsim, source, tmp):
    out = os.path.join(tmp, "reused")
    golden = golden_with_right_blinker(source, tmp)
    run([signalsim, "check", "scenarios/intersection_left.yaml", "--golden", golden, "--out", out, "-q"], 1, source)
    check(os.path.isfile(os.path.join(out, "check.json")), "check wrote no check.json")
    run([signalsim, "batch", "scenarios/intersection_left.yaml", "--out", out, "-q", "--report"], 0, source)
    check(not os.path.exists(os.path.join(out, "check.json")), "the batch left the earlier check's check.json")
    text, rows = table_rows(out)
    check([r["status"] for r in rows] == ["passed"] and not rows[0]["problem"],
          f"the batch's report shows the earlier check's verdict: {rows}")
    check('id="count-failed"><b>0<' in text, "the batch's report counts a failed run")


def earlier_compare_runs(signalsim, source, tmp):
    out = os.path.join(tmp, "compare")
    run([signalsim, "compare", "scenarios/intersection_left.yaml", "scenarios/intersection_right.yaml", "--out", out,
         "-j", "2", "-q"], 0, source)
    run([signalsim, "compare", "scenarios/intersection_right.yaml", "--out", out, "-j", "2", "-q", "--report"], 0, source)
    _, rows = table_rows(out)
    check(sorted((r["scenario"], r["driver"]) for r in rows) ==
          [("intersection_right", "signalsim"), ("intersection_right", "sumo")],
          f"the compare's report has the runs of an earlier compare: {[(r['scenario'], r['driver']) for r in rows]}")


def interrupted_check(signalsim, source, tmp):
    out = os.path.join(tmp, "interrupted")
    golden = os.path.join(source, "tests", "golden")
    run([signalsim, "check", "scenarios/intersection_right.yaml", "--golden", golden, "--out", out, "-q", "--report"],
        0, source)
    check(os.path.isfile(os.path.join(out, "report.html")), "no report of the first check")
    slow = os.path.join(tmp, "slow_turns.yaml")  # a few seconds of 2 ms steps: Ctrl-C comes while it runs
    with open(os.path.join(source, "tests", "batch", "data", "turns.yaml")) as f:
        text = f.read().replace("../../../", source + "/").replace("name: turns", "name: slow_turns")
    with open(slow, "w") as f:
        f.write(text.replace("step_length: 0.1", "step_length: 0.002").replace("duration: 60", "duration: 600"))
    with open(os.path.join(golden, "intersection_right.events.csv")) as f:
        slow_golden = os.path.join(tmp, "slow_golden")
        os.makedirs(slow_golden)
        shutil.copy(f.name, os.path.join(slow_golden, "slow_turns.events.csv"))
    process = subprocess.Popen([signalsim, "check", slow, "--golden", slow_golden, "--out", out, "-q", "-j", "1",
                                "--report"], cwd=source, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    started = os.path.join(out, "runs", "0000-slow_turns")
    for _ in range(600):  # until the run has begun (at most 30 s)
        if os.path.isdir(started) or process.poll() is not None:
            break
        time.sleep(0.05)
    check(process.poll() is None, "the slow check ended before it could be interrupted")
    process.send_signal(signal.SIGINT)
    check(process.wait(timeout=120) == 130, f"interrupted check: exit {process.returncode}, expected 130")
    for name in ("report.html", "report", "check.json"):
        check(not os.path.exists(os.path.join(out, name)), f"the interrupted check left the earlier check's {name}")


def unwritable_folder(signalsim, source, tmp):
    out = os.path.join(tmp, "unwritable")
    run([signalsim, "batch", "scenarios/intersection_left.yaml", "--out", out, "-q"], 0, source)
    with open(os.path.join(out, "report"), "w") as f:  # report/runs cannot be made (as in a read-only folder)
        f.write("not a folder\n")
    _, stderr = run([signalsim, "report", out], 3, source)
    lines = stderr.splitlines()
    check(len(lines) == 1 and lines[0].startswith("signalsim-plot: report: cannot write the report"),
          f"a folder the report cannot be written into is not one line: {stderr!r}")
    check(not os.path.exists(os.path.join(out, "report.html")), "a report.html without its run pages")


def foreign_results(signalsim, source, tmp):
    out = os.path.join(tmp, "foreign")
    os.makedirs(out)
    with open(os.path.join(out, "results.csv"), "w") as f:
        f.write("a,b\n1,2\n")
    _, stderr = run([signalsim, "report", out], 2, source)
    check(stderr.count("\n") == 1 and "not a results.csv of signalsim" in stderr, f"a foreign results.csv: {stderr!r}")
    check(not os.path.exists(os.path.join(out, "report.html")), "a report of a foreign results.csv")


def latin1_file_name(signalsim, source, tmp):
    suite = os.path.join(tmp, "latin1").encode()
    os.makedirs(suite)
    bad = os.path.join(suite, b"caf\xe9.yaml")  # its run is an error row: the net has no edge 'nowhere'
    with open(bad, "wb") as f:
        f.write(f"name: cafe\nnet: {source}/sumo_nets/cross/cross.net.xml\nego: {{route: [in_S, nowhere]}}\n".encode())
    out = os.path.join(tmp, "latin1_out")
    junit = os.path.join(out, "junit.xml")
    _, stderr = run([signalsim, "batch", bad, os.path.join(source, "scenarios", "intersection_left.yaml"), "--out", out,
                     "-q", "--report", "--junit", junit], 4, source)
    check("plotting failed" not in stderr and "pictures not drawn" not in stderr,
          f"pictures of a run that wrote no timeline were drawn for JUnit: {stderr!r}")
    cases = ElementTree.parse(junit).getroot().iter("testcase")  # expat refuses bytes that are not UTF-8
    check(sorted(c.get("name") for c in cases) == ["caf\ufffd", "intersection_left"], "JUnit cases")
    _, rows = table_rows(out)
    check(sorted(r["status"] for r in rows) == ["error", "passed"], f"the report's rows: {rows}")
    with open(os.path.join(out, "command.json"), encoding="utf-8") as f:
        check("caf\ufffd.yaml" in json.load(f)["argv"][2], "command.json's argv")


def main():
    signalsim, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    tmp = tempfile.mkdtemp(prefix="signalsim-report-folder-")
    try:
        for part in (foreign_results, unwritable_folder, earlier_check_verdicts, earlier_compare_runs,
                     latin1_file_name, interrupted_check):
            part(signalsim, source, tmp)
            print(f"ok {part.__name__}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
