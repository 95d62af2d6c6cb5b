"""Fleet mode's cost (docs/fleet.md, docs/performance.md "Fleet mode"): `tools/bench --only fleet`.

For each SUMO configuration (a real net with its demand: the bundled bologna/acosta by default, more
with --fleet-sumocfg PATH), three contestants on the same inputs, interleaved:
  sumo       the sumo binary alone: `sumo -c CFG --end D` (the demand, no ego)
  plain      `signalsim run` of a scenario on CFG for D seconds: an ego signalsim adds on an edge no
             vehicle of the demand uses, so slow that it lasts the whole run and meets nobody
  fleet      the same with --fleet: every vehicle of the demand gets its blinker from the decider
Figures: CPU time (user + sys of the child) and peak RSS (the child's own, os.wait4), medians;
fleet's own cost = fleet - plain; per vehicle-step = that over summary.json `fleet.vehicle_steps`,
against SUMO's per vehicle-step (sumo's CPU over the same vehicle-steps: the same denominator, so the
ratio is (fleet - plain) / sumo); the whole fleet run against SUMO alone; fleet's memory (fleet - plain
peak RSS) against `fleet.routes.distinct` and `fleet.vehicles.followed`, at two durations.
"""
import json
import os
import shutil
import statistics
import subprocess
import time
import xml.etree.ElementTree as ET

from measure import BenchError, interleaved

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ACOSTA = os.path.join(ROOT, "sumo_nets", "bologna_acosta", "acosta.sumocfg")
STEP_LENGTH = 0.1  # [s] both contestants' (a sumocfg without step-length would give sumo 1 s)


class Run:
    def __init__(self, cpu, wall, rss_kib):
        self.cpu, self.wall, self.rss_kib = cpu, wall, rss_kib
        self.result = None


def run_measured(argv, env, cwd=None, ok_codes=(0, 1)):
    """Runs argv to its end; its own CPU time, wall time and peak RSS (os.wait4: this child only)."""
    start = time.perf_counter()
    process = subprocess.Popen(argv, env=env, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    stderr = process.stderr.read()
    process.stderr.close()
    code = os.waitstatus_to_exitcode(status)
    process.returncode = code
    if code not in ok_codes:
        last = (stderr.strip().splitlines() or ["(no message)"])[-1]
        raise BenchError("%s: exit code %d: %s" % (" ".join(argv[:3]), code, last))
    return Run(usage.ru_utime + usage.ru_stime, wall, usage.ru_maxrss)


def _files(cfg, section_names):
    """The files a sumocfg names under `section_names` (net-file, route-files, ...), absolute."""
    root = ET.parse(cfg).getroot()
    base = os.path.dirname(os.path.abspath(cfg))
    out = []
    for element in root.iter():
        if element.tag in section_names and element.get("value"):
            out += [os.path.join(base, f.strip()) for f in element.get("value").split(",") if f.strip()]
    return out


def quiet_edge(cfg):
    """An edge no route of the demand uses, that a passenger car may drive, at least 60 m long: the
    ego's, so that it meets nobody. Returns (edge, length)."""
    used = set()
    for routes in _files(cfg, ("route-files", "additional-files")):
        for _, element in ET.iterparse(routes):
            if element.tag == "route" and element.get("edges"):
                used.update(element.get("edges").split())
            element.clear()
    net = _files(cfg, ("net-file",))[0]
    best = None
    for _, edge in ET.iterparse(net):
        if edge.tag != "edge" or edge.get("function") == "internal" or edge.get("id") in used:
            continue
        lanes = [lane for lane in edge.iter("lane")
                 if "passenger" not in (lane.get("disallow") or "") and
                 (lane.get("allow") is None or "passenger" in lane.get("allow"))]
        if lanes and float(lanes[0].get("length")) >= 60.0:
            length = float(lanes[0].get("length"))
            if best is None or length > best[1]:
                best = (edge.get("id"), length)
        edge.clear()
    if best is None:
        raise BenchError("%s: no edge of 60 m or more that no route uses (for the ego)" % cfg)
    return best


def write_scenario(work, cfg, duration):
    edge, length = quiet_edge(cfg)
    speed = max(0.1, round(0.7 * length / duration, 2))  # never arrives within the duration
    path = os.path.join(work, "fleet_bench.yaml")
    with open(path, "w") as f:
        f.write("# tools/bench --only fleet: the demand of %s; an ego on edge %s (%.0f m, used by no route)\n"
                "# at %.2f m/s, so that it lasts the run and meets nobody.\n"
                "name: fleet_bench\nsumocfg: %s\nstep_length: %g\nduration: %g\nego:\n  route: ['%s']\n  max_speed: %g\n"
                % (cfg, edge, length, speed, os.path.abspath(cfg), STEP_LENGTH, duration, edge, speed))
    return path


def measure_config(cfg, duration, binary, env, runs, warm_up, work):
    os.makedirs(work, exist_ok=True)
    scenario = write_scenario(work, cfg, duration)
    # SUMO alone: the configuration's own outputs and log go to the scratch folder.
    sumo_argv = ["sumo", "-c", os.path.abspath(cfg), "--end", "%g" % duration, "--step-length", "%g" % STEP_LENGTH,
                 "--no-step-log", "true",
                 "--tripinfo-output", os.path.join(work, "sumo_tripinfo.xml"),
                 "--log", os.path.join(work, "sumo_alone.log")]

    def signalsim(fleet):
        def case():
            out = os.path.join(work, "fleet" if fleet else "plain")
            shutil.rmtree(out, ignore_errors=True)
            run = run_measured([binary, "run", scenario, "--out", out, "--quiet"] + (["--fleet"] if fleet else []), env)
            summary = json.load(open(os.path.join(out, "summary.json")))
            end = summary["counts"]["end_time"]
            if abs(end - duration) > 0.5:
                raise BenchError("%s: signalsim's run ended at %.1f s, not %g s" % (cfg, end, duration))
            run.result = summary.get("fleet")
            return run
        return case

    cases = {"sumo": lambda: run_measured(sumo_argv, env, cwd=work, ok_codes=(0,)),
             "plain": signalsim(False), "fleet": signalsim(True)}
    samples = interleaved(cases, runs, warm_up)
    cpu = {k: statistics.median(s.cpu for s in v) for k, v in samples.items()}
    wall = {k: statistics.median(s.wall for s in v) for k, v in samples.items()}
    rss = {k: statistics.median(s.rss_kib for s in v) for k, v in samples.items()}
    fleet = samples["fleet"][-1].result
    return {"cfg": cfg, "duration": duration, "cpu": cpu, "wall": wall, "rss_kib": rss,
            "vehicle_steps": fleet["vehicle_steps"], "followed": fleet["vehicles"]["followed"],
            "left_to_sumo": fleet["vehicles"]["left_to_sumo"], "distinct_routes": fleet["routes"]["distinct"],
            "signals_on": fleet["signals"]["on"]}


def report(rows):
    print("\nfleet mode (docs/fleet.md): medians of CPU s (user + sys), peak RSS MiB")
    print("%-34s %6s %8s %7s %7s %7s %9s %8s %8s %7s %7s" % (
        "configuration", "sim s", "veh-steps", "routes", "sumo", "plain", "fleet", "own/vs", "fleet/", "rss+", "rss+/"))
    print("%-34s %6s %8s %7s %7s %7s %9s %8s %8s %7s %7s" % (
        "", "", "", "", "cpu", "cpu", "cpu", "sumo/vs", "sumo", "MiB", "route KiB"))
    for r in rows:
        own = r["cpu"]["fleet"] - r["cpu"]["plain"]
        rss_delta = (r["rss_kib"]["fleet"] - r["rss_kib"]["plain"]) / 1024.0
        name = os.path.relpath(r["cfg"], ROOT) if r["cfg"].startswith(ROOT) else r["cfg"]
        print("%-34s %6g %8d %7d %7.2f %7.2f %9.2f %8.3f %8.2f %7.1f %7.1f" % (
            name[-34:], r["duration"], r["vehicle_steps"], r["distinct_routes"], r["cpu"]["sumo"], r["cpu"]["plain"],
            r["cpu"]["fleet"], own / r["cpu"]["sumo"], r["cpu"]["fleet"] / r["cpu"]["sumo"], rss_delta,
            rss_delta * 1024.0 / max(1, r["distinct_routes"])))
        print("   fleet's own cost %.2f us per vehicle-step, SUMO's %.2f us; %d vehicles followed, %d left to SUMO, "
              "%d blinker episodes; wall s: sumo %.2f, plain %.2f, fleet %.2f" % (
                  own / r["vehicle_steps"] * 1e6, r["cpu"]["sumo"] / r["vehicle_steps"] * 1e6, r["followed"],
                  r["left_to_sumo"], r["signals_on"], r["wall"]["sumo"], r["wall"]["plain"], r["wall"]["fleet"]))
    print("   targets: own/vs sumo <= 0.1 (per vehicle-step), fleet/sumo <= 1.3 (whole run); "
          "rss+ grows with routes, not with vehicles x route length")


def bench_fleet(configs, durations, binary, env, runs, warm_up, work):
    rows = []
    for n, cfg in enumerate(configs):
        for duration in durations:
            rows.append(measure_config(cfg, duration, binary, env, runs, warm_up,
                                       os.path.join(work, "fleet%d_%g" % (n, duration))))
    report(rows)
    return rows
