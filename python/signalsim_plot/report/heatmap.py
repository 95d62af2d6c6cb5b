"""A sweep's heat maps as HTML tables on the report's first page: the mean of a metric per cell of two
swept columns (one table per scenario when several), the failed and errored runs counted, each cell
linking to its runs in the table (#cell=...). Which maps: the sweep file's plot: entries as the sweep
recorded them (command.json), else the first *.lead_distance column over the first two swept columns."""
import json
import math
from urllib.parse import quote

from signalsim_plot.report.html_bits import esc

SIGNED = ("lead_distance", "lead_time", "stop_position_error")  # a diverging scale centred on 0


def value_of(text):
    if text in ("true", "false"):
        return 1.0 if text == "true" else 0.0
    try:
        v = float(text)
        return v if math.isfinite(v) else None
    except (TypeError, ValueError):
        return None


def ordered(values):
    distinct = list(dict.fromkeys(values))
    if all(value_of(v) is not None and v not in ("true", "false") for v in distinct):
        return sorted(distinct, key=float)
    return distinct


def default_specs(header, rows, swept):
    """[{metric, x, y}]: the first *.lead_distance column with a value (else max_decel) over the first two
    swept columns (scenario and the swept one when only one is swept)."""
    metric = next((c for c in header if c.endswith(".lead_distance") and any(value_of(r.get(c)) is not None for r in rows)),
                  "max_decel" if "max_decel" in header else None)
    axes = list(swept[:2]) if len(swept) >= 2 else (["scenario"] + list(swept[:1]) if swept else [])
    if metric is None or len(axes) < 2:
        return []
    return [{"metric": metric, "x": axes[1], "y": axes[0]}]


def colour(value, low, high, signed):
    """Background colour of a cell: white to blue, or red (negative) / white / blue centred on 0."""
    if value is None:
        return "#ffffff"
    if signed:
        span = max(abs(low), abs(high)) or 1.0
        t = max(-1.0, min(1.0, value / span))
        r, g, b = (255, int(255 * (1 + t)), int(255 * (1 + t))) if t < 0 else (int(255 * (1 - t * 0.8)), int(255 * (1 - t * 0.5)), 255)
    else:
        t = 0.0 if high == low else (value - low) / (high - low)
        r, g, b = int(255 * (1 - t * 0.8)), int(255 * (1 - t * 0.5)), 255
    return f"#{r:02x}{g:02x}{b:02x}"


def cells(rows, spec, panel_key, panel):
    """(x, y) -> {values, runs, failed, errors} for one panel."""
    out = {}
    for r in rows:
        if panel_key and r.get(panel_key) != panel:
            continue
        cell = out.setdefault((r.get(spec["x"], ""), r.get(spec["y"], "")), {"values": [], "runs": 0, "failed": 0, "errors": 0})
        cell["runs"] += 1
        cell["failed"] += r.get("status") == "failed"
        cell["errors"] += r.get("status") == "error"
        v = value_of(r.get(spec["metric"], ""))
        if v is not None:
            cell["values"].append(v)
    return out


def cell_html(cell, selection, low, high, signed):
    if cell is None:
        return "<td></td>"
    mean = sum(cell["values"]) / len(cell["values"]) if cell["values"] else None
    text = "-" if mean is None else f"{mean:.3g}"
    marks = (f" ✗{cell['failed']}" if cell["failed"] else "") + (f" !{cell['errors']}" if cell["errors"] else "")
    cls = " class=\"bad\"" if cell["failed"] else " class=\"err\"" if cell["errors"] else ""
    href = "#cell=" + quote(json.dumps(selection, separators=(",", ":")))
    title = f"{len(cell['values'])} of {cell['runs']} runs with a value; {cell['failed']} failed, {cell['errors']} errors"
    return (f"<td{cls} style=\"background:{colour(mean, low, high, signed)}\" title=\"{esc(title)}\">"
            f"<a href=\"{esc(href)}\">{esc(text)}<small>{esc(marks)} n={cell['runs']}</small></a></td>")


def heatmap_html(rows, spec):
    """One metric over two columns: a table per scenario (one when the scenario is an axis or single)."""
    metric, x, y = spec["metric"], spec["x"], spec["y"]
    scenarios = list(dict.fromkeys(r.get("scenario", "") for r in rows))
    panel_key = "scenario" if len(scenarios) > 1 and "scenario" not in (x, y) else None
    all_values = [v for r in rows if (v := value_of(r.get(metric, ""))) is not None]
    low, high = (min(all_values), max(all_values)) if all_values else (0.0, 0.0)
    signed = metric.rsplit(".", 1)[-1] in SIGNED
    xs, ys = ordered([r.get(x, "") for r in rows]), ordered([r.get(y, "") for r in rows])
    parts = [f"<h3>{esc(metric)} by {esc(y)} (rows) and {esc(x)} (columns)</h3>"]
    for panel in (scenarios if panel_key else [None]):
        grid = cells(rows, spec, panel_key, panel)
        head = "".join(f"<th>{esc(v)}</th>" for v in xs)
        body = ""
        for yv in ys:
            tds = ""
            for xv in xs:
                selection = {x: xv, y: yv}
                if panel_key:
                    selection["scenario"] = panel
                tds += cell_html(grid.get((xv, yv)), selection, low, high, signed)
            body += f"<tr><th>{esc(yv)}</th>{tds}</tr>"
        caption = f"<caption>{esc(panel)}</caption>" if panel_key else ""
        parts.append(f"<table class=\"heat\">{caption}<thead><tr><th>{esc(y)} \\ {esc(x)}</th>{head}</tr></thead>"
                     f"<tbody>{body}</tbody></table>")
    parts.append("<p class=\"note\">Mean per cell over the runs with a value (true/false as 1/0); ✗ failed runs, "
                 "! runs in error, n runs. A cell shows its runs in the table below.</p>")
    return "\n".join(parts)
