"""An output folder as the report sees it: which command made it (batch, sweep, check, compare), the
facts that command recorded (command.json), the table's rows (results.csv, or compare's runs/), the
swept columns and check's verdicts (check.json)."""
import csv
import json
import os

from signalsim_plot.cli import InputError

COMMAND_FILE = "command.json"  # written by the batch commands (src/app/html_report.cpp)
CHECK_FILE = "check.json"      # check's verdict per scenario (src/app/html_report.cpp)
RESULTS_COLUMNS = ("run", "scenario", "status", "run_dir")  # what the report needs of results.csv


def read_json(path):
    """A JSON file as a dict; None when missing; InputError naming it when unreadable."""
    if not os.path.exists(path):
        return None
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise InputError(f"{path}: {e}") from e


def read_table(path):
    """(header, rows as dicts) of a CSV file."""
    try:
        with open(path, newline="", encoding="utf-8", errors="replace") as f:  # a Latin-1 file name: U+FFFD
            reader = csv.DictReader(f)
            rows = list(reader)
            return list(reader.fieldnames or []), rows
    except (OSError, csv.Error, UnicodeDecodeError) as e:
        raise InputError(f"{path}: {e}") from e


def swept_columns(header):
    """The columns between 'file' and 'status' of results.csv: what a sweep varied."""
    if "file" not in header or "status" not in header:
        return []
    return header[header.index("file") + 1:header.index("status")]


class Folder:
    """kind: 'batch', 'sweep', 'check' or 'compare'; facts: command.json (or {}); header, rows: the
    table (compare: one row per run folder); swept: the swept columns; checks: scenario file -> check's
    case (check.json); comparison: (header, rows) of comparison.csv for compare."""

    def __init__(self, out_dir):
        if not os.path.isdir(out_dir):
            raise InputError(f"{out_dir}: not a folder")
        self.out_dir = out_dir
        self.facts = read_json(os.path.join(out_dir, COMMAND_FILE)) or {}
        self.checks = {}
        self.comparison = None
        results = os.path.join(out_dir, "results.csv")
        comparison = os.path.join(out_dir, "comparison.csv")
        if os.path.isfile(results):
            self.header, self.rows = read_table(results)
            missing = [c for c in RESULTS_COLUMNS if c not in self.header]
            if missing:
                raise InputError(f"{results}: not a results.csv of signalsim (no column {', '.join(missing)})")
            self.swept = swept_columns(self.header)
            cases = read_json(os.path.join(out_dir, CHECK_FILE))
            self.kind = self.facts.get("command") or ("check" if cases is not None else "sweep" if self.swept else "batch")
            for case in (cases or {}).get("cases", []) if self.kind == "check" else []:  # not an earlier check's
                self.checks[case.get("file", "")] = case
        elif os.path.isfile(comparison):
            self.kind = "compare"
            self.comparison = read_table(comparison)
            self.swept = []
            self.header, self.rows = ["run", "driver", "run_dir"], self.compare_rows()
        else:
            raise InputError(f"{out_dir}: neither a batch, sweep or check folder (results.csv) "
                             "nor a compare folder (comparison.csv)")

    def compare_rows(self):
        """One row per run of comparison.csv (its run_dir: runs/NNNN-<name>-<driver>), in the table's order;
        a folder of runs/ that comparison.csv does not name is an earlier compare's."""
        rows, seen = [], set()
        for r in self.comparison[1]:
            run_dir = r.get("run_dir", "")
            if run_dir and run_dir not in seen:
                seen.add(run_dir)
                rows.append({"run": str(len(rows)), "driver": r.get("driver", ""), "run_dir": run_dir})
        return rows

    def run_dir(self, row):
        return row.get("run_dir", "")
