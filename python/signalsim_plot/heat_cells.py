"""What a heat-map cell of a sweep says, one home for both heat maps (the PNG of sweep_plots.py and the
HTML table of report/heatmap.py; standard library only): a results.csv cell as a number, the axis
order, which metrics are signed (a diverging scale centred on 0) and the gap that keeps a small value
apart from 0's white, the value's text (never rounded to 0), and the line about the blinker at the
section start (arrows, and whether it was to another side than the section asks)."""
from signalsim_plot.data import number

ZERO_GAP = 0.25  # the diverging scale: a value v != 0 is drawn at least this share of the half range from 0
ARROWS = {"left": "←", "right": "→", "hazard": "↔", "none": "·"}
# Signed metrics: a diverging map centred on 0, and what a negative value means.
SIGNED = {"lead_distance": "< 0: late, the blinker came on after the section start",
          "lead_time": "< 0: late, the blinker came on after the section start",
          "stop_position_error": "< 0: at rest short of the stop point"}


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


def gapped_share(value, half):
    """Where a value lies on a diverging scale over [-half, half], as -1..1: 0 at 0, any other value at
    least ZERO_GAP / (1 + ZERO_GAP) from it (the same mapping as sweep_plots.gapped_norm)."""
    if value == 0 or half <= 0:
        return 0.0
    gap = ZERO_GAP * half
    shifted = value + (gap if value > 0 else -gap)
    return max(-1.0, min(1.0, shifted / (half + gap)))


def format_value(value):
    """A cell's value as text: never rounded to 0 (-0.004), 2 decimals, whole numbers from 1000."""
    if value == 0:
        return "0"
    if abs(value) < 0.005:
        return f"{value:.2g}"
    return f"{value:.2f}" if abs(value) < 1000 else f"{value:.0f}"


def section_of_metric(metric, header):
    """The section a metric column belongs to (turn1 of turn1.lead_distance) when results.csv has its
    blinker_at_start column, else None."""
    item = metric.rsplit(".", 1)[0] if "." in metric else None
    return item if item and f"{item}.blinker_at_start" in header else None


def direction_text(directions, asked):
    """The cell's line about the blinker at the section start: arrows with counts when the runs differ;
    (text, wrong) where wrong says a run showed a blinker other than `asked` (and not none)."""
    if not directions:
        return "", False
    if len(directions) == 1:
        parts = [f"{ARROWS.get(b, b)} {b}" for b in directions]
    else:
        parts = [f"{ARROWS.get(b, b)}×{n}" for b, n in directions.items()]
    wrong = any(b not in (asked, "none", "") for b in directions) and asked not in ("", None)
    return "start: " + ", ".join(parts) + (f" ≠ asks {ARROWS.get(asked, asked)}" if wrong else ""), wrong
