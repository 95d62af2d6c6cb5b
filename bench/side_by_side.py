"""One scenario, several contestants, interleaved: the sumo binary alone, signalsim, the Python TraCI
controller, each for the full run and for its start-up (a one-step run of the same scenario), and SUMO
in-process (bench/sumo_steps) for SUMO's own step.

Two per-step costs:
  whole runs   (median CPU of the full run - median CPU of the start-up run) / (SUMO steps of the full
               run - SUMO steps of the start-up): anything a step costs, outputs included, but a small
               difference of two large numbers when the start-up dominates
  in-process   signalsim under the step clock (bench/step_clock.cpp, LD_PRELOAD): its CPU time from
               the end of step 100 (scenarios.CLOCK_FROM) to SUMO's close, over those steps (the
               outputs are written after close); bench/sumo_steps: the CPU time of the same steps
  SUMO's share signalsim's full run again with the step clock's split (SIGNALSIM_STEP_CLOCK_SPLIT=1):
               the wall time inside Simulation::step over the wall time of those steps, the share of
               signalsim's step that is SUMO's own step (as signalsim drives the ego); the split's clock
               reads are left out of signalsim's step, which comes from the runs without it
Every run is checked to end at the SUMO time signalsim's run ends at (scenarios.py).
"""
import os
import shutil
import statistics

from measure import interleaved, median_cpu, median_wall, run_child

CONTESTANTS = {"sumo": "sumo binary alone", "signalsim": "signalsim run", "python": "Python TraCI controller",
               "libsumo": "SUMO in-process"}
STEP_CLOCK, SUMO_STEPS = "libsignalsim_step_clock.so", "sumo_steps"  # in bench/ of the build
SIDE_BY_SIDE = {"sumo": ("full", "startup"), "signalsim": ("full", "startup"), "python": ("full", "startup"),
                "libsumo": ("full",)}
# Ego only, where SUMO's step is a small part: also the split runs.
EGO_SIDE_BY_SIDE = dict(SIDE_BY_SIDE, signalsim=("full", "startup", "split"))


def _case(scenario, contestant, variant, binary, env, bench_dir):
    work = scenario.work
    if contestant == "signalsim":
        step_clock = os.path.join(bench_dir, STEP_CLOCK) if bench_dir else None
        clock = os.path.join(work, "step_clock_%s.json" % variant) if step_clock else None
        run_variant = "startup" if variant == "startup" else "full"  # the split is a full run
        run_env = dict(env, LD_PRELOAD=step_clock, SIGNALSIM_STEP_CLOCK=clock,
                       SIGNALSIM_STEP_CLOCK_FROM=str(scenario.clock_from() if run_variant == "full" else 1),
                       SIGNALSIM_STEP_CLOCK_SPLIT="1" if variant == "split" else "0") \
            if step_clock else env

        def case():
            out = os.path.join(work, "signalsim_" + variant)
            shutil.rmtree(out, ignore_errors=True)
            if clock and os.path.exists(clock):
                os.remove(clock)
            sample = run_child(scenario.signalsim_argv(binary, run_variant, out), env=run_env, ok_codes=(0, 1))
            sample.result = scenario.check_signalsim(run_variant, out, clock)
            return sample
    elif contestant == "sumo":
        def case():
            log = os.path.join(work, "sumo_%s.log" % variant)
            sample = run_child(scenario.sumo_argv(variant, log), env=env)
            scenario.check_sumo(variant, log)
            return sample
    elif contestant == "libsumo":
        argv = scenario.sumo_steps_argv(os.path.join(bench_dir, SUMO_STEPS), variant)

        def case():
            sample = run_child(argv, env=env, capture=True)
            sample.result = scenario.check_sumo_steps(sample.stdout, variant)
            return sample
    else:
        argv = scenario.controller_argv(variant)

        def case():
            sample = run_child(argv, env=env, capture=True)
            sample.result = scenario.check_controller(variant, sample.stdout)
            return sample
    return case


def _median_of(samples, figure):
    values = [figure(s.result) for s in samples if getattr(s, "result", None)]
    return statistics.median(values) if values else None


class Measured:
    """One contestant's medians on one scenario (None where that contestant did not measure it)."""

    def __init__(self, name, samples, scenario):
        full, startup = samples.get("full"), samples.get("startup")
        steps_full = scenario.sumo_steps("full")
        self.name = name
        self.run_cpu = median_cpu(full) if full else None
        self.run_wall = median_wall(full) if full else None
        # (max - min) / median of the full runs' CPU: how much the machine's other work moved them
        self.run_spread = (max(s.cpu for s in full) - min(s.cpu for s in full)) / self.run_cpu if full else None
        self.startup_cpu = median_cpu(startup) if startup else None
        self.step_cpu = None  # from whole runs
        if full and startup:
            self.step_cpu = (self.run_cpu - self.startup_cpu) / (steps_full - scenario.sumo_steps("startup"))
        self.step_cpu_in_process = None
        self.ego_steps = None
        self.sumo_share = None  # of signalsim's step, SUMO's own step (the split runs)
        if name == "signalsim" and full:
            self.step_cpu_in_process = _median_of(
                full, lambda r: (r["close_cpu"] - r["from_cpu"]) / (r["step_calls"] - r["from"]))
        if name == "signalsim" and samples.get("split"):
            self.sumo_share = _median_of(
                samples["split"], lambda r: r["in_step_wall"] / (r["close_wall"] - r["from_wall"]))
        elif name == "libsumo" and full:
            self.step_cpu_in_process = _median_of(full, lambda r: r["step_cpu"] / r["steps"])
        if name == "libsumo":
            # Its start-up: the whole process of a one-step run when measured (closing SUMO and
            # exiting included, as for the others), else the CPU until SUMO had loaded.
            self.startup_cpu = median_cpu(startup) if startup else _median_of(full, lambda r: r["load_cpu"])
        elif name == "python" and full:
            self.ego_steps = full[-1].result["ego_steps"]
        self.runs = len(full or startup)

    def step(self):
        """The per-step cost: in-process when measured, else from whole runs."""
        return self.step_cpu_in_process if self.step_cpu_in_process is not None else self.step_cpu

    def sumo_part(self):
        """Of signalsim's in-process step, SUMO's own step (None unless split runs measured it)."""
        if self.sumo_share is None or self.step_cpu_in_process is None:
            return None
        return self.sumo_share * self.step_cpu_in_process


def compare(scenario, plan, binary, env, runs, warm_up, bench_dir=None):
    """Calibrates the scenario on signalsim (unless done), then runs every (contestant, variant) of
    `plan` interleaved (without bench_dir, the build's bench/ folder, no in-process figures and no
    SUMO in-process); returns {contestant: Measured}."""
    if not bench_dir:
        plan = {c: tuple(v for v in variants if v != "split") for c, variants in plan.items() if c != "libsumo"}
    if not scenario.runs:
        scenario.calibrate(binary, env)
    cases = {}
    for contestant, variants in plan.items():
        for variant in variants:
            cases[(contestant, variant)] = _case(scenario, contestant, variant, binary, env, bench_dir)
    samples = interleaved(cases, runs, warm_up)
    by_contestant = {}
    for (contestant, variant), taken in samples.items():
        by_contestant.setdefault(contestant, {})[variant] = taken
    return {c: Measured(c, by_contestant[c], scenario) for c in plan}


def ratio(a, b):
    if a is None or b is None or b <= 0:
        return None
    return a / b
