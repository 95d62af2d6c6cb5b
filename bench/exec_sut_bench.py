"""tools/bench --only exec: a Python decider in the loop through JSON lines against the same kind of
Python logic as a TraCI controller (docs/performance.md "A Python decider in the loop").

On one ego-only scenario, interleaved and repeated, whole runs:
  exec       `signalsim run --set decider=exec:/usr/bin/python3 examples/python_decider/decider.py`:
             signalsim drives SUMO in-process, the Python decider (docs/behaviour.md §T4 in Python, the
             route read once from hello) answers one JSON line per step
  traci      bench/traci_controller.py: a Python TraCI controller driving a sumo binary, doing per step
             what a planning script written in Python would (its queries, a blinker from the turn ahead,
             a speed), as in the `ego` benchmark
  signalsim  signalsim alone (its own decider), for scale
and, as a suite runs, `signalsim batch --jobs 1` over BATCH_COPIES copies of the scenario, with the
Python decider and alone: the wall time per run (one worker keeps libsumo loaded from run to run; each
run starts its own Python decider). Every run must end at the SUMO time of signalsim's own run. Prints
medians of wall and CPU time and the ratios exec ÷ traci of a run's wall time (the target: <= 0.2),
one `signalsim run` and per run of a batch.
"""
import csv
import os
import shutil

import yaml

import report
import scenarios
from measure import BenchError, interleaved, median_cpu, median_wall, run_child

DECIDER = os.path.join(scenarios.ROOT, "examples", "python_decider", "decider.py")
BATCH_COPIES = 12


def write_copies(scenario_path, folder):
    """BATCH_COPIES copies of the scenario in `folder`, their files named by absolute paths."""
    with open(scenario_path) as f:
        data = yaml.safe_load(f)
    here = os.path.dirname(os.path.abspath(scenario_path))
    data["net"] = os.path.join(here, data["net"])
    data["additional"] = [os.path.join(here, a) for a in data.get("additional", [])]
    if "files" in data.get("params", {}):
        data["params"]["files"] = [os.path.join(here, a) for a in data["params"]["files"]]
    os.makedirs(folder, exist_ok=True)
    for k in range(BATCH_COPIES):
        data["name"] = "copy_%02d" % k
        scenarios.write_yaml(os.path.join(folder, "copy_%02d.yaml" % k), data)


def batch_case(binary, env, folder, out, extra):
    """signalsim batch --jobs 1 over the copies; a Sample per run (wall and CPU divided by the copies)."""
    def case():
        shutil.rmtree(out, ignore_errors=True)
        sample = run_child([binary, "batch", folder, "--out", out, "--jobs", "1", "--quiet"] + extra, env=env,
                           ok_codes=(0, 1))
        with open(os.path.join(out, "results.csv")) as f:
            statuses = [row["status"] for row in csv.DictReader(f)]
        if len(statuses) != BATCH_COPIES or "error" in statuses:
            raise BenchError("signalsim batch %s: statuses %s" % (" ".join(extra), statuses))
        sample.wall /= BATCH_COPIES
        sample.cpu /= BATCH_COPIES
        return sample
    return case


def bench_exec(scenario_path, work, binary, env, runs, warm_up):
    scenario = scenarios.BenchScenario("exec", scenario_path, work)
    scenario.calibrate(binary, env)
    spec = "decider=exec:%s %s" % (scenarios.DEBIAN_PYTHON, DECIDER)

    def signalsim_case(extra, name):
        def case():
            out = os.path.join(work, name)
            shutil.rmtree(out, ignore_errors=True)
            sample = run_child(scenario.signalsim_argv(binary, "full", out) + extra, env=env, ok_codes=(0, 1))
            scenario.check_signalsim("full", out)
            if extra and not os.path.exists(os.path.join(out, "decider.stderr.txt")):
                raise BenchError("signalsim run with %s: no decider ran" % spec)
            return sample
        return case

    controller = scenario.controller_argv("full")

    def traci_case():
        sample = run_child(controller, env=env, capture=True)
        scenario.check_controller("full", sample.stdout)
        return sample

    copies = os.path.join(work, "copies")
    write_copies(scenario_path, copies)
    cases = {"exec": signalsim_case(["--set", spec], "exec"), "traci": traci_case,
             "signalsim": signalsim_case([], "signalsim"),
             "batch_exec": batch_case(binary, env, copies, os.path.join(work, "batch_exec"), ["--set", spec]),
             "batch_signalsim": batch_case(binary, env, copies, os.path.join(work, "batch_signalsim"), [])}
    samples = interleaved(cases, runs, warm_up)
    print("\n== a Python decider in the loop: JSON lines vs a Python TraCI controller")
    print("   %s: %d SUMO steps of %g s, %d run(s) each" % (
        scenarios.shown(scenario_path), scenario.sumo_steps("full"), scenario.step_length, runs))
    labels = {"exec": "signalsim + exec: Python", "traci": "Python TraCI controller", "signalsim": "signalsim alone",
              "batch_exec": "batch, + exec: Python", "batch_signalsim": "batch, signalsim alone"}
    for name, taken in samples.items():
        print("   %-25s %s wall %s   %s CPU %s" % (labels[name], "run", report.fmt_s(median_wall(taken)), "run",
                                                  report.fmt_s(median_cpu(taken))))
    print("   (batch: per run of `signalsim batch --jobs 1` over %d copies)" % BATCH_COPIES)
    ratio = median_wall(samples["exec"]) / median_wall(samples["traci"])
    batch_ratio = median_wall(samples["batch_exec"]) / median_wall(samples["traci"])
    print("   exec ÷ TraCI controller, wall (target <= 0.2): one `signalsim run` %s (%s), per run of a batch %s (%s); "
          "CPU: %s, %s" % (report.fmt_ratio(ratio), "met" if ratio <= 0.2 else "NOT met", report.fmt_ratio(batch_ratio),
                           "met" if batch_ratio <= 0.2 else "NOT met",
                           report.fmt_ratio(median_cpu(samples["exec"]) / median_cpu(samples["traci"])),
                           report.fmt_ratio(median_cpu(samples["batch_exec"]) / median_cpu(samples["traci"]))))
    return ratio
