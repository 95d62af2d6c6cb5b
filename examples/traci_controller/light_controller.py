#!/usr/bin/env python3
"""A traffic-light judge as a TraCI client beside signalsim (docs/decider.md "Another TraCI client").

Connects to a SUMO started with --num-clients 2 (or more), steps as client --order (lower than
signalsim's --client-order), and each step answers for every light ahead of the ego
(Vehicle.getNextTLS) by setting the ego parameter `signalsim.light.<tls id>` to `stop` or `go`,
followed by `:` and a reason: stop while the ego's link shows red or yellow, go otherwise; and stop,
whatever the light shows, while SUMO's time is below --hold-until (a controller that holds the ego).
signalsim (`--light-judge traci`) reads the parameters at its turn of the same step. SUMO keeps a
parameter until it is set again.

--log FILE writes one line per light and step: `time,tls_id,answer`. Leaves once the ego has arrived
(or at --until seconds).

usage: light_controller.py PORT [--host 127.0.0.1] [--order 1] [--ego ego] [--hold-until 0]
                           [--log FILE] [--until 3600]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get("SUMO_HOME", "/usr/share/sumo"), "tools"))
import traci  # noqa: E402  (sumo-tools)

PREFIX = "signalsim.light."


def answer(state, time, hold_until):
    """stop or go, with the reason, for a light showing the ego's link `state`."""
    if time < hold_until:
        return "stop:held by the controller"
    if state in "rRyYu":
        return "stop:" + ("red" if state in "rR" else "yellow")
    return "go:" + state


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("port", type=int)
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--order", type=int, default=1)
    parser.add_argument("--ego", default="ego")
    parser.add_argument("--hold-until", type=float, default=0.0, help="[s] stop at every light until this time")
    parser.add_argument("--log", help="one `time,tls_id,answer` line per light and step")
    parser.add_argument("--until", type=float, default=3600.0, help="[s] leave at this SUMO time at the latest")
    args = parser.parse_args()
    log = open(args.log, "w") if args.log else None
    traci.init(args.port, host=args.host)
    traci.setOrder(args.order)
    seen = False
    while traci.simulation.getTime() < args.until:
        if args.ego in traci.vehicle.getIDList():
            seen = True
            now = traci.simulation.getTime()
            for tls_id, _link, _distance, state in traci.vehicle.getNextTLS(args.ego):
                said = answer(state, now, args.hold_until)
                traci.vehicle.setParameter(args.ego, PREFIX + tls_id, said)
                if log:
                    log.write("%.2f,%s,%s\n" % (now, tls_id, said))
        elif seen:
            break  # the ego arrived
        traci.simulationStep()
    if log:
        log.close()
    traci.close()


if __name__ == "__main__":
    main()
