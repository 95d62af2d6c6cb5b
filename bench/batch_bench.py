"""Batch throughput over the bundled suite: `signalsim batch` with --jobs 1 and --jobs 2, and for scale
what a run in a process of its own pays before its steps: a one-step `signalsim run` of the suite's
first scenario (the program, libsumo's module, the net, SUMO's load, the ego), interleaved. (A no-op
`signalsim countries` served until libsumo was loaded on first use: it no longer loads it.)

runs/s is the suite's run count over the batch's median wall time; CPU per run is the batch's median
CPU (the command and every worker it waited for) over the run count. The load average is read before
and after, since --jobs 2 can only be twice as fast with two idle cores.
"""
import csv
import glob
import os
import shutil

from measure import BenchError, interleaved, median_cpu, median_wall, run_child

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
QUICK_SUITE = 6  # scenarios of the suite a --quick batch runs (the first, by name)


class BatchMeasured:
    def __init__(self, runs, samples):
        self.runs = runs
        self.cpu = median_cpu(samples)
        self.wall = median_wall(samples)
        self.runs_per_s = runs / self.wall
        self.cpu_per_run = self.cpu / runs


def suite_files(quick):
    files = sorted(glob.glob(os.path.join(ROOT, "scenarios", "*.yaml")))
    return files[:QUICK_SUITE] if quick else files


def bench_batch(binary, env, work, runs, warm_up, quick):
    """Returns ({1: BatchMeasured, 2: BatchMeasured}, one-step run CPU median, its wall median, load before,
    after)."""
    files = suite_files(quick)

    def batch(jobs):
        def case():
            out = os.path.join(work, "batch_jobs%d" % jobs)
            shutil.rmtree(out, ignore_errors=True)
            sample = run_child([binary, "batch"] + files + ["--out", out, "--jobs", str(jobs), "--quiet"], env=env,
                               ok_codes=(0, 1))
            with open(os.path.join(out, "results.csv")) as f:
                rows = list(csv.DictReader(f))
            errors = [r["scenario"] for r in rows if r["status"] == "error"]
            if len(rows) != len(files) or errors:
                raise BenchError("signalsim batch --jobs %d: %d rows for %d scenarios, errors: %s"
                                 % (jobs, len(rows), len(files), ", ".join(errors) or "none"))
            return sample
        return case

    def noop():
        out = os.path.join(work, "one_step")
        shutil.rmtree(out, ignore_errors=True)
        return run_child([binary, "run", files[0], "--out", out, "--quiet", "--set", "duration=0.1"], env=env,
                         ok_codes=(0, 1))

    load_before = os.getloadavg()
    samples = interleaved({"jobs1": batch(1), "jobs2": batch(2), "noop": noop}, runs, warm_up)
    load_after = os.getloadavg()
    measured = {1: BatchMeasured(len(files), samples["jobs1"]), 2: BatchMeasured(len(files), samples["jobs2"])}
    return measured, median_cpu(samples["noop"]), median_wall(samples["noop"]), load_before, load_after
