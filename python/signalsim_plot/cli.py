"""Command line of signalsim-plot: decides between a run directory and a sweep's results.csv."""
import argparse
import os
import sys

try:
    import matplotlib
except ImportError:  # signalsim-plot runs /usr/bin/python3: Debian's python3-matplotlib
    print("signalsim-plot: matplotlib is missing (Debian 12: apt-get install python3-matplotlib)", file=sys.stderr)
    sys.exit(2)

matplotlib.use("Agg")


class InputError(Exception):
    """Bad input: printed as 'signalsim-plot: <message>', exit code 2."""


def main(argv):
    if argv[:1] == ["report"]:  # the HTML report of a batch, sweep, check or compare folder
        from signalsim_plot.report.cli import main as report_main
        return report_main(argv[1:])
    parser = argparse.ArgumentParser(prog="signalsim-plot", description=(__doc__ or "").strip())
    parser.add_argument("path", help="a run directory (timeline.csv ...) or a sweep directory / results.csv")
    parser.add_argument("--out", help="where the PNGs go (default: PATH/plots)")
    parser.add_argument("--metric", action="append",
                        help="sweep: results.csv column to show (default: the first *.lead_distance); "
                             "repeat it for one picture per metric")
    parser.add_argument("--x", help="sweep: swept column along x")
    parser.add_argument("--y", help="sweep: swept column along y")
    parser.add_argument("--quiet", action="store_true", help="do not print the files written")
    parser.add_argument("--gui-caption", type=float, metavar="TIME",
                        help="run: caption PATH/gui.png (signalsim run --gui) with the timeline row at TIME s; "
                             "nothing else is drawn")
    parser.add_argument("--gui-junction", default="", help="with --gui-caption: the junction the view is framed on")
    parser.add_argument("--gui-light", default="", help="with --gui-caption: the light framed with it")
    parser.add_argument("--gui-view", default="", help="with --gui-caption: the view's extent x0,y0,x1,y1 [m]")
    args = parser.parse_args(argv)
    try:
        path = args.path
        from signalsim_plot import comparison_plots
        if args.gui_caption is not None:
            from signalsim_plot import gui_caption
            written = [gui_caption.caption_picture(path, args.gui_caption, args.gui_junction, args.gui_light,
                                                   args.gui_view)]
        elif os.path.isfile(path) and path.endswith(".csv") and comparison_plots.is_comparison(path):
            written = comparison_plots.plot_comparison(path, args.out or os.path.dirname(path) or ".")
        elif os.path.isfile(path) and path.endswith(".csv"):
            from signalsim_plot import sweep_plots
            out = args.out or os.path.join(os.path.dirname(path) or ".", "plots")
            written = [f for m in args.metric or [None] for f in sweep_plots.plot_results(path, out, m, args.x, args.y)]
        elif os.path.isfile(os.path.join(path, "results.csv")):
            from signalsim_plot import sweep_plots
            out = args.out or os.path.join(path, "plots")
            csv_path = os.path.join(path, "results.csv")
            written = [f for m in args.metric or [None] for f in sweep_plots.plot_results(csv_path, out, m, args.x, args.y)]
        elif os.path.isfile(os.path.join(path, "summary.json")):
            from signalsim_plot import run_plots
            out = args.out or os.path.join(path, "plots")
            written = run_plots.plot_run(path, out)
        else:
            raise InputError(f"{path}: neither a run directory (summary.json) nor a sweep (results.csv)")
    except InputError as e:
        print(f"signalsim-plot: {e}", file=sys.stderr)
        return 2
    for f in written if not args.quiet else []:
        print(f)
    return 0
