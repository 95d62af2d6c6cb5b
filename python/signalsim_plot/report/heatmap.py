"""A sweep's heat maps as HTML tables on the report's first page: the mean of a metric per cell of two
swept columns (one table per scenario when several), the failed and errored runs counted, the blinker
at the section start (signalsim_plot.heat_cells, as the PNG heat maps), each cell linking to its runs
in the table (#cell=...). Which maps: the sweep file's plot: entries as the sweep
recorded them (command.json), else the first *.lead_distance column over the first two swept columns."""
import json
from urllib.parse import quote

from signalsim_plot.heat_cells import (SIGNED, cell_value, direction_text, format_value, gapped_share,
                                       ordered_values, section_of_metric)
from signalsim_plot.report.html_bits import esc


def default_specs(header, rows, swept):
    """[{metric, x, y}]: the first *.lead_distance column with a value (else max_decel) over the first two
    swept columns (scenario and the swept one when only one is swept)."""
    metric = next((c for c in header if c.endswith(".lead_distance") and any(cell_value(r.get(c)) is not None for r in rows)),
                  "max_decel" if "max_decel" in header else None)
    axes = list(swept[:2]) if len(swept) >= 2 else (["scenario"] + list(swept[:1]) if swept else [])
    if metric is None or len(axes) < 2:
        return []
    return [{"metric": metric, "x": axes[1], "y": axes[0]}]


def colour(value, low, high, signed):
    """Background colour of a cell: white to blue, or red (negative) / white / blue centred on 0 with a
    gap around 0 (heat_cells.gapped_share): a small late value is tinted, not the white of 0."""
    if value is None:
        return "#ffffff"
    if signed:
        t = gapped_share(value, max(abs(low), abs(high)))
        r, g, b = (255, int(255 * (1 + t)), int(255 * (1 + t))) if t < 0 else (int(255 * (1 - t * 0.8)), int(255 * (1 - t * 0.5)), 255)
    else:
        t = 0.0 if high == low else (value - low) / (high - low)
        r, g, b = int(255 * (1 - t * 0.8)), int(255 * (1 - t * 0.5)), 255
    return f"#{r:02x}{g:02x}{b:02x}"


def cells(rows, spec, panel_key, panel, section):
    """(x, y) -> {values, runs, failed, errors, directions, asked} for one panel; directions: the blinker at
    the section start -> runs (section metrics), asked: the blinker the section asks."""
    out = {}
    for r in rows:
        if panel_key and r.get(panel_key) != panel:
            continue
        cell = out.setdefault((r.get(spec["x"], ""), r.get(spec["y"], "")),
                              {"values": [], "runs": 0, "failed": 0, "errors": 0, "directions": {}, "asked": ""})
        cell["runs"] += 1
        cell["failed"] += r.get("status") == "failed"
        cell["errors"] += r.get("status") == "error"
        if section and r.get(f"{section}.blinker_at_start"):
            b = r[f"{section}.blinker_at_start"]
            cell["directions"][b] = cell["directions"].get(b, 0) + 1
            cell["asked"] = r.get(f"{section}.blinker", "") or cell["asked"]
        v = cell_value(r.get(spec["metric"], ""))
        if v is not None:
            cell["values"].append(v)
    return out


def cell_html(cell, selection, low, high, signed):
    if cell is None:
        return "<td></td>"
    mean = sum(cell["values"]) / len(cell["values"]) if cell["values"] else None
    text = "-" if mean is None else format_value(mean)
    marks = (f" ✗{cell['failed']}" if cell["failed"] else "") + (f" !{cell['errors']}" if cell["errors"] else "")
    direction, wrong = direction_text(cell["directions"], cell["asked"])
    cls = " class=\"bad\"" if cell["failed"] else " class=\"err\"" if cell["errors"] else " class=\"wrong\"" if wrong else ""
    href = "#cell=" + quote(json.dumps(selection, separators=(",", ":")))
    title = f"{len(cell['values'])} of {cell['runs']} runs with a value; {cell['failed']} failed, {cell['errors']} errors"
    start = f"<br><small class=\"start\">{esc(direction)}</small>" if direction else ""
    return (f"<td{cls} style=\"background:{colour(mean, low, high, signed)}\" title=\"{esc(title)}\">"
            f"<a href=\"{esc(href)}\">{esc(text)}<small>{esc(marks)} n={cell['runs']}</small>{start}</a></td>")


def heatmap_html(rows, spec):
    """One metric over two columns: a table per scenario (one when the scenario is an axis or single)."""
    metric, x, y = spec["metric"], spec["x"], spec["y"]
    scenarios = list(dict.fromkeys(r.get("scenario", "") for r in rows))
    panel_key = "scenario" if len(scenarios) > 1 and "scenario" not in (x, y) else None
    all_values = [v for r in rows if (v := cell_value(r.get(metric, ""))) is not None]
    low, high = (min(all_values), max(all_values)) if all_values else (0.0, 0.0)
    signed = metric.rsplit(".", 1)[-1] in SIGNED
    section = section_of_metric(metric, list(rows[0].keys()) if rows else [])
    xs, ys = ordered_values([r.get(x, "") for r in rows]), ordered_values([r.get(y, "") for r in rows])
    parts = [f"<h3>{esc(metric)} by {esc(y)} (rows) and {esc(x)} (columns)</h3>"]
    for panel in (scenarios if panel_key else [None]):
        grid = cells(rows, spec, panel_key, panel, section)
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
                 "! runs in error, n runs; start: the blinker as the front reached the section start (← left, "
                 "→ right, ↔ hazard, · none), framed purple when it is not the one the section asks. A cell shows "
                 "its runs in the table below.</p>")
    return "\n".join(parts)
