"""dilemma.png: the dilemma-zone diagram (docs/behaviour.md §L2) of each light where the ego met a yellow or a red.

Per light: the jerk-limited stopping distance and the yellow lamp line d = v · yellow_lamp_period over
the speed as the run's judge computed them (the run's judge_curves.csv: nothing of the judge is computed
here; a run without the file is drawn without the curves and says so), the zones between them, and the ego's approach (d, v) per step coloured by the light's state,
with where the yellow (red) began and where the judge first ordered a stop. A light the ego met only
in green (or off) has no panel; a run with no such light has no dilemma.png.

dilemma_data() computes what is drawn; dilemma_plot() draws it (tests read the data)."""
import math
import os

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D

from signalsim_plot.data import number, read_csv
from signalsim_plot.style import LIGHT_COLORS, LIGHT_NAMES, STOP_STATES

MAX_PANELS = 3
CURVES_FILE = "judge_curves.csv"


def read_curves(run_dir):
    """The judge's curves the run wrote ({v, judge, yellow}, lists over the speed), None without the file."""
    path = os.path.join(run_dir, CURVES_FILE)
    if not os.path.isfile(path):
        return None
    rows = read_csv(path)
    return {"v": [float(r["speed"]) for r in rows], "judge": [float(r["judge_distance"]) for r in rows],
            "yellow": [float(r["yellow_lamp_line"]) for r in rows]}


def lights_of(metrics, timeline, params):
    """[(light id, stop point s or None)]: the metrics' lights, else the lights the timeline names."""
    margin = params.get("stop_margin", 0.0) or 0.0
    lights = [(l["id"], l["stop_line_s"] - margin) for l in metrics.get("lights", []) if "stop_line_s" in l]
    if lights:
        return lights
    seen = []
    for r in timeline:
        if r.get("tl_id") and r["tl_id"] not in [x[0] for x in seen]:
            seen.append((r["tl_id"], None))
    return seen


def stop_distances(timeline, light, stop_s):
    """d (front bumper to the stop point) per row approaching `light`, None elsewhere."""
    out = []
    for r in timeline:
        d = None
        if r.get("tl_id") == light:
            d = number(r.get("stop_distance"))
            if d is None and stop_s is not None:
                d = stop_s - float(r["s_front"])
        out.append(d)
    return out


def dilemma_data(timeline, summary, metrics, curves):
    """What dilemma.png draws, or None when no light met the ego with a yellow or a red.

    panels: per such light {light, stop_s, points [(d, v, state, decision, t)] (the approach, d >= -2),
            met (the states seen on the approach), first_stop_state (index of the first point with a yellow
            or red ahead of the line), first_stop_decision (index of the first point the judge said stop or
            emergency_stop, or None), d_range (x range: from the line to the farthest of the first yellow/red,
            the first stop decision and the zone curves), zoom (x range of a second panel on the zones when the
            approach is much longer than they are, else None)}
    curve:  {v, judge, yellow} over the speed axis up to v_top: the rows of the run's judge_curves.csv
            (`curves`, read_curves()), None without them; params: the parameters used; skipped: lights the
            ego met with no yellow or red
    """
    params = summary.get("parameters", {})
    t_y = params.get("yellow_lamp_period", 2.75)
    a_s = params.get("max_accel", -2.8)
    j_s = params.get("max_jerk", -5.0)
    t_d = params.get("delay_response_time", 0.5)
    speeds = [float(r["speed"]) for r in timeline]
    times = [float(r["time"]) for r in timeline]
    v_top = max(max(speeds) * 1.3, 12.0)
    curve = None
    if curves:
        keep = [k for k, v in enumerate(curves["v"]) if v <= v_top + 1e-9]
        curve = {name: [curves[name][k] for k in keep] for name in ("v", "judge", "yellow")}
    d_curves = max(max(curve["judge"]), max(curve["yellow"])) * 1.05 if curve else 0.0
    panels, skipped = [], []
    for light, stop_s in lights_of(metrics, timeline, params):
        d = stop_distances(timeline, light, stop_s)
        points = [(d[i], speeds[i], timeline[i].get("tl_state", ""), timeline[i].get("tl_decision", ""), times[i])
                  for i in range(len(d)) if d[i] is not None and d[i] >= -2.0]
        first = next((k for k, p in enumerate(points) if p[2] in STOP_STATES and p[0] >= 0), None)
        if first is None:
            skipped.append(light)
            continue
        decision = next((k for k, p in enumerate(points) if p[3] in ("stop", "emergency_stop")), None)
        far = max([points[first][0], d_curves] + ([points[decision][0]] if decision is not None else []))
        d_range = (min([-2.0] + [p[0] for p in points]), far * 1.06)
        panels.append({"light": light, "stop_s": stop_s, "points": points,
                       "met": list(dict.fromkeys(p[2] for p in points if p[2] and p[0] <= d_range[1])),
                       "first_stop_state": first, "first_stop_decision": decision, "d_range": d_range,
                       "zoom": (d_range[0], d_curves) if curve and far > 2.5 * d_curves else None})
    if not panels:
        return None
    return {"panels": panels[:MAX_PANELS], "curve": curve, "v_top": v_top, "skipped": skipped,
            "params": {"yellow_lamp_period": t_y, "max_accel": a_s, "max_jerk": j_s, "delay_response_time": t_d,
                       "yellow_light_stop_velocity": params.get("yellow_light_stop_velocity")}}


def draw_curves(ax, data, d_range):
    """The judge's curves and zones, as the run wrote them; a note when it wrote none."""
    c, prm, v_top = data["curve"], data["params"], data["v_top"]
    d_lo, d_hi = d_range
    if c is None:
        ax.text(0.5, 0.5, f"no {CURVES_FILE} in the run folder: the judge's curves are not drawn",
                transform=ax.transAxes, ha="center", fontsize=8.5, color="#777777")
        return
    vs, judge, yellow = c["v"], c["judge"], c["yellow"]
    ax.fill_betweenx(vs, yellow, judge, where=[j > y for j, y in zip(judge, yellow)], color="#d7191c",
                     alpha=0.18, lw=0, label="dilemma zone: emergency stop")
    ax.fill_betweenx(vs, judge, yellow, where=[y > j for j, y in zip(judge, yellow)], color="#2b83ba",
                     alpha=0.15, lw=0, label="optional zone: stop")
    ax.plot(judge, vs, color="#d7191c", lw=1.8, label=f"stopping distance (a {prm['max_accel']} m/s², "
                                                       f"j {prm['max_jerk']} m/s³, delay {prm['delay_response_time']} s)")
    ax.plot(yellow, vs, color="#e6a000", lw=1.8, label=f"yellow lamp line d = v · {prm['yellow_lamp_period']} s")
    v_slow = prm["yellow_light_stop_velocity"]
    if v_slow:
        ax.axhline(v_slow, color="#555555", lw=0.8, ls=":")
        ax.text(d_hi - 0.02 * (d_hi - d_lo), v_slow, f"below {v_slow} m/s: always stop", fontsize=7, ha="right",
                va="bottom", color="#555555")
    ax.text(d_hi - 0.03 * (d_hi - d_lo), v_top * 0.3, "can stop → stop", fontsize=8.5, color="#555555", ha="right")
    ax.text(d_lo + 0.03 * (d_hi - d_lo), v_top * 0.97, "cannot stop,\nreaches the line\n→ pass", fontsize=8.5,
            color="#555555", ha="left", va="top")


def draw_panel(ax, panel, data, d_range, title):
    v_top = data["v_top"]
    d_lo, d_hi = d_range
    draw_curves(ax, data, d_range)

    pts = panel["points"]
    ax.plot([p[0] for p in pts], [p[1] for p in pts], color="#333333", lw=0.8, zorder=3)
    ax.scatter([p[0] for p in pts], [p[1] for p in pts], c=[LIGHT_COLORS.get(p[2], "#bdbdbd") for p in pts],
               s=13, zorder=4, edgecolors="black", linewidths=0.3)
    marks = [(panel["first_stop_state"], "*", 15, None)]
    if panel["first_stop_decision"] is not None:
        marks.append((panel["first_stop_decision"], "X", 10, "black"))
    for k, marker, size, color in marks:
        d0, v0, state, decision, t0 = pts[k]
        if not d_lo <= d0 <= d_hi:
            continue
        text = (f"{LIGHT_NAMES.get(state, state)} met at d {d0:.1f} m, v {v0:.1f} m/s" if marker == "*"
                else f"judge: {decision} (t {t0:.1f} s, d {d0:.1f} m)")
        ax.plot([d0], [v0], marker=marker, ms=size, color=color or LIGHT_COLORS.get(state, "#e6a000"), mec="black",
                zorder=5)
        near_right = d0 > d_lo + 0.6 * (d_hi - d_lo)
        ax.annotate(text, (d0, v0), xytext=(-12 if near_right else 12, 16 if marker == "*" else -18),
                    textcoords="offset points", fontsize=8, ha="right" if near_right else "left",
                    arrowprops=dict(arrowstyle="-", color="black", lw=0.6))
    ax.set_xlim(d_lo, d_hi)
    ax.set_ylim(0, v_top)
    ax.axvline(0, color="black", lw=0.8)
    ax.set_xlabel("distance d from the front bumper to the stop point [m]")
    ax.set_ylabel("speed v [m/s]")
    ax.grid(alpha=0.3)
    ax.set_title(title)


def dilemma_plot(timeline, summary, metrics, curves, path):
    data = dilemma_data(timeline, summary, metrics, curves)
    if data is None:
        return None
    panels = data["panels"]
    cols = 2 if any(p["zoom"] for p in panels) else 1
    height = 6.2 * len(panels) + 1.1
    fig, axes = plt.subplots(len(panels), cols, figsize=(7.4 * cols, height), squeeze=False)
    for row, panel in zip(axes, panels):
        draw_panel(row[0], panel, data, panel["d_range"], f"light {panel['light']}: the approach")
        if panel["zoom"]:
            draw_panel(row[1], panel, data, panel["zoom"], f"light {panel['light']}: near the line (the zones)")
        elif cols == 2:
            row[1].axis("off")
    handles, _ = axes[0][0].get_legend_handles_labels()
    met = list(dict.fromkeys(st for p in panels for st in p["met"]))
    handles += [Line2D([], [], ls="none", marker="o", ms=5, mfc=LIGHT_COLORS.get(st, "#bdbdbd"), mec="black",
                       mew=0.3, label=f"ego approach, light {LIGHT_NAMES.get(st, st)}") for st in met]
    handles.append(Line2D([], [], ls="none", marker="*", ms=10, mfc="white", mec="black", label="first yellow / red met"))
    if any(p["first_stop_decision"] is not None for p in panels):
        handles.append(Line2D([], [], ls="none", marker="X", ms=8, color="black", label="judge's first stop"))
    ncol = 2 if cols == 1 else 4
    fig.legend(handles=handles, loc="lower center", fontsize=7.5, ncol=ncol, frameon=False)
    note = f"; no yellow or red met at {', '.join(data['skipped'])}" if data["skipped"] else ""
    fig.suptitle(f"{summary.get('scenario', '?')}: dilemma-zone diagram (docs/behaviour.md §L2){note}", fontsize=11)
    legend_h = 0.2 * math.ceil(len(handles) / ncol) + 0.15
    fig.tight_layout(rect=(0, legend_h / height, 1, 1 - 0.2 / height))
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
