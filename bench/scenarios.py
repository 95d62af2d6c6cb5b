"""The scenarios tools/bench compares on, and the same run for each contestant.

A BenchScenario is a signalsim scenario file plus what the other contestants need to run the same
simulation: the SUMO inputs (net, route files, additional files, step length, seed, resolved from the
scenario file), the ego as signalsim's own run used it (summary.json `ego`, `route`) and the end of
that run. `calibrate` runs signalsim once for the full run and once for its start-up (a one-step
run, `--set duration=STEP`); every later run of every contestant must end at the same SUMO time.

  the sumo binary alone   the ego as a plain vehicle of a generated ego.rou.xml (same vType values,
                          route, departure), `--end` at signalsim's end, SUMO options as signalsim sets
                          them (session/sumo_command_line.cpp), its log read for "Simulation ended at time"
  the Python controller   traci_controller.py with a JSON spec: the same sumo command line without
                          the ego's route file (it adds the ego over TraCI, as signalsim does)
  SUMO in-process         bench/sumo_steps: the sumo binary's command line in libsumocpp, the library
                          signalsim embeds, its steps timed inside the process

Made here, reproducibly, in a temporary folder: `traffic_scenario` (bologna_acosta with random trips
of randomTrips.py, fixed seeds) and `grid_scenario` (a netgenerate grid, one route across it).
"""
import json
import os
import re
import subprocess
import xml.etree.ElementTree as ElementTree

import yaml

from measure import BenchError

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SUMO_HOME = "/usr/share/sumo"
RANDOM_TRIPS = os.path.join(SUMO_HOME, "tools", "randomTrips.py")
DEBIAN_PYTHON = "/usr/bin/python3"
ACOSTA = os.path.join(ROOT, "sumo_nets", "bologna_acosta")


def shown(path):
    """A path as printed: relative to the source tree when inside it, else ".../" and its file name (a
    generated file in the temporary folder, another build's binary), so that no folder of the machine
    that measured appears in what is printed (and pasted into docs/performance.md)."""
    if not path:
        return path
    relative = os.path.relpath(os.path.abspath(path), ROOT)
    return ".../" + os.path.basename(os.path.normpath(path)) if relative.startswith("..") else relative
UNSUPPORTED_KEYS = ("sumocfg", "sumo_args", "obstacles", "maneuvers", "light_offsets")
CLOCK_FROM = 100  # steps (10 s at 0.1 s)
END_LINE = re.compile(r"^Simulation ended at time: ([0-9.]+)", re.M)


class BenchScenario:
    def __init__(self, label, path, work):
        self.label = label  # what the table calls it
        self.path = path
        self.work = work  # this scenario's own folder of generated files
        os.makedirs(work, exist_ok=True)
        with open(path) as f:
            data = yaml.safe_load(f)
        bad = [k for k in UNSUPPORTED_KEYS if k in data] + (["ego.id"] if "id" in data.get("ego", {}) else [])
        if bad:
            raise BenchError("%s: %s not supported by the side-by-side benchmark (the sumo binary alone could "
                             "not do the same)" % (path, ", ".join(bad)))
        here = os.path.dirname(os.path.abspath(path))
        self.net = os.path.join(here, data["net"])
        self.routes = [os.path.join(here, f) for f in data.get("routes", [])]
        self.additional = [os.path.join(here, f) for f in data.get("additional", [])]
        self.step_length = float(data.get("step_length", 0.1))
        self.seed = int(data.get("seed", 1))
        self.runs = {}  # variant ("full", "startup") -> {"end": SUMO end time, "steps": signalsim's steps}
        self.ego = None
        self.vehicles = None  # (mean, max) vehicles in the net while the ego drives, when counted

    # -- signalsim ---------------------------------------------------------------------------
    def signalsim_argv(self, binary, variant, out):
        argv = [binary, "run", self.path, "--out", out, "--quiet"]
        return argv + (["--set", "duration=%g" % self.step_length] if variant == "startup" else [])

    def read_summary(self, out):
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        ego = summary["ego"]
        end = ego["depart_time"] + self.step_length * (summary["counts"]["steps"] + 1)  # + the insertion step
        return summary, round(end, 6)

    def calibrate(self, binary, env):
        """One signalsim run of each variant: the ego as used, each variant's end time and steps."""
        for variant in ("full", "startup"):
            out = os.path.join(self.work, "calibrate_" + variant)
            result = subprocess.run(self.signalsim_argv(binary, variant, out), env=env, capture_output=True, text=True)
            if result.returncode not in (0, 1):
                raise BenchError("signalsim run %s: exit code %d: %s" % (self.path, result.returncode,
                                                                         result.stderr.strip()))
            summary, end = self.read_summary(out)
            self.runs[variant] = {"end": end, "steps": summary["counts"]["steps"],
                                  "depart_time": summary["ego"]["depart_time"]}
            if variant == "full":
                if summary["route"]["lane_changes"]:
                    raise BenchError("%s: its route needs lane changes, which signalsim drives with SUMO's "
                                     "sublane model: not supported by the side-by-side benchmark" % self.path)
                e = summary["ego"]
                # decel: SUMO's, the vType's (signalsim plans with its own, e["decel"]).
                self.ego = {"route": summary["route"]["edges"], "length": e["length"], "width": e["width"],
                            "max_speed": e["max_speed"], "accel": e["accel"], "decel": e["type_decel"],
                            "emergency_decel": e["emergency_decel"], "plan_decel": e["decel"],
                            "depart_lane": e["depart_lane"], "depart_pos": e["depart_pos"],
                            "depart_speed": e["depart_speed"]}
        self.write_ego_routes()

    def sumo_steps(self, variant):
        return int(round(self.runs[variant]["end"] / self.step_length))

    def check_signalsim(self, variant, out, clock=None):
        """The run ended where the first did; with the step clock's file, its figures (None without)."""
        _summary, end = self.read_summary(out)
        if abs(end - self.runs[variant]["end"]) > 1e-6:
            raise BenchError("signalsim run %s ended at t=%g, its first run at t=%g (not deterministic?)"
                             % (self.path, end, self.runs[variant]["end"]))
        if clock is None:
            return None
        with open(clock) as f:
            figures = json.load(f)
        if figures["step_calls"] != self.sumo_steps(variant) or figures["from_cpu"] < 0:
            raise BenchError("signalsim run %s: the step clock counted %d steps, SUMO ran %d"
                             % (self.path, figures["step_calls"], self.sumo_steps(variant)))
        return figures

    # -- the sumo binary alone ---------------------------------------------------------------
    def sumo_options(self):
        """SUMO's options as signalsim's embedded back-end sets them for this scenario."""
        options = ["-n", self.net, "--step-length", "%g" % self.step_length, "--seed", str(self.seed),
                   "--collision.action", "warn"]
        if self.routes:
            options += ["-r", ",".join(self.routes)]
        if self.additional:
            options += ["-a", ",".join(self.additional)]
        return options + ["--time-to-teleport", "-1", "--no-step-log", "true", "--duration-log.disable", "true"]

    def write_ego_routes(self):
        e = self.ego
        self.ego_routes = os.path.join(self.work, "ego.rou.xml")
        with open(self.ego_routes, "w") as f:
            f.write('<routes>\n  <vType id="ego_type" length="%r" width="%r" maxSpeed="%r" accel="%r" decel="%r" '
                    'emergencyDecel="%r" sigma="0" speedFactor="1" speedDev="0"/>\n'
                    % (e["length"], e["width"], e["max_speed"], e["accel"], e["decel"], e["emergency_decel"]))
            f.write('  <route id="ego_route" edges="%s"/>\n' % " ".join(e["route"]))
            f.write('  <vehicle id="ego" type="ego_type" route="ego_route" depart="%r" departLane="%d" '
                    'departPos="%r" departSpeed="%r"/>\n</routes>\n'
                    % (self.runs["full"]["depart_time"], e["depart_lane"], e["depart_pos"], e["depart_speed"]))

    def sumo_argv(self, variant, log):
        options = self.sumo_options()
        if self.routes:
            options[options.index("-r") + 1] = self.ego_routes + "," + options[options.index("-r") + 1]
        else:
            options += ["-r", self.ego_routes]
        return ["sumo"] + options + ["--end", "%r" % self.runs[variant]["end"], "--log", log]

    def check_sumo(self, variant, log):
        with open(log) as f:
            ended = END_LINE.search(f.read())
        if not ended or abs(float(ended.group(1)) - self.runs[variant]["end"]) > 1e-6:
            raise BenchError("the sumo binary alone ended at t=%s, signalsim at t=%g (%s)"
                             % (ended.group(1) if ended else "?", self.runs[variant]["end"], log))

    def count_vehicles(self, env):
        """Mean and max vehicles running from the ego's departure to the end (one untimed sumo run)."""
        out = os.path.join(self.work, "vehicles.xml")
        argv = self.sumo_argv("full", os.path.join(self.work, "count.log")) + ["--summary-output", out]
        subprocess.run(argv, env=env, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        start = self.runs["full"]["depart_time"]
        running = [int(step.get("running")) for step in ElementTree.parse(out).getroot()
                   if float(step.get("time")) >= start]
        self.vehicles = (sum(running) / len(running), max(running))

    # -- SUMO in-process (bench/sumo_steps) --------------------------------------------------
    def clock_from(self):
        """The steps the in-process clocks leave out at the start (bench/step_clock.cpp says why)."""
        return max(1, min(CLOCK_FROM, self.sumo_steps("full") // 4))

    def sumo_steps_argv(self, binary, variant="full"):
        """The full run: its first clock_from() steps apart; the start-up: one step, then the rest."""
        argv = self.sumo_argv(variant, os.path.join(self.work, "sumo_steps_%s.log" % variant))
        first = str(self.clock_from()) if variant == "full" else "1"
        return [binary, first, "%r" % self.runs[variant]["end"]] + argv[1:]

    def check_sumo_steps(self, stdout, variant="full"):
        result = json.loads(stdout)
        if abs(result["end_time"] - self.runs[variant]["end"]) > 1e-6:
            raise BenchError("SUMO in-process ended at t=%s, signalsim at t=%g" % (result["end_time"],
                                                                                 self.runs[variant]["end"]))
        return result

    # -- the Python TraCI controller ---------------------------------------------------------
    def controller_argv(self, variant):
        spec = os.path.join(self.work, "controller_%s.json" % variant)
        with open(spec, "w") as f:
            json.dump({"sumo": ["sumo"] + self.sumo_options() + ["--log", os.path.join(self.work, "py.log")],
                       "ego": self.ego, "step_length": self.step_length, "end": self.runs[variant]["end"]}, f)
        return [DEBIAN_PYTHON, os.path.join(ROOT, "bench", "traci_controller.py"), spec]

    def check_controller(self, variant, stdout):
        lines = stdout.strip().splitlines()
        result = json.loads(lines[-1]) if lines else {}
        run = self.runs[variant]
        if abs(result.get("end_time", -1) - run["end"]) > 1e-6 or result.get("steps") != self.sumo_steps(variant):
            raise BenchError("the Python controller ended at t=%s after %s steps, signalsim at t=%g after %d"
                             % (result.get("end_time"), result.get("steps"), run["end"], self.sumo_steps(variant)))
        if abs(result.get("depart_time", -1) - run["depart_time"]) > 1e-6:
            raise BenchError("the Python controller's ego departed at t=%s, signalsim's at t=%g"
                             % (result.get("depart_time"), run["depart_time"]))
        return result


def write_yaml(path, data):
    with open(path, "w") as f:
        f.write("# written by tools/bench\n")
        yaml.safe_dump(data, f, sort_keys=False)
    return path


def random_trips(net, out, seed, begin, end, period, prefix, extra, env):
    trips = out.replace(".rou.xml", ".trips.xml")
    argv = [DEBIAN_PYTHON, RANDOM_TRIPS, "-n", net, "--seed", str(seed), "-b", str(begin), "-e", str(end),
            "-p", str(period), "--prefix", prefix, "--min-distance", "300", "-o", trips, "-r", out] + extra
    result = subprocess.run(argv, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        raise BenchError("randomTrips.py: exit code %d: %s" % (result.returncode, result.stderr.strip()[-300:]))
    return out


def traffic_scenario(work, env, quick):
    """bologna_acosta, the ego on edges 131, 117, 209 (874 m, a light, two right turns) among random
    trips: about 100 vehicles placed anywhere at t=0 (departPos random_free) and one every 0.25 s
    from the fringe, for 300 s. Seeds 43 and 42, so the traffic is the same every time."""
    os.makedirs(work, exist_ok=True)
    net = os.path.join(ACOSTA, "acosta_buslanes.net.xml")
    initial = random_trips(net, os.path.join(work, "initial.rou.xml"), 43, 0, 1, 0.008, "initial",
                           ["--trip-attributes", 'departPos="random_free" departLane="random"'], env)
    flow = random_trips(net, os.path.join(work, "traffic.rou.xml"), 42, 0, 300, 0.25, "bg",
                        ["--fringe-factor", "10"], env)
    path = write_yaml(os.path.join(work, "bench_traffic.yaml"), {
        "name": "bench_traffic", "net": net, "additional": [os.path.join(ACOSTA, "acosta_tls.add.xml")],
        "routes": [initial, flow], "step_length": 0.1, "duration": 20 if quick else 120, "seed": 1,
        "ego": {"route": ["131", "117", "209"], "depart_speed": 5}})
    return BenchScenario("with traffic: bologna_acosta + random trips", path, work)


def grid_node(x, y, number):
    """netgenerate's junction id at column x, row y: letters for x (two, AA AB ..., when the grid has
    more than 26 columns), the number for y."""
    letters = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
    column = letters[x] if number <= 26 else letters[x // 26] + letters[x % 26]
    return "%s%d" % (column, y)


def grid_route(number):
    """East along row 2 from column 0 to 13 (13 edges), left, north to row 12 (10 edges): 2.3 km, the
    same on every grid of 15 or more junctions a side; and its four lights (columns 3, 7, 13 of row 2,
    row 7 of column 13)."""
    node = lambda x, y: grid_node(x, y, number)  # noqa: E731
    route = [node(x, 2) + node(x + 1, 2) for x in range(13)] + [node(13, y) + node(13, y + 1) for y in range(2, 12)]
    return route, ",".join([node(3, 2), node(7, 2), node(13, 2), node(13, 7)])


def grid_scenario(work, number, env, quick):
    """A netgenerate grid of `number` x `number` junctions 100 m apart (one lane each way, 50 km/h,
    four lights), the ego on grid_route; 95 gives 35 720 edges, Bad Hersfeld's size."""
    os.makedirs(work, exist_ok=True)
    route, lights = grid_route(number)
    net = os.path.join(work, "grid%d.net.xml" % number)
    argv = ["netgenerate", "--grid", "--grid.number", str(number), "--grid.length", "100", "--tls.set", lights,
            "--seed", "1", "-o", net]
    result = subprocess.run(argv, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        raise BenchError("netgenerate: exit code %d: %s" % (result.returncode, result.stderr.strip()[-300:]))
    path = write_yaml(os.path.join(work, "grid%d.yaml" % number), {
        "name": "bench_grid%d" % number, "net": net, "step_length": 0.1, "duration": 60 if quick else 400,
        "seed": 1, "ego": {"route": route, "depart_speed": 0}})
    edges = sum(1 for line in open(net) if line.lstrip().startswith("<edge ") and 'function="internal"' not in line)
    return BenchScenario("grid %d x %d (%d edges)" % (number, number, edges), path, work)
