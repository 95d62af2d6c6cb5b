"""OUT/report/runs/<run folder>.html: one run's page. Its facts, the expectations and law verdicts with
ok/FAIL lines, check's verdict with the golden diff, the SUT beside the reference (decider,
light_judge), the pictures (RUN_DIR/plots), the event list and links to the run's files."""
import csv
import os

from signalsim_plot.report.html_bits import esc, facts_list, joined, link, page, status_badge, table
from signalsim_plot.report.pictures import NOT_FINISHED, existing

RUN_FILES = ("summary.json", "timeline.csv", "events.csv", "sumo.log", "decider.stderr.txt", "light_judge.stderr.txt")
MAX_EVENTS = 2000


def verdict_lines(items, label):
    """<ul> of ok/FAIL lines."""
    lines = "".join(f"<li><span class=\"{'ok' if ok else 'fail'}\">{'ok' if ok else 'FAIL'}</span> "
                    f"{esc(text)}: <span class=\"detail\">{esc(detail)}</span></li>" for ok, text, detail in items)
    return f"<ul class=\"{label}\">{lines}</ul>"


def expectations_html(summary):
    expectations = [(e.get("passed", False), e.get("expectation", "?"), e.get("detail", ""))
                    for e in summary.get("expectations") or [] if isinstance(e, dict)]
    law = summary.get("law") if isinstance(summary.get("law"), dict) else {}
    verdicts = [(v.get("passed", False), f"{v.get('section', '')} {v.get('id', '')} {v.get('rule', '')}", v.get("detail", ""))
                for v in law.get("verdicts") or [] if isinstance(v, dict)]
    out = ["<h2>Expectations</h2>", verdict_lines(expectations, "expectations") if expectations else
           "<p class=\"note\">the scenario has no expectations</p>"]
    if verdicts:
        failed = [v for v in verdicts if not v[0]]
        out.append(f"<h2>Law verdicts ({len(failed)} failed of {len(verdicts)})</h2>")
        out.append(verdict_lines(failed, "law") if failed else "")
        out.append(f"<details><summary>all {len(verdicts)} verdicts</summary>{verdict_lines(verdicts, 'law')}</details>")
    return "\n".join(out)


def check_html(case):
    if not case:
        return ""
    detail = f"<pre>{esc(case['details'])}</pre>" if case.get("details") else ""
    extra = f"<pre>{esc(case['system_out'])}</pre>" if case.get("system_out") else ""
    return (f"<h2>check against the golden file: {status_badge(case.get('status', ''))}</h2>"
            f"<p>{esc(case.get('message', ''))}</p>{detail}{extra}")


def sut_html(summary):
    """The decider and light judge under test beside the reference."""
    out = []
    decider = summary.get("decider")
    if isinstance(decider, dict):
        out.append(f"<h2>Decider under test: {esc(decider.get('name', ''))}</h2>"
                   f"<p>agreement with the reference {esc(decider.get('agreement'))} "
                   f"({esc(decider.get('agreeing_steps'))} of {esc(decider.get('steps'))} steps)</p>")
        rows = []
        for s in decider.get("sections") or []:
            sut, ref = s.get("sut") or {}, s.get("reference") or {}
            rows.append([s.get("kind", ""), s.get("id", ""), s.get("blinker", ""), s.get("s_start", ""),
                         sut.get("lead_distance"), ref.get("lead_distance"), sut.get("missed"), ref.get("missed")])
        out.append(table(["kind", "id", "blinker", "s_start m", "SUT lead m", "reference lead m", "SUT missed",
                          "reference missed"], rows))
    judge = summary.get("light_judge")
    if isinstance(judge, dict):
        out.append(f"<h2>Light judge under test: {esc(judge.get('name', ''))}</h2>"
                   f"<p>agreement with the reference {esc(judge.get('agreement'))} "
                   f"({esc(judge.get('agreeing_steps'))} of {esc(judge.get('steps'))} judged steps)</p>")
        out.append(table(["light", "agreement", "SUT decisions", "reference decisions"],
                         [[l.get("id", ""), l.get("agreement"), " → ".join(l.get("sut") or []),
                           " → ".join(l.get("reference") or [])] for l in judge.get("lights") or []]))
    return "\n".join(out)


def pictures_html(out_dir, run, drawn_error, wanted):
    run_dir = os.path.join(out_dir, run.run_dir)
    names = existing(run_dir)
    out = ["<h2>Pictures</h2>"]
    if drawn_error == NOT_FINISHED:
        out.append("<p class=\"note\">no pictures: the run did not finish (no timeline.csv)</p>")
    elif drawn_error:
        out.append(f"<p class=\"fail\">the pictures could not be drawn: {esc(drawn_error)}</p>")
    if names:
        out.append("<div class=\"pictures\">" + "".join(
            f"<img src=\"../../{esc(run.run_dir)}/plots/{esc(n)}\" alt=\"{esc(n)}\">" for n in names) + "</div>")
    elif not wanted:
        out.append(f"<p class=\"note\">pictures of passed runs are drawn with <code>--report=all</code> "
                   f"(or <code>python/signalsim-plot {esc(run.run_dir)}</code>)</p>")
    elif not drawn_error:
        out.append("<p class=\"note\">nothing to draw</p>")
    return "\n".join(out)


def events_html(run_dir):
    path = os.path.join(run_dir, "events.csv")
    if not os.path.isfile(path):
        return ""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return ""
    header, rows = rows[0], rows[1:]
    more = f"<p class=\"note\">the first {MAX_EVENTS} of {len(rows)} events</p>" if len(rows) > MAX_EVENTS else ""
    return f"<h2>Events ({len(rows)})</h2>" + table(header, rows[:MAX_EVENTS]) + more


def run_page(out_dir, run, summary, swept, drawn_error, wanted):
    run_dir = os.path.join(out_dir, run.run_dir)
    files = " · ".join(link(f"../../{run.run_dir}/{n}", n) for n in RUN_FILES if os.path.isfile(os.path.join(run_dir, n)))
    not_arrived = summary.get("not_arrived") if isinstance(summary.get("not_arrived"), dict) else {}
    facts = facts_list([
        ("status", status_badge(run.status)), ("scenario", esc(run.scenario)), ("file", esc(run.file)),
        ("net", esc(run.net)), ("country", esc(run.country)), ("decider", esc(run.decider)),
        ("swept", joined((f"{k}={run.row.get(k, '')}" for k in swept), "")),
        ("driver", esc(summary.get("driver", ""))), ("seed", esc(summary.get("seed", ""))),
        ("parameter files", joined(run.parameter_files)),
        ("not arrived", esc(not_arrived.get("detail", ""))),
        ("error", esc(run.problem) if run.status == "error" else ""),
        ("notes", joined(summary.get("notes") or [], "")),
        ("folder", link(f"../../{run.run_dir}/", run.run_dir)), ("files", files),
    ])
    title = f"run {run.index} {run.scenario}: {run.status}"
    body = [f"<p>{link('../../report.html', '← all runs')}</p><h1>{esc(title)}</h1>", facts,
            check_html(run.check), expectations_html(summary) if summary.get("status") != "error" else "",
            sut_html(summary), pictures_html(out_dir, run, drawn_error, wanted), events_html(run_dir)]
    return page(title, "\n".join(b for b in body if b))
