"""The run pictures the report shows (signalsim_plot.run_plots into RUN_DIR/plots): those of failed
and errored runs always, of the others only with --all; drawn by several processes at a time."""
import multiprocessing
import os

PICTURES = ("blinker.png", "speed.png", "lateral.png", "dilemma.png")
NOT_FINISHED = "no timeline.csv (the run did not finish)"  # said on the page, not warned about


def wants_pictures(status, all_runs):
    return all_runs or status in ("failed", "error")


def draw_one(run_dir):
    """(run_dir, None) once drawn, (run_dir, message) when it could not be."""
    from signalsim_plot.cli import InputError
    from signalsim_plot import run_plots
    if not os.path.isfile(os.path.join(run_dir, "timeline.csv")):
        return run_dir, NOT_FINISHED
    try:
        run_plots.plot_run(run_dir, os.path.join(run_dir, "plots"))
        return run_dir, None
    except InputError as e:
        return run_dir, str(e)
    except Exception as e:  # a picture that fails must not cost the other runs' pages
        return run_dir, f"{type(e).__name__}: {e}"


def draw(run_dirs, jobs):
    """Draws the pictures of run_dirs; returns run_dir -> why it could not be drawn (the failures)."""
    if not run_dirs:
        return {}
    jobs = max(1, min(jobs or os.cpu_count() or 1, len(run_dirs)))
    if jobs == 1:
        results = [draw_one(d) for d in run_dirs]
    else:
        with multiprocessing.get_context("fork").Pool(jobs) as pool:
            results = pool.map(draw_one, run_dirs, chunksize=1)
    return {d: message for d, message in results if message}


def existing(run_dir):
    """The pictures in RUN_DIR/plots, in the page's order, that are not older than the run's summary.json:
    a picture of an earlier run in the same folder (a batch rewrites the run files, not plots/) is not
    this run's."""
    plots = os.path.join(run_dir, "plots")
    try:
        run_time = os.path.getmtime(os.path.join(run_dir, "summary.json"))
    except OSError:
        return []
    return [p for p in PICTURES if os.path.isfile(os.path.join(plots, p))
            and os.path.getmtime(os.path.join(plots, p)) >= run_time]
