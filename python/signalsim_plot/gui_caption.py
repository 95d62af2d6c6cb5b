"""The caption of `signalsim run --gui`'s gui.png (signalsim-plot RUN_DIR --gui-caption TIME ...).

signalsim tells the time of the timeline.csv row whose command the screenshot follows, the junction
and light the view is framed on and the view's extent; the caption says, from that row: the time, the
blinker and the request that won (its source), the light the judge looks at with what it saw and
decided. The caption is drawn in a strip under the picture and kept in the PNG's text chunks
(Description, and signalsim:time, signalsim:junction, signalsim:light, signalsim:view), which the
tests read back. A picture that already has a caption is left as it is."""
import matplotlib.image as mpimg
import matplotlib.pyplot as plt
from PIL import Image

from signalsim_plot.cli import InputError
from signalsim_plot.data import read_csv

STRIP_PX = 64  # the caption strip under the picture [px]


def caption_row(timeline, time):
    """The timeline row written at `time` (3 decimals, as timeline.csv has it)."""
    wanted = f"{time:.3f}"
    for row in timeline:
        if row.get("time") == wanted:
            return row
    raise InputError(f"timeline.csv has no row at t={wanted} s")


def caption_lines(row, junction, light):
    """Two lines: where and when with the blinker; the light and the judge's decision."""
    blinker = row.get("blinker") or "none"
    source = row.get("blinker_source") or "none"
    where = f"framed on junction {junction}" if junction else "the ego tracked"
    first = f"t = {row['time']} s   blinker: {blinker} (source: {source})   {where}"
    tl = row.get("tl_id") or ""
    if tl:
        seen = row.get("tl_observed") or "nothing delivered"
        zone = row.get("zone") or ""
        second = (f"light {tl}: state {row.get('tl_state') or '?'}, judge saw {seen}, decided "
                  f"{row.get('tl_decision') or 'none'}" + (f" ({zone})" if zone else ""))
        if light and light != tl:
            second += f"   framed light: {light}"
    else:
        second = "no light ahead: the judge has nothing to decide"
    return [first, second]


def caption_picture(run_dir, time, junction="", light="", view=""):
    """Adds the caption to RUN_DIR/gui.png in place; returns its path."""
    path = f"{run_dir}/gui.png"
    try:
        with Image.open(path) as im:
            if "signalsim:time" in im.info:
                return path  # captioned already
    except OSError as e:
        raise InputError(f"{path}: {e}") from e
    row = caption_row(read_csv(f"{run_dir}/timeline.csv"), time)
    lines = caption_lines(row, junction, light)
    picture = mpimg.imread(path)
    height, width = picture.shape[0], picture.shape[1]
    dpi = 100
    fig = plt.figure(figsize=(width / dpi, (height + STRIP_PX) / dpi), dpi=dpi)
    ax = fig.add_axes((0, STRIP_PX / (height + STRIP_PX), 1, height / (height + STRIP_PX)))
    ax.imshow(picture, interpolation="none")
    ax.set_axis_off()
    for i, line in enumerate(lines):
        fig.text(0.01, (STRIP_PX - 20 - 24 * i) / (height + STRIP_PX), line, fontsize=12, family="monospace",
                 va="center")
    metadata = {"Description": " | ".join(lines), "signalsim:time": row["time"], "signalsim:junction": junction,
                "signalsim:light": light, "signalsim:view": view}
    fig.savefig(path, dpi=dpi, metadata=metadata)
    plt.close(fig)
    return path
