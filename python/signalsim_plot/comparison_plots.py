"""The picture of `signalsim compare` (comparison.csv -> comparison.png).

One row of panels per scenario. Left: the blinker's lead distance per section (turn, roundabout entry,
exit), signalsim and SUMO (and, with a decider or light judge under test, the SUT first: driver `sut`)
side by side as horizontal bars; a missed blinker, a section never reached
or a run in error is written where its bar would be, and a section that asks for no blinker shows
which blinker each driver had on as the front reached it. Right (when some route has lights): the
stop position error per light (rest position - stop point), or how the ego went through.
"""
import os

import matplotlib.pyplot as plt
from matplotlib.patches import Patch

from signalsim_plot.cli import InputError
from signalsim_plot.data import number, read_csv

# Fixed colours per driver (tests look for them in the PNG).
DRIVER_COLORS = {"sut": "#2ca02c", "signalsim": "#1f77b4", "sumo": "#ff7f0e"}
DRIVERS = ("sut", "signalsim", "sumo")  # the order of the bars; only the drivers the CSV has are drawn
REQUIRED = ("scenario", "section", "kind", "id", "blinker", "driver", "status", "lead_distance", "missed",
            "blinker_at_start", "state_at_line", "red_light_violation", "stop_position_error", "notes")
BAR_H = 0.38  # two drivers; three share the same height between them


def drivers_of(rows):
    """The drivers the CSV has, in DRIVERS order."""
    present = {r["driver"] for r in rows}
    return [d for d in DRIVERS if d in present]


def is_comparison(path):
    """True when the CSV at `path` has comparison.csv's columns (driver and section)."""
    try:
        with open(path) as f:
            header = f.readline().strip().split(",")
    except OSError:
        return False
    return "driver" in header and "section" in header


def grouped(rows):
    """[(scenario, [(item key, {driver: row})])], both in file order."""
    out = {}
    for r in rows:
        items = out.setdefault(r["scenario"], {})
        items.setdefault(r["section"], {})[r["driver"]] = r
    return [(sc, list(items.items())) for sc, items in out.items()]


def note_of(row, light):
    """Text in place of a bar: why there is no value."""
    if row["status"] == "error":
        return "error"
    if "not reached" in row["notes"]:
        return "not reached"
    if light:
        if row["red_light_violation"] == "true":
            return "RED crossed"
        return f"through at {row['state_at_line']}" if row["state_at_line"] else "-"
    if row["blinker"] == "none":
        shown = row["blinker_at_start"]
        return f"{shown} on (none asked)" if shown and shown != "none" else "none (none asked)"
    if row["missed"] == "true":
        shown = row["blinker_at_start"]
        return f"missed ({shown} on)" if shown and shown != "none" else "missed"
    return "-"


def draw_panel(ax, items, light, drivers):
    labels = []
    value_key = "stop_position_error" if light else "lead_distance"
    values = [number(r.get(value_key)) for _, by in items for r in by.values()]
    span = max([abs(v) for v in values if v is not None] + [1.0])
    for k, (name, by) in enumerate(items):
        first = next(iter(by.values()))
        want = "" if light else f" ({first['blinker']})"
        labels.append(f"{name} {first['id']}{want}")
        bar_h = BAR_H if len(drivers) <= 2 else 0.78 / len(drivers)
        for d, driver in enumerate(drivers):
            row = by.get(driver)
            y = k + (d - (len(drivers) - 1) / 2) * bar_h
            if row is None:
                continue
            v = number(row.get(value_key))
            late = not light and row["missed"] == "true"
            if v is not None and row["status"] != "error":
                ax.barh(y, v, height=bar_h, color=DRIVER_COLORS[driver], edgecolor="black", lw=0.4,
                        hatch="//" if late else None)
                lead_time = number(row.get("lead_time"))
                text = f"{v:g} m" + (f", {lead_time:g} s" if lead_time is not None else "") + (" (late)" if late else "")
                ax.text(v + (0.01 if v >= 0 else -0.01) * span, y, text, va="center",
                        ha="left" if v >= 0 else "right", fontsize=7)
            else:
                ax.plot([0], [y], marker="x", color=DRIVER_COLORS[driver], ms=6)
                ax.text(0.02 * span, y, note_of(row, light), va="center", ha="left", fontsize=7,
                        color=DRIVER_COLORS[driver])
    ax.set_yticks(range(len(items)))
    ax.set_yticklabels(labels, fontsize=8)
    ax.set_ylim(len(items) - 0.5, -0.5)
    ax.axvline(0, color="black", lw=0.8)
    ax.set_xlim(min(-0.1 * span, min([v for v in values if v is not None] + [0]) * 1.35),
                max([v for v in values if v is not None] + [0]) * 1.35 + 0.25 * span)
    ax.grid(axis="x", alpha=0.3)


def plot_comparison(csv_path, out):
    rows = read_csv(csv_path)
    if not rows:
        raise InputError(f"{csv_path}: no rows")
    missing = [c for c in REQUIRED if c not in rows[0]]
    if missing:
        raise InputError(f"{csv_path}: missing column(s) {', '.join(missing)}")
    scenarios = grouped(rows)
    drivers = drivers_of(rows)
    with_lights = any(by and next(iter(by.values()))["kind"] == "light" for _, items in scenarios for _, by in items)
    ncols = 2 if with_lights else 1
    heights = []
    for _, items in scenarios:
        n = max(sum(1 for _, by in items if next(iter(by.values()))["kind"] != "light"),
                sum(1 for _, by in items if next(iter(by.values()))["kind"] == "light"), 1)
        heights.append(0.55 * n + 0.9)
    fig, axes = plt.subplots(len(scenarios), ncols, figsize=(7.5 * ncols, sum(heights) + 0.8), squeeze=False,
                             gridspec_kw={"height_ratios": heights})
    for row_axes, (scenario, items) in zip(axes, scenarios):
        sections = [(n, by) for n, by in items if n and next(iter(by.values()))["kind"] != "light"]
        lights = [(n, by) for n, by in items if n and next(iter(by.values()))["kind"] == "light"]
        for col, (part, light) in enumerate(((sections, False), (lights, True))[:ncols]):
            ax = row_axes[col]
            if part:
                draw_panel(ax, part, light, drivers)
            else:
                ax.set_axis_off()
                ax.text(0.5, 0.5, "no lights" if light else "no blinker sections", ha="center", va="center",
                        fontsize=8, transform=ax.transAxes, color="#666666")
            title = "stop position error [m]" if light else "blinker lead distance [m]"
            ax.set_title(f"{scenario}: {title}", fontsize=9, loc="left")
    fig.legend(handles=[Patch(color=DRIVER_COLORS[d], label=d) for d in drivers], loc="upper right", ncol=len(drivers),
               fontsize=8)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.5 / (sum(heights) + 0.8)))
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "comparison.png")
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return [path]
