"""The HTML report of a batch, sweep, check or compare folder (signalsim report OUT, --report):
OUT/report.html (counts, the command and its inputs, the table of runs, heat maps, compare's table)
and one page per run in OUT/report/runs/. Standard library only (html, json); the run pictures come
from signalsim_plot.run_plots. See docs/report.md."""
