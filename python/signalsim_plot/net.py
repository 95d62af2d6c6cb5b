"""What the pictures need of a SUMO net (.net.xml): each lane's speed limit, width, length and shape.

timeline.csv names the lane of the front bumper at every step but not its speed limit nor where it
starts on the route; both come from the net the run's summary.json names (`net`), read with SUMO's own
reader, sumolib (installed with SUMO's tools: $SUMO_HOME/tools, else /usr/share/sumo/tools)."""
import os
import sys

SOURCE_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # python/signalsim_plot/../..: the source tree or share/signalsim
DEFAULT_LANE_WIDTH = 3.2  # SUMO's default lane width [m]: lateral.png's assumption without the net
SUMO_TOOLS = (os.path.join(os.environ["SUMO_HOME"], "tools") if os.environ.get("SUMO_HOME") else None,
              "/usr/share/sumo/tools")


def sumolib_module():
    """SUMO's sumolib, from $SUMO_HOME/tools or /usr/share/sumo/tools; None when neither has it."""
    for tools in SUMO_TOOLS:
        if tools and os.path.isdir(os.path.join(tools, "sumolib")) and tools not in sys.path:
            sys.path.append(tools)
    try:
        import sumolib
    except ImportError:
        return None
    return sumolib


class Lane:
    """A lane as the pictures use it (from sumolib's lane)."""
    __slots__ = ("id", "edge", "index", "speed", "length", "width", "shape", "internal")

    def __init__(self, lane_id, edge, index, speed, length, width, shape, internal):
        self.id, self.edge, self.index, self.speed = lane_id, edge, index, speed
        self.length, self.width, self.shape, self.internal = length, width, shape, internal

    def position_of(self, x, y):
        """Lane position [m] of the point of the lane's shape nearest (x, y), scaled to the lane's length
        (sumolib.geomhelper's offset along the shape)."""
        geomhelper = sumolib_module().geomhelper
        offset = geomhelper.polygonOffsetWithMinimumDistanceToPoint((x, y), self.shape)
        walked = geomhelper.polyLength(self.shape)
        return offset * (self.length / walked) if walked > 0 else 0.0


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
    """The net at `path` read by sumolib (internal lanes included), or None when it cannot be read or
    sumolib is missing."""
    sumolib = sumolib_module()
    if sumolib is None:
        return None
    try:
        net = sumolib.net.readNet(path, withInternal=True)
    except Exception:  # sumolib raises what its SAX parser or its number conversions raise
        return None
    lanes = {}
    for edge in net.getEdges(withInternal=True):
        for lane in edge.getLanes():
            lanes[lane.getID()] = Lane(lane.getID(), edge.getID(), lane.getIndex(), lane.getSpeed(), lane.getLength(),
                                       lane.getWidth(), [tuple(p[:2]) for p in lane.getShape()],
                                       edge.getFunction() == "internal")
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
