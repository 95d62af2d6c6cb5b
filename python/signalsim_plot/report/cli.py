"""signalsim-plot report OUT [--all] [--jobs N] [--quiet]: the HTML report of a batch, sweep, check or
compare folder (called by `signalsim report` and the commands' --report). Exit 2: not an output folder;
3: the report could not be written."""
import argparse
import sys

from signalsim_plot.cli import InputError


def main(argv):
    parser = argparse.ArgumentParser(prog="signalsim-plot report", description=(__doc__ or "").strip())
    parser.add_argument("out", help="the output folder of batch, sweep, check or compare")
    parser.add_argument("--all", action="store_true", help="draw the pictures of every run, not only failed and errored ones")
    parser.add_argument("--jobs", type=int, default=0, help="processes drawing pictures (default: the number of cores)")
    parser.add_argument("--quiet", action="store_true", help="do not print the page written")
    args = parser.parse_args(argv)
    from signalsim_plot.report.build import build
    try:
        index, failures = build(args.out, args.all, args.jobs)
    except InputError as e:
        print(f"signalsim-plot: {e}", file=sys.stderr)
        return 2
    except OSError as e:  # a folder that cannot be written into (read-only, full): one line, exit 3
        print(f"signalsim-plot: report: cannot write the report into {args.out}: {e}", file=sys.stderr)
        return 3
    from signalsim_plot.report.pictures import NOT_FINISHED
    for run_dir, message in sorted(failures.items()):
        if message != NOT_FINISHED:
            print(f"signalsim-plot: warning: {run_dir}: pictures not drawn: {message}", file=sys.stderr)
    if not args.quiet:
        print(index)
    return 0
