"""Reading signalsim's files: CSV columns by name, summary.json, the run's metrics, and the inputs a
run names (its net, its scenario file)."""
import csv
import json
import os

from signalsim_plot.cli import InputError
from signalsim_plot.net import find_input, load_net, sumolib_module


def read_csv(path):
    """Rows of a CSV file as dicts (column -> text)."""
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as e:
        raise InputError(f"{path}: {e.strerror}") from e


def number(text):
    """float of a cell, None when empty or not a number."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def column(rows, name, convert=number):
    return [convert(r.get(name, "")) for r in rows]


# The columns every picture reads (written by `signalsim run`).
REQUIRED_TIMELINE_COLUMNS = ("time", "s_front", "speed", "blinker", "blinker_source", "sumo_signals")


def read_run(run_dir):
    """timeline rows, events rows, summary dict and metrics dict (possibly empty) of a run."""
    summary_path = os.path.join(run_dir, "summary.json")
    try:
        with open(summary_path) as f:
            summary = json.load(f)
    except (OSError, ValueError) as e:
        raise InputError(f"{summary_path}: {e}") from e
    if summary.get("status") == "error":
        raise InputError(f"{run_dir}: the run ended in an error: {summary.get('error', '?')}")
    timeline = read_csv(os.path.join(run_dir, "timeline.csv"))
    if not timeline:
        raise InputError(f"{run_dir}/timeline.csv: no rows")
    missing = [c for c in REQUIRED_TIMELINE_COLUMNS if c not in timeline[0]]
    if missing:
        raise InputError(f"{run_dir}/timeline.csv: missing column(s) {', '.join(missing)}")
    events_path = os.path.join(run_dir, "events.csv")
    events = read_csv(events_path) if os.path.exists(events_path) else []
    metrics = summary.get("metrics")
    if metrics is None and os.path.exists(os.path.join(run_dir, "metrics.json")):
        with open(os.path.join(run_dir, "metrics.json")) as f:
            metrics = json.load(f)
    return timeline, events, summary, metrics or {}


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


def load_scenario_file(path):
    """The scenario YAML as a dict, None when it cannot be read (or python3-yaml is missing)."""
    if not path:
        return None
    try:
        import yaml
    except ImportError:
        return None
    try:
        with open(path) as f:
            doc = yaml.safe_load(f)
    except (OSError, yaml.YAMLError):
        return None
    return doc if isinstance(doc, dict) else None


class RunInputs:
    """The inputs a run's summary names, where they could be found: `net` (signalsim_plot.net.Net or None),
    `scenario` (the scenario file as a dict or None) and `notes` (why something is missing)."""

    def __init__(self, run_dir, summary):
        self.notes = []
        self.scenario_path = find_input(summary.get("file"), run_dir)
        self.scenario = load_scenario_file(self.scenario_path)
        net_path = find_input(summary.get("net"), run_dir)
        if net_path is None and self.scenario and isinstance(self.scenario.get("net"), str):
            candidate = os.path.join(os.path.dirname(self.scenario_path), self.scenario["net"])
            net_path = candidate if os.path.isfile(candidate) else None
        self.net = load_net(net_path) if net_path else None
        if self.net is None and net_path and sumolib_module() is None:
            self.notes.append("sumolib not found: set SUMO_HOME (Debian: apt-get install sumo-tools)")
        elif self.net is None:
            self.notes.append(f"net {summary.get('net') or '?'} not found")
        if self.scenario is None:
            self.notes.append(f"scenario file {summary.get('file') or '?'} not readable")
