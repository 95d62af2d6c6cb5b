#!/usr/bin/env python3
"""A turn-signal decider as a TraCI client beside signalsim (docs/decider.md "Another TraCI client").

Connects to a SUMO started with --num-clients 2 (or more), steps as client --order (lower than
signalsim's --client-order), and each step sets the ego's blinker with Vehicle.setSignals by one
simple rule: within --within metres of the end of a lane whose link onto the ego's next edge turns
left (right), the left (right) blinker; on the junction's internal lanes, the blinker of the approach;
otherwise none. SUMO keeps a mask set over TraCI for one step only, so it is set every step.
signalsim (`--decider traci`) reads the mask back at its turn of the same step.

--log FILE writes one line per step it set: `time,mask` (SUMO time [s] when set, TraCI signal bits:
right 1, left 2, hazard 4). Leaves once the ego has arrived (or at --until seconds).

usage: blinker_controller.py PORT [--host 127.0.0.1] [--order 1] [--ego ego] [--within 70]
                             [--log FILE] [--until 3600]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get("SUMO_HOME", "/usr/share/sumo"), "tools"))
import traci  # noqa: E402  (sumo-tools)

LEFT, RIGHT = 2, 1


def turn_mask(ego, within):
    """The blinker for the ego's position now by the rule above; None inside a junction."""
    road = traci.vehicle.getRoadID(ego)
    if road.startswith(":"):
        return None  # keep the approach's blinker
    lane = traci.vehicle.getLaneID(ego)
    to_end = traci.lane.getLength(lane) - traci.vehicle.getLanePosition(ego)
    route, index = traci.vehicle.getRoute(ego), traci.vehicle.getRouteIndex(ego)
    if to_end > within or index + 1 >= len(route):
        return 0
    next_edge = route[index + 1]
    for link in traci.lane.getLinks(lane, extended=True):
        to_lane, direction = link[0], link[6]
        if traci.lane.getEdgeID(to_lane) == next_edge:
            return LEFT if direction in ("l", "L") else RIGHT if direction in ("r", "R") else 0
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("port", type=int)
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--order", type=int, default=1)
    parser.add_argument("--ego", default="ego")
    parser.add_argument("--within", type=float, default=70.0, help="[m] before the lane's end")
    parser.add_argument("--log", help="one `time,mask` line per step set")
    parser.add_argument("--until", type=float, default=3600.0, help="[s] leave at this SUMO time at the latest")
    args = parser.parse_args()
    log = open(args.log, "w") if args.log else None
    traci.init(args.port, host=args.host)
    traci.setOrder(args.order)
    seen, mask = False, 0
    while traci.simulation.getTime() < args.until:
        if args.ego in traci.vehicle.getIDList():
            seen = True
            turn = turn_mask(args.ego, args.within)
            mask = mask if turn is None else turn
            traci.vehicle.setSignals(args.ego, mask)
            if log:
                log.write("%.2f,%d\n" % (traci.simulation.getTime(), mask))
        elif seen:
            break  # the ego arrived
        traci.simulationStep()
    if log:
        log.close()
    traci.close()


if __name__ == "__main__":
    main()
