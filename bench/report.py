"""What tools/bench prints: a table per benchmark, then the performance targets' ratios with the measured
value beside each (docs/performance.md). Values are medians; a ratio is of medians; "-" where a
contestant does not measure that column; "spread" is (max - min) / median of the full runs' CPU.
"""
from scenarios import shown
from side_by_side import CONTESTANTS, ratio

# The bundled suite's CPU per run with one process per run (the 2-core development machine; 0.111 to
# 0.119 s in five calls at load 3 to 9). The target "5x the runs/s of one process per run" is judged on
# it as CPU per run <= 1/5 of it, because runs/s follow the machine's load and the CPU per run hardly
# does (docs/performance.md).
BASELINE_CPU_PER_RUN = 0.113


def fmt_s(seconds):
    return "-" if seconds is None else "%.3f s" % seconds


def fmt_us(seconds):
    return "-" if seconds is None else "%.1f µs" % (seconds * 1e6)


def fmt_ratio(value):
    if value is None:
        return "-"
    return "%.2f" % value if abs(value) < 10 else "%.0f" % value


def side_by_side_table(title, scenario, measured):
    print("\n== %s" % title)
    print("   %s: %d SUMO steps of %g s (the start-up: a run of %d), ego route %d edges%s" % (
        shown(scenario.path), scenario.sumo_steps("full"), scenario.step_length, scenario.sumo_steps("startup"),
        len(scenario.ego["route"]), "; vehicles in the net while the ego drives: mean %.0f, max %d" % scenario.vehicles
        if scenario.vehicles else ""))
    header = ("contestant", "run CPU", "spread", "run wall", "start-up CPU", "step, whole", "step, in-proc",
              "run÷sumo")
    print("   %-25s %9s %7s %9s %13s %12s %14s %9s" % header)
    base = measured.get("sumo")
    for name, m in measured.items():
        print("   %-25s %9s %7s %9s %13s %12s %14s %9s" % (
            CONTESTANTS[name], fmt_s(m.run_cpu), "%.0f %%" % (100 * m.run_spread), fmt_s(m.run_wall),
            fmt_s(m.startup_cpu), fmt_us(m.step_cpu), fmt_us(m.step_cpu_in_process),
            fmt_ratio(ratio(m.run_cpu, base.run_cpu)) if base else "-"))
    s, sumo_step = measured.get("signalsim"), measured.get("libsumo") or measured.get("sumo")
    if s and sumo_step:
        print("   signalsim's step ÷ SUMO's: %s (in-process), %s (whole runs)" % (
            fmt_ratio(ratio(s.step(), sumo_step.step())),
            fmt_ratio(ratio(s.step_cpu, measured["sumo"].step_cpu)) if "sumo" in measured else "-"))
    if s and s.sumo_part() is not None and sumo_step:
        print("   inside signalsim's step: SUMO's step %s (%s× SUMO's alone), the rest %s: signalsim's calls to "
              "libsumo and its own work (split runs: SUMO %.0f %% of the step)" % (
                  fmt_us(s.sumo_part()), fmt_ratio(ratio(s.sumo_part(), sumo_step.step())),
                  fmt_us(s.step() - s.sumo_part()), 100 * s.sumo_share))
    if "python" in measured and s:
        p = measured["python"]
        print("   Python ÷ signalsim: whole run %s, per step %s (its step from whole runs ÷ signalsim's in-process; "
              "the controller's ego was in the net %s of %d steps)" % (
                  fmt_ratio(ratio(p.run_cpu, s.run_cpu)), fmt_ratio(ratio(p.step_cpu, s.step())), p.ego_steps,
                  scenario.runs["full"]["steps"]))


def net_size_table(small, big):
    (small_scenario, small_m), (_big_scenario, big_m) = small, big
    print("\n== net size: the same %d-edge route (%d SUMO steps) on two netgenerate grids" % (
        len(small_scenario.ego["route"]), small_scenario.sumo_steps("full")))
    print("   %-30s %-27s %13s %14s" % ("net", "contestant", "start-up CPU", "step, in-proc"))
    for scenario, measured in (small, big):
        for name, m in measured.items():
            print("   %-30s %-27s %13s %14s" % (scenario.label, CONTESTANTS[name], fmt_s(m.startup_cpu),
                                              fmt_us(m.step_cpu_in_process)))
    for scenario, measured in (small, big):
        load = measured["sumo"].startup_cpu
        own, embedded = own_startup(measured), own_startup(measured, "sumo")
        print("   %s: signalsim's own start-up (its one-step run - SUMO in-process's) %s = %s of SUMO's load "
              "(the sumo binary's one-step run, %s)" % (scenario.label, fmt_s(own), fmt_ratio(ratio(own, load)),
                                                       fmt_s(load)))
        print("   %s  with SUMO's load in libsumocpp (signalsim's one-step run - the sumo binary's) %s = %s" % (
            " " * len(scenario.label), fmt_s(embedded), fmt_ratio(ratio(embedded, load))))
    print("   per step, big net ÷ small net: signalsim %s, SUMO in-process %s" % (
        fmt_ratio(ratio(big_m["signalsim"].step(), small_m["signalsim"].step())),
        fmt_ratio(ratio(big_m["libsumo"].step(), small_m["libsumo"].step())) if "libsumo" in big_m else "-"))
    if "libsumo" in big_m:
        own = [m["signalsim"].step() - m["libsumo"].step() for m in (small_m, big_m)]
        print("   signalsim's own part of a step (its step - SUMO's): %s on the small net, %s on the big one (%s)" % (
            fmt_us(own[0]), fmt_us(own[1]), fmt_ratio(ratio(own[1], own[0]))))


def own_startup(measured, against="libsumo"):
    """signalsim's one-step run - SUMO's: SUMO in-process's (the same library, loading the same net:
    what signalsim itself adds), or the sumo binary's (SUMO's load in libsumocpp.so included)."""
    s = measured["signalsim"].startup_cpu
    sumo = measured[against].startup_cpu if against in measured else None
    return None if s is None or sumo is None else s - sumo


def batch_table(batch, noop_cpu, noop_wall, load_before, load_after):
    print("\n== batch: the bundled suite, %d scenarios, `signalsim batch --jobs N`" % batch[1].runs)
    for jobs in (1, 2):
        b = batch[jobs]
        print("   --jobs %d: %5.2f runs/s (%s wall), %s CPU per run (%s for the batch)" % (
            jobs, b.runs_per_s, fmt_s(b.wall), fmt_s(b.cpu_per_run), fmt_s(b.cpu)))
    print("   one one-step `signalsim run` (a run's start in a process of its own): %s CPU, %s wall" % (
        fmt_s(noop_cpu), fmt_s(noop_wall)))
    print("   load average before %s, after %s" % (" ".join("%.2f" % x for x in load_before),
                                                   " ".join("%.2f" % x for x in load_after)))


def targets(results, quick):
    """results: what was measured (keys ego, traffic, batch, netsize); prints the target lines."""
    rows = []

    def add(what, value, goal, met):
        rows.append((what, fmt_ratio(value) if value is not None else "not measured", goal,
                     "" if value is None or met is None else ("met" if met(value) else "NOT MET")))

    batch, traffic, ego, sizes = (results.get(k) for k in ("batch", "traffic", "ego", "netsize"))
    small, big = (sizes[0][1], sizes[1][1]) if sizes else (None, None)
    add("batch CPU per run ÷ one one-step signalsim run",
        ratio(batch["measured"][1].cpu_per_run, batch["noop_cpu"]) if batch else None, "≤ 0.30", lambda v: v <= 0.30)
    add("with traffic: signalsim ÷ sumo binary, whole run",
        ratio(traffic["signalsim"].run_cpu, traffic["sumo"].run_cpu) if traffic else None, "≤ 1.05",
        lambda v: v <= 1.05)
    add("ego only: signalsim's step ÷ SUMO's step (in-process)",
        ratio(ego["signalsim"].step(), (ego.get("libsumo") or ego["sumo"]).step()) if ego else None, "≤ 1.5",
        lambda v: v <= 1.5)
    add("  SUMO's step inside signalsim's run ÷ SUMO's alone (the floor)",
        ratio(ego["signalsim"].sumo_part(), (ego.get("libsumo") or ego["sumo"]).step()) if ego else None,
        "(for reference)", None)
    add("ego only: Python TraCI step ÷ signalsim's step",
        ratio(ego["python"].step_cpu, ego["signalsim"].step()) if ego else None, "≥ 50", lambda v: v >= 50)
    add("--jobs 2 ÷ --jobs 1 runs/s" + (" (load %.1f at the start)" % batch["load_before"][0] if batch else ""),
        ratio(batch["measured"][2].runs_per_s, batch["measured"][1].runs_per_s) if batch else None, "≥ 1.8",
        lambda v: v >= 1.8)
    add("suite CPU per run (--jobs 2) ÷ %.3f s (one process per run)" % BASELINE_CPU_PER_RUN,
        batch["measured"][2].cpu_per_run / BASELINE_CPU_PER_RUN if batch and not quick else None, "≤ 0.20",
        lambda v: v <= 0.20)
    add("per step flat: signalsim's step, big net ÷ small net",
        ratio(big["signalsim"].step(), small["signalsim"].step()) if sizes else None, "0.90 to 1.10",
        lambda v: 0.9 <= v <= 1.1)
    add("signalsim's own start-up on the big net ÷ SUMO's load",
        ratio(own_startup(big), big["sumo"].startup_cpu) if sizes else None, "≤ 0.10", lambda v: v <= 0.10)
    add("  the same with SUMO's load in libsumocpp counted as signalsim's",
        ratio(own_startup(big, "sumo"), big["sumo"].startup_cpu) if sizes else None, "(for reference)", None)
    print("\n== targets: CPU-time ratios of medians%s" % (
        " (--quick: small sizes, one run; not the targets' numbers)" if quick else ""))
    print("   %-62s %12s  %-13s" % ("target", "measured", "goal"))
    for what, value, goal, verdict in rows:
        print("   %-62s %12s  %-13s %s" % (what, value, goal, verdict))
