"""How tools/bench measures a process: CPU and wall time of one child, interleaved rounds, medians.

CPU time is user + sys of the child and every descendant it waited for (a batch's workers, the sumo a
Python controller started), read as the difference of getrusage(RUSAGE_CHILDREN) around it; children
run one at a time, so the difference is that child's. Wall time is time.perf_counter around it.
"""
import os
import resource
import statistics
import subprocess
import time


class BenchError(Exception):
    """A benchmark that cannot give a valid number: one line for the user, exit 1."""


class Sample:
    def __init__(self, cpu, wall, stdout):
        self.cpu = cpu
        self.wall = wall
        self.stdout = stdout


def children_cpu():
    """User + sys seconds of every child waited for so far."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run_child(argv, env=None, ok_codes=(0,), capture=False, cwd=None):
    """Runs argv to its end; returns a Sample. An exit code outside ok_codes is a BenchError."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    result = subprocess.run(argv, env=env, cwd=cwd, stdout=subprocess.PIPE if capture else subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode not in ok_codes:
        last = (result.stderr.strip().splitlines() or ["(no message)"])[-1]
        raise BenchError("%s: exit code %d: %s" % (" ".join(argv[:3]), result.returncode, last))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return Sample(cpu, wall, result.stdout if capture else "")


def interleaved(cases, runs, warm_up=True):
    """Runs every case once per round, `runs` rounds (after one warm-up round unless warm_up is False),
    the order rotated from round to round so that no case always follows the same one. `cases` maps a
    name to a function returning a Sample (it checks its own result). Returns name -> [Sample]."""
    names = list(cases)
    samples = {name: [] for name in names}
    for round_number in range(runs + (1 if warm_up else 0)):
        shift = round_number % len(names)
        for name in names[shift:] + names[:shift]:
            sample = cases[name]()
            if round_number > 0 or not warm_up:
                samples[name].append(sample)
    return samples


def median_cpu(samples):
    return statistics.median(s.cpu for s in samples)


def median_wall(samples):
    return statistics.median(s.wall for s in samples)


def load_average():
    return os.getloadavg()
