"""The other TraCI client of fleet_test.sh's --connect run (order 1, beside signalsim): every step it
reads the signals of every vehicle (subscribed at departure) and writes "time,vehicle,signals" rows;
one step after VEHICLE departs it re-routes it to TARGET (changeTarget), and two steps after REMOVED
departs it removes that one, as a co-simulation would (unsubscribing it first: SUMO 1.15 answered
signalsim's next step with this client's failed subscription of the removed vehicle, variable 0x5b,
and signalsim's run ended with that error; docs/fleet.md).

usage: fleet_client.py PORT UNTIL SAMPLES.csv VEHICLE TARGET REMOVED
"""
import sys

sys.path.insert(0, "/usr/share/sumo/tools")
import traci  # noqa: E402
import traci.constants as tc  # noqa: E402

port, until, samples, vehicle, target = int(sys.argv[1]), float(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
removed_vehicle = sys.argv[6]
seen_steps = 0
removed = False
traci.init(port, host="127.0.0.1")
traci.setOrder(1)
rerouted = False
with open(samples, "w") as out:
    while traci.simulation.getTime() < until:
        traci.simulationStep()
        t = traci.simulation.getTime()
        for v in traci.simulation.getDepartedIDList():
            traci.vehicle.subscribe(v, [tc.VAR_SIGNALS])
        present = traci.vehicle.getIDList()
        if not rerouted and vehicle in present and vehicle not in traci.simulation.getDepartedIDList():
            traci.vehicle.changeTarget(vehicle, target)
            rerouted = True
        if not removed and removed_vehicle in present:
            seen_steps += 1
            if seen_steps == 3:
                traci.vehicle.unsubscribe(removed_vehicle)
                traci.vehicle.remove(removed_vehicle)
                removed = True
        for v, values in sorted(traci.vehicle.getAllSubscriptionResults().items()):
            if tc.VAR_SIGNALS in values and v != "ego":
                out.write("%.1f,%s,%d\n" % (t, v, values[tc.VAR_SIGNALS]))
print("fleet client reached", traci.simulation.getTime(), "rerouted" if rerouted else "not rerouted",
      "removed" if removed else "not removed")
traci.close()
