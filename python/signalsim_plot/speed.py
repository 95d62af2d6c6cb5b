"""speed.png: why the ego drove the speed it did.

Top: along s, SUMO's speed and the speed signalsim planned (commanded) under the lane speed limit, with
strips below saying what set the plan (timeline speed_limited_by), where SUMO's speed after a step fell
short of the plan (sumo_limited_by: a leader, named once per stretch, or another SUMO rule) and the next
light's state. Then acceleration and jerk along s, and speed over time on the light's state with strips
for the judge's decision, what set the plan and SUMO's shortfalls (time shows how long the ego waited).

timeline.csv has no speed limit column: the limit of the lane the front bumper is in (the speed
planner's, spec: planning/speed_limit_planner.hpp) is read from the run's net (.net.xml) by the lane
names the timeline gives; without the net the picture says so. The plan columns (planned_speed,
speed_limited_by, sumo_speed, sumo_limited_by, leader, leader_gap) are optional: a timeline written
without them is drawn without the plan and its strips. A row's planned speed is the command for the
step that starts there, so it is drawn where the step ends (the next row), as a band under the speed
SUMO reached. The speed axes are fitted to the speeds drawn (speed, plan, lane limits), not to max_speed.
The jerk is the acceleration column's difference quotient, as metrics.cpp computes max_jerk.

speed_data() computes what is drawn; speed_plot() draws it (tests read the data)."""
import math

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.transforms import blended_transform_factory

from signalsim_plot.data import number, runs_of, span_end
from signalsim_plot.style import DECISION_COLORS, LIGHT_COLORS, LIGHT_NAMES

LIMIT_COLOR = "#2166ac"
PLANNED_COLOR = "#35b5d6"
# speed_limited_by: colour and meaning, in legend order; a value not listed is drawn in OTHER_COLOR.
LIMITERS = {
    "max_speed": ("#969696", "the ego's max_speed"),
    "lane_limit": (LIMIT_COLOR, "the lane's speed limit"),
    "limit_ahead": ("#92c5de", "a lower limit ahead (a turn)"),
    "held_on_yellow": ("#f0c000", "held through a light passed on yellow"),
    "light_stop": ("#d7191c", "stopping for a light"),
    "pull_over_goal": ("#1b7837", "stopping at the pull-over goal"),
    "lane_change_hold": ("#762a83", "a lane change's hold point"),
    "avoidance_hold": ("#c51b7d", "an avoidance's hold point"),
    "pull_out_wait": ("#8c510a", "the start planner's wait"),
    "backing": ("#01665e", "backing up"),
}
OTHER_COLOR = "#bdbdbd"
# sumo_limited_by: colour and meaning.
SHORTFALLS = {"leader": ("#ff7f00", "a leader"), "sumo": ("#6a51a3", "another SUMO rule (right of way, lane limit)")}
MERGE_GAP = 3.0  # [s] stretches of one cause closer than this are one stretch (its leader is named once)
HEADROOM = 1.1   # the speed axes' top over the highest speed drawn
HEADER_GID = "legend-heading"


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


def planned_series(timeline):
    """Per row the planned speed, nan where the row has none (SUMO drove, or the timeline has no such column)."""
    values = [number(r.get("planned_speed")) for r in timeline]
    return [math.nan if x is None else x for x in values]


def value_runs(timeline, name, s, t):
    """[(value, s0, s1, t0, t1)] of a text column: consecutive rows with one non-empty value, from the first
    row to the row after the last (a row's value holds for the step that starts there)."""
    return [(value, s[i], span_end(s, j), t[i], span_end(t, j))
            for value, i, j in runs_of([r.get(name, "") for r in timeline]) if value]


def ordered_kinds(values, known):
    """The distinct non-empty values, those in `known` first in its order, then the others as they come."""
    seen = [v for v in dict.fromkeys(values) if v]
    return [k for k in known if k in seen] + [v for v in seen if v not in known]


def shortfall_stretches(timeline, s, t):
    """Where SUMO's speed after a step fell short of the plan: [{kind, leader, first, last, s0, s1, t0, t1,
    steps, min_gap}], one per stretch of one cause (sumo_limited_by and, for `leader`, its id). Stretches
    of one cause less than MERGE_GAP apart are one; `steps` counts the rows that fell short."""
    out = []
    for i, r in enumerate(timeline):
        kind = r.get("sumo_limited_by", "")
        if not kind:
            continue
        who = r.get("leader", "") if kind == "leader" else ""
        last = out[-1] if out else None
        if not (last and (last["kind"], last["leader"]) == (kind, who)
                and t[i] - span_end(t, last["last"]) < MERGE_GAP):
            last = {"kind": kind, "leader": who, "first": i, "steps": 0, "min_gap": None}
            out.append(last)
        last["last"] = i
        last["steps"] += 1
        gap = number(r.get("leader_gap"))
        if gap is not None and (last["min_gap"] is None or gap < last["min_gap"]):
            last["min_gap"] = gap
    for st in out:
        st.update(s0=s[st["first"]], s1=span_end(s, st["last"]), t0=t[st["first"]], t1=span_end(t, st["last"]))
    return out


def speed_range(v, planned, limits):
    """(bottom, top) of the speed axes: the top HEADROOM over the highest speed drawn (speed, plan, lane
    limits; at least 1 m/s), the bottom a little under the lowest speed or 0 (backing goes below 0)."""
    values = [x for x in v + planned if not math.isnan(x)] + [seg[2] for seg in limits]
    lo = min(values + [0.0])
    top = max(values + [1.0]) * HEADROOM
    return lo - 0.03 * (top - lo), top


def limit_info(timeline, net):
    """(limit segments, note): limit_segments(), or [] and why the limit is unknown."""
    if "lane" not in timeline[0]:
        return [], "no lane column in timeline.csv: lane speed limit unknown"
    if net is None:
        return [], "net not found: lane speed limit unknown (timeline.csv has no limit column)"
    limits = limit_segments(timeline, net)
    return limits, None if limits else "the timeline's lanes are not in the net: lane speed limit unknown"


def speed_data(timeline, summary, metrics, net):
    """What speed.png draws.

    s, t, v, a:     per row (front bumper s, time, speed, acceleration)
    jerk:           [(row index, jerk m/s³)] (jerk_series); jerk_s, jerk_t: s and t of those rows
    limits:         limit_segments() or [] without the net; limit_note: why there is no limit line (or None)
    max_speed:      the ego's max_speed (summary ego); accel, decel: its comfortable limits
    lights:         [(light id, stop line s)]; has_light: the timeline names a light
    has_plan:       the timeline has the planned_speed column (older ones do not)
    planned:        per row the planned speed (nan: none); planned_s, planned_t: where it is drawn (next row)
    limited_by:     [(speed_limited_by, s0, s1, t0, t1)] runs; limited_by_kinds: the values met, legend order
    short:          per row sumo_limited_by ('' when SUMO executed the plan or there is no column)
    short_runs:     [(sumo_limited_by, s0, s1, t0, t1)] runs; short_kinds: the values met
    short_stretches: shortfall_stretches() (a leader's id once per stretch)
    y_range:        (bottom, top) of both speed axes (speed_range); max_speed_drawn: max_speed is under the top
    """
    s = [float(r["s_front"]) for r in timeline]
    t = [float(r["time"]) for r in timeline]
    v = [float(r["speed"]) for r in timeline]
    a = [number(r.get("accel")) or 0.0 for r in timeline]
    jerk = jerk_series(t, a)
    ego = summary.get("ego") or {}
    limits, note = limit_info(timeline, net)
    planned = planned_series(timeline)
    limited_by = value_runs(timeline, "speed_limited_by", s, t)
    short_runs = value_runs(timeline, "sumo_limited_by", s, t)
    y_range = speed_range(v, planned, limits)
    max_speed = ego.get("max_speed")
    return {"s": s, "t": t, "v": v, "a": a, "jerk": jerk, "jerk_s": [s[i] for i, _ in jerk],
            "jerk_t": [t[i] for i, _ in jerk], "limits": limits, "limit_note": note,
            "max_speed": max_speed, "accel": ego.get("accel"), "decel": ego.get("decel"),
            "lights": [(l["id"], l["stop_line_s"]) for l in metrics.get("lights", []) if "stop_line_s" in l],
            "has_light": any(r.get("tl_id") for r in timeline),
            "has_plan": "planned_speed" in timeline[0], "planned": planned,
            "planned_s": [span_end(s, i) for i in range(len(s))], "planned_t": [span_end(t, i) for i in range(len(t))],
            "limited_by": limited_by, "limited_by_kinds": ordered_kinds([r[0] for r in limited_by], LIMITERS),
            "short": [r.get("sumo_limited_by", "") for r in timeline], "short_runs": short_runs,
            "short_kinds": ordered_kinds([r[0] for r in short_runs], SHORTFALLS),
            "short_stretches": shortfall_stretches(timeline, s, t),
            "y_range": y_range, "max_speed_drawn": bool(max_speed) and max_speed <= y_range[1]}


# ---- drawing ----

def limiter_color(kind):
    return LIMITERS.get(kind, (OTHER_COLOR, ""))[0]


def shortfall_color(kind):
    return SHORTFALLS.get(kind, (OTHER_COLOR, ""))[0]


def header(text):
    """A legend entry without a symbol: the heading of the entries after it (drawn bold)."""
    return Line2D([], [], linestyle="none", label=text, gid=HEADER_GID)


def bold_headers(legend, headers):
    """Draws the legend texts named in `headers` bold."""
    for text in legend.get_texts():
        if text.get_text() in headers:
            text.set_fontweight("bold")


def side_legend(ax, handles):
    """The legend right of the axes (the curves use the whole height); headings in bold."""
    if not handles:
        return
    legend = ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7.5,
                       framealpha=0.9, borderaxespad=0.0)
    bold_headers(legend, {h.get_label() for h in handles if h.get_gid() == HEADER_GID})


def rows_at(data, x_of_run):
    """The strip rows shared by both strip panels: what set the plan, and where SUMO fell short of it.
    x_of_run picks (x0, x1) from a (value, s0, s1, t0, t1) run."""
    rows = []
    if data["limited_by"]:
        rows.append(("plan set by", [(limiter_color(r[0]), *x_of_run(r)) for r in data["limited_by"]]))
    if data["short_runs"]:
        rows.append(("SUMO short of plan", [(shortfall_color(r[0]), *x_of_run(r)) for r in data["short_runs"]]))
    return rows


def draw_strips(ax, rows, xlim):
    """Rows of coloured spans, top to bottom, each named on the y axis: rows = [(name, [(colour, x0, x1)])]."""
    for k, (_name, spans) in enumerate(rows):
        for color, x0, x1 in spans:
            ax.barh(k, x1 - x0, left=x0, height=0.8, color=color, lw=0, antialiased=False)  # no seams
    ax.set_ylim(len(rows) - 0.5, -0.5)
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels([name for name, _ in rows], fontsize=8)
    ax.tick_params(axis="y", length=0)
    ax.set_xlim(*xlim)
    for side in ("top", "right", "left"):
        ax.spines[side].set_visible(False)


def label_leaders(ax, rows, stretches, x_of_stretch):
    """The leader's id once per stretch, just after its end in the 'SUMO short of plan' row (the stretch's
    marks stay visible); returns the texts."""
    names = [name for name, _ in rows]
    if "SUMO short of plan" not in names:
        return []
    row = names.index("SUMO short of plan")
    texts = []
    for st in stretches:
        if st["kind"] == "leader" and st["leader"]:
            gap = f" (closest {st['min_gap']:.1f} m)" if st["min_gap"] is not None else ""
            texts.append(ax.text(x_of_stretch(st), row, f" behind {st['leader']}{gap}", fontsize=7, va="center",
                                 ha="left", clip_on=True, color="#7f3b08"))
    return texts


def hide_overlapping(fig, texts):
    """Hides each label that overlaps one drawn before it (left to right), so no labels overlap."""
    if len(texts) < 2:
        return
    fig.canvas.draw()  # lays the figure out: the labels' extents are final
    renderer = fig.canvas.get_renderer()
    kept = []
    for text in sorted(texts, key=lambda x: x.get_window_extent(renderer).x0):
        box = text.get_window_extent(renderer)
        if any(box.overlaps(k) for k in kept):
            text.set_visible(False)
        else:
            kept.append(box)


def draw_speed_lines(ax, x, planned_x, data):
    """The plan as a light band under SUMO's speed (black): where SUMO executed it the black line runs inside
    the band, where SUMO fell short the band stays above; the steps that fell short are marked where they
    ended, coloured by the cause. Returns the legend handles."""
    v, short = data["v"], data["short"]
    handles = [Line2D([], [], color="black", lw=1.3, label="speed (SUMO)")]
    if any(not math.isnan(p) for p in data["planned"]):
        ax.plot(planned_x, data["planned"], color=PLANNED_COLOR, lw=3.2, alpha=0.55, solid_capstyle="butt", zorder=1)
        handles.append(Line2D([], [], color=PLANNED_COLOR, lw=3.2, alpha=0.55,
                              label="planned speed (signalsim's command)"))
    ax.plot(x, v, color="black", lw=1.3, zorder=2)
    for kind in data["short_kinds"]:  # at the row after the short step: the speed SUMO reached
        ends = [i + 1 for i in range(len(v) - 1) if short[i] == kind]
        ax.plot([x[i] for i in ends], [v[i] for i in ends], "v", color=shortfall_color(kind), ms=3.5, zorder=3)
        handles.append(Line2D([], [], marker="v", ls="none", color=shortfall_color(kind), ms=3.5,
                              label=f"short of plan: {kind} ({SHORTFALLS.get(kind, ('', kind))[1]})"))
    return handles


def draw_limits(ax, data):
    """The lane speed limit along s, its changes labelled; the ego's max_speed when it is within the axis.
    Returns the legend handles."""
    handles = []
    limits = data["limits"]
    for k, (s0, s1, limit, _lane) in enumerate(limits):
        ax.plot([s0, s1], [limit, limit], color=LIMIT_COLOR, lw=1.6)
        if k + 1 < len(limits):
            ax.plot([s1, s1], [limit, limits[k + 1][2]], color=LIMIT_COLOR, lw=0.8, ls=":")
            ax.text(s1, limits[k + 1][2], f" {limits[k + 1][2]:.2f}", fontsize=7, color=LIMIT_COLOR,
                    va="bottom", ha="left")
    if limits:
        handles.append(Line2D([], [], color=LIMIT_COLOR, lw=1.6, label="lane speed limit (net)"))
    if data["max_speed_drawn"]:
        ax.axhline(data["max_speed"], color="#777777", lw=1.0, ls="--")
        handles.append(Line2D([], [], color="#777777", lw=1.0, ls="--",
                              label=f"ego max_speed {data['max_speed']:g} m/s"))
    elif data["max_speed"]:
        handles.append(Line2D([], [], linestyle="none",
                              label=f"(ego max_speed {data['max_speed']:g} m/s: above the axis)"))
    return handles


def draw_stop_lines(ax, data):
    """The stop lines along s, named above the axes; returns the names (texts)."""
    above = blended_transform_factory(ax.transData, ax.transAxes)
    texts = []
    for light, stop_s in data["lights"]:
        ax.axvline(stop_s, color="#d7191c", lw=1.2, ls="--")
        texts.append(ax.text(stop_s, 1.0, f"stop line {light}", transform=above, color="#d7191c", fontsize=8,
                             va="bottom", ha="center"))
    return texts


def strip_legend(data, light_states):
    """Legend entries of the strips: a heading and one patch per value met."""
    handles = []
    if data["limited_by_kinds"]:
        handles.append(header("plan set by (strip)"))
        handles += [Patch(color=limiter_color(k), label=f"{k}: {LIMITERS[k][1]}" if k in LIMITERS else k)
                    for k in data["limited_by_kinds"]]
    if data["short_kinds"]:
        handles.append(header("SUMO short of plan (strip)"))
        handles += [Patch(color=shortfall_color(k), label=k) for k in data["short_kinds"]]
    if light_states:
        handles.append(header("next light (strip)"))
        handles += [Patch(color=LIGHT_COLORS.get(k, OTHER_COLOR), label=LIGHT_NAMES.get(k, k)) for k in light_states]
    return handles


def light_runs(timeline):
    """[((light, state), i, j)] runs of the next light's state, only where there is one."""
    pairs = [(r.get("tl_id", ""), r.get("tl_state", "")) for r in timeline]
    return [(key, i, j) for key, i, j in runs_of(pairs) if key[0] and key[1]]


def draw_along_s(ax, ax_strip, timeline, summary, data):
    """The speed-along-s panel and its strips; returns the labels to keep apart."""
    s = data["s"]
    xlim = (min(s), max(s))
    handles = draw_speed_lines(ax, s, data["planned_s"], data)
    handles += draw_limits(ax, data)
    texts = draw_stop_lines(ax, data)
    v = data["v"]
    rest = [(s[i], v[i]) for i in range(len(v)) if abs(v[i]) < 0.05 and i + 1 < len(v)]
    if rest:
        ax.plot([p[0] for p in rest], [p[1] for p in rest], "o", color="#984ea3", ms=4, zorder=4)
        handles.append(Line2D([], [], marker="o", color="#984ea3", ms=4, ls="none", label="at rest"))
    ax.set_ylim(*data["y_range"])
    ax.set_xlim(*xlim)
    ax.set_ylabel("speed [m/s]")
    ax.grid(alpha=0.3)
    rows = rows_at(data, lambda r: (r[1], r[2]))
    states = []
    if data["has_light"]:
        lights = light_runs(timeline)
        states = list(dict.fromkeys(state for (_, state), _, _ in lights))
        rows.append(("next light", [(LIGHT_COLORS.get(state, OTHER_COLOR), s[i], span_end(s, j))
                                    for (_, state), i, j in lights]))
    if ax_strip is not None:
        draw_strips(ax_strip, rows, xlim)
        ax_strip.tick_params(axis="x", labelbottom=False)
        texts += label_leaders(ax_strip, rows, data["short_stretches"], lambda st: st["s1"])
    side_legend(ax, handles + strip_legend(data, states))
    title = f"{summary.get('scenario', '?')}: speed along the route"
    if data["has_plan"]:
        title += ", the plan and what set it"
    if data["limits"]:
        title += ", under the lane speed limit"
    ax.set_title(title, pad=14 if data["lights"] else 6)
    if data["limit_note"]:
        ax.text(0.99, 0.97, data["limit_note"], transform=ax.transAxes, ha="right", va="top", fontsize=8,
                color="#b00000")
    return texts


def draw_accel(ax, data, metrics):
    """Acceleration along s with the ego's limits."""
    s, a = data["s"], data["a"]
    ax.plot(s, a, color="#4d4d4d", lw=1.1)
    if data["accel"]:
        ax.axhline(data["accel"], color="#777777", lw=0.8, ls="--")
    if data["decel"]:
        ax.axhline(-data["decel"], color="#777777", lw=0.8, ls="--")
    ax.axhline(0, color="black", lw=0.5)
    ax.set_ylabel("accel [m/s²]")
    ax.set_xlim(min(s), max(s))
    ax.grid(alpha=0.3)
    limits_text = (f" (dashed: ego accel {data['accel']:g}, decel {data['decel']:g} m/s²)"
                   if data["accel"] and data["decel"] else "")
    ax.set_title(f"acceleration (timeline accel column){limits_text}; max decel "
                 f"{metrics.get('max_decel', max([-x for x in a] + [0])):g} m/s²", fontsize=9)


def draw_jerk(ax, data):
    """Jerk along s: the accel column's difference quotient."""
    s = data["s"]
    jerks = [j for _, j in data["jerk"]]
    ax.plot(data["jerk_s"], jerks, color="#8c2d04", lw=1.0)
    ax.axhline(0, color="black", lw=0.5)
    ax.set_ylabel("jerk [m/s³]")
    ax.set_xlim(min(s), max(s))
    ax.set_xlabel("route position s of the front bumper [m]")
    ax.grid(alpha=0.3)
    worst = max([abs(j) for j in jerks] + [0.0])
    ax.set_title(f"jerk = Δaccel / Δt between rows; max |jerk| {worst:.2f} m/s³", fontsize=9)


def draw_stop_line_times(ax, data):
    """When the front crossed each stop line."""
    s, t = data["s"], data["t"]
    bottom = blended_transform_factory(ax.transData, ax.transAxes)
    for light, stop_s in data["lights"]:
        for i in range(1, len(s)):
            if s[i - 1] < stop_s <= s[i]:
                ax.axvline(t[i], color="#d7191c", lw=1.2, ls="--")
                ax.text(t[i], 0.03, f"front crosses stop line {light} ", transform=bottom, color="#d7191c",
                        fontsize=8, va="bottom", ha="right", rotation=90)
                break


def draw_over_time(ax, ax_strip, timeline, data):
    """Speed over time on the next light's state, with its strips; returns the labels to keep apart."""
    t = data["t"]
    xlim = (min(t), max(t))
    handles = draw_speed_lines(ax, t, data["planned_t"], data)
    used = set()
    for (_, state), i, j in light_runs(timeline):
        ax.axvspan(t[i], span_end(t, j), color=LIGHT_COLORS.get(state, OTHER_COLOR), alpha=0.25, lw=0)
        used.add(state)
    draw_stop_line_times(ax, data)
    ax.set_ylim(*data["y_range"])
    ax.set_xlim(*xlim)
    ax.set_ylabel("speed [m/s]")
    ax.grid(alpha=0.3)
    decisions = [r.get("tl_decision", "") for r in timeline]
    rows = []
    if any(d in DECISION_COLORS for d in decisions):
        rows.append(("judge", [(DECISION_COLORS[d], t[i], span_end(t, j))
                               for d, i, j in runs_of(decisions) if d in DECISION_COLORS]))
        handles.append(header("judge's decision (strip)"))
        handles += [Patch(color=c, label=d) for d, c in DECISION_COLORS.items() if d in decisions]
    rows += rows_at(data, lambda r: (r[3], r[4]))
    texts = []
    if ax_strip is not None:
        draw_strips(ax_strip, rows, xlim)
        ax_strip.set_xlabel("time [s]")
        texts = label_leaders(ax_strip, rows, data["short_stretches"], lambda st: st["t1"])
    else:
        ax.set_xlabel("time [s]")
    if used:
        handles.append(header("next light (background)"))
        handles += [Patch(color=LIGHT_COLORS[k], alpha=0.25, label=LIGHT_NAMES[k]) for k in LIGHT_COLORS if k in used]
    if data["limited_by"] or data["short_runs"]:
        handles.append(header("other strips: colours as above"))
    if len(handles) > 1:  # (more than the speed line alone)
        side_legend(ax, handles)
    ax.set_title("speed over time" + (" on the next light's state" if used else ""))
    return texts


def strip_rows_count(data, timeline):
    """(rows of the strip under speed along s, rows of the strip under speed over time)."""
    shared = bool(data["limited_by"]) + bool(data["short_runs"])
    judged = any(r.get("tl_decision", "") in DECISION_COLORS for r in timeline)
    return shared + data["has_light"], shared + judged


def speed_plot(timeline, summary, metrics, net, path):
    """Draws speed.png to `path` (panels top to bottom: speed along s and its strips, acceleration, jerk,
    speed over time and its strips); returns `path`."""
    data = speed_data(timeline, summary, metrics, net)
    n_s, n_t = strip_rows_count(data, timeline)
    panels = ["speed_s"] + (["strip_s"] if n_s else []) + ["accel", "jerk", "speed_t"] + (["strip_t"] if n_t else [])
    ratios = {"speed_s": 3.2, "strip_s": 0.22 * n_s + 0.1, "accel": 1.3, "jerk": 1.3, "speed_t": 2.4,
              "strip_t": 0.22 * n_t + 0.1}
    heights = [ratios[p] for p in panels]
    fig = plt.figure(figsize=(15, sum(heights) + 2.4), layout="constrained")
    grid = fig.add_gridspec(len(panels), 1, height_ratios=heights)
    axes = {}
    for k, name in enumerate(panels):
        share = axes.get("speed_s") if name in ("strip_s", "accel", "jerk") else axes.get("speed_t")
        axes[name] = fig.add_subplot(grid[k], sharex=share)
    texts = draw_along_s(axes["speed_s"], axes.get("strip_s"), timeline, summary, data)
    draw_accel(axes["accel"], data, metrics)
    draw_jerk(axes["jerk"], data)
    texts_t = draw_over_time(axes["speed_t"], axes.get("strip_t"), timeline, data)
    hide_overlapping(fig, texts + texts_t)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
