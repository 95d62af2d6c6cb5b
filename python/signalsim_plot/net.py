"""What the pictures need of a SUMO net (.net.xml): each lane's speed limit, width, length and shape.

timeline.csv names the lane of the front bumper at every step but not its speed limit nor where it
starts on the route; both come from the net the run's summary.json names (`net`)."""
import math
import os
import xml.etree.ElementTree as ET

SOURCE_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # python/signalsim_plot/../..: the source tree or share/signalsim
DEFAULT_LANE_WIDTH = 3.2  # SUMO's default when a lane has no width attribute [m]


class Lane:
    __slots__ = ("id", "edge", "index", "speed", "length", "width", "shape", "internal")

    def __init__(self, lane_id, edge, index, speed, length, width, shape, internal):
        self.id, self.edge, self.index, self.speed = lane_id, edge, index, speed
        self.length, self.width, self.shape, self.internal = length, width, shape, internal

    def position_of(self, x, y):
        """Lane position [m] of the point of the lane's shape nearest (x, y), scaled to the lane's length."""
        best, best_d2, walked = 0.0, math.inf, 0.0
        for (x0, y0), (x1, y1) in zip(self.shape, self.shape[1:]):
            dx, dy = x1 - x0, y1 - y0
            seg = math.hypot(dx, dy)
            u = 0.0 if seg == 0 else max(0.0, min(1.0, ((x - x0) * dx + (y - y0) * dy) / (seg * seg)))
            px, py = x0 + u * dx, y0 + u * dy
            d2 = (x - px) ** 2 + (y - py) ** 2
            if d2 < best_d2:
                best, best_d2 = walked + u * seg, d2
            walked += seg
        return best * (self.length / walked) if walked > 0 else 0.0


class Net:
    def __init__(self, path, lanes):
        self.path = path
        self.lanes = lanes  # lane id -> Lane
        self.edges = {}     # edge id -> [Lane] by index (right to left)
        for lane in lanes.values():
            self.edges.setdefault(lane.edge, []).append(lane)
        for group in self.edges.values():
            group.sort(key=lambda l: l.index)

    def lane_centres(self, edge):
        """{lane index: lateral position of its centre from the edge's right border} (left positive)."""
        out, right = {}, 0.0
        for lane in self.edges.get(edge, []):
            out[lane.index] = right + lane.width / 2
            right += lane.width
        return out

    def lane_borders(self, edge):
        """Lateral positions of the edge's lane borders from its right border, right to left."""
        borders, right = [0.0], 0.0
        for lane in self.edges.get(edge, []):
            right += lane.width
            borders.append(right)
        return borders


def load_net(path):
    """The net at `path`, or None when it cannot be read."""
    lanes = {}
    try:
        for _, element in ET.iterparse(path, events=("end",)):
            if element.tag != "edge":
                continue
            edge = element.get("id")
            internal = element.get("function") == "internal"
            for lane in element.findall("lane"):
                shape = [tuple(float(c) for c in p.split(",")[:2]) for p in lane.get("shape", "").split()]
                lanes[lane.get("id")] = Lane(lane.get("id"), edge, int(lane.get("index", 0)),
                                             float(lane.get("speed", "nan")), float(lane.get("length", "0")),
                                             float(lane.get("width", DEFAULT_LANE_WIDTH)), shape, internal)
            element.clear()
    except (OSError, ET.ParseError, ValueError):
        return None
    return Net(path, lanes) if lanes else None


def find_input(path, run_dir):
    """An input file a summary names (`net`, `file`), relative to where the run was started: tried as
    given (absolute, or relative to the current directory), then relative to the run directory and its
    ancestors, then to the tree signalsim-plot is in (the source tree, or the installed share/signalsim) (the bundled scenarios and nets, named from the
    source tree's root). None when not found."""
    if not path:
        return None
    candidates = [path]
    if not os.path.isabs(path):
        folder = os.path.abspath(run_dir)
        for _ in range(6):
            candidates.append(os.path.join(folder, path))
            folder = os.path.dirname(folder)
        candidates.append(os.path.join(SOURCE_ROOT, path))
    for c in candidates:
        if os.path.isfile(c):
            return c
    return None
