"""Pictures of one run: blinker along s, speed profile with lights, dilemma-zone diagram."""
import math
import os

import matplotlib.pyplot as plt
from matplotlib.patches import Patch

from plotting.data import number, read_run

BLINKER_COLORS = {"left": "#1f77b4", "right": "#ff7f0e", "hazard": "#d62728"}
LIGHT_COLORS = {"G": "#1a9641", "g": "#78c679", "y": "#f0c000", "Y": "#f0c000", "r": "#d7191c",
                "u": "#fd8d3c", "s": "#a6d96a", "o": "#bdbdbd", "O": "#bdbdbd"}
LIGHT_NAMES = {"G": "green (priority)", "g": "green", "y": "yellow", "Y": "yellow", "r": "red",
               "u": "red-yellow", "s": "green arrow, stop first", "o": "off (blinking)", "O": "off"}
DECISION_COLORS = {"pass": "#4daf4a", "stop": "#e41a1c", "emergency_stop": "#984ea3"}
SUMO_BITS = (("hazard", 4), ("left", 2), ("right", 1))


def runs_of(values):
    """[(value, first index, last index)] for consecutive equal values."""
    out = []
    for i, v in enumerate(values):
        if out and out[-1][0] == v:
            out[-1][2] = i
        else:
            out.append([v, i, i])
    return [tuple(r) for r in out]


def span_end(xs, last):
    """Where a run ending at row `last` ends: the next row's x (the value holds until then)."""
    return xs[last + 1] if last + 1 < len(xs) else xs[last]


def sumo_blinker(text):
    mask = number(text)
    if mask is None:
        return "gone"
    for name, bit in SUMO_BITS:
        if int(mask) & bit:
            return name
    return "none"


def lights_of(metrics, timeline, params):
    """[(light id, stop point s or None)]: the metrics' lights, else the lights the timeline names."""
    margin = params.get("stop_margin", 0.0) or 0.0
    lights = [(l["id"], l["stop_line_s"] - margin) for l in metrics.get("lights", []) if "stop_line_s" in l]
    if lights:
        return lights
    seen = []
    for r in timeline:
        if r.get("tl_id") and r["tl_id"] not in [s[0] for s in seen]:
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


# --- blinker along s -----------------------------------------------------------------------------

def blinker_plot(timeline, summary, metrics, path):
    s = [float(r["s_front"]) for r in timeline]
    fig, ax = plt.subplots(figsize=(13, 4.6))
    track_h = 0.5

    # Sections (turns, roundabout entries/exits): shaded spans, start solid, end dashed, lead arrows.
    label_y = [1.95, 2.3]
    last_label_s = -1e9
    flip = 0
    for sec in metrics.get("sections", []):
        color = BLINKER_COLORS.get(sec.get("blinker"), "#999999")
        a, b = sec["s_start"], sec["s_end"]
        ax.axvspan(a, b, color=color, alpha=0.13, lw=0)
        ax.axvline(a, color=color, lw=1.2)
        ax.axvline(b, color=color, lw=1.2, ls="--")
        flip = 1 - flip if a - last_label_s < 70 else 0
        last_label_s = a
        y = label_y[flip]
        kind = sec["kind"].replace("_", " ")
        ax.text((a + b) / 2, y, f"{kind} {sec['id']}\nasks {sec.get('blinker', '?')}", ha="center", va="bottom",
                fontsize=8, color="black")
        lead = sec.get("lead_distance")
        if lead is not None:
            ax.annotate("", xy=(a, 1.72), xytext=(a - lead, 1.72),
                        arrowprops=dict(arrowstyle="->", color=color, lw=1.4))
            ax.text(a - lead / 2, 1.75, f"lead {lead:.1f} m / {sec.get('lead_time', 0):.1f} s", ha="center",
                    va="bottom", fontsize=7.5, color=color)
        if sec.get("missed"):
            ax.text(a, 1.6, "missed", ha="right", va="center", fontsize=8, color="#d62728", fontweight="bold")

    # Stop lines of the lights.
    for light in metrics.get("lights", []):
        ax.axvline(light["stop_line_s"], color="#444444", lw=1, ls=":")
        ax.text(light["stop_line_s"], -0.55, f"stop line {light['id']}", rotation=90, fontsize=7, ha="right",
                va="bottom", color="#444444")

    # Track 1: the decided blinker, segmented by (blinker, source).
    pairs = [(r["blinker"], r.get("blinker_source", "")) for r in timeline]
    for (blinker, source), i, j in runs_of(pairs):
        if blinker == "none":
            continue
        x0, x1 = s[i], span_end(s, j)
        ax.barh(1.0, x1 - x0, left=x0, height=track_h, color=BLINKER_COLORS.get(blinker, "#777777"), edgecolor="black",
                lw=0.5)
        ax.plot([x0], [1.0 + track_h / 2 + 0.05], marker="v", color="black", ms=4)
        ax.text(x0, 1.0 + track_h / 2 + 0.1, f"{s[i]:.1f} m: {blinker} ({source})", fontsize=7, ha="left",
                va="bottom")
        if j + 1 < len(pairs) and pairs[j + 1][0] == "none":
            ax.text(x1, 1.0 - track_h / 2 - 0.05, f"off {x1:.1f}", fontsize=6.5, ha="center", va="top")

    # Track 0: what SUMO showed while executing each decision.
    shown = [sumo_blinker(r.get("sumo_signals")) for r in timeline]
    for value, i, j in runs_of(shown):
        if value in ("none", "gone"):
            continue
        ax.barh(0.0, span_end(s, j) - s[i], left=s[i], height=track_h, color=BLINKER_COLORS.get(value, "#777777"),
                alpha=0.75, edgecolor="black", lw=0.5)

    ax.set_yticks([0.0, 1.0])
    ax.set_yticklabels(["SUMO shows", "decided\n(source)"])
    ax.set_ylim(-0.6, 2.9)
    length = (summary.get("route") or {}).get("length") or s[-1]
    ax.set_xlim(0, max(length, s[-1]))
    ax.set_xlabel("route position s of the front bumper [m]")
    ax.grid(axis="x", alpha=0.3)
    handles = [Patch(color=c, label=n) for n, c in BLINKER_COLORS.items()]
    handles.append(Patch(color="#999999", alpha=0.3, label="section (start solid, end dashed)"))
    ax.legend(handles=handles, loc="upper right", fontsize=7.5, ncol=4, framealpha=0.9)
    ax.set_title(f"{summary.get('scenario', '?')}: blinker along the route ({summary.get('status', '?')})")
    if not metrics.get("sections"):
        ax.text(0.01, 0.97, "no sections: summary.json has no metrics", transform=ax.transAxes, fontsize=8,
                va="top", color="#777777")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


# --- speed profile ----------------------------------------------------------------------------------

def speed_plot(timeline, summary, metrics, path):
    s = [float(r["s_front"]) for r in timeline]
    t = [float(r["time"]) for r in timeline]
    v = [float(r["speed"]) for r in timeline]
    states = [r.get("tl_state", "") for r in timeline]
    ids = [r.get("tl_id", "") for r in timeline]
    decisions = [r.get("tl_decision", "") for r in timeline]
    has_decisions = any(d and d != "none" for d in decisions)

    fig, (ax_s, ax_t) = plt.subplots(2, 1, figsize=(13, 7.2))

    # Speed along s; below it, the light state the ego saw at each position.
    ax_s.plot(s, v, color="black", lw=1.4, label="speed")
    vmax = max(v + [1.0]) * 1.45  # room for the legend
    for light in metrics.get("lights", []):
        ax_s.axvline(light["stop_line_s"], color="#d7191c", lw=1.2, ls="--")
        ax_s.text(light["stop_line_s"], vmax * 0.97, f"stop line {light['id']} ", color="#d7191c", fontsize=8,
                  va="top", ha="right", rotation=90)
    rest = [(s[i], v[i]) for i in range(len(v)) if v[i] < 0.05 and i + 1 < len(v)]
    if rest:
        ax_s.plot([p[0] for p in rest], [p[1] for p in rest], "o", color="#984ea3", ms=4, label="at rest")
    strip_h = vmax * 0.06
    seen_states = []
    for (light, state), i, j in runs_of(list(zip(ids, states))):
        if not light or not state:
            continue
        ax_s.barh(-strip_h * 0.9, span_end(s, j) - s[i], left=s[i], height=strip_h,
                  color=LIGHT_COLORS.get(state, "#bdbdbd"), lw=0)
        if state not in seen_states:
            seen_states.append(state)
    ax_s.set_ylim(-strip_h * 1.6, vmax)
    ax_s.set_xlim(min(s), max(s))
    ax_s.set_xlabel("route position s of the front bumper [m]")
    ax_s.set_ylabel("speed [m/s]")
    ax_s.grid(alpha=0.3)
    handles, _ = ax_s.get_legend_handles_labels()
    handles += [Patch(color=LIGHT_COLORS.get(k, "#bdbdbd"), label=f"strip: next light {LIGHT_NAMES.get(k, k)}")
                for k in seen_states]
    ax_s.legend(handles=handles, loc="upper left", fontsize=7.5, ncol=2, framealpha=0.9)
    ax_s.set_title(f"{summary.get('scenario', '?')}: speed profile")

    # Speed over time on the light states (time shows how long the ego waited).
    ax_t.plot(t, v, color="black", lw=1.4)
    used = set()
    for (light, state), i, j in runs_of(list(zip(ids, states))):
        if not light or not state:
            continue
        ax_t.axvspan(t[i], span_end(t, j), color=LIGHT_COLORS.get(state, "#bdbdbd"), alpha=0.25, lw=0)
        used.add(state)
    vmax_t = max(v + [1.0]) * 1.25
    if has_decisions:
        strip = vmax_t * 0.06
        for d, i, j in runs_of(decisions):
            if d in DECISION_COLORS:
                ax_t.barh(-strip * 0.9, span_end(t, j) - t[i], left=t[i], height=strip, color=DECISION_COLORS[d], lw=0)
        ax_t.set_ylim(-strip * 1.6, vmax_t)
    else:
        ax_t.set_ylim(0, vmax_t)
    for light in metrics.get("lights", []):  # when the front crossed each stop line
        for i in range(1, len(s)):
            if s[i - 1] < light["stop_line_s"] <= s[i]:
                ax_t.axvline(t[i], color="#d7191c", lw=1.2, ls="--")
                ax_t.text(t[i], vmax_t * 0.03, f"front crosses stop line {light['id']} ", color="#d7191c",
                          fontsize=8, va="bottom", ha="right", rotation=90)
                break
    ax_t.set_xlim(min(t), max(t))
    ax_t.set_xlabel("time [s]")
    ax_t.set_ylabel("speed [m/s]")
    ax_t.grid(alpha=0.3)
    handles = [Patch(color=LIGHT_COLORS[k], alpha=0.5, label=LIGHT_NAMES[k]) for k in LIGHT_COLORS if k in used]
    if has_decisions:
        handles += [Patch(color=c, label=f"judge: {d}") for d, c in DECISION_COLORS.items() if d in decisions]
    if handles:
        ax_t.legend(handles=handles, loc="upper right", fontsize=7.5, ncol=2, framealpha=0.9)
    ax_t.set_title("speed over time on the next light's state" + (" (bottom strip: the judge's decision)"
                                                                    if has_decisions else ""))
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


# --- dilemma zone -----------------------------------------------------------------------------------

def judge_distance(v, a0, a_s, j_s, t_d):
    """spec TLJ §2.2 calcJudgeLineDistWithJerkLimit (as coded upstream)."""
    if v <= 0:
        return 0.0
    x1 = v * t_d
    v2 = v + (a_s * a_s - a0 * a0) / (2 * j_s)
    if v2 > 0:
        t2 = (a_s - a0) / j_s
        x2 = v * t2 + a0 * t2 ** 2 / 2 + j_s * t2 ** 3 / 6
        x3 = -v2 * v2 / (2 * a_s)
        return max(0.0, x1 + x2 + x3)
    t2 = -(a_s + math.sqrt(a0 * a0 - 2 * j_s * v)) / j_s
    x2 = v * t2 + a0 * t2 ** 2 / 2 + j_s * t2 ** 3 / 6
    return max(0.0, x1 + x2)


def dilemma_plot(timeline, summary, metrics, path):
    params = summary.get("parameters", {})
    lights = lights_of(metrics, timeline, params)
    if not lights:
        return None
    t_y = params.get("yellow_lamp_period", 2.75)
    a_s = params.get("max_accel", -2.8)
    j_s = params.get("max_jerk", -5.0)
    t_d = params.get("delay_response_time", 0.5)
    v_slow = params.get("yellow_light_stop_velocity")
    speeds = [float(r["speed"]) for r in timeline]
    v_top = max(max(speeds) * 1.3, 12.0)
    vs = [v_top * k / 200 for k in range(201)]
    judge = [judge_distance(v, 0.0, a_s, j_s, t_d) for v in vs]
    yellow = [v * t_y for v in vs]
    d_top = max(max(judge), max(yellow)) * 1.15

    lights = lights[:3]
    fig, axes = plt.subplots(1, len(lights), figsize=(6.8 * len(lights), 6.6), squeeze=False)
    for ax, (light, stop_s) in zip(axes[0], lights):
        ax.fill_betweenx(vs, yellow, judge, where=[j > y for j, y in zip(judge, yellow)], color="#d7191c", alpha=0.22,
                         lw=0, label="dilemma zone: emergency stop")
        ax.fill_betweenx(vs, judge, yellow, where=[y > j for j, y in zip(judge, yellow)], color="#1a9641", alpha=0.18,
                         lw=0, label="optional zone: stop")
        ax.plot(judge, vs, color="#d7191c", lw=1.8,
                label=f"stopping distance (a {a_s} m/s², j {j_s} m/s³, delay {t_d} s)")
        ax.plot(yellow, vs, color="#e6a000", lw=1.8, label=f"yellow lamp line d = v · {t_y} s")
        if v_slow:
            ax.axhline(v_slow, color="#555555", lw=0.8, ls=":")
            ax.text(d_top * 0.98, v_slow, f"below {v_slow} m/s: always stop", fontsize=7, ha="right", va="bottom",
                    color="#555555")
        ax.text(d_top * 0.8, v_top * 0.2, "can stop\n→ stop", fontsize=8.5, color="#555555", ha="center")
        ax.text(d_top * 0.03, v_top * 0.95, "cannot stop,\nreaches the line\n→ pass", fontsize=8.5, color="#555555",
                ha="left", va="top")

        # The ego's approach: (d, v) per step, coloured by the light's state.
        d = stop_distances(timeline, light, stop_s)
        pts = [(d[i], speeds[i], timeline[i].get("tl_state", "")) for i in range(len(d))
               if d[i] is not None and -2.0 <= d[i] <= d_top]
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], color="#333333", lw=0.8, zorder=3, label="ego approach")
            ax.scatter([p[0] for p in pts], [p[1] for p in pts], c=[LIGHT_COLORS.get(p[2], "#bdbdbd") for p in pts],
                       s=9, zorder=4, edgecolors="none")
            for i in range(1, len(pts)):
                if pts[i][2] in ("y", "Y") and pts[i - 1][2] not in ("y", "Y"):
                    ax.plot([pts[i][0]], [pts[i][1]], marker="*", ms=14, color="#e6a000", mec="black", zorder=5)
                    ax.annotate(f"yellow at d {pts[i][0]:.1f} m, v {pts[i][1]:.1f} m/s", (pts[i][0], pts[i][1]),
                                xytext=(10, 12), textcoords="offset points", fontsize=8,
                                arrowprops=dict(arrowstyle="-", color="black", lw=0.6))
                    break
        else:
            ax.text(0.5, 0.5, "the ego never approached this light", transform=ax.transAxes, ha="center")
        ax.set_xlim(0, d_top)
        ax.set_ylim(0, v_top)
        ax.set_xlabel("distance d from the front bumper to the stop point [m]")
        ax.set_ylabel("speed v [m/s]")
        ax.grid(alpha=0.3)
        ax.set_title(f"light {light}")
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), fontsize=7.5, ncol=2, frameon=False)
    fig.suptitle(f"{summary.get('scenario', '?')}: dilemma-zone diagram (spec TLJ §2)", fontsize=11)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_run(run_dir, out):
    timeline, _events, summary, metrics = read_run(run_dir)
    os.makedirs(out, exist_ok=True)
    written = [blinker_plot(timeline, summary, metrics, os.path.join(out, "blinker.png")),
               speed_plot(timeline, summary, metrics, os.path.join(out, "speed.png"))]
    dilemma = dilemma_plot(timeline, summary, metrics, os.path.join(out, "dilemma.png"))
    if dilemma:
        written.append(dilemma)
    return written
