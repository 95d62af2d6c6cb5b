"""Pictures of one run (signalsim-plot RUN_DIR): blinker.png, lateral.png, speed.png, dilemma.png.

Each picture has its module with a *_data() function (what is drawn, read by the tests) and a *_plot()
function (the drawing): signalsim_plot.blinker, signalsim_plot.lateral, signalsim_plot.speed, signalsim_plot.dilemma."""
import os

from signalsim_plot.blinker import blinker_plot
from signalsim_plot.data import RunInputs, read_run
from signalsim_plot.dilemma import dilemma_plot, read_curves
from signalsim_plot.lateral import lateral_plot
from signalsim_plot.speed import speed_plot

PICTURES = ("blinker.png", "lateral.png", "speed.png", "dilemma.png")


def plot_run(run_dir, out):
    """Draws the run's pictures into `out`; returns the files written. A picture with nothing to show
    is not drawn (no blinker.png without sections nor blinker, no lateral.png without a maneuver, no
    dilemma.png without a yellow or red met); one such picture left in `out` by an earlier call is removed."""
    timeline, events, summary, metrics = read_run(run_dir)
    inputs = RunInputs(run_dir, summary)
    os.makedirs(out, exist_ok=True)
    drawn = {
        "blinker.png": blinker_plot(timeline, summary, metrics, os.path.join(out, "blinker.png")),
        "lateral.png": lateral_plot(timeline, events, summary, inputs, os.path.join(out, "lateral.png")),
        "speed.png": speed_plot(timeline, summary, metrics, inputs.net, os.path.join(out, "speed.png")),
        "dilemma.png": dilemma_plot(timeline, summary, metrics, read_curves(run_dir), os.path.join(out, "dilemma.png")),
    }
    for name, path in drawn.items():
        stale = os.path.join(out, name)
        if path is None and os.path.exists(stale):
            os.remove(stale)
    return [path for path in drawn.values() if path]
