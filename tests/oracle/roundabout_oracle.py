#!/usr/bin/env python3
"""Independent expectation of roundabout (and intersection) blinkers on a signalsim scenario.

Pure Python 3 standard library. It shares no code with signalsim: it reads the built .net.xml and the
scenario/parameter files itself and restates, from docs/behaviour.md §T and
docs/behaviour.md §S, where each blinker turns on and off:

  route      the planned lane of every route edge followed by the via lane(s) of the connection taken
             (chained internal lanes included); s = 0 at the start of the first route edge, lengths
             from the lanes' `length` attributes (docs/behaviour.md §S3)
  roles      <roundabout edges=...>: ring lanes and internal lanes between ring edges are internal, an
             internal lane from a non-ring edge onto the ring is an entry, one from the ring to a
             non-ring edge is an exit (docs/behaviour.md §S3); turn lanelets l/L left, r/R right, t left (right in
             left-hand nets), T right
  required   docs/behaviour.md §T7: 1 m resampling (last sample merged with the end when < 0.1 m away), Akima
  end        spline in x and y (the reference's default; `--linear` for linear interpolation), yaw from
             consecutive samples, backward scan for |yaw - yaw_end| >= threshold; the arc length found
             is scaled by lane length / shape length (SUMO rounds lengths to 0.01 m)
  decider    docs/behaviour.md §T4 (intersection requests, remembered desired starts), §T5 (roundabout entry and
             exit requests, entries before exits, FIRST_ACTIVE), §T6 (RESOLVE, PRIOR_WINS); start points
             against the front bumper, end points against base_link = front - base_link_to_front
  previous   turn_signal_roundabout_exit_signal_from_previous_exit (signalsim, Japan): the ring lanelets
  exit       after the last ring node, before the ego's exit, where another exit branches off (after the
             entry when there is none) are marked enable_exit_turn_signal, so the exit request's desired
             start is the start of the first marked lanelet (docs/behaviour.md §T5.3). "After the node" = the node's
             own internal lane is not marked: the chain starts at the ring lane leaving that node
             (the law: on having passed beside the previous exit). `--mark-node-lane` marks it too.
  motion     an estimate of the ego's speed: each step the commanded speed is the highest from which every
             lanelet ahead can still be entered (front) at its speed limit with `decel`, within +accel/-decel
             per step, capped by max_speed; SUMO's Euler update s += v_next * dt. signalsim's own plan is
             jerk-limited (docs/behaviour.md §P) and brakes a little earlier and more gently, so a
             speed-dependent switch predicted this way can be off by a few metres. Or, with --timeline,
             the (s_front, speed) rows of a real run, so the prediction is exact to the step.

Usage:
  tests/oracle/roundabout_oracle.py scenarios/roundabout_de_exit2.yaml [...]   # table per scenario
      [--timeline out/<name>/timeline.csv] [--linear] [--mark-node-lane] [--check] [--steps]
  --check   also evaluate the scenario's expectations on the predicted timeline and print the margin of
            every expectation boundary to the nearest predicted switch (exit 1 if one fails)
Only the subset of YAML the bundled scenario and parameter files use is read (block maps, flow lists
and flow maps of scalars).
"""

from __future__ import annotations

import argparse
import bisect
import csv
import gzip
import math
import os
import re
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import Optional

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
LEFT, RIGHT, NONE = "left", "right", "none"

# ----------------------------------------------------------------------------------------------
# Minimal YAML (the subset of the bundled files)
# ----------------------------------------------------------------------------------------------


def _scalar(text: str):
    t = text.strip()
    if len(t) >= 2 and t[0] == t[-1] and t[0] in "\"'":
        return t[1:-1]
    if t in ("true", "True"):
        return True
    if t in ("false", "False"):
        return False
    if t in ("null", "~", ""):
        return None
    try:
        return int(t)
    except ValueError:
        pass
    try:
        return float(t)
    except ValueError:
        return t


def _split_flow(body: str) -> list[str]:
    parts, depth, cur, quote = [], 0, "", None
    for ch in body:
        if quote:
            cur += ch
            if ch == quote:
                quote = None
            continue
        if ch in "\"'":
            quote = ch
        elif ch in "[{":
            depth += 1
        elif ch in "]}":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    if cur.strip():
        parts.append(cur)
    return parts


def _value(text: str):
    t = text.strip()
    if t.startswith("[") and t.endswith("]"):
        return [_value(p) for p in _split_flow(t[1:-1])]
    if t.startswith("{") and t.endswith("}"):
        out = {}
        for p in _split_flow(t[1:-1]):
            k, _, v = p.partition(":")
            out[k.strip()] = _value(v)
        return out
    return _scalar(t)


def _strip_comment(line: str) -> str:
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "\"'":
            quote = ch
        elif ch == "#" and (i == 0 or line[i - 1] in " \t"):
            return line[:i].rstrip()
    return line.rstrip()


def load_yaml(path: str):
    """Block maps, block lists of flow maps ("- key: {..}") and flow values."""
    lines = []
    with open(path, encoding="utf-8") as f:
        for raw in f:
            s = _strip_comment(raw.rstrip("\n"))
            if s.strip():
                lines.append((len(s) - len(s.lstrip(" ")), s.strip()))

    def parse(i: int, indent: int):
        if i < len(lines) and lines[i][1].startswith("- "):
            out = []
            while i < len(lines) and lines[i][0] == indent and lines[i][1].startswith("- "):
                item = lines[i][1][2:]
                k, sep, v = item.partition(":")
                if sep and not item.startswith(("[", "{")):
                    out.append({k.strip(): _value(v)})
                else:
                    out.append(_value(item))
                i += 1
            return out, i
        out = {}
        while i < len(lines) and lines[i][0] == indent:
            k, _, v = lines[i][1].partition(":")
            i += 1
            if v.strip():
                out[k.strip()] = _value(v)
            elif i < len(lines) and lines[i][0] > indent:
                out[k.strip()], i = parse(i, lines[i][0])
            else:
                out[k.strip()] = None
        return out, i

    if not lines:
        return {}
    return parse(0, lines[0][0])[0]


def flatten(d: dict, prefix: str = "") -> dict:
    out = {}
    for k, v in (d or {}).items():
        key = f"{prefix}{k}"
        if k == "/**" or k == "ros__parameters":
            out.update(flatten(v, prefix))
        elif isinstance(v, dict):
            out.update(flatten(v, key + "."))
        else:
            out[key] = v
    return out


# ----------------------------------------------------------------------------------------------
# Net and route
# ----------------------------------------------------------------------------------------------


@dataclass
class Conn:
    frm: str
    to: str
    from_lane: int
    to_lane: int
    via: str
    dir: str


@dataclass
class Lane:
    id: str
    edge: str
    index: int
    length: float
    speed: float
    shape: list
    params: dict


class Net:
    def __init__(self, path: str):
        opener = gzip.open if path.endswith(".gz") else open
        with opener(path, "rb") as f:
            root = ET.parse(f).getroot()
        self.lefthand = root.get("lefthand") == "true"
        self.lanes: dict[str, Lane] = {}
        self.edges: dict[str, dict] = {}
        for e in root.iter("edge"):
            eparams = {p.get("key"): p.get("value") for p in e.findall("param")}
            lanes = []
            for l in e.findall("lane"):
                shape = [tuple(float(c) for c in p.split(",")[:2]) for p in l.get("shape").split()]
                params = dict(eparams)
                params.update({p.get("key"): p.get("value") for p in l.findall("param")})
                lane = Lane(l.get("id"), e.get("id"), int(l.get("index")), float(l.get("length")),
                            float(l.get("speed")), shape, params)
                self.lanes[lane.id] = lane
                lanes.append(lane)
            self.edges[e.get("id")] = {"function": e.get("function", "normal"), "from": e.get("from"),
                                       "to": e.get("to"), "lanes": lanes}
        self.conns: list[Conn] = []
        for c in root.iter("connection"):
            self.conns.append(Conn(c.get("from"), c.get("to"), int(c.get("fromLane")), int(c.get("toLane")),
                                   c.get("via") or "", c.get("dir")))
        self.ring_of_edge: dict[str, int] = {}
        self.ring_nodes: list[list[str]] = []
        for k, r in enumerate(root.iter("roundabout")):
            for e in r.get("edges").split():
                self.ring_of_edge[e] = k
            self.ring_nodes.append(r.get("nodes").split())

    def conns_from_edge(self, edge: str):
        return [c for c in self.conns if c.frm == edge]

    def conn_via(self, via: str) -> Optional[Conn]:
        for c in self.conns:
            if c.via == via:
                return c
        return None


def turn_of(dir_: str, lefthand: bool) -> str:
    if dir_ in ("l", "L"):
        return LEFT
    if dir_ in ("r", "R"):
        return RIGHT
    if dir_ == "t":
        return RIGHT if lefthand else LEFT
    if dir_ == "T":
        return RIGHT
    if dir_ == "s":
        return "straight"
    return NONE


@dataclass
class Lanelet:
    id: str
    edge: str
    s0: float
    length: float
    speed: float
    shape: list
    internal: bool
    junction: str = ""
    turn: str = NONE
    role: str = NONE  # none / entry / exit / internal
    ring: Optional[int] = None
    params: dict = field(default_factory=dict)
    req_end: Optional[float] = None  # s of the required end (entry/exit lanelets)

    @property
    def s1(self) -> float:
        return self.s0 + self.length


def junction_of(internal_lane_id: str) -> str:
    parts = internal_lane_id.lstrip(":").split("_")
    return "_".join(parts[:-2])


def build_route(net: Net, edges: list[str]) -> list[Lanelet]:
    # Planned lanes backward: the last edge's lane 0 (all nets here: one lane per direction); each earlier
    # edge: the lowest from-lane with a connection to the next edge's planned lane, else to any lane.
    planned = [0] * len(edges)
    links: list[Conn] = [None] * (len(edges) - 1)
    for i in range(len(edges) - 2, -1, -1):
        cands = [c for c in net.conns_from_edge(edges[i]) if c.to == edges[i + 1]]
        if not cands:
            raise SystemExit(f"route edges {edges[i]} -> {edges[i+1]} are not connected")
        exact = [c for c in cands if c.to_lane == planned[i + 1]]
        c = min(exact or cands, key=lambda c: c.from_lane)
        links[i], planned[i] = c, c.from_lane
        if not exact:
            planned[i + 1] = c.to_lane
    out: list[Lanelet] = []
    s = 0.0
    for i, e in enumerate(edges):
        lane = net.edges[e]["lanes"][planned[i]]
        ring = net.ring_of_edge.get(e)
        out.append(Lanelet(lane.id, e, s, lane.length, lane.speed, lane.shape, False,
                           role="internal" if ring is not None else NONE, ring=ring, params=dict(lane.params)))
        s += lane.length
        if i + 1 == len(edges):
            break
        c = links[i]
        approach = net.edges[e]["lanes"][c.from_lane]
        rf, rt = net.ring_of_edge.get(e), net.ring_of_edge.get(edges[i + 1])
        if rf is not None and rf == rt:
            role, rid = "internal", rf
        elif rt is not None:
            role, rid = "entry", rt
        elif rf is not None:
            role, rid = "exit", rf
        else:
            role, rid = NONE, None
        via = c.via
        while via:
            vl = net.lanes[via]
            vc = net.conn_via(via)
            out.append(Lanelet(vl.id, vl.edge, s, vl.length, vl.speed, vl.shape, True, junction_of(via),
                               turn_of(vc.dir if vc else c.dir, net.lefthand), role, rid, dict(approach.params)))
            s += vl.length
            nxt = [k for k in net.conns_from_edge(vl.edge) if k.to == edges[i + 1]]
            via = nxt[0].via if nxt else ""
    return out


def lanelet_at(route: list[Lanelet], s: float) -> int:
    starts = [l.s0 for l in route]
    return max(0, bisect.bisect_right(starts, s) - 1)


# ----------------------------------------------------------------------------------------------
# Required end (docs/behaviour.md §T7)
# ----------------------------------------------------------------------------------------------


def akima(keys: list[float], vals: list[float], queries: list[float]) -> list[float]:
    n = len(keys)
    if n < 3:
        return lerp(keys, vals, queries)
    m = [(vals[i + 1] - vals[i]) / (keys[i + 1] - keys[i]) for i in range(n - 1)]
    sl = []
    for i in range(n):
        if i == 0:
            sl.append(m[0])
        elif i == n - 1:
            sl.append(m[-1])
        elif i == 1 or i == n - 2:
            sl.append((m[i - 1] + m[i]) / 2.0)
        else:
            den = abs(m[i + 1] - m[i]) + abs(m[i - 1] - m[i - 2])
            if abs(den) < 1e-5:
                sl.append((m[i - 1] + m[i]) / 2.0)
            else:
                sl.append((abs(m[i + 1] - m[i]) * m[i - 1] + abs(m[i - 1] - m[i - 2]) * m[i]) / den)
    out = []
    for q in queries:
        k = min(max(bisect.bisect_right(keys, q) - 1, 0), n - 2)
        dx = keys[k + 1] - keys[k]
        d = q - keys[k]
        c2 = (3.0 * m[k] - 2.0 * sl[k] - sl[k + 1]) / dx
        c3 = (sl[k] + sl[k + 1] - 2.0 * m[k]) / (dx * dx)
        out.append(vals[k] + sl[k] * d + c2 * d * d + c3 * d * d * d)
    return out


def lerp(keys, vals, queries):
    out = []
    for q in queries:
        k = min(max(bisect.bisect_right(keys, q) - 1, 0), len(keys) - 2)
        t = (q - keys[k]) / (keys[k + 1] - keys[k])
        out.append(vals[k] + t * (vals[k + 1] - vals[k]))
    return out


def norm_angle(a: float) -> float:
    while a > math.pi:
        a -= 2 * math.pi
    while a < -math.pi:
        a += 2 * math.pi
    return a


def required_end_arc(shape: list, thr_deg: float, linear: bool = False) -> float:
    pts = [shape[0]]
    for p in shape[1:]:
        if math.dist(p, pts[-1]) >= 1e-8:
            pts.append(p)
    if len(pts) < 2:
        return 0.0
    keys = [0.0]
    for a, b in zip(pts, pts[1:]):
        keys.append(keys[-1] + math.dist(a, b))
    L = keys[-1]
    samples = [float(k) for k in range(int(math.floor(L)) + 1) if k < L]
    if L - samples[-1] < 0.1:
        samples[-1] = L
    else:
        samples.append(L)
    f = lerp if linear else akima
    xs = f(keys, [p[0] for p in pts], samples)
    ys = f(keys, [p[1] for p in pts], samples)
    yaws = [math.atan2(ys[i + 1] - ys[i], xs[i + 1] - xs[i]) for i in range(len(samples) - 1)]
    yaws.append(yaws[-1])
    end = yaws[-1]
    thr = math.radians(thr_deg)
    for i in range(len(samples) - 1, -1, -1):
        if abs(norm_angle(yaws[i] - end)) >= thr:
            return samples[i]
    return samples[-1]


def shape_length(shape):
    return sum(math.dist(a, b) for a, b in zip(shape, shape[1:]))


def merged_shape(lls: list[Lanelet]) -> list:
    out = []
    for l in lls:
        for p in l.shape:
            if all(math.dist(p, q) > 0.01 for q in out):
                out.append(p)
    return out


def required_end_s(lls: list[Lanelet], thr_deg: float, linear: bool) -> float:
    shape = merged_shape(lls)
    total = sum(l.length for l in lls)
    sl = shape_length(shape)
    scale = total / sl if sl > 0 else 1.0
    return lls[0].s0 + required_end_arc(shape, thr_deg, linear) * scale


# ----------------------------------------------------------------------------------------------
# Parameters and scenario
# ----------------------------------------------------------------------------------------------


def load_params(scn_path: str, scn: dict, extra_set: dict) -> dict:
    base = os.path.dirname(os.path.abspath(scn_path))
    p = {}
    params = scn.get("params") or {}
    for f in params.get("files") or []:
        p.update(flatten(load_yaml(os.path.join(base, f))))
    if scn.get("country"):
        c = load_yaml(os.path.join(REPO, "config", "countries", f"{scn['country']}.yaml"))
        p.update(flatten(c.get("parameters") or {}))
    p.update(flatten(params.get("set") or {}))
    p.update(extra_set)
    return p


def cmd_of(text) -> str:
    return {"Left": LEFT, "Right": RIGHT}.get(text, NONE)


# ----------------------------------------------------------------------------------------------
# Decider (docs/behaviour.md §T4, §T5, §T6) on route s
# ----------------------------------------------------------------------------------------------


@dataclass
class Req:
    kind: str  # intersection / roundabout
    cmd: str
    ds: float  # desired start, s (a base_link position for remembered ego poses, else a lane position)
    ds_is_pose: bool
    rs: float
    re: float
    de: float
    key: str


class Decider:
    def __init__(self, route: list[Lanelet], net: Net, p: dict, b2f: float, linear: bool, mark_node_lane: bool):
        self.r, self.net, self.p, self.b2f = route, net, p, b2f
        self.imap: dict[int, float] = {}
        self.rmap: dict[int, float] = {}
        thr_i = float(p.get("turn_signal_intersection_angle_threshold_deg", 15.0))
        thr_r = float(p.get("turn_signal_roundabout_angle_threshold_deg", 15.0))
        # Intersection groups (docs/behaviour.md §T4.2): consecutive non-roundabout left/right lanelets.
        self.groups = []
        i = 0
        while i < len(route):
            l = route[i]
            if l.role == NONE and l.turn in (LEFT, RIGHT):
                j = i
                while j + 1 < len(route) and route[j + 1].turn == l.turn and route[j + 1].role == NONE:
                    j += 1
                lls = route[i:j + 1]
                self.groups.append({"first": i, "last": j, "s0": lls[0].s0, "s1": lls[-1].s1, "cmd": l.turn,
                                    "re": required_end_s(lls, thr_i, linear),
                                    "tsd": _float_or_none(lls[0].params.get("turn_signal_distance"))})
                i = j + 1
            else:
                i += 1
        for l in route:
            if l.role in ("entry", "exit"):
                l.req_end = required_end_s([l], thr_r, linear)
        # Exit chains (docs/behaviour.md §T5.3): enable_exit_turn_signal params, plus the previous-exit marking.
        self.marked = [str(l.params.get("enable_exit_turn_signal", "")).lower() == "true" for l in route]
        self.prev_exit_mark_start: dict[int, int] = {}
        if p.get("turn_signal_roundabout_exit_signal_from_previous_exit") is True:
            for x, l in enumerate(route):
                if l.role != "exit":
                    continue
                k = x - 1
                start = None
                while k >= 0 and route[k].role == "internal" and route[k].ring == l.ring:
                    if route[k].internal and self.exit_branches_at(route[k]):
                        start = k if mark_node_lane else k + 1
                        break
                    k -= 1
                if start is None:
                    start = k + 1  # after the entry (k = the entry lanelet or the last non-ring one)
                for m in range(start, x):
                    self.marked[m] = True
                self.prev_exit_mark_start[x] = start

    def exit_branches_at(self, ring_internal: Lanelet) -> bool:
        """Another exit leaves the ring at this ring node: a connection from the ring lane that ends here
        to a non-ring edge."""
        c = self.net.conn_via(ring_internal.id)
        if c is None:
            return False
        return any(k.to not in self.net.ring_of_edge for k in self.net.conns_from_edge(c.frm)
                   if not k.to.startswith(":"))

    # -- docs/behaviour.md §T4.3 --------------------------------------------------------------------------------
    def intersection(self, s_front: float, v: float, window) -> Optional[Req]:
        s_base = s_front - self.b2f
        search0 = float(self.p["turn_signal_search_time"]) * v + float(self.p["turn_signal_intersection_search_distance"])
        queue = []
        for g in self.groups:
            if not (window[0] <= g["first"] < window[1]):
                continue
            search = g["tsd"] if g["tsd"] is not None else search0
            d_front = g["s0"] - s_front
            d_back = g["s1"] - s_base
            if d_back < 0:
                self.imap.pop(g["first"], None)
                continue
            if search <= d_front:
                continue
            self.imap.setdefault(g["first"], s_base)
            queue.append(Req("intersection", g["cmd"], self.imap[g["first"]], True, g["s0"], g["re"], g["s1"],
                             self.r[g["first"]].id))
        return self.first_active(queue, s_base)

    # -- docs/behaviour.md §T5.2, §T5.3 ----------------------------------------------------------------------------
    def roundabout(self, s_front: float, v: float, window) -> Optional[Req]:
        s_base = s_front - self.b2f
        p = self.p
        search0 = float(p["turn_signal_search_time"]) * v + float(p["turn_signal_roundabout_search_distance"])
        on_entry, on_exit = cmd_of(p["turn_signal_roundabout_on_entry"]), cmd_of(p["turn_signal_roundabout_on_exit"])
        persist = p["turn_signal_roundabout_entry_indicator_persistence"] is True
        idx = range(window[0], window[1])
        queue = []
        for e in (i for i in idx if self.r[i].role == "entry"):
            E = self.r[e]
            d_front = E.s0 - s_front
            tsd = _float_or_none(E.params.get("turn_signal_distance"))
            search = tsd if tsd is not None else search0
            if search <= d_front and e not in self.rmap:
                continue
            self.rmap.setdefault(e, s_base)
            x = None
            n = e
            while n + 1 < len(self.r):
                n += 1
                if self.r[n].ring != E.ring or self.r[n].role == NONE:
                    break
                x = n
            cmd = on_entry
            X = self.r[x] if x is not None else None
            tagged = None
            if X is not None:
                ids = _exit_names(self.r, x)
                if ids & set(_tag_list(E.params.get("exit_turn_signal_left"))):
                    tagged = LEFT
                elif ids & set(_tag_list(E.params.get("exit_turn_signal_right"))):
                    tagged = RIGHT
            if tagged:
                cmd = tagged
            elif on_entry == NONE:
                self.rmap.pop(e, None)
                continue
            de = X.s1 if (persist and X is not None) else E.s1
            if de - s_base < 0:
                self.rmap.pop(e, None)
                continue
            queue.append(Req("roundabout", cmd, self.rmap[e], True, E.s0, E.req_end, de, E.id))
        for x in (i for i in idx if self.r[i].role == "exit"):
            X = self.r[x]
            if X.s1 - s_base < 0:
                self.rmap.pop(x, None)
                continue
            z = x
            while z - 1 >= 0 and self.marked[z - 1]:
                z -= 1
            ds = self.r[z].s0
            if ds - s_base - self.b2f >= 0:
                continue
            self.rmap.setdefault(x, ds)
            queue.append(Req("roundabout", on_exit, self.rmap[x], False, X.s0, X.req_end, X.s1, X.id))
        return self.first_active(queue, s_base)

    @staticmethod
    def first_active(queue: list[Req], s_base: float) -> Optional[Req]:
        while queue:
            if len(queue) == 1:
                return queue[0]
            if queue[0].re - s_base >= 0:
                return queue[0]
            queue.pop(0)
        return None

    # -- docs/behaviour.md §T6 -----------------------------------------------------------------------------------
    def resolve(self, s_front: float, cands: list[Optional[Req]]) -> tuple[str, str]:
        s_base = s_front - self.b2f
        valid = []
        for order, c in enumerate(cands):
            if c is None or c.cmd not in (LEFT, RIGHT):
                continue
            ds = (c.ds - s_base - self.b2f) if c.ds_is_pose else (c.ds - s_front)
            de = c.de - s_base
            if ds <= 0 and de >= 0:
                valid.append((ds, order, c.rs - s_front, c.re - s_base, c))
        if not valid:
            return NONE, "none"
        valid.sort(key=lambda t: (t[0], t[1]))
        w = valid[0]
        for s in valid[1:]:
            w = w if prior_wins(w[2], w[3], s[2], s[3]) else s
        return w[4].cmd, w[4].kind

    def snapshot(self):
        return (dict(self.imap), dict(self.rmap))

    def restore(self, snap):
        self.imap, self.rmap = dict(snap[0]), dict(snap[1])

    def step(self, s_front: float, v: float):
        s_base = s_front - self.b2f
        back = float(self.p.get("turn_signal_path_backward_length", 100.0))
        # docs/behaviour.md §T5.4, simplified: inside a roundabout keep the remembered entry start on the path.
        cur = self.r[lanelet_at(self.r, max(0.0, s_base))]
        if cur.role in ("internal", "exit") and cur.ring is not None:
            for e, s_reg in self.rmap.items():
                if self.r[e].role == "entry":
                    back = max(back, s_base - s_reg + 1.0)
        lo, hi = s_base - back, s_base + float(self.p.get("forward_path_length", 300.0))
        window = (next((i for i, l in enumerate(self.r) if l.s1 > lo), len(self.r)),
                  next((i for i, l in enumerate(self.r) if l.s0 >= hi), len(self.r)))
        i_req = self.intersection(s_front, v, window)
        r_req = self.roundabout(s_front, v, window)
        return self.resolve(s_front, [i_req, r_req]) + (i_req, r_req)


def prior_wins(ps, pe, ss, se) -> bool:
    before_prior = ps > 0
    before_subseq = ss > 0
    inside_prior = ps < 0 and pe >= 0
    if ps < ss:
        if se < pe:
            return True
        if before_prior or inside_prior:
            return True
        if before_subseq:
            return True
        return False
    if pe < se:
        return before_prior or inside_prior
    return not before_prior


def _float_or_none(v):
    try:
        return float(v) if v is not None and v != "" else None
    except ValueError:
        return None


def _tag_list(v) -> list[str]:
    return [t for t in re.split(r"[,\s\[\]]+", v or "") if t]


def _exit_names(route: list[Lanelet], x: int) -> set[str]:
    """The names an exit tag item may give the exit ending at route[x] (docs/behaviour.md §T5.2): the lane ids
    of the exit connection's lanelets and the normal edge the exit leads onto; an exit that is not an exit
    lanelet (the route ends on the ring) only by its own lane id."""
    X = route[x]
    if X.role != "exit":
        return {X.id}
    names = {X.id}
    k = x
    while k > 0 and route[k - 1].role == "exit" and route[k - 1].ring == X.ring:
        k -= 1
        names.add(route[k].id)
    for later in route[x + 1:]:
        if not later.internal:
            names.add(later.edge)
            break
    return names


# ----------------------------------------------------------------------------------------------
# Motion
# ----------------------------------------------------------------------------------------------


def simulate(route: list[Lanelet], ego: dict, dt: float, duration: float):
    vmax = float(ego.get("max_speed", 13.89))
    acc = float(ego.get("accel", 1.0))
    dec = float(ego.get("decel", 1.0))
    s = float(ego.get("depart_pos", 0.0))
    v = float(ego.get("depart_speed", 0.0))
    end = route[-1].s1
    rows = []
    t = 0.0
    while t <= duration + 1e-9:
        rows.append((s, v))
        horizon = vmax * vmax / (2 * dec) + 1.0
        allowed = vmax
        for l in route:
            if l.s1 <= s or l.s0 > s + horizon:
                continue
            ahead = max(0.0, l.s0 - s)
            allowed = min(allowed, math.sqrt(l.speed ** 2 + 2 * dec * ahead))
        lo = max(0.0, v - dec * dt)
        v = min(max(allowed, lo), max(lo, v + acc * dt))
        s += v * dt
        t += dt
        if s >= end:
            break
    return rows


def read_timeline(path: str):
    rows = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            rows.append((float(r["s_front"]), float(r["speed"]), r.get("blinker", "")))
    return rows


# ----------------------------------------------------------------------------------------------
# Report
# ----------------------------------------------------------------------------------------------


def analyse(scn_path: str, args) -> int:
    scn = load_yaml(scn_path)
    base = os.path.dirname(os.path.abspath(scn_path))
    net = Net(os.path.join(base, scn["net"]))
    ego = scn["ego"]
    route = build_route(net, ego["route"])
    p = load_params(scn_path, scn, {})
    b2f = float(ego.get("base_link_to_front", 3.7))
    dec = Decider(route, net, p, b2f, args.linear, args.mark_node_lane)
    dt = float(scn.get("step_length", 0.1))
    if args.timeline:
        rows = read_timeline(args.timeline)
        source = f"timeline {args.timeline}"
    else:
        rows = [(s, v, "") for s, v in simulate(route, ego, dt, float(scn.get("duration", 60)))]
        source = "kinematic model"

    print(f"== {scn.get('name')}  ({os.path.relpath(scn_path, REPO)}; net {os.path.basename(scn['net'])}; "
          f"{'left' if net.lefthand else 'right'}-hand; country {scn.get('country', '-')}; motion: {source}; "
          f"required end: {'linear' if args.linear else 'Akima'})")
    keys = ["turn_signal_roundabout_on_entry", "turn_signal_roundabout_on_exit",
            "turn_signal_roundabout_entry_indicator_persistence",
            "turn_signal_roundabout_exit_signal_from_previous_exit", "turn_signal_search_time",
            "turn_signal_intersection_search_distance", "turn_signal_roundabout_search_distance"]
    print("   params: " + ", ".join(f"{k.replace('turn_signal_', '')}={p.get(k)}" for k in keys))
    print(f"   {'lanelet':<11} {'s_start':>8} {'s_end':>8} {'len':>6} {'v_max':>6}  turn      role      req_end  params")
    for i, l in enumerate(route):
        extra = []
        if dec.marked[i]:
            extra.append("marked(exit chain)")
        for k in ("exit_turn_signal_left", "exit_turn_signal_right", "turn_signal_distance", "enable_exit_turn_signal"):
            if k in l.params and (not l.internal or l.role in ("entry", NONE)):
                extra.append(f"{k}={l.params[k]}")
        re_txt = f"{l.req_end:8.2f}" if l.req_end is not None else ""
        for g in dec.groups:
            if g["first"] == i:
                re_txt = f"{g['re']:8.2f}"
        print(f"   {l.id:<11} {l.s0:8.2f} {l.s1:8.2f} {l.length:6.2f} {l.speed:6.2f}  {l.turn:<9} {l.role:<9} "
              f"{re_txt:>8}  {' '.join(extra)}")

    # Predicted blinker per row; at a change, the switch position s* between the two rows (the state and
    # the speed of the row held, 1 mm steps): exact for a position switch, an estimate for a speed-dependent one.
    preds = []
    events = []
    prev = NONE
    for k, (s, v, *_) in enumerate(rows):
        snap = dec.snapshot()
        b, src, *_ = dec.step(s, v)
        if b != prev:
            star = s
            if preds:
                after = dec.snapshot()
                p0 = preds[-1][0]
                n = max(2, int(math.ceil((s - p0) / 0.001)))
                for i in range(1, n + 1):
                    q = p0 + (s - p0) * i / n
                    dec.restore(snap)
                    if dec.step(q, v)[0] == b:
                        star = q
                        break
                dec.restore(after)
            events.append((k, s, v, prev, b, src, star, geometric_reason(route, dec, star, b2f)))
            prev = b
        preds.append((s, v, b, src))

    # Conditions.
    print("   switch conditions (front = s_front, base = s_front - %.2f):" % b2f)
    for line in conditions(route, dec, p, b2f):
        print("     " + line)
    print("   predicted blinker changes (%s; s* = switch position between the two rows):" % source)
    print(f"     {'prev row':>8} {'row':>8} {'s*':>8} {'speed':>6}  change          source        cause")
    for k, s, v, a, b, src, star, why in events:
        sp = preds[k - 1][0] if k > 0 else float("nan")
        print(f"     {sp:8.2f} {s:8.2f} {star:8.2f} {v:6.2f}  {a:>5} -> {b:<6}  {src:<12}  "
              f"{why or 'speed-dependent (lane start within search distance at this speed)'}")
    if args.steps:
        for s, v, b, src in preds:
            print(f"       {s:8.3f} {v:6.3f} {b:<6} {src}")

    status = 0
    if args.timeline and any(r[2] for r in rows):
        mism = [(s, r[2], b) for (s, v, b, src), r in zip(preds, rows) if r[2] != b]
        print(f"   timeline vs oracle: {len(rows) - len(mism)}/{len(rows)} rows agree")
        for s, got, want in mism[:10]:
            print(f"     s_front {s:8.2f}: signalsim {got}, oracle {want}")
        if mism:
            status = 1
    if args.check:
        status |= check_expectations(scn, route, preds, b2f, [(e[6], e[7]) for e in events])
    print()
    return status


def geometric_reason(route, dec: Decider, star: float, b2f: float) -> str:
    """The fixed route position a switch at s* coincides with (within 3 mm), if any."""
    cands = []
    for l in route:
        cands.append((l.s0, f"front reaches {l.id} start"))
        cands.append((l.s1 + b2f, f"base passes {l.id} end {l.s1:.2f}"))
        if l.req_end is not None:
            cands.append((l.req_end + b2f, f"base passes {l.id} required end {l.req_end:.2f}"))
    for g in dec.groups:
        cands.append((g["re"] + b2f, f"base passes {route[g['first']].id} group required end {g['re']:.2f}"))
    for pos, why in cands:
        if abs(pos - star) < 0.003:
            return why
    return ""


def conditions(route, dec: Decider, p, b2f) -> list[str]:
    out = []
    st, isd, rsd = (float(p["turn_signal_search_time"]), float(p["turn_signal_intersection_search_distance"]),
                    float(p["turn_signal_roundabout_search_distance"]))
    on_entry, on_exit = cmd_of(p["turn_signal_roundabout_on_entry"]), cmd_of(p["turn_signal_roundabout_on_exit"])
    persist = p["turn_signal_roundabout_entry_indicator_persistence"] is True
    for g in dec.groups:
        search = f"{g['tsd']:.2f}" if g["tsd"] is not None else f"{st:g}*v + {isd:g}"
        out.append(f"intersection {route[g['first']].id}..{route[g['last']].id} {g['cmd']}: on at the first step with "
                   f"{g['s0']:.2f} - front < {search}; required [{g['s0']:.2f}, {g['re']:.2f}(base)]; "
                   f"off when base > {g['s1']:.2f} (front > {g['s1'] + b2f:.2f})")
    for e, E in enumerate(route):
        if E.role != "entry":
            continue
        x = e
        while x + 1 < len(route) and route[x + 1].ring == E.ring and route[x + 1].role != NONE:
            x += 1
        X = route[x]
        tag = None
        if set(_tag_list(E.params.get("exit_turn_signal_left"))) & _exit_names(route, x):
            tag = LEFT
        elif set(_tag_list(E.params.get("exit_turn_signal_right"))) & _exit_names(route, x):
            tag = RIGHT
        cmd = tag or on_entry
        if cmd == NONE:
            out.append(f"entry {E.id}: no request (on_entry None, no exit tag for {X.id})")
            continue
        de = X.s1 if persist else E.s1
        out.append(f"entry {E.id} {cmd}{' (exit tag)' if tag else ''}: on at the first step with {E.s0:.2f} - front < "
                   f"{st:g}*v + {rsd:g}; required [{E.s0:.2f}, {E.req_end:.2f}(base)]; desired end {de:.2f} "
                   f"{'(exit ' + X.id + ' end, persistence)' if persist else ''}: off when base > {de:.2f} "
                   f"(front > {de + b2f:.2f}), or earlier when the exit request is queued and base > {E.req_end:.2f}")
    for x, X in enumerate(route):
        if X.role != "exit":
            continue
        z = x
        while z - 1 >= 0 and dec.marked[z - 1]:
            z -= 1
        ds = route[z].s0
        how = f"chain start {route[z].id}" if z != x else "exit lanelet start"
        out.append(f"exit {X.id} {on_exit}: desired start {ds:.2f} ({how}): on when front >= {ds:.2f}; required "
                   f"[{X.s0:.2f}, {X.req_end:.2f}(base)]; off when base > {X.s1:.2f} (front > {X.s1 + b2f:.2f})")
    return out


def check_expectations(scn, route, preds, b2f, stars) -> int:
    def margin(a, b):
        m = float("inf")
        for star, _ in stars:
            m = min(m, abs(a - star), abs(b - star))
        return m

    status = 0
    print("   expectations on the predicted timeline:")
    for exp in scn.get("expect") or []:
        (kind, arg), = exp.items()
        ok, note = True, ""
        if kind == "blinker_on":
            sel = [b for s, v, b, _ in preds if arg["from_s"] <= s <= arg["to_s"]]
            ok = bool(sel) and all(b == arg["blinker"] for b in sel)
            note = f"margin {margin(arg['from_s'], arg['to_s']):.2f} m"
        elif kind == "no_blinker":
            sel = [b for s, v, b, _ in preds if arg["from_s"] <= s <= arg["to_s"]]
            ok = bool(sel) and all(b == NONE for b in sel)
            note = f"margin {margin(arg['from_s'], arg['to_s']):.2f} m"
        elif kind == "blinker_never":
            ok = all(b != arg for s, v, b, _ in preds)
        elif kind in ("blinker_through_junction", "blinker_through_lanelet"):
            if kind == "blinker_through_junction":
                lls = [l for l in route if l.internal and l.junction == arg["junction"]]
            else:
                lls = [l for l in route if l.id == arg["lanelet"]]
            a, b = lls[0].s0 - float(arg["lead"]), lls[-1].s1
            sel = [bb for s, v, bb, _ in preds if a <= s and s - b2f <= b]
            left = any(s - b2f > b for s, *_ in preds)
            ok = left and bool(sel) and all(x == arg["blinker"] for x in sel)
            note = f"front {a:.2f} .. base {b:.2f} (front {b + b2f:.2f}); margin {margin(a, b + b2f):.2f} m"
            if margin(a, b + b2f) < 0.01:
                note += " (0: the span edge is the request's own on/off condition)"
        print(f"     [{'ok' if ok else 'FAIL'}] {kind} {arg} {note}")
        if not ok:
            status = 1
    return status


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scenarios", nargs="+")
    ap.add_argument("--timeline", help="timeline.csv of a signalsim run of the (single) scenario")
    ap.add_argument("--linear", action="store_true", help="linear instead of Akima resampling in §T7")
    ap.add_argument("--mark-node-lane", action="store_true",
                    help="previous-exit marking includes the previous exit's ring-node internal lane")
    ap.add_argument("--check", action="store_true", help="evaluate the scenario's expectations on the prediction")
    ap.add_argument("--steps", action="store_true", help="print every predicted step")
    args = ap.parse_args()
    if args.timeline and len(args.scenarios) != 1:
        ap.error("--timeline needs exactly one scenario")
    status = 0
    for s in args.scenarios:
        status |= analyse(s, args)
    return status


if __name__ == "__main__":
    sys.exit(main())
