"""A lane change in city traffic against the same run without one (tools/bench --only lanechange).

bologna_acosta with its full demand (acosta.sumocfg: 8 622 vehicles over the hour), and a taken-over
vehicle of a route file written here: it departs at 400 s (about 300 vehicles in the net) on edge 46
and drives 46 201 201c. Departing on lane 2 it needs no lane change; departing on lane 1 its lane
plan shifts it one lane to the left on 46 (3.2 m, to the lane with the connection to 201). Both runs are the same
simulation up to the departure; what a lane change costs is the model SUMO runs for it
(docs/performance.md "Lane changes in traffic"). `--bin` measures another build, e.g. one from before
a change. Interleaved runs; medians of CPU time (user + sys) and wall time.
"""
import csv
import os
import shutil

from measure import BenchError, interleaved, median_cpu, median_wall, run_child

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ACOSTA = os.path.join(ROOT, "sumo_nets", "bologna_acosta")
EGO_ID = "bench_ego"
DEPART = 400      # [s] the taken-over vehicle's departure
DURATION = 600    # [s] the run's limit; the vehicle arrives well before


def write_case(work, lane, duration):
    """The scenario whose taken-over vehicle departs on `lane`; returns its path."""
    routes = os.path.join(work, "ego_lane%d.rou.xml" % lane)
    with open(routes, "w") as f:
        f.write('<routes>\n    <vehicle id="%s" depart="%d" departPos="0" departLane="%d" departSpeed="5" '
                'type="private"><route edges="46 201 201c"/></vehicle>\n</routes>\n' % (EGO_ID, DEPART, lane))
    path = os.path.join(work, "acosta_lane%d.yaml" % lane)
    with open(path, "w") as f:
        f.write("name: acosta_lane%d\ndescription: a taken-over vehicle among bologna_acosta's demand, departing "
                "on lane %d\nsumocfg: %s\nroutes: [%s]\nstep_length: 0.1\nduration: %d\nseed: 1\nego:\n  id: %s\n"
                "params:\n  files: [%s]\n" % (lane, lane, os.path.join(ACOSTA, "acosta.sumocfg"), routes, duration,
                                              EGO_ID, os.path.join(ROOT, "config", "autoware_defaults.yaml")))
    return path


def lane_change_events(out):
    with open(os.path.join(out, "events.csv")) as f:
        return sum(1 for row in csv.DictReader(f) if row["kind"] == "lane_change")


def bench_lanechange(binary, env, work, runs, warm_up, quick):
    """Returns (samples without, samples with a lane change), each a list of measure.Sample."""
    os.makedirs(work, exist_ok=True)
    duration = DEPART + (30 if quick else DURATION - DEPART)
    paths = {"without": write_case(work, 2, duration), "with": write_case(work, 1, duration)}

    def case(name):
        def run():
            out = os.path.join(work, "out_" + name)
            shutil.rmtree(out, ignore_errors=True)
            sample = run_child([binary, "run", paths[name], "--out", out, "--quiet"], env=env, ok_codes=(0,))
            changes = lane_change_events(out)
            if (changes > 0) != (name == "with"):
                raise BenchError("%s: %d lane-change events in the run %s a lane change"
                                 % (paths[name], changes, name))
            return sample
        return run

    samples = interleaved({"without": case("without"), "with": case("with")}, runs, warm_up)
    return samples["without"], samples["with"]


def report(without, with_change):
    print("\n== a lane change among bologna_acosta's demand (a taken-over vehicle departing at %d s)" % DEPART)
    for name, samples in (("without a lane change", without), ("with a lane change", with_change)):
        print("   %-24s %8.2f s CPU  %8.2f s wall  (median of %d)"
              % (name, median_cpu(samples), median_wall(samples), len(samples)))
    print("   with / without: %.2f CPU, %.2f wall (goal <= 1.2)"
          % (median_cpu(with_change) / median_cpu(without), median_wall(with_change) / median_wall(without)),
          flush=True)
