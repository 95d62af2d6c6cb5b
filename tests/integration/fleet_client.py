"""The other TraCI client of fleet_test.sh's --connect run (order 1, beside signalsim): every step it
reads the signals of every vehicle (subscribed at departure) and writes "time,vehicle,signals" rows;
one step after VEHICLE departs it re-routes it to TARGET (changeTarget), as a co-simulation would.

usage: fleet_client.py PORT UNTIL SAMPLES.csv VEHICLE TARGET
"""
import sys

sys.path.insert(0, "/usr/share/sumo/tools")
import traci  # noqa: E402
import traci.constants as tc  # noqa: E402

port, until, samples, vehicle, target = int(sys.argv[1]), float(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
traci.init(port, host="127.0.0.1")
traci.setOrder(1)
rerouted = False
with open(samples, "w") as out:
    while traci.simulation.getTime() < until:
        traci.simulationStep()
        t = traci.simulation.getTime()
        for v in traci.simulation.getDepartedIDList():
            traci.vehicle.subscribe(v, [tc.VAR_SIGNALS])
        if not rerouted and vehicle in traci.vehicle.getIDList() and vehicle not in traci.simulation.getDepartedIDList():
            traci.vehicle.changeTarget(vehicle, target)
            rerouted = True
        for v, values in sorted(traci.vehicle.getAllSubscriptionResults().items()):
            if tc.VAR_SIGNALS in values and v != "ego":
                out.write("%.1f,%s,%d\n" % (t, v, values[tc.VAR_SIGNALS]))
print("fleet client reached", traci.simulation.getTime(), "rerouted" if rerouted else "not rerouted")
traci.close()
