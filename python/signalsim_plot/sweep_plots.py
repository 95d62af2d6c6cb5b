"""A sweep's results.csv as a heat map (a table with colours) of one metric over two swept columns.

A true/false column (light<n>.red_light_violation, light<n>.emergency_stop) is shown as the share of
runs where it is true (true = 1, false = 0, averaged like any number). Signed metrics (lead distances
and times, stop position errors) use a diverging map centred on 0 (red: negative, e.g. a blinker that
came on after the section start); the others a sequential one. The diverging map keeps a gap around 0:
any value but 0 gets a visible tint (a lead of -0.2 m is not the white of 0), and cell values never
round to 0 (-0.004, not -0.00). The colour bar carries the unit. A cell with failed runs has a red border
and says how many failed; a cell with runs in error an orange dashed border and says how many (an
errored run has no value). For a section's metric (`turn1.lead_distance`) each cell also says which
blinker was on as the front reached the section start (results.csv `<section>.blinker_at_start`, arrows
← left, → right, ↔ hazard, with the count when the runs differ) and marks one other than the section
asks (`<section>.blinker`), a blinker to the wrong side, which has no lead to show. Runs differing in
swept keys not on an axis are averaged, and the title names those keys.

heatmap_data() computes what is drawn; plot_results() draws it (tests read the data)."""
import math
import os
import re

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.colors import FuncNorm, Normalize
from matplotlib.patches import Rectangle

from signalsim_plot.cli import InputError
from signalsim_plot.data import number, read_csv
from signalsim_plot.heat_cells import (SIGNED, ZERO_GAP, cell_value, direction_text,  # noqa: F401
                                       format_value, ordered_values, section_of_metric)

FIXED_BEFORE = ("run", "scenario", "file")
FIXED_AFTER = ("status",)


def swept_columns(header):
    """The columns between 'file' and 'status': what the sweep varied."""
    try:
        return header[header.index("file") + 1:header.index("status")]
    except ValueError as e:
        raise InputError("results.csv lacks the 'file' or 'status' column") from e


def default_metric(header, rows):
    for col in header:
        if col.endswith(".lead_distance") and any(number(r.get(col)) is not None for r in rows):
            return col
    for col in ("max_decel", "max_jerk"):
        if col in header:
            return col
    raise InputError("no metric column to plot; give --metric")


# The unit of a results.csv column, by its last dotted part (metrics.cpp, results_csv).
UNITS = {"lead_distance": "m", "stop_position_error": "m", "lead_time": "s", "time_on": "s", "wall_time": "s",
         "max_decel": "m/s²", "max_jerk": "m/s³", "collisions": "count", "blinker_events": "count",
         "flickers": "count", "missed_signals": "count", "red_light_violations": "count",
         "expectations_passed": "count", "expectations_total": "count"}
FAIL_COLOR, ERROR_COLOR, WRONG_COLOR = "#d00000", "#ff8c00", "#7b1fa2"
MAX_NAME = 64


def gapped_norm(half):
    """A diverging normalisation over [-half, half] with a gap around 0: 0 maps to 0.5 and any other value
    at least ZERO_GAP / (2 (1 + ZERO_GAP)) away from it, so a small late value is tinted, not white."""
    gap = ZERO_GAP * half
    forward = lambda v: np.where(np.asarray(v) == 0, 0.0, np.asarray(v) + np.sign(v) * gap)  # noqa: E731
    inverse = lambda u: np.sign(u) * np.maximum(np.abs(u) - gap, 0.0)  # noqa: E731
    return FuncNorm((forward, inverse), vmin=-half, vmax=half)


def metric_kind(metric, rows):
    """(unit text, signed note or None, boolean) of a metric column."""
    base = metric.rsplit(".", 1)[-1]
    values = [r.get(metric) for r in rows if r.get(metric) not in (None, "")]
    boolean = bool(values) and all(v in ("true", "false") for v in values)
    if boolean:
        return "share of runs where true, 0-1", None, True
    return UNITS.get(base, "value"), SIGNED.get(base), False


def short_key(key):
    """A swept key for a file name: its last dotted part (ego.max_speed -> max_speed)."""
    return key.rsplit(".", 1)[-1]


def file_name(metric, x, y):
    """<metric>_by_<y>_<x>.png with the keys' last dotted parts; past MAX_NAME characters each word of the
    keys is cut to 4 letters (stop_release_confirmation_time -> stop_rele_conf_time)."""
    keys = [short_key(k) for k in ([y] if y else []) + [x]]
    name = f"{metric}_by_{'_'.join(keys)}"
    if len(name) > MAX_NAME:
        keys = ["_".join(w[:4] for w in k.split("_")) for k in keys]
        name = f"{metric}_by_{'_'.join(keys)}"
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name) + ".png"


def heatmap_data(csv_path, metric, x, y):
    """What the heat map draws.

    metric, x, y: the columns (defaults resolved); xs, ys: their values, in axis order; averaged: the swept
    keys averaged over; panels: [{panel (scenario or None), grid (mean per cell, NaN: no value), counts (runs
    with a value), runs, failed, errors (per cell)}]; norm: the colour normalisation (matplotlib Normalize;
    centred on 0 for signed metrics: vmin = -vmax); cmap: its name; unit, signed (the note or None), boolean;
    marked: [(panel index, row, column, failed, errors)] of the cells drawn with a failure/error mark;
    section: the section of a section metric (or None); per panel also directions (per cell a dict
    blinker_at_start -> runs) and asked (per cell the blinker the section asks, "" when unknown);
    wrong: [(panel index, row, column)] of the cells where a run showed a blinker to the other side;
    title; colorbar_label (with the unit); name (the PNG's file name)
    """
    rows = read_csv(csv_path)
    if not rows:
        raise InputError(f"{csv_path}: no rows")
    header = list(rows[0].keys())
    swept = swept_columns(header)
    metric = metric or default_metric(header, rows)
    if metric not in header:
        numeric = [c for c in header if any(number(r.get(c)) is not None for r in rows) and c != "run"]
        raise InputError(f"{csv_path}: no column '{metric}' (numeric columns: {', '.join(numeric)})")
    choices = [c for c in swept] + ["scenario"]
    if not x:
        x = choices[0]
    if not y:
        rest = [c for c in choices if c != x]
        y = rest[0] if rest else None
    for name, col in (("--x", x), ("--y", y)):
        if col is not None and col not in header:
            raise InputError(f"{name} {col}: not a column of {csv_path} (swept: {', '.join(swept) or 'none'})")

    scenarios = ordered_values([r["scenario"] for r in rows])
    panels = scenarios if "scenario" not in (x, y) and len(scenarios) > 1 else [None]
    if panels != [None]:  # only the scenarios that have the metric (e.g. a roundabout exit)
        having = [p for p in panels if any(r["scenario"] == p and cell_value(r.get(metric)) is not None for r in rows)]
        panels = having or panels
        if len(panels) == 1:
            rows = [r for r in rows if r["scenario"] == panels[0]]
    xs = ordered_values([r[x] for r in rows])
    ys = ordered_values([r[y] for r in rows]) if y else [""]
    averaged = [c for c in swept if c not in (x, y)]
    unit, signed, boolean = metric_kind(metric, rows)
    section = section_of_metric(metric, header)

    out = []
    for panel in panels:
        shape = (len(ys), len(xs))
        counts, runs = np.zeros(shape, dtype=int), np.zeros(shape, dtype=int)
        failed, errors = np.zeros(shape, dtype=int), np.zeros(shape, dtype=int)
        sums = np.zeros(shape)
        directions = [[{} for _ in xs] for _ in ys]
        asked = [["" for _ in xs] for _ in ys]
        for r in rows:
            if panel is not None and r["scenario"] != panel:
                continue
            i, j = ys.index(r[y]) if y else 0, xs.index(r[x])
            runs[i, j] += 1
            failed[i, j] += r.get("status") == "failed"
            errors[i, j] += r.get("status") == "error"
            if section and r.get(f"{section}.blinker_at_start"):
                b = r[f"{section}.blinker_at_start"]
                directions[i][j][b] = directions[i][j].get(b, 0) + 1
                asked[i][j] = r.get(f"{section}.blinker", "") or asked[i][j]
            v = cell_value(r.get(metric))
            if v is not None and r.get("status") != "error":
                sums[i, j] += v
                counts[i, j] += 1
        grid = np.full(shape, np.nan)
        mask = counts > 0
        grid[mask] = sums[mask] / counts[mask]
        out.append({"panel": panel, "grid": grid, "counts": counts, "runs": runs, "failed": failed, "errors": errors,
                    "directions": directions, "asked": asked})

    finite = [float(v) for p in out for v in p["grid"][~np.isnan(p["grid"])]]
    if signed:
        half = max([abs(v) for v in finite] + [1e-9])
        norm, cmap = gapped_norm(half), "RdBu"
    elif boolean:
        norm, cmap = Normalize(vmin=0.0, vmax=1.0), "viridis"
    else:
        lo, hi = (min(finite), max(finite)) if finite else (0.0, 1.0)
        if lo == hi:
            lo, hi = lo - 1, hi + 1
        norm, cmap = Normalize(vmin=lo, vmax=hi), "viridis"
    marked = [(k, i, j, int(p["failed"][i, j]), int(p["errors"][i, j])) for k, p in enumerate(out)
              for i in range(len(ys)) for j in range(len(xs)) if p["failed"][i, j] or p["errors"][i, j]]
    wrong = [(k, i, j) for k, p in enumerate(out) for i in range(len(ys)) for j in range(len(xs))
             if direction_text(p["directions"][i][j], p["asked"][i][j])[1]]

    runs_per_cell = sorted({int(n) for p in out for n in p["runs"].ravel() if n})
    per_cell = (f"{runs_per_cell[0]}" if len(runs_per_cell) == 1 else
                f"{runs_per_cell[0]}-{runs_per_cell[-1]}") if runs_per_cell else "0"
    title = f"{metric} by {y} and {x}" if y else f"{metric} by {x}"
    if averaged:
        title += f"\nmean over {', '.join(averaged)} ({per_cell} runs per cell)"
    else:
        title += "\none run per cell" if per_cell == "1" else f"\nmean of {per_cell} runs per cell"
    sub = os.path.basename(os.path.dirname(os.path.abspath(csv_path)))
    title += f"; {sub}; grey: no value"
    if marked:
        title += "; red border: failed runs, orange dashed: runs in error"
    if wrong:
        title += "; purple: a blinker to the wrong side"
    label = f"{metric} [{unit}]" + (f"\n{signed}" if signed else "")
    return {"metric": metric, "x": x, "y": y, "xs": xs, "ys": ys, "averaged": averaged, "panels": out, "norm": norm,
            "cmap": cmap, "unit": unit, "signed": signed, "boolean": boolean, "marked": marked, "section": section,
            "wrong": wrong, "title": title,
            "colorbar_label": label, "name": file_name(metric, x, y)}


def text_color(rgba):
    r, g, b = rgba[:3]
    return "black" if 0.299 * r + 0.587 * g + 0.114 * b > 0.5 else "white"


def plot_results(csv_path, out, metric, x, y):
    data = heatmap_data(csv_path, metric, x, y)
    xs, ys, x, y, norm = data["xs"], data["ys"], data["x"], data["y"], data["norm"]
    panels = data["panels"]
    cols = min(len(panels), 3)
    prow = math.ceil(len(panels) / cols)
    cell_w, cell_h = max(0.9, 0.16 * max(len(v) for v in xs) + 0.5), 0.62
    if data["section"]:  # room for the line about the blinker at the section start
        cell_w, cell_h = max(cell_w, 1.5), 0.8
    fig_w = min(22, max(6.0, cols * (len(xs) * cell_w + 2.8)))
    fig_h = min(20, max(3.4, prow * (len(ys) * cell_h + 1.9) + 1.0))
    fig, axes = plt.subplots(prow, cols, figsize=(fig_w, fig_h), squeeze=False)
    cmap = plt.get_cmap(data["cmap"]).copy()
    cmap.set_bad("#e0e0e0")
    image = None
    for k, p in enumerate(panels):
        ax = axes[k // cols][k % cols]
        grid = p["grid"]
        image = ax.imshow(np.ma.masked_invalid(grid), cmap=cmap, norm=norm, aspect="auto")
        for i in range(len(ys)):
            for j in range(len(xs)):
                lines = []
                if p["counts"][i, j]:
                    value = grid[i, j]
                    lines.append(format_value(value))
                    if p["counts"][i, j] > 1:
                        lines.append(f"(n={p['counts'][i, j]})")
                    color = text_color(cmap(norm(value)))
                else:
                    lines.append("–")
                    color = "#555555"
                if p["failed"][i, j]:
                    lines.append(f"✗ {p['failed'][i, j]}/{p['runs'][i, j]} failed")
                if p["errors"][i, j]:
                    lines.append(f"{p['errors'][i, j]}/{p['runs'][i, j]} error")
                direction, wrong = direction_text(p["directions"][i][j], p["asked"][i][j])
                if direction:
                    lines.append(direction)
                ax.text(j, i, "\n".join(lines), ha="center", va="center", fontsize=7.5, color=color)
                if wrong:  # a blinker to the wrong side: a purple frame inside the cell
                    ax.add_patch(Rectangle((j - 0.34, i - 0.34), 0.68, 0.68, fill=False, lw=2.0, edgecolor=WRONG_COLOR))
                if p["failed"][i, j]:  # solid red border: failed runs; dashed (inside it): errors
                    ax.add_patch(Rectangle((j - 0.46, i - 0.46), 0.92, 0.92, fill=False, lw=2.2, edgecolor=FAIL_COLOR))
                if p["errors"][i, j]:
                    inset = 0.4 if p["failed"][i, j] else 0.46
                    ax.add_patch(Rectangle((j - inset, i - inset), 2 * inset, 2 * inset, fill=False, lw=2.0,
                                           edgecolor=ERROR_COLOR, ls=(0, (3, 2))))
        wide = max(len(v) for v in xs) > 6
        ax.set_xticks(range(len(xs)))
        ax.set_xticklabels(xs, rotation=30 if wide else 0, ha="right" if wide else "center", fontsize=8)
        ax.set_yticks(range(len(ys)))
        ax.set_yticklabels(ys, fontsize=8)
        ax.set_xlabel(x)
        if y:
            ax.set_ylabel(y)
        if p["panel"] is not None:
            ax.set_title(p["panel"], fontsize=9)
    for k in range(len(panels), prow * cols):
        axes[k // cols][k % cols].axis("off")
    fig.suptitle(data["title"], fontsize=10)
    fig.subplots_adjust(top=1 - 0.85 / fig_h, hspace=0.45)
    fig.colorbar(image, ax=axes.ravel().tolist(), shrink=0.9, label=data["colorbar_label"])
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, data["name"])
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return [path]
