"""How soon a large suite or sweep starts its first run, and the parent's memory (tools/bench --only
batchstart).

Writes FILES copies of scenarios/intersection_left.yaml (each its own name, the net's path made
absolute) and a sweep over them with a grid of `seed` values: FILES x SEEDS runs (1 280 x 16 = 20 480).
Then, ROUNDS times: starts `signalsim sweep FILE --jobs 1 --quiet`, polls (every 2 ms) for the first
run directory under OUT/runs/ (a worker creates it as its run starts: the time to the first run
start), reads the parent's peak RSS (VmHWM of /proc/PID/status) once that run is under way,
interrupts it with SIGINT (exit code 130 expected: finished rows are kept) and checks that --resume
is accepted (a second start, interrupted the same way, must print "resuming: K of N runs already
done" when K > 0, or start from the first run). Medians of the time to the first run and of the
peak RSS. The same for `signalsim batch` over the FILES files (a suite; interrupted, not resumed).
`--bin` measures another build, e.g. one from before a change.
"""
import os
import re
import shutil
import signal
import statistics
import subprocess
import time

from measure import BenchError

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCE = os.path.join(ROOT, "scenarios", "intersection_left.yaml")
FILES, SEEDS = 1280, 16
QUICK_FILES = 64


def write_sweep(work, files):
    folder = os.path.join(work, "scenarios")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    with open(SOURCE) as f:
        text = f.read()
    text = re.sub(r"(?m)^net: *(\S+)", lambda m: "net: " + os.path.normpath(os.path.join(ROOT, "scenarios", m.group(1))),
                  text)
    text = text.replace("../config/", os.path.join(ROOT, "config") + "/")
    for i in range(files):
        with open(os.path.join(folder, "s%04d.yaml" % i), "w") as f:
            f.write(re.sub(r"(?m)^name: *\S+", "name: s%04d" % i, text))
    sweep = os.path.join(work, "large.sweep.yaml")
    with open(sweep, "w") as f:
        f.write("name: large\nscenarios: [scenarios]\ngrid:\n  seed: [%s]\n" % ", ".join(str(s) for s in range(1, SEEDS + 1)))
    return sweep


def peak_rss_kb(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1])
    return 0


def start_and_interrupt(binary, env, sweep, out, resume, command="sweep"):
    """Seconds to the first run directory, the parent's peak RSS [kB], its stdout. `command` "batch"
    runs the sweep's scenario folder as a suite instead."""
    target = sweep if command == "sweep" else os.path.join(os.path.dirname(sweep), "scenarios")
    argv = [binary, command, target, "--out", out, "--jobs", "1"] + (["--resume"] if resume else [])
    runs_dir = os.path.join(out, "runs")
    before = set(os.listdir(runs_dir)) if resume and os.path.isdir(runs_dir) else set()
    start = time.perf_counter()
    child = subprocess.Popen(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    first = None
    while first is None:
        if child.poll() is not None:
            raise BenchError("%s ended (exit code %d) before a run started: %s"
                             % (" ".join(argv[:3]), child.returncode, child.stderr.read().strip()[-300:]))
        if os.path.isdir(runs_dir) and set(os.listdir(runs_dir)) - before:
            first = time.perf_counter() - start
        else:
            time.sleep(0.002)
    time.sleep(0.3)  # the run under way, the parent past its start
    rss = peak_rss_kb(child.pid)
    child.send_signal(signal.SIGINT)
    stdout, stderr = child.communicate(timeout=60)
    if child.returncode != 130:
        raise BenchError("%s: exit code %d after SIGINT, not 130: %s" % (" ".join(argv[:3]), child.returncode,
                                                                      stderr.strip()[-300:]))
    return first, rss, stdout


def bench_batch_start(binary, env, work, runs, quick):
    """Returns (first-run seconds, peak RSS kB) per round of the sweep, of the suite (`batch` over the
    files), and the sweep's run count."""
    files = QUICK_FILES if quick else FILES
    sweep = write_sweep(work, files)
    firsts, rss, suite_firsts, suite_rss = [], [], [], []
    for _ in range(runs):
        out = os.path.join(work, "suite_out")
        shutil.rmtree(out, ignore_errors=True)
        first, peak, _ = start_and_interrupt(binary, env, sweep, out, False, "batch")
        suite_firsts.append(first)
        suite_rss.append(peak)
        out = os.path.join(work, "out")
        shutil.rmtree(out, ignore_errors=True)
        first, peak, _ = start_and_interrupt(binary, env, sweep, out, False)
        firsts.append(first)
        rss.append(peak)
        with open(os.path.join(out, "results.csv")) as f:
            done = sum(1 for _ in f) - 1
        _, _, stdout = start_and_interrupt(binary, env, sweep, out, True)
        if done > 0 and "resuming: %d of %d runs already done" % (done, files * SEEDS) not in stdout:
            raise BenchError("--resume after SIGINT: no 'resuming: %d of %d' line in %r" % (done, files * SEEDS,
                                                                                             stdout[:300]))
    return (firsts, rss), (suite_firsts, suite_rss), files * SEEDS


def report(sweep, suite, total):
    print("\n== a suite of %d scenario files (batch FOLDER), --jobs 1" % (total // SEEDS))
    print("   time to the first run's start  %.3f s (median of %d; %.3f-%.3f)"
          % (statistics.median(suite[0]), len(suite[0]), min(suite[0]), max(suite[0])))
    print("   the parent's peak RSS           %.1f MB (median)" % (statistics.median(suite[1]) / 1024.0))
    firsts, rss = sweep
    print("\n== a sweep of %d runs (%d scenario files x %d seeds), --jobs 1" % (total, total // SEEDS, SEEDS))
    print("   time to the first run's start  %.3f s (median of %d; %.3f-%.3f)"
          % (statistics.median(firsts), len(firsts), min(firsts), max(firsts)))
    print("   the parent's peak RSS           %.1f MB (median)" % (statistics.median(rss) / 1024.0), flush=True)
