"""blinker.png: the blinker along the route, and why it was on there.

Tracks, bottom to top: what SUMO showed (coloured by blinker); what the decider decided, coloured by
the request that won (its source: a lane change handing over to a turn changes colour, not blinker),
with the blinker it decided as a stripe along the bar's top;
what the scenario's expectations check (blinker_on, no_blinker, blinker_through_* ranges, with their
verdicts); above them each section (turn, roundabout entry/exit, lane change, avoidance, pull out/over)
with its actual lead and, where an expectation checks it, the required lead before the section.

blinker_data() computes what is drawn; blinker_plot() draws it (tests read the data)."""
import re

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from signalsim_plot.data import number, runs_of, span_end
from signalsim_plot.labels import overlapping_pairs, separate_labels
from signalsim_plot.style import BLINKER_COLORS

# The decided bar's colour: the request source that won (turn_signal_info.cpp to_string(RequestSource)).
SOURCE_COLORS = {"intersection": "#6a3d9a", "roundabout_entry": "#1b9e77", "roundabout_exit": "#66a61e",
                 "lane_change": "#e7298a", "avoidance": "#8c564b", "pull_out": "#17becf", "pull_over": "#bcbd22",
                 "sumo": "#7f7f7f"}
OTHER_SOURCE_COLOR = "#bdbdbd"
# The source that asks for each section kind (metrics.cpp section kinds).
SECTION_SOURCE = {"turn": "intersection", "roundabout_entry": "roundabout_entry", "roundabout_exit": "roundabout_exit",
                  "lane_change": "lane_change", "avoidance": "avoidance", "pull_out": "pull_out", "pull_over": "pull_over"}
SECTION_SHADE = {"facecolor": "#9e9e9e", "alpha": 0.16}
SUMO_ALPHA = 0.75
NO_BLINKER_LINE = "#777777"  # the lines of a section that asks for no blinker (a roundabout entry)
PASS_COLOR, FAIL_COLOR = "#1a7f37", "#c62828"
SUMO_BITS = (("hazard", 4), ("left", 2), ("right", 1))

THROUGH = re.compile(r"^blinker_through_(junction|lanelet) (\S+) (\w+) lead (\S+)$")
ON = re.compile(r"^blinker_on (\w+) from_s (\S+) to_s (\S+)$")
NONE = re.compile(r"^no_blinker from_s (\S+) to_s (\S+)$")
NEVER = re.compile(r"^blinker_never (\w+)$")
FAILED_AT = re.compile(r"at t=(\S+) s, s_front=(\S+) m")  # expectations.cpp at(): the first failing step

# y of the tracks
Y_SUMO, Y_DECIDED, Y_EXPECTED, Y_ACTUAL, Y_REQUIRED, Y_LABEL = 0.0, 1.0, 2.0, 2.45, 2.9, 3.3
TRACK_H = 0.5


def sumo_blinker(text):
    mask = number(text)
    if mask is None:
        return "gone"
    for name, bit in SUMO_BITS:
        if int(mask) & bit:
            return name
    return "none"


def source_color(source):
    return SOURCE_COLORS.get(source, OTHER_SOURCE_COLOR)


def interpolate(xs, ys, x):
    """ys at x on the polyline (xs increasing where it matters); None outside."""
    for i in range(1, len(xs)):
        if xs[i - 1] <= x <= xs[i]:
            if xs[i] == xs[i - 1]:
                return ys[i]
            u = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
            return ys[i - 1] + u * (ys[i] - ys[i - 1])
    return None


def section_of(kind, name, sections):
    """The metrics section a blinker_through expectation checks (junction id or lanelet)."""
    for sec in sections:
        if kind == "junction" and sec.get("id") == name and sec.get("kind") in ("turn", "roundabout_entry",
                                                                                 "roundabout_exit"):
            return sec
        if kind == "lanelet" and name in (sec.get("lanelets") or []):
            return sec
    return None


def entered_in_timeline(kind, name, timeline):
    """(enter s, leave s) of the front in the junction's internal lanes / the lanelet, from the timeline
    (to a step): for a junction or lanelet no section describes."""
    inside = [float(r["s_front"]) for r in timeline
              if (r.get("lane", "") == name if kind == "lanelet" else r.get("lane", "").startswith(f":{name}_"))]
    return (min(inside), max(inside)) if inside else (None, None)


def blinker_data(timeline, summary, metrics):
    """What blinker.png draws, or None when the route has no sections and the blinker was never on.

    segments: the decided blinker, one per run of equal (blinker, source), blinker != none:
              {s0, s1, t0, t1, blinker, source, reversing}; s0 <= s1 (a reversing run is drawn half height)
    shown:    what SUMO showed: {s0, s1, blinker, reversing}
    sections: the metrics' sections, each with `source` (the request that asks for it)
    required: per blinker_through_* expectation: {expectation, passed, kind, name, lead, enter_s, leave_s,
              from_s (= enter_s - lead: where the blinker must be on), until_s (front when base_link
              leaves), speed (at from_s), lead_time (lead / speed), section (or None), approximate}
    expected: blinker_on / no_blinker ranges: {blinker ('none' for no_blinker), from_s, to_s, passed, expectation,
              failed_at (s_front of the first failing step the detail names, or None)}; required has failed_at too
    never:    [(blinker, passed)] of blinker_never
    """
    s = [float(r["s_front"]) for r in timeline]
    t = [float(r["time"]) for r in timeline]
    v = [float(r["speed"]) for r in timeline]
    f = (summary.get("ego") or {}).get("base_link_to_front", 0.0) or 0.0
    sections = [dict(sec, source=SECTION_SOURCE.get(sec.get("kind"), sec.get("kind"))) for sec in
                metrics.get("sections", [])]

    segments = []
    pairs = [(r["blinker"], r.get("blinker_source", "")) for r in timeline]
    for (blinker, source), i, j in runs_of(pairs):
        if blinker == "none":
            continue
        a, b = s[i], span_end(s, j)
        reversing = b < a or any(v[k] < 0 for k in range(i, j + 1))
        segments.append({"s0": min(a, b), "s1": max(a, b), "t0": t[i], "t1": span_end(t, j), "blinker": blinker,
                         "source": source, "reversing": reversing, "on_s": s[i]})
    shown = []
    for value, i, j in runs_of([sumo_blinker(r.get("sumo_signals")) for r in timeline]):
        if value not in ("none", "gone"):
            a, b = s[i], span_end(s, j)
            shown.append({"s0": min(a, b), "s1": max(a, b), "blinker": value,
                          "reversing": b < a or any(v[k] < 0 for k in range(i, j + 1))})

    required, expected, never = [], [], []
    for e in summary.get("expectations", []):
        text, passed = e.get("expectation", ""), bool(e.get("passed"))
        at = FAILED_AT.search(e.get("detail", "")) if not passed else None
        failed_at = float(at.group(2)) if at else None
        m = THROUGH.match(text)
        if m:
            kind, name, blinker, lead = m.group(1), m.group(2), m.group(3), float(m.group(4))
            sec = section_of(kind, name, sections)
            approximate = sec is None
            if sec is not None:
                enter, leave = sec["s_start"], sec["s_end"]
            else:
                enter, leave = entered_in_timeline(kind, name, timeline)
            if enter is None:
                continue
            from_s = enter - lead
            speed = interpolate(s, v, from_s)
            required.append({"expectation": text, "passed": passed, "kind": kind, "name": name, "blinker": blinker,
                             "lead": lead, "enter_s": enter, "leave_s": leave, "from_s": from_s,
                             "until_s": leave + f, "speed": speed,
                             "lead_time": lead / speed if speed and speed > 0.1 else None, "section": sec,
                             "approximate": approximate, "failed_at": failed_at})
            continue
        m = ON.match(text)
        if m:
            expected.append({"blinker": m.group(1), "from_s": float(m.group(2)), "to_s": float(m.group(3)),
                             "passed": passed, "expectation": text, "failed_at": failed_at})
            continue
        m = NONE.match(text)
        if m:
            expected.append({"blinker": "none", "from_s": float(m.group(1)), "to_s": float(m.group(2)),
                             "passed": passed, "expectation": text, "failed_at": failed_at})
            continue
        m = NEVER.match(text)
        if m:
            never.append((m.group(1), passed))

    if not sections and not segments and not shown:
        return None  # nothing asked for a blinker and none came on: no picture
    lights = [(l["id"], l["stop_line_s"]) for l in metrics.get("lights", []) if "stop_line_s" in l]
    return {"segments": segments, "shown": shown, "sections": sections, "required": required, "expected": expected,
            "never": never, "lights": lights, "has_metrics": bool(metrics), "s_last": s[-1],
            "length": (summary.get("route") or {}).get("length") or s[-1]}


def staggered(xs, span, levels=2, gap=0.07):
    """A level (0..levels-1) per x so that labels closer than gap * span alternate."""
    out, last = [], None
    for x in xs:
        if last is not None and x - last[0] < gap * span:
            level = (last[1] + 1) % levels
        else:
            level = 0
        out.append(level)
        last = (x, level)
    return out


def blinker_legend(data):
    """The legend's handles: only what is drawn, in the colours it is drawn in (a source, blinker or
    verdict that does not occur has no entry)."""
    handles = [Patch(facecolor=source_color(src), edgecolor="black", lw=0.5, label=f"decided, source {src}")
               for src in dict.fromkeys(seg["source"] for seg in data["segments"])]
    for b in BLINKER_COLORS:  # a blinker's colour: where SUMO showed it, where it is expected, section lines
        where = [name for name, used in (
            ("decided: stripe", any(seg["blinker"] == b for seg in data["segments"])),
            ("SUMO", any(seg["blinker"] == b for seg in data["shown"])),
            ("expected", any(e["blinker"] == b for e in data["expected"] + data["required"])),
            ("section lines", any(sec.get("blinker") == b for sec in data["sections"]))) if used]
        if where:
            handles.append(Patch(facecolor=BLINKER_COLORS[b], alpha=SUMO_ALPHA, edgecolor="black", lw=0.5,
                                 label=f"{b} ({', '.join(where)})"))
    if any(sec.get("blinker") not in BLINKER_COLORS for sec in data["sections"]):
        handles.append(Line2D([], [], color=NO_BLINKER_LINE, lw=1.1, label="section asking for no blinker"))
    if any(e["blinker"] == "none" for e in data["expected"]):
        handles.append(Patch(facecolor="white", edgecolor="#555555", hatch="////", label="expected: no blinker"))
    if data["expected"] or data["required"]:
        outcomes = [e["passed"] for e in data["expected"] + data["required"]]
        if any(outcomes):
            handles.append(Patch(facecolor="white", edgecolor=PASS_COLOR, lw=1.3, label="✓ expectation held"))
        if not all(outcomes):
            handles.append(Patch(facecolor="white", edgecolor=FAIL_COLOR, lw=2.0, label="✗ expectation failed"))
    if any(seg["reversing"] for seg in data["segments"] + data["shown"]):
        handles.append(Patch(facecolor="white", edgecolor="black", hatch="xx", label="while reversing (half height)"))
    if data["sections"]:
        handles.append(Patch(edgecolor="none", label="section (start solid, end dashed)", **SECTION_SHADE))
    if any(sec.get("lead_distance") is not None for sec in data["sections"]):
        handles.append(Line2D([], [], color="black", lw=1.1, marker=">", ms=4, label="actual lead"))
    for ok in (True, False):
        if any(r["passed"] == ok for r in data["required"]):
            handles.append(Line2D([], [], color=PASS_COLOR if ok else FAIL_COLOR, lw=1.3, ls=(0, (4, 2)),
                                  label=f"required lead ({'held' if ok else 'failed'})"))
    return handles


def blinker_plot(timeline, summary, metrics, path):
    data = blinker_data(timeline, summary, metrics)
    if data is None:
        return None
    fig, _, _ = blinker_figure(data, summary)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def blinker_figure(data, summary, separate=True):
    """The figure of blinker_data()'s `data`: (figure, axes, its text labels). `separate` False leaves
    overlapping labels where they were put (the tests compare)."""
    x_max = max(data["length"], data["s_last"])
    fig, ax = plt.subplots(figsize=(13, 5.6))
    labels = []  # (text, direction to move it when it overlaps another: +1 up, -1 down), by priority

    # Sections: grey span, start solid, end dashed, in the blinker the section asks for.
    order = sorted(data["sections"], key=lambda sec: sec["s_start"])
    label_levels = staggered([sec["s_start"] for sec in order], x_max, gap=0.09)
    arrow_levels = []  # (from, to) of the actual-lead arrows drawn per level
    for sec, level in zip(order, label_levels):
        color = BLINKER_COLORS.get(sec.get("blinker"), NO_BLINKER_LINE)
        a, b = sec["s_start"], sec["s_end"]
        ax.axvspan(a, b, lw=0, **SECTION_SHADE)
        ax.axvline(a, color=color, lw=1.1)
        ax.axvline(b, color=color, lw=1.1, ls="--")
        kind = sec["kind"].replace("_", " ")
        labels.append((ax.text((a + b) / 2, Y_LABEL + 0.3 * level, f"{kind} {sec['id']}: asks {sec.get('blinker', '?')}",
                               ha="center", va="bottom", fontsize=7.5), +1))
        lead = sec.get("lead_distance")
        if lead is not None:  # the actual lead: from where the blinker came on to the section's start
            lo, hi = sorted((a - lead, a))
            row = next((k for k, spans in enumerate(arrow_levels)
                        if all(hi + 0.1 * x_max < p or lo > q + 0.1 * x_max for p, q in spans)), len(arrow_levels))
            if row == len(arrow_levels):
                arrow_levels.append([])
            arrow_levels[row].append((lo, hi))
            y = Y_ACTUAL - 0.2 * row
            late = lead < 0 or bool(sec.get("missed"))
            ax.annotate("", xy=(a, y), xytext=(a - lead, y),
                        arrowprops=dict(arrowstyle="->", color=FAIL_COLOR if late else "black", lw=1.1))
            lt = sec.get("lead_time")
            text = f"{'late: ' if late else ''}actual lead {lead:.1f} m" + (f" / {lt:.1f} s" if lt is not None else "")
            text += " (missed)" if sec.get("missed") else ""
            right = late and lo > 0.25 * x_max  # a late lead's text ends at the arrow, room allowing
            labels.append((ax.text(lo if right or not late else hi, y + 0.03, text, ha="right" if right else "left",
                                   va="bottom", fontsize=7, color=FAIL_COLOR if late else "black"), +1))
        elif sec.get("missed"):
            labels.append((ax.text(a, Y_ACTUAL, "missed ", ha="right", va="center", fontsize=7.5, color=FAIL_COLOR,
                                   fontweight="bold"), +1))

    # The required lead of each blinker_through_* expectation: the blinker must be on from from_s.
    for req in data["required"]:
        color = PASS_COLOR if req["passed"] else FAIL_COLOR
        ax.plot([req["from_s"]] * 2, [Y_DECIDED - TRACK_H / 2, Y_REQUIRED], color=color, lw=1.3, ls=(0, (4, 2)))
        ax.annotate("", xy=(req["enter_s"], Y_REQUIRED), xytext=(req["from_s"], Y_REQUIRED),
                    arrowprops=dict(arrowstyle="|-|,widthA=0.25,widthB=0.25", color=color, lw=1.1))
        when = f" ≈ {req['lead_time']:.1f} s at {req['speed']:.1f} m/s" if req["lead_time"] is not None else ""
        verdict = "ok" if req["passed"] else "FAILED"
        labels.append((ax.text(req["from_s"], Y_REQUIRED + 0.04,
                               f"required: on from {req['from_s']:.1f} m{' (≈)' if req['approximate'] else ''}, "
                               f"lead ≥ {req['lead']:g} m{when} [{verdict}]", ha="left", va="bottom", fontsize=7,
                               color=color), +1))

    # Expectations' ranges: blinker_on / no_blinker below, blinker_through_* above.
    ranges = [(exp, Y_EXPECTED - 0.1) for exp in data["expected"]]
    ranges += [({"blinker": r["blinker"], "from_s": r["from_s"], "to_s": r["until_s"], "passed": r["passed"],
                 "failed_at": r["failed_at"]}, Y_EXPECTED + 0.1) for r in data["required"]]
    for exp, y in ranges:  # edge and mark: the expectation's verdict
        face = BLINKER_COLORS.get(exp["blinker"], "white")
        verdict = PASS_COLOR if exp["passed"] else FAIL_COLOR
        ax.barh(y, exp["to_s"] - exp["from_s"], left=exp["from_s"], height=0.17, color=face,
                alpha=0.45 if exp["blinker"] != "none" else 1.0, edgecolor="#555555", lw=0.6,
                hatch=None if exp["blinker"] != "none" else "////")
        ax.barh(y, exp["to_s"] - exp["from_s"], left=exp["from_s"], height=0.17, fill=False, edgecolor=verdict,
                lw=1.3 if exp["passed"] else 2.0)
        ax.text((exp["from_s"] + exp["to_s"]) / 2, y, "✓" if exp["passed"] else "✗", fontsize=9.5, va="center",
                ha="center", color=verdict, fontweight="bold",
                bbox=dict(boxstyle="circle,pad=0.12", fc="white", ec=verdict, lw=0.8), zorder=6)
        if exp.get("failed_at") is not None:  # the first failing step
            ax.plot([exp["failed_at"]], [y], marker="X", ms=9, color=FAIL_COLOR, mec="white", mew=0.8, zorder=7)
            upper = y > Y_EXPECTED
            labels.append((ax.text(exp["failed_at"], y + (0.1 if upper else -0.1), f"fails at {exp['failed_at']:.1f} m",
                                   fontsize=7, color=FAIL_COLOR, ha="center", va="bottom" if upper else "top", zorder=7),
                           +1 if upper else -1))

    # Stop lines of the lights.
    for light, stop_s in data["lights"]:
        ax.axvline(stop_s, color="#444444", lw=1, ls=":")
        labels.append((ax.text(stop_s, -0.55, f"stop line {light}", rotation=90, fontsize=7, ha="right", va="bottom",
                               color="#444444"), -1))

    # The decided blinker, coloured by its source.
    segs = data["segments"]
    for seg, level in zip(segs, staggered([seg["on_s"] for seg in segs], x_max, gap=0.06)):
        h = TRACK_H / 2 if seg["reversing"] else TRACK_H
        y = Y_DECIDED + (TRACK_H / 4 if seg["reversing"] else 0)
        ax.barh(y, max(seg["s1"] - seg["s0"], 0.3), left=seg["s0"], height=h, color=source_color(seg["source"]),
                edgecolor="black", lw=0.5, hatch="xx" if seg["reversing"] else None, zorder=3 if seg["reversing"] else 2)
        top = y + h / 2  # the decided blinker as a stripe along the bar's top, in its blinker colour
        ax.barh(top - 0.05, max(seg["s1"] - seg["s0"], 0.3), left=seg["s0"], height=0.1,
                color=BLINKER_COLORS.get(seg["blinker"], "#777777"), edgecolor="black", lw=0.4,
                zorder=3 if seg["reversing"] else 2)
        ax.plot([seg["on_s"]], [Y_DECIDED + TRACK_H / 2 + 0.04], marker="v", color="black", ms=4)
        labels.append((ax.text(seg["on_s"], Y_DECIDED + TRACK_H / 2 + 0.09 + 0.17 * level,
                               f"{seg['on_s']:.1f} m: {seg['blinker']}" + (" (reversing)" if seg["reversing"] else ""),
                               fontsize=7, ha="left", va="bottom"), +1))
    for k, seg in enumerate(segs):  # where the blinker went off
        nxt = segs[k + 1] if k + 1 < len(segs) else None
        if nxt is None or abs(nxt["s0"] - seg["s1"]) > 0.5 and not seg["reversing"]:
            labels.append((ax.text(seg["s1"], Y_DECIDED - TRACK_H / 2 - 0.04, f"off {seg['s1']:.1f}", fontsize=6.5,
                                   ha="center", va="top"), -1))

    # What SUMO showed.
    for seg in data["shown"]:  # (what was shown while reversing: half height, on top, hatched)
        rev = seg["reversing"]
        ax.barh(Y_SUMO + (TRACK_H / 4 if rev else 0), max(seg["s1"] - seg["s0"], 0.3), left=seg["s0"],
                height=TRACK_H / 2 if rev else TRACK_H, color=BLINKER_COLORS.get(seg["blinker"], "#777777"),
                alpha=SUMO_ALPHA, edgecolor="black", lw=0.5, hatch="xx" if rev else None, zorder=3 if rev else 2)

    ax.set_yticks([Y_SUMO, Y_DECIDED, Y_EXPECTED])
    ax.set_yticklabels(["SUMO shows", "decided\n(colour: source)", "expected"])
    ax.set_ylim(-0.6, Y_LABEL + 0.3 * max(label_levels + [0]) + (0.45 if order else 0.2))
    ax.set_xlim(0, x_max)
    ax.set_xlabel("route position s of the front bumper [m]")
    ax.grid(axis="x", alpha=0.3)

    handles = blinker_legend(data)
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.13), fontsize=7.5, ncol=4, frameon=False)

    never = "; ".join(f"never {b}: {'ok' if ok else 'FAILED'}" for b, ok in data["never"])
    title = f"{summary.get('scenario', '?')}: blinker along the route ({summary.get('status', '?')})"
    ax.set_title(title + (f"   [{never}]" if never else ""))
    if not data["has_metrics"]:
        ax.text(0.01, 0.97, "summary.json has no metrics: sections unknown", transform=ax.transAxes, fontsize=8,
                va="top", color="#777777")
    elif not data["sections"]:
        ax.text(0.01, 0.97, "no sections on this route: no turn, roundabout or maneuver asks for a blinker",
                transform=ax.transAxes, fontsize=8, va="top", color="#777777")
    if separate:
        keep_labels_apart(fig, ax, labels)
    else:
        fig.tight_layout()
    return fig, ax, [t for t, _ in labels]


def keep_labels_apart(fig, ax, labels, rounds=3):
    """Moves overlapping labels apart (signalsim_plot.labels); the layout is redone after each round, since
    widening the y range to hold the moved labels rescales the axes."""
    fig.tight_layout()
    for _ in range(rounds):
        separate_labels(fig, ax, labels, step=0.12)
        fig.tight_layout()
        if not overlapping_pairs(fig, [t for t, _ in labels]):
            return
