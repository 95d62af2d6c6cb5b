#!/usr/bin/python3
"""A Python TraCI controller doing signalsim's per-step work, for tools/bench (docs/performance.md).

  /usr/bin/python3 bench/traci_controller.py SPEC.json

SPEC.json (written by bench/scenarios.py) gives the sumo command line (without --remote-port),
the ego as signalsim adds it (route, vehicle type values, departure) and `end`, the simulated time
signalsim's own run of the scenario ended at. The controller starts sumo on a free 127.0.0.1 port and
connects with traci.connect, the call traci.start makes, but retrying every 20 ms: traci.start waits
a whole second before its first retry, which would add a second of wall time (no CPU) to every run.
It adds the ego the way signalsim does (Route.add, a copy of DEFAULT_VEHTYPE, Vehicle.add "now"),
steps until it departs and then, every step, as a planning script written in Python would:
  queries   the ego's position, speed, lane, lane position and route index, its next traffic
            lights (getNextTLS), its leader (getLeader), and whether it arrived
  decides   a blinker from the turn of the connection ahead (directions read once at the start),
            a speed from the ego's top speed, a red or yellow light ahead and the leader's gap
  commands  the blinker (vehicle.setSignals) and the speed (vehicle.setSpeed)
It steps until `end` (on after the ego arrived, so that it runs as many steps as signalsim and the
sumo binary alone) and prints one JSON line, its last: steps (SUMO steps), ego_steps (steps with the
ego in the net), depart_time, end_time, arrived. Exit 0, or 2 with one line on stderr when SUMO
refuses something; sumo is stopped (traci.close waits for it) in every case.
"""
import contextlib
import io
import json
import math
import os
import socket
import subprocess
import sys

sys.path.append(os.path.join(os.environ.get("SUMO_HOME", "/usr/share/sumo"), "tools"))
import traci  # noqa: E402  (SUMO's own Python client, from sumo-tools)

EGO = "ego"
BLINKER_RIGHT, BLINKER_LEFT = 1, 2  # TraCI's signal bits
STOP_STATES = set("rRuyY")  # red, red-yellow, yellow: stop when possible
TIME_GAP = 1.5  # s kept behind a leader
LEFT_TURNS, RIGHT_TURNS = set("lLt"), set("rR")


def add_ego(t, ego):
    t.route.add("ego_route", ego["route"])
    t.vehicletype.copy("DEFAULT_VEHTYPE", "ego_type")
    t.vehicletype.setLength("ego_type", ego["length"])
    t.vehicletype.setWidth("ego_type", ego["width"])
    t.vehicletype.setMaxSpeed("ego_type", ego["max_speed"])
    t.vehicletype.setAccel("ego_type", ego["accel"])
    t.vehicletype.setDecel("ego_type", ego["decel"])
    t.vehicletype.setEmergencyDecel("ego_type", ego["emergency_decel"])
    t.vehicletype.setImperfection("ego_type", 0.0)
    t.vehicletype.setSpeedFactor("ego_type", 1.0)
    t.vehicletype.setSpeedDeviation("ego_type", 0.0)
    t.vehicle.add(EGO, "ego_route", "ego_type", "now", str(ego["depart_lane"]), str(ego["depart_pos"]),
                  str(ego["depart_speed"]))


def turn_directions(t, route):
    """For each route edge, the direction (SUMO's l, r, s, t, ...) of its connection to the next ("s" last)."""
    directions = []
    for edge, following in zip(route, route[1:]):
        direction = "s"
        for k in range(t.edge.getLaneNumber(edge)):
            for link in t.lane.getLinks("%s_%d" % (edge, k)):
                if link[0].rsplit("_", 1)[0] == following:
                    direction = link[6]
        directions.append(direction)
    return directions + ["s"]


class Controller:
    """The per-step queries, decisions and commands; one instance per run."""

    def __init__(self, t, ego, step_length):
        self.t = t
        self.ego = ego
        self.dt = step_length
        self.directions = turn_directions(t, ego["route"])
        self.lane_lengths = {}
        self.signals = 0

    def lane_length(self, lane):
        if lane not in self.lane_lengths:
            self.lane_lengths[lane] = self.t.lane.getLength(lane)
        return self.lane_lengths[lane]

    def step(self):
        vehicle = self.t.vehicle
        vehicle.getPosition(EGO)
        speed = vehicle.getSpeed(EGO)
        lane = vehicle.getLaneID(EGO)
        lane_pos = vehicle.getLanePosition(EGO)
        route_index = vehicle.getRouteIndex(EGO)
        lights = vehicle.getNextTLS(EGO)
        leader = vehicle.getLeader(EGO, 100.0)

        if not lane.startswith(":"):  # inside a junction the blinker stays as it was
            ahead = self.lane_length(lane) - lane_pos
            direction = self.directions[min(max(route_index, 0), len(self.directions) - 1)]
            self.signals = 0
            if ahead < 3.0 * speed + 30.0:  # Autoware's search distance at this speed
                if direction in LEFT_TURNS:
                    self.signals = BLINKER_LEFT
                elif direction in RIGHT_TURNS:
                    self.signals = BLINKER_RIGHT

        target = self.ego["max_speed"]
        for _tls, _index, distance, state in lights[:1]:  # the nearest light
            if state in STOP_STATES and distance < 150.0:
                target = min(target, math.sqrt(2.0 * self.ego["plan_decel"] * max(0.0, distance - 2.0)))
        if leader is not None and leader[0]:
            target = min(target, max(0.0, leader[1] - 2.0) / TIME_GAP)
        command = min(target, speed + self.ego["accel"] * self.dt)

        vehicle.setSignals(EGO, self.signals)
        vehicle.setSpeed(EGO, max(0.0, command))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_sumo(command):
    port = free_port()
    process = subprocess.Popen(command + ["--remote-port", str(port)], stdout=subprocess.DEVNULL)
    try:
        with contextlib.redirect_stdout(io.StringIO()):  # traci prints every retry
            return traci.connect(port, numRetries=1000, host="127.0.0.1", proc=process, waitBetweenRetries=0.02)
    except BaseException:
        process.kill()
        process.wait()
        raise


def drive(t, spec):
    """Inserts the ego, then observes, decides, commands and steps until spec["end"]."""
    end = spec["end"]
    add_ego(t, spec["ego"])
    steps = ego_steps = 0
    while EGO not in t.simulation.getDepartedIDList():  # the insertion step(s), as signalsim's
        if t.simulation.getTime() >= end - 1e-9:
            raise traci.exceptions.TraCIException("the ego was not inserted by t=%g" % end)
        t.simulation.step()
        steps += 1
    depart_time = t.simulation.getTime() - spec["step_length"]  # inserted in the step just done
    controller = Controller(t, spec["ego"], spec["step_length"])
    present, arrived = True, False
    while t.simulation.getTime() < end - 1e-9:
        if present:
            controller.step()
            ego_steps += 1
        t.simulation.step()
        steps += 1
        if present and EGO in t.simulation.getArrivedIDList():
            present, arrived = False, True
    return {"steps": steps, "ego_steps": ego_steps, "depart_time": round(depart_time, 6),
            "end_time": round(t.simulation.getTime(), 6), "arrived": arrived}


def main():
    if len(sys.argv) != 2:
        print("usage: traci_controller.py SPEC.json", file=sys.stderr)
        return 2
    with open(sys.argv[1]) as f:
        spec = json.load(f)
    try:
        t = start_sumo(spec["sumo"])
        try:
            result = drive(t, spec)
        finally:
            t.close()
    except traci.exceptions.TraCIException as e:
        print("traci_controller.py: SUMO refused a command: %s" % e, file=sys.stderr)
        return 2
    except traci.exceptions.FatalTraCIError as e:
        print("traci_controller.py: the connection to sumo failed: %s" % e, file=sys.stderr)
        return 2
    print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
