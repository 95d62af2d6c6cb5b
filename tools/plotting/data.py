"""Reading signalsim's files: CSV columns by name, summary.json, the run's metrics."""
import csv
import json
import os

from plotting.cli import InputError


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
