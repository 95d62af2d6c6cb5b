#!/usr/bin/env python3
"""A turn-signal decider for signalsim's JSON-lines protocol (docs/decider.md "JSON lines"), Python
standard library only: the intersection rule of docs/behaviour.md §T4 (turn lanelet groups, the
search distance, the remembered desired start, FIRST_ACTIVE, the required end of §T7) and the
behaviour modules' hazard. Roundabouts (§T5) and the behaviour modules' turn requests (§T8) are left
out: on scenarios whose only signal sections are intersection turns it agrees with signalsim's
reference at every step.

Run: signalsim run scenarios/intersection_left.yaml --decider "exec:python3 examples/python_decider/decider.py"
"""
import bisect
import json
import math
import sys

STOP_SPEED = 0.1  # [m/s] §T4.1


def azimuth(a, b):
    return math.atan2(b[1] - a[1], b[0] - a[0])


def normalize(angle):
    a = math.fmod(angle + math.pi, 2.0 * math.pi)
    if a < 0.0:
        a += 2.0 * math.pi
    return a - math.pi


def cumulative(points):
    s = [0.0]
    for a, b in zip(points, points[1:]):
        s.append(s[-1] + math.hypot(b[0] - a[0], b[1] - a[1]))
    return s


def akima(keys, values, queries):
    """Akima interpolation as Autoware's interpolation::spline (the knots next to either end averaged)."""
    n = len(keys)
    m = [(values[i + 1] - values[i]) / (keys[i + 1] - keys[i]) for i in range(n - 1)]
    t = []
    for i in range(n):
        if i == 0:
            t.append(m[0])
        elif i == n - 1:
            t.append(m[-1])
        elif i == 1 or i == n - 2:
            t.append((m[i - 1] + m[i]) / 2.0)
        else:
            wl, wr = abs(m[i + 1] - m[i]), abs(m[i - 1] - m[i - 2])
            t.append((m[i - 1] + m[i]) / 2.0 if abs(wl + wr) < 1e-5 else (wl * m[i - 1] + wr * m[i]) / (wl + wr))
    out = []
    for q in queries:
        j = min(bisect.bisect_left(keys, q, 1, n - 1) - 1, n - 2)
        h = keys[j + 1] - keys[j]
        d = (t[j] + t[j + 1] - 2.0 * m[j]) / (h * h)
        c = (3.0 * m[j] - 2.0 * t[j] - t[j + 1]) / h
        x = q - keys[j]
        out.append(values[j] + (t[j] + (c + d * x) * x) * x)
    return out


def forward_yaws(points):
    yaws = [azimuth(points[i], points[i + 1]) for i in range(len(points) - 1)]
    return yaws + [yaws[-1]] if yaws else [0.0]


def required_end_arc_length(raw, threshold_deg):
    """§T7: scan the 1 m-resampled centre line backward for the last heading off the final one."""
    if len(raw) < 2:
        return 0.0
    length = cumulative(raw)[-1]
    stations = []
    s = 0.0
    while s < length:
        stations.append(s)
        s += 1.0
    if not stations:
        return 0.0
    if length - stations[-1] < 0.1:
        stations[-1] = length
    else:
        stations.append(length)
    distinct = []
    for p in raw:
        if distinct and abs(p[0] - distinct[-1][0]) < 1e-8 and abs(p[1] - distinct[-1][1]) < 1e-8:
            continue
        distinct.append(p)
    ok = len(distinct) >= 2 and len(stations) >= 2 and cumulative(distinct)[-1] >= stations[-1] and all(
        math.hypot(b[0] - a[0], b[1] - a[1]) >= 1e-6 for a, b in zip(distinct, distinct[1:]))
    if ok:
        keys = cumulative(distinct)
        xs = akima(keys, [p[0] for p in distinct], stations)
        ys = akima(keys, [p[1] for p in distinct], stations)
        poses = list(zip(stations, forward_yaws(list(zip(xs, ys)))))
    else:
        poses = list(zip(cumulative(raw), forward_yaws(raw)))
    end_yaw = poses[-1][1]
    threshold = math.radians(threshold_deg)
    for s, yaw in reversed(poses):
        if abs(normalize(yaw - end_yaw)) >= threshold:
            return s
    return poses[-1][0]


class Decider:
    def __init__(self, hello):
        p = hello["parameters"]
        self.search_time = float(p["turn_signal_search_time"])
        self.search_distance = float(p["turn_signal_intersection_search_distance"])
        self.angle_threshold = float(p["turn_signal_intersection_angle_threshold_deg"])
        self.lanelets = hello["lanelets"]
        self.desired_starts = {}  # front route index of a group -> the remembered desired start [m]
        self.required_ends = {}   # front route index of a group -> its required end [m]

    def group_end(self, i):
        last = i
        while last + 1 < len(self.lanelets) and \
                self.lanelets[last + 1]["turn_direction"] == self.lanelets[i]["turn_direction"]:
            last += 1
        return last

    def required_end(self, front, back):
        if front not in self.required_ends:
            merged = []
            for i in range(front, back + 1):
                for pt in self.lanelets[i]["centerline"]:
                    if not any(math.hypot(pt[0] - q[0], pt[1] - q[1]) < 0.01 for q in merged):
                        merged.append(pt)
            s_front, s_back = self.lanelets[front]["s_start"], self.lanelets[back]["s_end"]
            length = cumulative(merged)[-1] if len(merged) >= 2 else 0.0
            scale = (s_back - s_front) / length if length > 0.0 else 1.0
            end = s_front + required_end_arc_length(merged, self.angle_threshold) * scale
            self.required_ends[front] = (len(merged) >= 2, end)
        return self.required_ends[front]

    def intersection_request(self, ego, first, last):
        """§T4.2-§T4.3 with no behaviour turn request: the groups of left and right turn lanelets."""
        base_search = self.search_time * ego["speed"] + self.search_distance
        queue = []
        i = first
        while i < last:
            lanelet = self.lanelets[i]
            if lanelet["roundabout_role"] != "none" or lanelet["turn_direction"] not in ("left", "right"):
                i += 1
                continue
            back = self.group_end(i)
            has_centerline, required_end = self.required_end(i, back)
            front = i
            i = back + 1
            if not has_centerline:
                continue
            tsd = lanelet["turn_signal_distance"]
            search = base_search if tsd is None else tsd
            d_front = lanelet["s_start"] - ego["s_front"]
            desired_end = self.lanelets[back]["s_end"]
            if desired_end - ego["s_base"] < 0.0:
                self.desired_starts.pop(front, None)
                continue
            if search <= d_front:
                continue
            start = self.desired_starts.setdefault(front, ego["s_base"])
            queue.append((lanelet["turn_direction"], start, required_end, desired_end))
        for k, request in enumerate(queue):  # FIRST_ACTIVE
            if k + 1 == len(queue) or request[2] - ego["s_base"] >= 0.0:
                return request
        return None

    def step(self, message):
        if message["request"]["hazard"] == "enable":
            return "hazard"
        ego, window = message["ego"], message["window"]
        request = self.intersection_request(ego, window["first"], window["last"])
        if request is None:
            return "none"
        turn, desired_start, _, desired_end = request
        if desired_start - ego["s_front"] <= 0.0 and desired_end - ego["s_base"] >= 0.0:  # RESOLVE's valid
            return turn
        return "none"


def main():
    decider = None
    for line in sys.stdin:
        message = json.loads(line)
        kind = message["type"]
        if kind == "hello":
            decider = Decider(message)
        elif kind == "step":
            sys.stdout.write(json.dumps({"blinker": decider.step(message)}) + "\n")
            sys.stdout.flush()
        elif kind == "bye":
            break


if __name__ == "__main__":
    main()
