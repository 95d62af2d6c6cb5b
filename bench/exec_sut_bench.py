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
Every run must end at the SUMO time of signalsim's own run. Prints medians of wall and CPU time and the
ratio exec ÷ traci of the whole run's wall time (the target: <= 0.2).
"""
import os
import shutil

import report
import scenarios
from measure import BenchError, interleaved, median_cpu, median_wall, run_child

DECIDER = os.path.join(scenarios.ROOT, "examples", "python_decider", "decider.py")


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

    cases = {"exec": signalsim_case(["--set", spec], "exec"), "traci": traci_case,
             "signalsim": signalsim_case([], "signalsim")}
    samples = interleaved(cases, runs, warm_up)
    print("\n== a Python decider in the loop: JSON lines vs a Python TraCI controller")
    print("   %s: %d SUMO steps of %g s, %d run(s) each" % (
        scenarios.shown(scenario_path), scenario.sumo_steps("full"), scenario.step_length, runs))
    labels = {"exec": "signalsim + exec: Python", "traci": "Python TraCI controller", "signalsim": "signalsim alone"}
    for name, taken in samples.items():
        print("   %-25s run wall %s   run CPU %s" % (labels[name], report.fmt_s(median_wall(taken)),
                                                     report.fmt_s(median_cpu(taken))))
    ratio = median_wall(samples["exec"]) / median_wall(samples["traci"])
    print("   exec ÷ TraCI controller, whole run wall: %s (target <= 0.2: %s); CPU: %s" % (
        report.fmt_ratio(ratio), "met" if ratio <= 0.2 else "NOT met",
        report.fmt_ratio(median_cpu(samples["exec"]) / median_cpu(samples["traci"]))))
    return ratio
