"""OUT/report.html: the first screen (counts, the command and its inputs, when and on what it ran, wall
time), a sweep's heat maps, compare's table and picture, and the table of runs (inline JSON drawn by
report.js: sortable, filterable)."""
import json
import os
import shlex

from signalsim_plot.report import heatmap
from signalsim_plot.report.html_bits import esc, facts_list, joined, link, page, table

SCRIPT_FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "report.js")
METRICS = ("max_decel", "max_jerk", "missed_signals", "flickers", "red_light_violations", "collisions")
COUNTED = (("passed", "passed"), ("failed", "failed"), ("error", "errors"), ("no_expectations", "without expectations"))


def number_or_text(text):
    if text in (None, ""):
        return None
    if isinstance(text, (int, float)):
        return text
    try:
        return float(text) if "." in text or "e" in text.lower() else int(text)
    except ValueError:
        return text


def plural(n, word):
    return f"{n} {word}" + ("" if n == 1 else "s")


def columns(folder, metrics):
    """The table's columns: [{key, label, kind}]; a row holds their values then its page."""
    cols = [{"key": "run", "label": "run", "kind": "link"}, {"key": "status", "label": "status", "kind": "status"},
            {"key": "scenario", "label": "scenario", "kind": "text"}]
    if folder.kind == "compare":
        cols.append({"key": "driver", "label": "driver", "kind": "text"})
    cols += [{"key": "net", "label": "net", "kind": "text"}, {"key": "country", "label": "country", "kind": "text"}]
    cols += [{"key": k, "label": k, "kind": "text", "title": "swept"} for k in folder.swept if k != "country"]
    cols += [{"key": "decider", "label": "decider", "kind": "text"},
             {"key": "problem", "label": "first failed expectation or error", "kind": "problem"}]
    cols += [{"key": m, "label": m, "kind": "num"} for m in metrics]
    cols.append({"key": "wall_time", "label": "wall s", "kind": "num"})
    return cols


def row_values(run, cols):
    facts = {"run": run.index, "status": run.status, "scenario": run.scenario, "net": os.path.basename(run.net),
             "country": run.country, "decider": run.decider, "problem": run.problem}
    out = []
    for c in cols:
        value = facts[c["key"]] if c["key"] in facts else run.row.get(c["key"], "")
        out.append(number_or_text(value) if c["kind"] == "num" or c["key"] == "run" else (value or None))
    return out + [run.page()]


def counts_html(runs):
    counted = {status: 0 for status, _ in COUNTED}
    for run in runs:
        counted[run.status] = counted.get(run.status, 0) + 1
    boxes = "".join(f"<div class=\"count {s}\" id=\"count-{s}\"><b>{counted[s]}</b>{esc(label)}</div>" for s, label in COUNTED)
    return f"<div class=\"counts\"><div class=\"count\" id=\"count-runs\"><b>{len(runs)}</b>runs</div>{boxes}</div>"


def facts_html(folder, runs):
    f = folder.facts
    distinct = lambda values: list(dict.fromkeys(v for v in values if v))
    param_files = distinct(p for run in runs for p in run.parameter_files)
    seconds = f.get("wall_time")
    machine = ", ".join(x for x in (f.get("host", ""), f.get("system", ""),
                                     f"{f['cores']} cores" if f.get("cores") else "",
                                     f"--jobs {f['jobs']}" if f.get("jobs") else "") if x)
    items = [
        ("command", f"<code>{esc(shlex.join(f['argv']))}</code>" if f.get("argv") else
         "<span class=\"note\">not recorded (no command.json: the folder was made by an older signalsim)</span>"),
        ("suite", "" if f.get("sweep_file") else joined(f.get("inputs", []))), ("sweep file", esc(f.get("sweep_file", ""))),
        ("golden folder", esc(f.get("golden", ""))),
        ("scenarios", plural(len(distinct(r.file for r in runs)), "file")),
        ("nets", joined(distinct(r.net for r in runs))),
        ("parameter files", joined(param_files)), ("--set", joined(f.get("set", []), "")),
        ("countries", joined(distinct(r.country for r in runs), "none (the scenarios' own parameters)")),
        ("decider", joined(distinct(r.decider for r in runs))),
        ("started", esc(f.get("started", ""))), ("finished", esc(f.get("finished", ""))),
        ("wall time", f"{seconds:.1f} s" if isinstance(seconds, (int, float)) else ""),
        ("on", esc(machine)), ("signalsim", esc(f.get("version", ""))),
    ]
    return facts_list(items)


def sweep_html(folder):
    specs = (folder.facts.get("sweep_plots") or []) or heatmap.default_specs(folder.header, folder.rows, folder.swept)
    specs = [s for s in specs if all(s.get(k) in folder.header for k in ("metric", "x", "y"))]
    if not specs:
        return ""
    parts = ["<h2>Heat maps</h2>"] + [heatmap.heatmap_html(folder.rows, s) for s in specs]
    plots = os.path.join(folder.out_dir, "plots")
    pngs = sorted(p for p in os.listdir(plots) if p.endswith(".png")) if os.path.isdir(plots) else []
    if pngs:
        parts.append("<details><summary>the heat-map pictures (sweep --plot)</summary><div class=\"pictures\">" +
                     "".join(f"<img src=\"plots/{esc(p)}\" alt=\"{esc(p)}\" loading=\"lazy\">" for p in pngs) + "</div></details>")
    return "\n".join(parts)


def compare_html(folder):
    header, rows = folder.comparison
    picture = ("<div class=\"pictures\"><img src=\"comparison.png\" alt=\"comparison.png\"></div>"
               if os.path.isfile(os.path.join(folder.out_dir, "comparison.png")) else
               "<p class=\"note\">no comparison.png</p>")
    shown = [h for h in header if h not in ("run_dir",)]
    return ("<h2>Comparison</h2>" + picture + link("comparison.csv", "comparison.csv") +
            table(shown, [[r.get(h, "") for h in shown] for r in rows]))


def index_page(folder, runs):
    plot_metrics = [s.get("metric") for s in folder.facts.get("sweep_plots") or []]
    metrics = [m for m in dict.fromkeys(list(METRICS) + plot_metrics) if m and (m in folder.header or folder.kind == "compare")]
    cols = columns(folder, metrics)
    data = json.dumps({"columns": cols, "rows": [row_values(r, cols) for r in runs]}, ensure_ascii=False,
                      separators=(",", ":")).replace("<", "\\u003c")  # no "</script>" or "<!--" in the data
    title = f"signalsim {folder.kind}: {os.path.basename(os.path.abspath(folder.out_dir))}"
    files = " · ".join(link(n, n) for n in ("results.csv", "comparison.csv", "junit.xml")
                       if os.path.isfile(os.path.join(folder.out_dir, n)))
    body = [f"<h1>{esc(title)}</h1>", counts_html(runs), facts_html(folder, runs), f"<p>{files}</p>" if files else ""]
    body.append(sweep_html(folder) if folder.kind == "sweep" else compare_html(folder) if folder.kind == "compare" else "")
    body.append(
        "<h2>Runs</h2><div class=\"controls\"><label>status <select id=\"status-filter\">"
        "<option value=\"\">all</option><option>passed</option><option>failed</option><option>error</option>"
        "<option>no_expectations</option></select></label>"
        "<label>text <input id=\"text-filter\" type=\"search\" placeholder=\"scenario, value, message\"></label>"
        "<span id=\"shown\"></span><span id=\"cell-filter\"></span></div>"
        "<table id=\"runs\"><thead><tr></tr></thead><tbody></tbody></table>"
        f"<script type=\"application/json\" id=\"report-data\">{data}</script>")
    with open(SCRIPT_FILE) as f:
        script = f.read()
    return page(title, "\n".join(b for b in body if b), script)
