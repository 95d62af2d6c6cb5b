"""What the report says about one run, read from its folder: summary.json (status, net, country,
decider, parameter files, expectations, the first failure) and the row results.csv gave it."""
import json
import os

FINISHED = ("passed", "failed", "no_expectations")
# check.json's verdicts as statuses: a scenario without expectations whose events match is "skipped" there
CHECK_STATUS = {"passed": "passed", "failed": "failed", "error": "error", "skipped": "no_expectations"}


def read_summary(run_dir):
    """The run's summary.json as a dict; {} when missing or unreadable (the row then says why)."""
    try:
        with open(os.path.join(run_dir, "summary.json")) as f:
            summary = json.load(f)
        return summary if isinstance(summary, dict) else {}
    except (OSError, ValueError):
        return {}


def country_of(summary):
    """The country preset the run used: summary.json's `country` ('' when none); a summary written
    before that field: the first parameter whose source is 'country XX'."""
    if isinstance(summary.get("country"), str):
        return summary["country"]
    for source in (summary.get("parameter_sources") or {}).values():
        where = source.get("from", "") if isinstance(source, dict) else ""
        if where.startswith("country "):
            return where[len("country "):]
    return ""


def parameter_files_of(summary):
    """The parameter files the run read, in first-use order (from parameter_sources' '<file>:<line>')."""
    files = []
    for source in (summary.get("parameter_sources") or {}).values():
        where = source.get("from", "") if isinstance(source, dict) else ""
        path, sep, line = where.rpartition(":")
        if sep and line.isdigit() and path not in files:
            files.append(path)
    return files


def decider_of(summary):
    """The decider (and light judge) that decided: 'reference' unless one was brought."""
    names = []
    for key in ("decider", "light_judge"):
        block = summary.get(key)
        if isinstance(block, dict) and block.get("name"):
            names.append(block["name"] if key == "decider" else f"light_judge {block['name']}")
    return ", ".join(names) or "reference"


def failed_expectations(summary):
    """'expectation: detail' of each failed expectation, then each failed law verdict."""
    lines = [f"{e.get('expectation', '?')}: {e.get('detail', '')}"
             for e in summary.get("expectations") or [] if isinstance(e, dict) and not e.get("passed", True)]
    law = summary.get("law") if isinstance(summary.get("law"), dict) else {}
    lines += [f"law {v.get('section', '')} {v.get('id', '')} {v.get('rule', '')}: {v.get('detail', '')}"
              for v in law.get("verdicts") or [] if isinstance(v, dict) and not v.get("passed", True)]
    return lines


def first_problem(status, summary, row_error):
    """The line the table shows: the first failed expectation, or the error."""
    if status == "error":
        return row_error or summary.get("error", "") or "no readable summary.json"
    if status == "failed":
        lines = failed_expectations(summary)
        return lines[0] if lines else ""
    return ""


class Run:
    """One run of the report: its row cells and the facts read from its folder."""

    def __init__(self, out_dir, index, run_dir, row, keep_summary=False):
        self.index = index
        self.run_dir = run_dir  # relative to out_dir: runs/NNNN-name
        self.row = row
        self.name = os.path.basename(run_dir.rstrip("/")) if run_dir else f"{index:04d}"
        summary = read_summary(os.path.join(out_dir, run_dir)) if run_dir else {}
        self.status = row.get("status") or summary.get("status") or "error"
        self.scenario = row.get("scenario") or summary.get("scenario", "")
        self.file = row.get("file") or summary.get("file", "")
        self.net = summary.get("net", "")
        self.country = row.get("country") or country_of(summary)
        self.decider = row.get("decider") or decider_of(summary)
        self.parameter_files = parameter_files_of(summary)
        self.problem = first_problem(self.status, summary, row.get("error", ""))
        self.check = None  # check's verdict of this run (check.json), when any
        metrics = summary.get("metrics") if isinstance(summary.get("metrics"), dict) else {}
        for key, value in metrics.items():  # compare's runs have no results.csv row: their run-level metrics
            if key not in row and not isinstance(value, (dict, list)):
                row[key] = "" if value is None else str(value)
        self.summary = summary if keep_summary else None

    def apply_check(self, case):
        """check's verdict replaces the run's status: a differing event fails a run whose expectations held."""
        self.check = case
        self.status = CHECK_STATUS.get(case.get("status", ""), self.status)
        if self.status in ("failed", "error") and not self.problem:
            self.problem = case.get("message", "")

    def page(self):
        """The run's page, relative to OUT."""
        return f"report/runs/{self.name}.html"
