"""lateral.png (runs with a maneuver: lane change, avoidance, pull out, pull over): the lateral plan and
what SUMO drove, along the route.

Top: planned_offset (the plan at base_link) and lateral_offset (measured), both from the centre of the
maneuver edge's planned lane, left positive, plotted at base_link's route position; the lane borders
of each maneuver edge (from the net) and the obstacles of the scenario file, where they stand on the
route; a band of the ego's width around the measured offset. Bottom strips: the decided blinker, and
each lane change's phases from events.csv (pending, waiting for approval, running: preparing then
shifting as summary.json's lane_changes give lateral_start_s / lateral_end_s) with where it was
approved and done.

lateral_data() computes what is drawn; lateral_plot() draws it (tests read the data)."""
import math

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle

from signalsim_plot.data import number, runs_of, span_end
from signalsim_plot.net import DEFAULT_LANE_WIDTH
from signalsim_plot.style import BLINKER_COLORS

OBSTACLE_WIDTH = 1.8  # scenario.hpp kObstacleWidth (SUMO DEFAULT_VEHTYPE) [m]
PHASE_COLORS = {"pending": "#d9d9d9", "waiting_approval": "#fdae61", "running": "#abd9e9", "shifting": "#2c7bb6"}
PHASE_NAMES = {"pending": "pending", "waiting_approval": "waiting for approval", "running": "running: preparing",
               "shifting": "running: shifting"}
MANEUVER_SOURCES = ("lane_change", "avoidance", "pull_out", "pull_over")
PLANNED_COLOR, MEASURED_COLOR = "#e7298a", "black"


def edge_starts(timeline, net):
    """{edge: route s (front bumper) where the edge starts}: from the first row on it, where the net puts
    the front's (x, y) on its lane (without the net: that row's s, to a step)."""
    out = {}
    for r in timeline:
        edge = r.get("edge", "")
        if not edge or edge in out:
            continue
        s = float(r["s_front"])
        lane = net.lanes.get(r.get("lane", "")) if net else None
        x, y = number(r.get("x")), number(r.get("y"))
        if lane is not None and x is not None and y is not None:
            p = lane.position_of(x, y)
            if 0 <= p <= lane.length + 0.5:
                s -= p
        out[edge] = s
    return out


def planned_lane(rows, net, edge):
    """The index of the edge's planned lane: the lane whose centre is lateral_offset away from the
    centre of the lane the ego is on, most often over the edge's rows."""
    centres = net.lane_centres(edge)
    votes = {}
    for r in rows:
        lane = net.lanes.get(r.get("lane", ""))
        o = number(r.get("lateral_offset"))
        if lane is None or o is None or lane.index not in centres:
            continue
        p = min(centres, key=lambda q: abs(o - (centres[lane.index] - centres[q])))
        votes[p] = votes.get(p, 0) + 1
    return max(votes, key=votes.get) if votes else None


def lane_change_phases(events, summary, f, entered):
    """(phases, marks): phases [{edge, phase, s0, s1, t0, t1}] in base_link s (pending from where the ego
    reached the edge, `entered`: {edge: (base_link s, time) of its first row there};
    running split into preparing (`running`) and `shifting` at summary's lateral_start_s/lateral_end_s);
    marks [{edge, what (approved, done, missed), s, t}]."""
    by_edge = {}
    for e in events:
        if e.get("kind") == "lane_change":
            by_edge.setdefault(e["source"], []).append(e)
    executed = {lc.get("edge"): lc for lc in summary.get("lane_changes", [])}
    phases, marks = [], []
    for edge, evs in by_edge.items():
        pts = [(float(e["s_front"]) - f, float(e["time"]), e["from"], e["to"]) for e in evs]
        first_s, first_t, first_from, _ = pts[0]
        s_in, t_in = entered.get(edge, (first_s, first_t))
        phases.append({"edge": edge, "phase": first_from, "s0": min(s_in, first_s), "s1": first_s, "t0": min(t_in, first_t),
                       "t1": first_t})
        for k, (s0, t0, _frm, to) in enumerate(pts):
            if to in ("done", "missed"):
                marks.append({"edge": edge, "what": to, "s": s0, "t": t0})
                continue
            s1, t1 = (pts[k + 1][0], pts[k + 1][1]) if k + 1 < len(pts) else (s0, t0)
            if to == "running":
                marks.append({"edge": edge, "what": "approved", "s": s0, "t": t0})
                lc = executed.get(edge, {})
                a, b = lc.get("lateral_start_s"), lc.get("lateral_end_s")
                if a is not None and b is not None and s0 <= a <= b:
                    phases.append({"edge": edge, "phase": "running", "s0": s0, "s1": a, "t0": t0, "t1": None})
                    phases.append({"edge": edge, "phase": "shifting", "s0": a, "s1": b, "t0": None, "t1": None})
                    if s1 > b:
                        phases.append({"edge": edge, "phase": "running", "s0": b, "s1": s1, "t0": None, "t1": t1})
                    continue
            phases.append({"edge": edge, "phase": to, "s0": s0, "s1": s1, "t0": t0, "t1": t1})
    return phases, marks


def has_maneuver(timeline, events, summary):
    return (any(r.get("planned_offset") not in (None, "") for r in timeline)
            or any(e.get("kind") == "lane_change" for e in events) or bool(summary.get("lane_changes")))


def lateral_data(timeline, events, summary, inputs):
    """What lateral.png draws, or None when the run has no maneuver.

    s_base:    base_link's route s per row (s_front - base_link_to_front)
    measured:  lateral_offset per row on a maneuver edge, NaN elsewhere (there it is from the lane's own centre)
    planned:   planned_offset per row, NaN where empty; planned_rows: how many rows have one
    edges:     per maneuver edge {edge, s0, s1 (route s), planned (lane index), borders (offsets of its lane
               borders from the planned lane's centre, right to left), assumed (no net: one 3.2 m lane)}
    obstacles: [{id, edge, s0, s1, y0, y1}] (route s of rear and front, lateral extent)
    phases, marks: lane_change_phases(); blinker: [(s0, s1, blinker, reversing)] in base_link s
    x_range:   (lo, hi): where the plan changes or is not followed, the phases but pending, the obstacles and
               where a maneuver had the blinker on, with a margin; notes: what is missing
    """
    if not has_maneuver(timeline, events, summary):
        return None
    net = inputs.net if inputs else None
    f = (summary.get("ego") or {}).get("base_link_to_front", 0.0) or 0.0
    width = (summary.get("ego") or {}).get("width", OBSTACLE_WIDTH)
    s_base = [float(r["s_front"]) - f for r in timeline]
    planned = [number(r.get("planned_offset")) for r in timeline]
    starts = edge_starts(timeline, net)
    scenario = (inputs.scenario if inputs else None) or {}
    maneuver_edges = list(dict.fromkeys(
        [r["edge"] for r, p in zip(timeline, planned) if p is not None and r.get("edge")]
        + [e["source"] for e in events if e.get("kind") == "lane_change"]
        + [lc.get("edge") for lc in summary.get("lane_changes", []) if lc.get("edge")]))
    on_maneuver_edge = [r.get("edge") in maneuver_edges for r in timeline]
    measured = [number(r.get("lateral_offset")) if on else None for r, on in zip(timeline, on_maneuver_edge)]
    notes = list(inputs.notes) if inputs else ["run inputs not read"]

    edges = []
    for edge in maneuver_edges:
        rows = [r for r in timeline if r.get("edge") == edge]
        if not rows or edge not in starts:
            continue
        lanes = net.edges.get(edge) if net else None
        p = planned_lane(rows, net, edge) if lanes else None
        if lanes and p is not None:
            centres = net.lane_centres(edge)
            borders = [b - centres[p] for b in net.lane_borders(edge)]
            length = lanes[0].length
            assumed = False
        else:
            borders, assumed = [-DEFAULT_LANE_WIDTH / 2, DEFAULT_LANE_WIDTH / 2], True
            length = max(float(r["s_front"]) for r in rows) - starts[edge]
        edges.append({"edge": edge, "s0": starts[edge], "s1": starts[edge] + length, "planned": p, "borders": borders,
                      "assumed": assumed, "lanes": len(lanes) if lanes else None})

    obstacles = []
    for ob in scenario.get("obstacles") or []:
        if not isinstance(ob, dict):
            continue
        edge = ob.get("edge")
        info = next((e for e in edges if e["edge"] == edge), None)
        if edge not in starts or info is None or info["planned"] is None or net is None:
            continue
        centres = net.lane_centres(edge)
        lane = int(ob.get("lane", 0))
        if lane not in centres:
            continue
        y = centres[lane] - centres[info["planned"]]
        front = starts[edge] + float(ob.get("pos", 0.0))
        obstacles.append({"id": ob.get("id", "?"), "edge": edge, "s0": front - float(ob.get("length", 4.5)),
                          "s1": front, "y0": y - OBSTACLE_WIDTH / 2, "y1": y + OBSTACLE_WIDTH / 2})

    entered = {}
    for r, sb in zip(timeline, s_base):
        entered.setdefault(r.get("edge", ""), (sb, float(r["time"])))
    phases, marks = lane_change_phases(events, summary, f, entered)
    blinker = []
    speed = [float(r["speed"]) for r in timeline]
    for value, i, j in runs_of([r["blinker"] for r in timeline]):
        if value != "none":
            a, b = s_base[i], span_end(s_base, j)
            blinker.append((min(a, b), max(a, b), value, b < a or any(speed[k] < 0 for k in range(i, j + 1))))

    # The x range: where the plan changes or is not followed, the phases (but pending) and the obstacles.
    active = [s_base[i] for i in range(1, len(planned)) if planned[i] is not None and planned[i - 1] is not None
              and abs(planned[i] - planned[i - 1]) > 1e-4]
    active += [s_base[i] for i in range(len(planned)) if planned[i] is not None and measured[i] is not None
               and abs(planned[i] - measured[i]) > 0.05]
    active += [x for ph in phases if ph["phase"] != "pending" for x in (ph["s0"], ph["s1"])]
    active += [x for o in obstacles for x in (o["s0"], o["s1"])]
    sources = [r.get("blinker_source", "") for r in timeline]
    for source, i, j in runs_of(sources):  # where a maneuver had the blinker on
        if source in MANEUVER_SOURCES:
            active += [s_base[i], span_end(s_base, j)]
    if active:
        margin = max(25.0, 0.15 * (max(active) - min(active)))
        lo, hi = max(min(s_base), min(active) - margin), min(max(s_base), max(active) + margin)
    else:
        lo, hi = min(s_base), max(s_base)
    nan = float("nan")
    return {"s_base": s_base, "measured": [nan if m is None else m for m in measured],
            "planned": [nan if p is None else p for p in planned], "planned_rows": sum(p is not None for p in planned),
            "measured_rows": sum(m is not None for m in measured), "edges": edges, "obstacles": obstacles,
            "phases": phases, "marks": marks, "blinker": blinker, "x_range": (lo, hi), "width": width,
            "base_link_to_front": f, "notes": notes}


def lateral_plot(timeline, events, summary, inputs, path):
    data = lateral_data(timeline, events, summary, inputs)
    if data is None:
        return None
    lo, hi = data["x_range"]
    has_phases = bool(data["phases"])
    fig, (ax, ax_b) = plt.subplots(2, 1, figsize=(13, 6.8), sharex=True,
                                   gridspec_kw={"height_ratios": [4, 1.1 if has_phases else 0.6]})
    s = data["s_base"]
    meas, plan = data["measured"], data["planned"]

    # Lane borders of each maneuver edge, over its span on the route.
    ys = [v for v in meas + plan if not math.isnan(v)]
    for e in data["edges"]:
        a, b = max(e["s0"], lo), min(e["s1"], hi)
        for k, y in enumerate(e["borders"]):
            outer = k in (0, len(e["borders"]) - 1)
            ax.plot([a, b], [y, y], color="#555555", lw=1.4 if outer else 0.9, ls="-" if outer else (0, (6, 4)))
            ys.append(y)
        ax.axhline(0, color="#bbbbbb", lw=0.6, ls=":")
        label = f"{e['edge']}: lanes of the net" + (f", planned lane {e['planned']}" if e["planned"] is not None else "")
        if e["assumed"]:
            label = f"{e['edge']}: one {DEFAULT_LANE_WIDTH} m lane assumed (net not found)"
        ax.text(a + 0.005 * (hi - lo), e["borders"][-1], " " + label, fontsize=7, va="bottom", ha="left",
                color="#555555")
        for k in range(len(e["borders"]) - 1):  # each lane's name just above its right border (off its centre)
            name = "planned lane" if e["assumed"] else f"lane {k}" + (" (planned)" if k == e["planned"] else "")
            ax.text(b - 0.005 * (hi - lo), e["borders"][k] + 0.08, name + " ", fontsize=7, va="bottom", ha="right",
                    color="#555555", zorder=5)
        if e["s0"] > lo:
            ax.axvline(e["s0"], color="#999999", lw=0.8, ls="-.")
        if e["s1"] < hi:
            ax.axvline(e["s1"], color="#999999", lw=0.8, ls="-.")

    for o in data["obstacles"]:
        ax.add_patch(Rectangle((o["s0"], o["y0"]), o["s1"] - o["s0"], o["y1"] - o["y0"], facecolor="#525252",
                               edgecolor="black", alpha=0.8, zorder=4))
        ax.text((o["s0"] + o["s1"]) / 2, o["y1"] + 0.1, f"obstacle {o['id']}", ha="center", va="bottom", fontsize=7.5)
        ys += [o["y0"], o["y1"]]

    w = data["width"] / 2
    ax.fill_between(s, [m - w for m in meas], [m + w for m in meas], color="#bdbdbd", alpha=0.35, lw=0,
                    label=f"ego width ({data['width']:g} m) around the measured offset")
    ax.plot(s, plan, color=PLANNED_COLOR, lw=2.6, alpha=0.75, label=f"planned_offset ({data['planned_rows']} rows)")
    ax.plot(s, meas, color=MEASURED_COLOR, lw=1.0, label=f"lateral_offset, measured ({data['measured_rows']} rows)")
    for m in data["marks"]:
        ax.axvline(m["s"], color="#2c7bb6" if m["what"] == "approved" else "#555555", lw=0.9, ls="--")

    pad = 0.6
    ax.set_ylim(min(ys + [0]) - pad, max(ys + [0]) + pad + 0.6)
    ax.set_xlim(lo, hi)
    ax.set_ylabel("lateral offset [m] (left +)\nfrom the planned lane's centre")
    ax.grid(alpha=0.3)
    ax.set_title(f"{summary.get('scenario', '?')}: lateral plan vs what SUMO drove (at base_link, "
                 f"{data['base_link_to_front']:g} m behind the front bumper)")
    if data["notes"]:
        ax.text(0.01, 0.02, "; ".join(data["notes"]), transform=ax.transAxes, fontsize=7.5, color="#b00000")

    # Strips: the blinker, the lane-change phases.
    rows = ["blinker"] + (["lane change"] if has_phases else [])
    for a, b, value, rev in data["blinker"]:  # (while reversing: half height, on top, hatched)
        ax_b.barh(0.15 if rev else 0, max(b - a, 0.2), left=a, height=0.3 if rev else 0.6, lw=0.4 if rev else 0,
                  color=BLINKER_COLORS.get(value, "#777777"), hatch="xx" if rev else None, edgecolor="black",
                  zorder=3 if rev else 2)
    handles, _ = ax.get_legend_handles_labels()
    handles += [Patch(color=BLINKER_COLORS[v], label=f"blinker {v}") for v in BLINKER_COLORS
                if v in [x[2] for x in data["blinker"]]]
    if any(x[3] for x in data["blinker"]):
        handles.append(Patch(facecolor="white", edgecolor="black", hatch="xx", label="blinker while reversing"))
    if data["obstacles"]:
        handles.append(Patch(facecolor="#525252", edgecolor="black", alpha=0.8, label="obstacle (scenario file)"))
    if has_phases:
        for ph in data["phases"]:
            ax_b.barh(1, max(ph["s1"] - ph["s0"], 0.0), left=ph["s0"], height=0.6,
                      color=PHASE_COLORS.get(ph["phase"], "#777777"), edgecolor="black", lw=0.4)
        used = list(dict.fromkeys(ph["phase"] for ph in data["phases"] if ph["s1"] > ph["s0"]))
        handles += [Patch(facecolor=PHASE_COLORS.get(p, "#777777"), edgecolor="black", lw=0.4,
                          label=PHASE_NAMES.get(p, p)) for p in used]
        for k, m in enumerate(data["marks"]):
            ax_b.plot([m["s"]], [1.42], marker="v", color="#2c7bb6" if m["what"] == "approved" else "black", ms=6)
            ax_b.text(m["s"], 1.5, f"{m['what']} t {m['t']:.1f} s", fontsize=7, ha="center", va="bottom")
        handles.append(Line2D([], [], ls="none", marker="v", color="#2c7bb6", label="approved (dashed line above)"))
    ax_b.set_yticks(range(len(rows)))
    ax_b.set_yticklabels(rows, fontsize=8)
    ax_b.set_ylim(-0.5, len(rows) - 0.5 + (0.6 if has_phases else 0))
    ax_b.set_xlabel("route position s [m] (the ego: its base_link)")
    ax_b.grid(axis="x", alpha=0.3)
    if handles:
        ax_b.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.55 if has_phases else -1.1),
                    fontsize=7.5, ncol=4, frameon=False)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
