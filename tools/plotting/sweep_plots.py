"""A sweep's results.csv as a heat map (a table with colours) of one metric over two swept columns.

A true/false column (light<n>.red_light_violation, light<n>.emergency_stop) is shown as the share of
runs where it is true (true = 1, false = 0, averaged like any number)."""
import math
import os
import re

import matplotlib.pyplot as plt
import numpy as np

from plotting.cli import InputError
from plotting.data import number, read_csv

FIXED_BEFORE = ("run", "scenario", "file")
FIXED_AFTER = ("status",)


def swept_columns(header):
    """The columns between 'file' and 'status': what the sweep varied."""
    try:
        return header[header.index("file") + 1:header.index("status")]
    except ValueError as e:
        raise InputError("results.csv lacks the 'file' or 'status' column") from e


def cell_value(text):
    """A cell as a number: numbers as they are, true/false as 1/0, anything else None."""
    if text in ("true", "false"):
        return 1.0 if text == "true" else 0.0
    return number(text)


def ordered_values(values):
    """Distinct values: numerically sorted when all are numbers, else in first-seen (sweep) order."""
    distinct = list(dict.fromkeys(values))
    if all(number(v) is not None for v in distinct):
        return sorted(distinct, key=float)
    return distinct


def default_metric(header, rows):
    for col in header:
        if col.endswith(".lead_distance") and any(number(r.get(col)) is not None for r in rows):
            return col
    for col in ("max_decel", "max_jerk"):
        if col in header:
            return col
    raise InputError("no metric column to plot; give --metric")


def plot_results(csv_path, out, metric, x, y):
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

    cols = min(len(panels), 3)
    prow = math.ceil(len(panels) / cols)
    cell_w, cell_h = max(0.9, 0.16 * max(len(v) for v in xs) + 0.5), 0.6
    fig_w = min(22, max(5.5, cols * (len(xs) * cell_w + 2.8)))
    fig_h = min(20, max(3.2, prow * (len(ys) * cell_h + 1.9) + 0.8))
    fig, axes = plt.subplots(prow, cols, figsize=(fig_w, fig_h), squeeze=False)

    # Cell means per panel first: the colour scale spans what is shown.
    grids = []
    for panel in panels:
        counts = np.zeros((len(ys), len(xs)), dtype=int)
        errors = np.zeros((len(ys), len(xs)), dtype=int)
        sums = np.zeros((len(ys), len(xs)))
        for r in rows:
            if panel is not None and r["scenario"] != panel:
                continue
            i, j = ys.index(r[y]) if y else 0, xs.index(r[x])
            v = cell_value(r.get(metric))
            if r.get("status") == "error":
                errors[i, j] += 1
            if v is not None:
                sums[i, j] += v
                counts[i, j] += 1
        grid = np.full((len(ys), len(xs)), np.nan)
        mask = counts > 0
        grid[mask] = sums[mask] / counts[mask]
        grids.append((grid, counts, errors))
    finite = [v for grid, _, _ in grids for v in grid[~np.isnan(grid)]]
    vmin, vmax = (float(min(finite)), float(max(finite))) if finite else (0.0, 1.0)
    if vmin == vmax:
        vmin, vmax = vmin - 1, vmax + 1
    cmap = plt.get_cmap("viridis").copy()
    cmap.set_bad("#e0e0e0")
    image = None
    for k, (panel, (grid, counts, errors)) in enumerate(zip(panels, grids)):
        ax = axes[k // cols][k % cols]
        image = ax.imshow(np.ma.masked_invalid(grid), cmap=cmap, vmin=vmin, vmax=vmax, aspect="auto")
        for i in range(len(ys)):
            for j in range(len(xs)):
                if counts[i, j]:
                    value = grid[i, j]
                    text = f"{value:.2f}" if abs(value) < 1000 else f"{value:.0f}"
                    if counts[i, j] > 1:
                        text += f"\n(n={counts[i, j]})"
                    shade = (value - vmin) / (vmax - vmin)
                    ax.text(j, i, text, ha="center", va="center", fontsize=8,
                            color="black" if shade > 0.55 else "white")
                else:
                    ax.text(j, i, "error" if errors[i, j] else "–", ha="center", va="center", fontsize=8,
                            color="#b00000" if errors[i, j] else "#555555")
        wide = max(len(v) for v in xs) > 6
        ax.set_xticks(range(len(xs)))
        ax.set_xticklabels(xs, rotation=30 if wide else 0, ha="right" if wide else "center", fontsize=8)
        ax.set_yticks(range(len(ys)))
        ax.set_yticklabels(ys, fontsize=8)
        ax.set_xlabel(x)
        if y:
            ax.set_ylabel(y)
        if panel is not None:
            ax.set_title(panel, fontsize=9)
    for k in range(len(panels), prow * cols):
        axes[k // cols][k % cols].axis("off")
    title = f"{metric} by {y} and {x}" if y else f"{metric} by {x}"
    sub = os.path.basename(os.path.dirname(os.path.abspath(csv_path)))
    note = f"\nmean over {', '.join(averaged)}; " if averaged else "  ("
    fig.suptitle(f"{title}{note}{sub}; grey: no value" + ("" if averaged else ")"), fontsize=10)
    fig.subplots_adjust(top=1 - (0.75 if averaged else 0.55) / fig_h, hspace=0.45)
    fig.colorbar(image, ax=axes.ravel().tolist(), shrink=0.9, label=metric)
    os.makedirs(out, exist_ok=True)
    name = re.sub(r"[^A-Za-z0-9_.-]+", "_", f"{metric}_by_{y}_{x}" if y else f"{metric}_by_{x}") + ".png"
    path = os.path.join(out, name)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return [path]
