"""speed.png: speed along s under the lane speed limit, acceleration and jerk, and speed over time.

timeline.csv has no speed limit column: the limit of the lane the front bumper is in (the speed
planner's, spec: planning/speed_limit_planner.hpp) is read from the run's net (.net.xml) by the lane
names the timeline gives; without the net the picture says so and shows only the ego's max_speed.
The jerk is the acceleration column's difference quotient, as metrics.cpp computes max_jerk.

speed_data() computes what is drawn; speed_plot() draws it (tests read the data)."""
import matplotlib.pyplot as plt
from matplotlib.patches import Patch

from signalsim_plot.data import number, runs_of, span_end
from signalsim_plot.style import DECISION_COLORS, LIGHT_COLORS, LIGHT_NAMES

LIMIT_COLOR = "#2166ac"


def jerk_series(t, a):
    """[(row index, jerk)] for rows after the first whose time advanced: (a[i] - a[i-1]) / (t[i] - t[i-1])."""
    return [(i, (a[i] - a[i - 1]) / (t[i] - t[i - 1])) for i in range(1, len(t)) if t[i] > t[i - 1]]


def limit_segments(timeline, net):
    """[(s0, s1, limit m/s, lane id)] along s_front: the speed limit of the lane the front is in. A lane of a
    new edge starts where the net puts the front's (x, y) on that lane (the lane's start on the route)."""
    s = [float(r["s_front"]) for r in timeline]
    out = []
    prev_edge = None
    for lane_id, i, j in runs_of([r.get("lane", "") for r in timeline]):
        lane = net.lanes.get(lane_id) if lane_id else None
        if lane is None:
            continue
        start = s[i]
        x, y = number(timeline[i].get("x")), number(timeline[i].get("y"))
        if out and lane.edge != prev_edge and x is not None and y is not None:
            p = lane.position_of(x, y)  # the front's lane position on its first row there
            if 0 <= p <= lane.length + 0.5 and s[i] - p >= out[-1][0]:
                start = s[i] - p
        if out:
            out[-1] = (out[-1][0], start, out[-1][2], out[-1][3])
        else:
            start = min(s[i:j + 1])  # (the first lane from where the ego was first: it may back up)
        out.append((start, span_end(s, j), lane.speed, lane_id))
        prev_edge = lane.edge
    merged = []  # consecutive lanes with the same limit: one segment
    for seg in out:
        if merged and merged[-1][2] == seg[2]:
            merged[-1] = (merged[-1][0], seg[1], seg[2], merged[-1][3])
        else:
            merged.append(seg)
    return merged


def speed_data(timeline, summary, metrics, net):
    """What speed.png draws.

    s, t, v, a:   per row (front bumper s, time, speed, acceleration)
    jerk:         [(row index, jerk m/s³)] (jerk_series); jerk_s, jerk_t: s and t of those rows
    limits:       limit_segments() or [] without the net; limit_note: why there is no limit line (or None)
    max_speed:    the ego's max_speed (summary ego); accel, decel: its comfortable limits
    lights:       [(light id, stop line s)]; has_light: the timeline names a light
    """
    s = [float(r["s_front"]) for r in timeline]
    t = [float(r["time"]) for r in timeline]
    v = [float(r["speed"]) for r in timeline]
    a = [number(r.get("accel")) or 0.0 for r in timeline]
    jerk = jerk_series(t, a)
    ego = summary.get("ego") or {}
    limits, note = [], None
    if "lane" not in timeline[0]:
        note = "no lane column in timeline.csv: lane speed limit unknown"
    elif net is None:
        note = "net not found: lane speed limit unknown (timeline.csv has no limit column)"
    else:
        limits = limit_segments(timeline, net)
        if not limits:
            note = "the timeline's lanes are not in the net: lane speed limit unknown"
    return {"s": s, "t": t, "v": v, "a": a, "jerk": jerk, "jerk_s": [s[i] for i, _ in jerk],
            "jerk_t": [t[i] for i, _ in jerk], "limits": limits, "limit_note": note,
            "max_speed": ego.get("max_speed"), "accel": ego.get("accel"), "decel": ego.get("decel"),
            "lights": [(l["id"], l["stop_line_s"]) for l in metrics.get("lights", []) if "stop_line_s" in l],
            "has_light": any(r.get("tl_id") for r in timeline)}


def speed_plot(timeline, summary, metrics, net, path):
    data = speed_data(timeline, summary, metrics, net)
    s, t, v, a = data["s"], data["t"], data["v"], data["a"]
    states = [r.get("tl_state", "") for r in timeline]
    ids = [r.get("tl_id", "") for r in timeline]
    decisions = [r.get("tl_decision", "") for r in timeline]
    has_decisions = any(d and d != "none" for d in decisions)
    has_light = data["has_light"]

    fig, (ax_s, ax_a, ax_j, ax_t) = plt.subplots(4, 1, figsize=(13, 11.5),
                                                 gridspec_kw={"height_ratios": [3, 1.4, 1.4, 2.4]})
    # Speed along s, under the lane limit; below it, the light state the ego saw at each position.
    top = max(v + [l[2] for l in data["limits"]] + [data["max_speed"] or 0, 1.0])
    vmax = top * 1.4  # room for the legend
    ax_s.plot(s, v, color="black", lw=1.4, label="speed")
    for k, (s0, s1, limit, _lane) in enumerate(data["limits"]):
        ax_s.plot([s0, s1], [limit, limit], color=LIMIT_COLOR, lw=1.6, label="lane speed limit (net)" if k == 0 else None)
        if k + 1 < len(data["limits"]):
            ax_s.plot([s1, s1], [limit, data["limits"][k + 1][2]], color=LIMIT_COLOR, lw=0.8, ls=":")
            ax_s.text(s1, data["limits"][k + 1][2], f" {data['limits'][k + 1][2]:.2f}", fontsize=7, color=LIMIT_COLOR,
                      va="bottom", ha="left")
    if data["max_speed"]:
        ax_s.axhline(data["max_speed"], color="#777777", lw=1.0, ls="--",
                     label=f"ego max_speed {data['max_speed']:g} m/s")
    for light, stop_s in data["lights"]:
        ax_s.axvline(stop_s, color="#d7191c", lw=1.2, ls="--")
        ax_s.text(stop_s, vmax * 0.97, f"stop line {light} ", color="#d7191c", fontsize=8, va="top", ha="right",
                  rotation=90)
    rest = [(s[i], v[i]) for i in range(len(v)) if abs(v[i]) < 0.05 and i + 1 < len(v)]
    if rest:
        ax_s.plot([p[0] for p in rest], [p[1] for p in rest], "o", color="#984ea3", ms=4, label="at rest")
    seen_states = []
    bottom = min(v + [0.0])
    if has_light:
        strip_h = vmax * 0.06
        for (light, state), i, j in runs_of(list(zip(ids, states))):
            if light and state:
                ax_s.barh(bottom - strip_h * 0.9, span_end(s, j) - s[i], left=s[i], height=strip_h,
                          color=LIGHT_COLORS.get(state, "#bdbdbd"), lw=0)
                if state not in seen_states:
                    seen_states.append(state)
        ax_s.set_ylim(bottom - strip_h * 1.6, vmax)
    else:
        ax_s.set_ylim(min(bottom * 1.2, 0), vmax)
    ax_s.set_xlim(min(s), max(s))
    ax_s.set_ylabel("speed [m/s]")
    ax_s.grid(alpha=0.3)
    handles, _ = ax_s.get_legend_handles_labels()
    handles += [Patch(color=LIGHT_COLORS.get(k, "#bdbdbd"), label=f"strip: next light {LIGHT_NAMES.get(k, k)}")
                for k in seen_states]
    # the legend on the top side with fewer stop lines (their labels stand at the top)
    mid = (min(s) + max(s)) / 2
    left_lines = sum(1 for _, stop_s in data["lights"] if stop_s < mid)
    right_lines = len(data["lights"]) - left_lines
    ax_s.legend(handles=handles, loc="upper right" if left_lines > right_lines else "upper left", fontsize=7.5,
                ncol=3, framealpha=0.9)
    title = f"{summary.get('scenario', '?')}: speed along the route"
    if data["limits"]:
        title += " under the lane speed limit"
    if seen_states:
        title += " (bottom strip: the next light's state)"
    ax_s.set_title(title)
    if data["limit_note"]:
        ax_s.text(0.99, 0.97, data["limit_note"], transform=ax_s.transAxes, ha="right", va="top", fontsize=8,
                  color="#b00000")

    # Acceleration and jerk along s.
    ax_a.plot(s, a, color="#4d4d4d", lw=1.1)
    if data["accel"]:
        ax_a.axhline(data["accel"], color="#777777", lw=0.8, ls="--")
    if data["decel"]:
        ax_a.axhline(-data["decel"], color="#777777", lw=0.8, ls="--")
    ax_a.axhline(0, color="black", lw=0.5)
    ax_a.set_ylabel("accel [m/s²]")
    ax_a.set_xlim(min(s), max(s))
    ax_a.grid(alpha=0.3)
    limits_text = f" (dashed: ego accel {data['accel']:g}, decel {data['decel']:g} m/s²)" if data["accel"] and data["decel"] else ""
    ax_a.set_title(f"acceleration (timeline accel column){limits_text}; max decel "
                   f"{metrics.get('max_decel', max([-x for x in a] + [0])):g} m/s²", fontsize=9)
    jerks = [j for _, j in data["jerk"]]
    ax_j.plot(data["jerk_s"], jerks, color="#8c2d04", lw=1.0)
    ax_j.axhline(0, color="black", lw=0.5)
    ax_j.set_ylabel("jerk [m/s³]")
    ax_j.set_xlim(min(s), max(s))
    ax_j.set_xlabel("route position s of the front bumper [m]")
    ax_j.grid(alpha=0.3)
    worst = max([abs(j) for j in jerks] + [0.0])
    ax_j.set_title(f"jerk = Δaccel / Δt between rows; max |jerk| {worst:.2f} m/s³", fontsize=9)

    # Speed over time, on the light states when there is a light (time shows how long the ego waited).
    ax_t.plot(t, v, color="black", lw=1.4)
    used = set()
    if has_light:
        for (light, state), i, j in runs_of(list(zip(ids, states))):
            if light and state:
                ax_t.axvspan(t[i], span_end(t, j), color=LIGHT_COLORS.get(state, "#bdbdbd"), alpha=0.25, lw=0)
                used.add(state)
    vmax_t = max(v + [1.0]) * 1.25
    bottom_t = min(v + [0.0])
    if has_decisions:
        strip = vmax_t * 0.06
        for d, i, j in runs_of(decisions):
            if d in DECISION_COLORS:
                ax_t.barh(bottom_t - strip * 0.9, span_end(t, j) - t[i], left=t[i], height=strip,
                          color=DECISION_COLORS[d], lw=0)
        ax_t.set_ylim(bottom_t - strip * 1.6, vmax_t)
    else:
        ax_t.set_ylim(min(bottom_t * 1.2, 0), vmax_t)
    for light, stop_s in data["lights"]:  # when the front crossed each stop line
        for i in range(1, len(s)):
            if s[i - 1] < stop_s <= s[i]:
                ax_t.axvline(t[i], color="#d7191c", lw=1.2, ls="--")
                ax_t.text(t[i], vmax_t * 0.03, f"front crosses stop line {light} ", color="#d7191c",
                          fontsize=8, va="bottom", ha="right", rotation=90)
                break
    ax_t.set_xlim(min(t), max(t))
    ax_t.set_xlabel("time [s]")
    ax_t.set_ylabel("speed [m/s]")
    ax_t.grid(alpha=0.3)
    handles = [Patch(color=LIGHT_COLORS[k], alpha=0.25, label=f"next light {LIGHT_NAMES[k]}")
               for k in LIGHT_COLORS if k in used]
    if has_decisions:
        handles += [Patch(color=c, label=f"judge: {d}") for d, c in DECISION_COLORS.items() if d in decisions]
    if handles:
        ax_t.legend(handles=handles, loc="upper right", fontsize=7.5, ncol=2, framealpha=0.9)
    title = "speed over time"
    if used:
        title += " on the next light's state"
    if has_decisions:
        title += " (bottom strip: the judge's decision)"
    ax_t.set_title(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
