#!/usr/bin/python3
"""python/signalsim-plot on real runs: what each picture draws, read from the plotting functions' data.

Runs the real binary (`run --plot`, `sweep --plot`; without SIGNALSIM_PLOT_TOOL the build tree's
binary finds python/signalsim-plot in its source tree), then checks, against what the run's own files say (summary.json's expectation
details and lane_changes, events.csv, timeline.csv, the net), the data behind:
  - blinker.png: the decided blinker's segments and sources (a lane change handing over to a turn),
    the required-lead marker, legend entries only for what is drawn (hazard only when used), no
    picture for a route without sections where no blinker came on, no two labels overlapping on a
    roundabout route whose labels crowd (they do when left where they are first put)
  - the net: read with sumolib (SUMO's tools), the plot package has no XML reader of its own
  - lateral.png: planned and measured series, lane-change phases and marks, obstacles
  - speed.png: the jerk series from the accel column, the lane speed limit from the net, the planned
    speed and what set it (a light stop among them), where SUMO fell short of the plan behind a leader
    (named once per stretch), the speed axis fitted to the speeds drawn (not to a large max_speed),
    and a timeline without the plan columns still drawn
  - dilemma.png: only for a light where a yellow or red was met, x range covering where it was met,
    the judge's curves exactly as the run wrote them (judge_curves.csv), none without the file
  - the sweep heat map: colour normalisation centred on 0 for a lead distance, failed and errored
    cells marked, the averaged key named, the unit on the colour bar, the short file name; a small
    late value tinted and written apart from 0; the blinker at the section start per cell and a
    blinker to the wrong side marked (a results.csv written here)
usage: plot_test.py SIGNALSIM_BINARY SOURCE_DIR  (exit 77: no matplotlib, skipped)
"""
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

try:
    import matplotlib  # noqa: F401
except ImportError:
    print("skip: /usr/bin/python3 has no matplotlib (python3-matplotlib)")
    sys.exit(77)

BIN, SRC = (sys.argv[1], sys.argv[2]) if len(sys.argv) >= 3 else (None, None)
sys.path.insert(0, os.path.join(SRC or ".", "python"))
WORK = None
RUNS = {}


def setUpModule():
    global WORK
    WORK = tempfile.mkdtemp(prefix="plot_test.")
    # No SIGNALSIM_PLOT_TOOL: the build tree's binary finds python/signalsim-plot in its source tree.
    env = {k: v for k, v in os.environ.items() if k not in ("SIGNALSIM_PLOT_TOOL", "SIGNALSIM_DATA_DIR")}
    runs = {name: (os.path.join(SRC, "scenarios", name + ".yaml"),) for name in (
        "lane_change_then_left", "lane_change_approval_delay", "avoidance_left", "pull_out_backward_hazard",
        "tl_yellow_pass", "roundabout_after_junction_de_left_exit1")}
    # a red light with a max_speed far over the lane limits; a taken-over vehicle behind SUMO's trip7
    runs["red_light_max_speed_40"] = (os.path.join(SRC, "scenarios", "tl_red_stop_then_go.yaml"), "--set",
                                      "ego.max_speed=40")
    runs["take_over_flow"] = (os.path.join(SRC, "tests", "data", "user_sumo", "take_over_flow.yaml"),)
    for name, (scenario, *extra) in runs.items():
        out = os.path.join(WORK, name)
        p = subprocess.run([BIN, "run", scenario, *extra, "--out", out, "--plot", "--quiet"], env=env,
                           capture_output=True, text=True, cwd=WORK)
        assert p.returncode == 0, (name, p.returncode, p.stdout, p.stderr)
        RUNS[name] = out
    sweep = os.path.join(SRC, "tests", "data", "sweeps", "plot_heatmap.yaml")
    p = subprocess.run([BIN, "sweep", sweep, "--out", os.path.join(WORK, "sweep"), "--jobs", "2", "--plot", "--quiet"],
                       env=env, capture_output=True, text=True, cwd=WORK)
    # 4 runs fail nothing but 4 are in error (SUMO refuses an option): the errors' exit code, pictures drawn
    assert p.returncode == 4, (p.returncode, p.stdout, p.stderr)
    RUNS["sweep"] = os.path.join(WORK, "sweep")


def tearDownModule():
    if WORK:
        shutil.rmtree(WORK, ignore_errors=True)


def load(name):
    from signalsim_plot.data import RunInputs, read_run
    d = RUNS[name]
    timeline, events, summary, metrics = read_run(d)
    return d, timeline, events, summary, metrics, RunInputs(d, summary)


def expectation(summary, prefix):
    matches = [e for e in summary["expectations"] if e["expectation"].startswith(prefix)]
    assert len(matches) == 1, (prefix, summary["expectations"])
    return matches[0]


def pictures(name):
    return sorted(os.listdir(os.path.join(RUNS[name], "plots")))


class Blinker(unittest.TestCase):
    def test_lane_change_hands_over_to_the_turn(self):
        from signalsim_plot.blinker import SOURCE_COLORS, blinker_data
        _, timeline, events, summary, metrics, _ = load("lane_change_then_left")
        data = blinker_data(timeline, summary, metrics)
        segs = data["segments"]
        self.assertEqual([(g["blinker"], g["source"]) for g in segs], [("left", "lane_change"), ("left", "intersection")])
        # on where events.csv turns it on, off where it turns it off; the handover where the timeline's source changes
        on = [e for e in events if e["kind"] == "blinker" and e["to"] == "left"]
        off = [e for e in events if e["kind"] == "blinker" and e["from"] == "left"]
        self.assertEqual(len(on), 1)
        self.assertAlmostEqual(segs[0]["s0"], float(on[0]["s_front"]), places=3)
        self.assertAlmostEqual(segs[1]["s1"], float(off[0]["s_front"]), places=3)
        handover = next(float(r["s_front"]) for r in timeline if r["blinker_source"] == "intersection")
        self.assertAlmostEqual(segs[0]["s1"], handover, places=3)
        self.assertAlmostEqual(segs[1]["s0"], handover, places=3)
        self.assertNotEqual(SOURCE_COLORS["lane_change"], SOURCE_COLORS["intersection"])

    def test_required_lead_marker_where_the_checker_starts(self):
        from signalsim_plot.blinker import blinker_data
        _, timeline, _, summary, metrics, _ = load("lane_change_then_left")
        data = blinker_data(timeline, summary, metrics)
        self.assertEqual(len(data["required"]), 1)
        req = data["required"][0]
        e = expectation(summary, "blinker_through_junction C left lead 30")
        # the checker's own start (expectations.cpp): "... steps from s_front 159.6 m until base_link passed ..."
        checker_from = float(re.search(r"from s_front (\S+) m", e["detail"]).group(1))
        self.assertAlmostEqual(req["from_s"], checker_from, places=2)
        turn = next(s for s in metrics["sections"] if s["kind"] == "turn")
        self.assertAlmostEqual(req["from_s"], turn["s_start"] - 30, places=3)
        self.assertTrue(req["passed"])
        self.assertEqual(req["section"]["id"], "C")
        # the speed there gives the time equivalent
        self.assertGreater(req["speed"], 1.0)
        self.assertAlmostEqual(req["lead_time"], 30 / req["speed"], places=6)

    def test_legend_only_for_what_is_drawn(self):
        from signalsim_plot.blinker import BLINKER_COLORS, SOURCE_COLORS, blinker_data, blinker_legend
        from matplotlib.colors import to_hex
        _, timeline, _, summary, metrics, _ = load("lane_change_then_left")
        handles = blinker_legend(blinker_data(timeline, summary, metrics))
        by_label = {h.get_label(): h for h in handles}
        self.assertEqual(to_hex(by_label["decided, source lane_change"].get_facecolor()), SOURCE_COLORS["lane_change"])
        self.assertEqual(to_hex(by_label["decided, source intersection"].get_facecolor()),
                         SOURCE_COLORS["intersection"])
        self.assertFalse([lab for lab in by_label if lab.startswith("hazard") or lab.startswith("right")], by_label)
        left = [h for lab, h in by_label.items() if lab.startswith("left (")]
        self.assertEqual(len(left), 1)
        self.assertEqual(to_hex(left[0].get_facecolor()), BLINKER_COLORS["left"])
        # hazard when used: backing out with hazard lights
        _, timeline, _, summary, metrics, _ = load("pull_out_backward_hazard")
        data = blinker_data(timeline, summary, metrics)
        hazard = [g for g in data["segments"] if g["blinker"] == "hazard"]
        self.assertEqual(len(hazard), 1)
        self.assertTrue(hazard[0]["reversing"])
        self.assertEqual(hazard[0]["source"], "pull_out")
        self.assertTrue([h for h in blinker_legend(data) if h.get_label().startswith("hazard (")])

    def test_no_blinker_picture_without_sections_and_blinker(self):
        from signalsim_plot.blinker import blinker_data
        _, timeline, _, summary, metrics, _ = load("tl_yellow_pass")
        self.assertEqual(metrics["sections"], [])
        self.assertTrue(all(r["blinker"] == "none" for r in timeline))
        self.assertIsNone(blinker_data(timeline, summary, metrics))
        self.assertNotIn("blinker.png", pictures("tl_yellow_pass"))
        self.assertIn("blinker.png", pictures("lane_change_then_left"))

    def test_roundabout_labels_do_not_overlap(self):
        import matplotlib.pyplot as plt
        from signalsim_plot.blinker import blinker_data, blinker_figure
        from signalsim_plot.labels import overlapping_pairs
        _, timeline, _, summary, metrics, _ = load("roundabout_after_junction_de_left_exit1")
        data = blinker_data(timeline, summary, metrics)
        crowded, _, texts = blinker_figure(data, summary, separate=False)
        self.assertTrue(overlapping_pairs(crowded, texts), "the route's labels do not crowd: the test shows nothing")
        plt.close(crowded)
        fig, ax, texts = blinker_figure(data, summary)
        self.assertEqual(overlapping_pairs(fig, texts), [], [t.get_text() for t in texts])
        lo, hi = ax.get_ylim()  # every label inside the axes
        renderer = fig.canvas.get_renderer()
        inside = ax.get_window_extent(renderer)
        for t in texts:
            box = t.get_window_extent(renderer)
            self.assertTrue(inside.y0 - 1 <= box.y0 and box.y1 <= inside.y1 + 1, t.get_text())
        plt.close(fig)
        self.assertIn("blinker.png", pictures("roundabout_after_junction_de_left_exit1"))


class Lateral(unittest.TestCase):
    def test_planned_and_measured_series(self):
        from signalsim_plot.lateral import lateral_data
        _, timeline, events, summary, metrics, inputs = load("lane_change_then_left")
        data = lateral_data(timeline, events, summary, inputs)
        self.assertEqual(len(data["planned"]), len(timeline))
        self.assertEqual(len(data["measured"]), len(timeline))
        planned_rows = sum(1 for r in timeline if r["planned_offset"] != "")
        self.assertGreater(planned_rows, 50)
        self.assertEqual(data["planned_rows"], planned_rows)
        # the checker counts the same steps ("152 steps, worst deviation ...")
        e = expectation(summary, "lateral_offset_follows_plan")
        self.assertEqual(data["planned_rows"], int(e["detail"].split()[0]))
        self.assertEqual(data["measured_rows"], sum(1 for r in timeline if r["edge"] == "in_S"))
        f = summary["ego"]["base_link_to_front"]
        self.assertAlmostEqual(data["s_base"][10], float(timeline[10]["s_front"]) - f, places=6)
        # the planned lane is the left one of in_S (two 3.2 m lanes): borders at -4.8, -1.6, 1.6
        (edge,) = data["edges"]
        self.assertEqual((edge["edge"], edge["planned"], edge["assumed"]), ("in_S", 1, False))
        self.assertEqual([round(b, 2) for b in edge["borders"]], [-4.8, -1.6, 1.6])
        self.assertIn("lateral.png", pictures("lane_change_then_left"))
        self.assertNotIn("lateral.png", pictures("tl_yellow_pass"))

    def test_lane_change_phases_from_events(self):
        from signalsim_plot.lateral import lateral_data
        _, timeline, events, summary, metrics, inputs = load("lane_change_approval_delay")
        data = lateral_data(timeline, events, summary, inputs)
        f = summary["ego"]["base_link_to_front"]
        (lc,) = summary["lane_changes"]
        ev = {(e["from"], e["to"]): e for e in events if e["kind"] == "lane_change"}
        phases = {p["phase"]: p for p in data["phases"] if p["s1"] > p["s0"]}
        self.assertEqual(sorted(phases), ["pending", "running", "shifting", "waiting_approval"])
        wait = phases["waiting_approval"]
        self.assertAlmostEqual(wait["s0"], float(ev[("pending", "waiting_approval")]["s_front"]) - f, places=3)
        self.assertAlmostEqual(wait["s1"], lc["approval_s_base"], places=2)
        self.assertAlmostEqual(phases["shifting"]["s0"], lc["lateral_start_s"], places=3)
        self.assertAlmostEqual(phases["shifting"]["s1"], lc["lateral_end_s"], places=3)
        self.assertLess(wait["s1"], phases["running"]["s1"])
        marks = {m["what"]: m for m in data["marks"]}
        self.assertAlmostEqual(marks["approved"]["t"], lc["approval_time"], places=3)
        self.assertAlmostEqual(marks["done"]["s"], float(ev[("running", "done")]["s_front"]) - f, places=3)

    def test_obstacle_where_the_scenario_puts_it(self):
        from signalsim_plot.lateral import lateral_data
        _, timeline, events, summary, metrics, inputs = load("avoidance_left")
        data = lateral_data(timeline, events, summary, inputs)
        self.assertEqual(data["phases"], [])  # no lane change
        (ob,) = data["obstacles"]
        # scenarios/avoidance_left.yaml: {id: parked, edge: in_S, lane: 0, pos: 120, length: 4.5}; in_S starts the route
        self.assertEqual(ob["id"], "parked")
        self.assertAlmostEqual(ob["s1"], 120.0, delta=0.05)
        self.assertAlmostEqual(ob["s0"], 115.5, delta=0.05)
        self.assertAlmostEqual(ob["y0"], -0.9, places=6)
        peak = max(v for v in data["planned"] if v == v)
        self.assertGreater(peak - summary["ego"]["width"] / 2, ob["y1"])  # the plan clears it
        self.assertLessEqual(data["x_range"][0], ob["s0"])
        self.assertGreaterEqual(data["x_range"][1], ob["s1"])


class Speed(unittest.TestCase):
    def test_jerk_from_the_accel_column(self):
        from signalsim_plot.speed import speed_data
        _, timeline, _, summary, metrics, inputs = load("lane_change_then_left")
        data = speed_data(timeline, summary, metrics, inputs.net)
        self.assertEqual(len(data["jerk"]), len(timeline) - 1)
        t = [float(r["time"]) for r in timeline]
        a = [float(r["accel"]) for r in timeline]
        for i, j in data["jerk"][:40]:
            self.assertAlmostEqual(j, (a[i] - a[i - 1]) / (t[i] - t[i - 1]), places=9)
        self.assertAlmostEqual(max(abs(j) for _, j in data["jerk"]), metrics["max_jerk"], delta=0.01)
        self.assertGreater(metrics["max_jerk"], 0.5)
        self.assertEqual(len(data["jerk_s"]), len(data["jerk"]))

    def test_net_read_with_sumolib(self):
        import signalsim_plot.net as net_module
        self.assertIsNotNone(net_module.sumolib_module())
        plot_dir = os.path.join(SRC, "python", "signalsim_plot")
        for name in os.listdir(plot_dir):  # no XML reader of its own
            if name.endswith(".py"):
                with open(os.path.join(plot_dir, name)) as f:
                    self.assertNotIn("xml.etree", f.read(), name)
        _, _, _, _, _, inputs = load("lane_change_then_left")
        lane = inputs.net.lanes[":C_0_0"] if ":C_0_0" in inputs.net.lanes else None
        self.assertIsNotNone(lane)
        self.assertTrue(lane.internal)
        x, y = lane.shape[-1]
        self.assertAlmostEqual(lane.position_of(x, y), lane.length, places=3)

    def test_lane_speed_limit_from_the_net(self):
        from signalsim_plot.speed import speed_data
        _, timeline, _, summary, metrics, inputs = load("lane_change_then_left")
        data = speed_data(timeline, summary, metrics, inputs.net)
        self.assertIsNone(data["limit_note"])
        net = ET.parse(os.path.join(SRC, "sumo_nets", "cross", "cross.net.xml"))
        speed = {l.get("id"): float(l.get("speed")) for l in net.iter("lane")}
        turn = next(s for s in metrics["sections"] if s["kind"] == "turn")
        internal = [seg for seg in data["limits"] if seg[2] < speed["in_S_1"]]
        self.assertEqual(len(internal), 1)
        s0, s1, limit, lane = internal[0]
        self.assertEqual(limit, speed[lane])
        self.assertTrue(lane.startswith(":C_"), lane)
        self.assertAlmostEqual(s0, turn["s_start"], delta=0.1)  # the junction's first internal lane starts there
        self.assertAlmostEqual(s1, turn["s_end"], delta=0.1)
        self.assertEqual(data["limits"][0][2], speed["in_S_1"])
        # the speed stays under the limit where the front is
        for r in timeline:
            if r["lane"] in speed:
                self.assertLessEqual(float(r["speed"]), speed[r["lane"]] + 0.05, r)

    def test_plan_and_what_set_it(self):
        from signalsim_plot.speed import speed_data
        _, timeline, _, summary, metrics, inputs = load("red_light_max_speed_40")
        data = speed_data(timeline, summary, metrics, inputs.net)
        self.assertTrue(data["has_plan"])
        for i, r in enumerate(timeline):  # the command for the step from row i, drawn at the row after it
            self.assertAlmostEqual(data["planned"][i], float(r["planned_speed"]), places=9)
            self.assertEqual(data["planned_s"][i], float(timeline[min(i + 1, len(timeline) - 1)]["s_front"]))
            if i + 1 < len(timeline) and not r["sumo_limited_by"]:  # SUMO executed it: the next row's speed
                self.assertAlmostEqual(data["planned"][i], float(timeline[i + 1]["speed"]), delta=0.011)
        # max_speed 40 is over every lane limit: the lane limits and the light set the plan
        self.assertEqual(data["limited_by_kinds"], ["lane_limit", "light_stop"])
        self.assertEqual(sorted({r[0] for r in data["limited_by"]}),
                         sorted({r["speed_limited_by"] for r in timeline}))
        ((stop_light, stop_s),) = data["lights"]
        stops = [r for r in data["limited_by"] if r[0] == "light_stop"]
        self.assertTrue(stops)
        self.assertTrue(all(s1 <= stop_s + 0.01 for _, _, s1, _, _ in stops), (stops, stop_s))
        # the runs cover the rows: each row's value holds from its s and time to the next row's
        rows = sum(1 for r in timeline if r["speed_limited_by"] == "light_stop")
        self.assertAlmostEqual(sum(t1 - t0 for _, _, _, t0, t1 in stops), rows * 0.1, delta=0.051)
        self.assertEqual(data["short_kinds"], [])
        # the legend names only the values met
        from signalsim_plot.speed import strip_legend
        labels = [h.get_label() for h in strip_legend(data, [])]
        self.assertEqual([lab.split(":")[0] for lab in labels], ["plan set by (strip)", "lane_limit", "light_stop"])
        self.assertIn("speed.png", pictures("red_light_max_speed_40"))

    def test_speed_axis_fits_the_speeds_not_max_speed(self):
        from signalsim_plot.speed import HEADROOM, speed_data
        _, timeline, _, summary, metrics, inputs = load("red_light_max_speed_40")
        data = speed_data(timeline, summary, metrics, inputs.net)
        self.assertEqual(data["max_speed"], 40)
        drawn = [float(r["speed"]) for r in timeline] + [float(r["planned_speed"]) for r in timeline]
        drawn += [seg[2] for seg in data["limits"]]
        bottom, top = data["y_range"]
        self.assertAlmostEqual(top, HEADROOM * max(drawn), places=9)
        self.assertLess(top, 0.5 * data["max_speed"])
        self.assertFalse(data["max_speed_drawn"])
        self.assertLess(bottom, 0.0)
        self.assertGreater(bottom, -0.05 * top)  # (nothing below 0: a margin for the rest marks)
        # a max_speed within the speeds drawn: its line is drawn
        _, timeline, _, summary, metrics, inputs = load("lane_change_then_left")
        data = speed_data(timeline, summary, metrics, inputs.net)
        self.assertLessEqual(data["max_speed"], data["y_range"][1])
        self.assertTrue(data["max_speed_drawn"])

    def test_sumo_short_of_the_plan_behind_a_leader(self):
        from signalsim_plot.speed import MERGE_GAP, speed_data
        _, timeline, _, summary, metrics, inputs = load("take_over_flow")
        data = speed_data(timeline, summary, metrics, inputs.net)
        short = [i for i, r in enumerate(timeline) if r["sumo_limited_by"]]
        self.assertGreater(len(short), 5)
        self.assertEqual(data["short"], [r["sumo_limited_by"] for r in timeline])
        self.assertEqual(data["short_kinds"], ["leader"])
        for i in short:  # SUMO's speed after the step fell short of the command by more than 0.01 m/s
            r = timeline[i]
            self.assertLess(float(r["sumo_speed"]), float(r["planned_speed"]) - 0.009, r)  # (3 decimals each)
            self.assertEqual(r["leader"], "trip7")
        stretches = data["short_stretches"]
        self.assertLess(len(stretches), len(short) / 3)  # the leader named once per stretch, not per step
        self.assertEqual(sum(st["steps"] for st in stretches), len(short))
        self.assertEqual({(st["kind"], st["leader"]) for st in stretches}, {("leader", "trip7")})
        t = data["t"]
        for st in stretches:
            inside = [i for i in short if st["first"] <= i <= st["last"]]
            self.assertEqual(len(inside), st["steps"])
            self.assertTrue(all(t[b] - t[a] < MERGE_GAP + 0.1 + 1e-9 for a, b in zip(inside, inside[1:])))
            self.assertAlmostEqual(st["min_gap"], min(float(timeline[i]["leader_gap"]) for i in inside), places=9)
            self.assertEqual((st["s0"], st["t0"]), (data["s"][st["first"]], t[st["first"]]))
        for a, b in zip(stretches, stretches[1:]):
            self.assertGreaterEqual(b["t0"] - a["t1"], MERGE_GAP)
        # one label a stretch, in the strip's "SUMO short of plan" row, where the stretch ends
        import matplotlib.pyplot as plt
        from signalsim_plot.speed import label_leaders, rows_at
        fig, ax = plt.subplots()
        rows = rows_at(data, lambda r: (r[1], r[2]))
        self.assertEqual([name for name, _ in rows], ["plan set by", "SUMO short of plan"])
        texts = label_leaders(ax, rows, stretches, lambda st: st["s1"])
        plt.close(fig)
        self.assertEqual([(x.get_position(), x.get_text().split("(")[0].strip()) for x in texts],
                         [((st["s1"], 1), "behind trip7") for st in stretches])
        # the run stops for the red light C, then follows trip7 away
        self.assertIn("light_stop", data["limited_by_kinds"])
        self.assertTrue(data["max_speed_drawn"])

    def test_timeline_without_the_plan_columns(self):
        from signalsim_plot.speed import speed_data, speed_plot
        _, timeline, _, summary, metrics, inputs = load("lane_change_then_left")
        plan_columns = ("planned_speed", "speed_limited_by", "sumo_speed", "sumo_limited_by", "leader", "leader_gap")
        old = [{k: v for k, v in r.items() if k not in plan_columns} for r in timeline]
        data = speed_data(old, summary, metrics, inputs.net)
        self.assertFalse(data["has_plan"])
        self.assertTrue(all(p != p for p in data["planned"]))  # nan: nothing planned
        self.assertEqual((data["limited_by"], data["short_runs"], data["short_stretches"]), ([], [], []))
        top = max([float(r["speed"]) for r in timeline] + [seg[2] for seg in data["limits"]])
        self.assertAlmostEqual(data["y_range"][1], 1.1 * top, places=9)
        path = os.path.join(WORK, "old_timeline_speed.png")
        self.assertEqual(speed_plot(old, summary, metrics, inputs.net, path), path)
        self.assertGreater(os.path.getsize(path), 10000)


class Dilemma(unittest.TestCase):
    def test_only_a_light_where_yellow_or_red_was_met(self):
        from signalsim_plot.dilemma import dilemma_data, read_curves
        d, timeline, _, summary, metrics, _ = load("lane_change_then_left")
        self.assertTrue(any(r["tl_id"] == "C" for r in timeline))
        self.assertTrue(all(r["tl_state"] in ("g", "G", "") for r in timeline))
        self.assertIsNone(dilemma_data(timeline, summary, metrics, read_curves(d)))
        self.assertNotIn("dilemma.png", pictures("lane_change_then_left"))
        d, timeline, _, summary, metrics, _ = load("tl_yellow_pass")
        data = dilemma_data(timeline, summary, metrics, read_curves(d))
        (panel,) = data["panels"]
        self.assertEqual(panel["light"], "C")
        d, v, state, _, t = panel["points"][panel["first_stop_state"]]
        first_yellow = next(r for r in timeline if r["tl_state"] in ("y", "Y"))
        self.assertEqual(state, first_yellow["tl_state"])
        self.assertAlmostEqual(t, float(first_yellow["time"]), places=3)
        self.assertAlmostEqual(d, float(first_yellow["stop_distance"]), places=3)
        lo, hi = panel["d_range"]
        self.assertLess(lo, 0)
        self.assertGreater(hi, d)
        self.assertGreaterEqual(hi, max(data["curve"]["yellow"]))
        self.assertIn("y", panel["met"])
        self.assertIn("dilemma.png", pictures("tl_yellow_pass"))

    def test_curves_as_the_run_wrote_them(self):
        from signalsim_plot.dilemma import dilemma_data
        d, timeline, _, summary, metrics, _ = load("tl_yellow_pass")
        with open(os.path.join(d, "judge_curves.csv"), newline="") as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(list(rows[0]), ["speed", "judge_distance", "yellow_lamp_line"])
        self.assertEqual((rows[0]["speed"], rows[0]["judge_distance"]), ("0.000", "0.000"))
        data = dilemma_data(timeline, summary, metrics, None)
        self.assertIsNone(data["curve"])  # without the file: no curves, nothing computed here
        from signalsim_plot.dilemma import read_curves
        data = dilemma_data(timeline, summary, metrics, read_curves(d))
        kept = [r for r in rows if float(r["speed"]) <= data["v_top"] + 1e-9]
        self.assertEqual(data["curve"]["v"], [float(r["speed"]) for r in kept])
        self.assertEqual(data["curve"]["judge"], [float(r["judge_distance"]) for r in kept])
        self.assertEqual(data["curve"]["yellow"], [float(r["yellow_lamp_line"]) for r in kept])
        # the judge's own number on a row with zero acceleration lies on the written curve (interpolated
        # between its 0.1 m/s points)
        speeds, judge = [float(c["speed"]) for c in rows], [float(c["judge_distance"]) for c in rows]
        checked = 0
        for r in timeline:
            if r["judge_distance"] and float(r["accel"]) == 0.0:
                v = float(r["speed"])
                k = min(int(v / 0.1), len(speeds) - 2)
                on_curve = judge[k] + (judge[k + 1] - judge[k]) * (v - speeds[k]) / (speeds[k + 1] - speeds[k])
                self.assertAlmostEqual(on_curve, float(r["judge_distance"]), delta=0.01, msg=r)
                checked += 1
        self.assertGreater(checked, 0, "no judged row at zero acceleration")
        self.assertFalse(os.path.exists(os.path.join(RUNS["roundabout_after_junction_de_left_exit1"],
                                                     "judge_curves.csv")), "a route without a light has none")


class HeatMap(unittest.TestCase):
    def test_centred_on_zero_with_failed_and_errored_cells(self):
        from signalsim_plot.sweep_plots import heatmap_data
        out = RUNS["sweep"]
        csv_path = os.path.join(out, "results.csv")
        data = heatmap_data(csv_path, "turn1.lead_distance", "turn_signal_search_time", "ego.max_speed")
        self.assertEqual(data["name"], "turn1.lead_distance_by_max_speed_turn_signal_search_time.png")
        self.assertTrue(os.path.isfile(os.path.join(out, "plots", data["name"])), os.listdir(os.path.join(out, "plots")))
        norm = data["norm"]
        self.assertEqual(data["cmap"], "RdBu")
        self.assertAlmostEqual(norm.vmin, -norm.vmax)
        self.assertAlmostEqual(float(norm(0.0)), 0.5)
        with open(csv_path, newline="") as f:
            rows = list(csv.DictReader(f))
        leads = [float(r["turn1.lead_distance"]) for r in rows if r["turn1.lead_distance"]]
        self.assertAlmostEqual(norm.vmax, max(abs(v) for v in leads), places=6)
        self.assertIn("[m]", data["colorbar_label"])
        self.assertEqual(data["averaged"], ["sumo_args"])
        self.assertIn("mean over sumo_args", data["title"])
        # marked cells: exactly those with a failed or errored run in results.csv
        want = {}
        for r in rows:
            key = (data["ys"].index(r["ego.max_speed"]), data["xs"].index(r["turn_signal_search_time"]))
            failed, errors = want.get(key, (0, 0))
            want[key] = (failed + (r["status"] == "failed"), errors + (r["status"] == "error"))
        want = {k: v for k, v in want.items() if v != (0, 0)}
        self.assertEqual({(i, j): (f, e) for _, i, j, f, e in data["marked"]}, want)
        self.assertEqual(sum(f for _, _, _, f, _ in data["marked"]), 2)  # search time 0.5 s: lead < 30 m, both speeds
        self.assertEqual(sum(e for _, _, _, _, e in data["marked"]), 4)
        # the errored runs give no value: each cell's mean is its one finished run's
        (panel,) = data["panels"]
        for r in rows:
            if r["status"] != "error":
                i, j = data["ys"].index(r["ego.max_speed"]), data["xs"].index(r["turn_signal_search_time"])
                self.assertAlmostEqual(panel["grid"][i, j], float(r["turn1.lead_distance"]), places=6)
                self.assertEqual(panel["counts"][i, j], 1)

    def test_small_late_values_and_the_blinker_at_the_start(self):
        from signalsim_plot.sweep_plots import format_value, heatmap_data
        # a roundabout exit swept over the exit rule: right asked; one run with the left blinker (no lead)
        path = os.path.join(WORK, "wrong_side", "results.csv")
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["run", "scenario", "file", "ego.max_speed", "turn_signal_search_time", "status",
                        "roundabout_exit1.id", "roundabout_exit1.blinker", "roundabout_exit1.blinker_at_start",
                        "roundabout_exit1.lead_distance"])
            w.writerow([0, "r", "r.yaml", "8", "1", "passed", "RE", "right", "right", "12.5"])
            w.writerow([1, "r", "r.yaml", "8", "3", "passed", "RE", "right", "right", "-0.2"])
            w.writerow([2, "r", "r.yaml", "10", "1", "failed", "RE", "right", "left", ""])
            w.writerow([3, "r", "r.yaml", "10", "3", "passed", "RE", "right", "right", "0"])
        data = heatmap_data(path, "roundabout_exit1.lead_distance", "turn_signal_search_time", "ego.max_speed")
        self.assertEqual(data["section"], "roundabout_exit1")
        (panel,) = data["panels"]
        self.assertEqual(panel["directions"][1][0], {"left": 1})
        self.assertEqual(panel["asked"][1][0], "right")
        self.assertEqual(data["wrong"], [(0, 1, 0)])
        norm = data["norm"]
        self.assertAlmostEqual(float(norm(0.0)), 0.5)
        self.assertLess(float(norm(-0.2)), 0.45)  # tinted red, not the white of 0
        self.assertGreater(float(norm(0.2)), 0.55)
        self.assertAlmostEqual(float(norm(-12.5)), 0.0)
        self.assertEqual((format_value(-0.004), format_value(0.0), format_value(-0.2)), ("-0.004", "0", "-0.20"))
        # the real sweep: every finished run's turn1 blinker at the start, from results.csv
        data = heatmap_data(os.path.join(RUNS["sweep"], "results.csv"), "turn1.lead_distance",
                            "turn_signal_search_time", "ego.max_speed")
        self.assertEqual(data["section"], "turn1")
        (panel,) = data["panels"]
        self.assertTrue(all(d == {"left": 1} for row in panel["directions"] for d in row), panel["directions"])
        self.assertEqual(data["wrong"], [])

    def test_boolean_share_and_sequential_map(self):
        from signalsim_plot.sweep_plots import file_name, heatmap_data
        data = heatmap_data(os.path.join(RUNS["sweep"], "results.csv"), "turn1.missed", "turn_signal_search_time",
                            "ego.max_speed")
        self.assertTrue(data["boolean"])
        self.assertEqual((data["norm"].vmin, data["norm"].vmax), (0.0, 1.0))
        self.assertIn("share of runs", data["colorbar_label"])
        self.assertLessEqual(len(file_name("red_light_violations", "stop_release_confirmation_time",
                                           "perception.misclassification_probability")), 64 + 4)


if __name__ == "__main__":
    if BIN is None:
        print(__doc__)
        sys.exit(2)
    unittest.main(argv=[sys.argv[0], "-v"] + sys.argv[3:])
