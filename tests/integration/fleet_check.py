"""Checks of fleet mode's outputs (docs/fleet.md), called by fleet_test.sh. Each check raises an
AssertionError naming what differs.

  junction RUN FCD        cross_traffic: every turning vehicle signals its turn at C by the rule
                          (intersection request, §T4), straight ones never; SUMO's FCD shows it
  roundabout RUN COUNTRY  roundabout_traffic under de, kr or jp: entry and exit signals by the preset
  teleport RUN            cross_teleport: the stuck vehicle's blinker goes off after its teleport
  samples RUN SAMPLES     another TraCI client read, every step, what fleet_events.csv says was set
  observe RUN             cross_traffic with signals: observe: SUMO's own blinker measured against the
                          rules (SUMO signals every turn at C, earlier than the rules: behaviour.md §S5)
  rerouted RUN VEHICLE BLINKER  the vehicle another client re-routed signals its new turn at C
  same A B                two runs' fleet_events.csv are byte-identical
"""
import csv
import json
import sys
import xml.etree.ElementTree as ET
from collections import defaultdict

BITS = {"none": 0, "right": 1, "left": 2, "hazard": 4}


def events(run):
    by_vehicle = defaultdict(list)
    for row in csv.DictReader(open(run + "/fleet_events.csv")):
        by_vehicle[row["vehicle"]].append(row)
    return by_vehicle


def fleet_summary(run):
    return json.load(open(run + "/summary.json"))["fleet"]


def mask_at(rows, decided_by):
    """The mask fleet mode last decided at or before SUMO time `decided_by` (None: none yet). A
    decision after the step that brought SUMO to time T is shown during the next step: TraCI reads it
    after that step, at T + 0.1; SUMO's FCD labels that step's state with T (written before SUMO
    advances its clock)."""
    mask = None
    for r in rows:
        if float(r["time"]) <= decided_by + 0.05:
            mask = BITS[r["blinker"]]
    return mask


def check_junction(run, fcd):
    ev = events(run)
    s = fleet_summary(run)
    # 9 flows x 6 vehicles, all departed within the run: every one followed.
    assert s["vehicles"]["followed"] == 54 and s["vehicles"]["left_to_sumo"] == 0, s["vehicles"]
    turning = 0
    for flow in ("N", "E", "W"):
        for turn in ("left", "right", "straight"):
            for k in range(6):
                v = f"{flow}_{turn}.{k}"
                rows = ev.get(v, [])
                if turn == "straight":
                    assert rows == [], (v, rows)
                    continue
                turning += 1
                got = [(r["blinker"], r["place"], r["source"]) for r in rows]
                assert got == [(turn, "C", "intersection"), ("none", "", "none")], (v, got)
                # On within the search distance of the turn lanes' start (s 189.60 on every approach):
                # at most 3 s x 13.89 m/s + 30 m (one 0.1 s step of travel beyond), never before;
                # off once base_link left the junction (s_front past 208.95 + 3.7 for a left turn).
                on, off = float(rows[0]["s_front"]), float(rows[1]["s_front"])
                assert 189.60 - 71.67 - 1.4 <= on <= 189.60 - 30.0, (v, on)
                assert off > 189.60 + 3.7, (v, off)
    assert turning == 36
    places = {p["id"]: p for p in s["places"]}
    assert set(places) == {"C"} and places["C"]["signals"] == 36, places
    assert places["C"]["left"] == 18 and places["C"]["right"] == 18, places["C"]
    assert 30.0 <= places["C"]["lead_min"] <= places["C"]["lead_max"] <= 73.1, places["C"]
    # SUMO's FCD (--fcd-output.signals) shows, every step, the blinker fleet mode set.
    checked = 0
    for step in ET.parse(fcd).getroot().iter("timestep"):
        t = float(step.get("time"))
        for veh in step.iter("vehicle"):
            if veh.get("id") == "ego":
                continue
            want = mask_at(ev.get(veh.get("id"), []), t)
            want = 0 if want is None else want
            got = int(veh.get("signals")) & 7
            assert got == want, (veh.get("id"), t, got, want)
            checked += 1
    assert checked > 5000, checked


def check_roundabout(run, country):
    ev = events(run)
    s = fleet_summary(run)
    assert s["country"] == country, s["country"]
    assert s["vehicles"]["rerouted"] == 1 and s["vehicles"]["left_to_sumo"] == 0, s["vehicles"]
    exits = {"N": ["RW", "RS", "RE"], "E": ["RN", "RW", "RS"], "W": ["RS", "RE", "RN"]}
    seen = 0
    for v, rows in ev.items():
        if v == "W_rerouted":
            frm, exit_place, entry = "W", "RS", "RW"  # sent to the first exit once on the ring
        else:
            frm, n = v.split("_exit")[0], int(v.split("_exit")[1].split(".")[0])
            exit_place, entry = exits[frm][n - 1], "R" + frm
        got = [(r["blinker"], r["place"], r["source"]) for r in rows]
        exit_side = "left" if country == "jp" else "right"  # the jp preset: exit_turn "left"
        want = [(exit_side, exit_place, "roundabout_exit"), ("none", "", "none")]
        if country == "kr":  # Art. 38(1): left on entry as well
            want = [("left", entry, "roundabout_entry"), ("none", "", "none")] + want
        assert got == want, (v, country, got)
        # The exit signal comes on as the front reaches the exit connection (§T5.3): for the second
        # exit at s 272.19 (scenarios/roundabout_de_exit2.yaml's oracle), within a step of travel.
        # Under jp the country's exit-signal marking applies to every fleet route as to the ego's: the
        # exit blinker comes on once the front leaves the previous exit's junction, a quarter ring
        # (about 28 m) earlier.
        if "_exit2" in v:
            on = float(rows[-2]["s_front"])
            if country == "jp":
                assert 235.0 <= on <= 262.0, (v, on)
            else:
                assert 272.19 <= on <= 273.7, (v, on)
        seen += 1
    assert seen == 28, seen
    assert all(p["kind"] == "roundabout" for p in s["places"]), s["places"]


def check_teleport(run):
    ev = events(run)
    s = fleet_summary(run)
    assert s["vehicles"]["teleports"] == 1, s["vehicles"]
    rows = ev["W_stuck"]
    got = [(r["blinker"], r["place"]) for r in rows]
    assert got == [("left", "C"), ("none", "")], got
    # waiting behind the blocker 178 m in, then teleported onto out_N (s > 208.95): off there
    assert float(rows[0]["s_front"]) < 178.0 and float(rows[1]["s_front"]) > 208.95, rows
    log = open(run + "/sumo.log").read()
    assert "Teleporting vehicle 'W_stuck'" in log, "SUMO did not teleport W_stuck"
    teleport_time = float(log.split("Teleporting vehicle 'W_stuck'")[1].split("time=")[1].split(".")[0])
    assert float(rows[1]["time"]) >= teleport_time, (rows[1]["time"], teleport_time)


def check_observe(run):
    s = fleet_summary(run)
    assert s["mode"] == "observe", s["mode"]
    sumo = s["sumo"]
    assert sum(sumo.values()) == s["vehicle_steps"], (sumo, s["vehicle_steps"])
    c = {p["id"]: p for p in s["places"]}["C"]
    assert c["signals"] == 36 and c["sumo_signalled"] == 36, c
    # SUMO comes on 7 s x 13.89 m/s (97 m) before the lane's end, the rules at most 71.67 m before the
    # turn lanes: SUMO alone is on for a while before each turn
    assert sumo["sumo_only_steps"] > 36 * 10 and sumo["opposite_steps"] == 0, sumo


def check_samples(run, samples):
    ev = events(run)
    first_seen = {}
    checked = 0
    for row in csv.reader(open(samples)):
        t, vehicle, signals = float(row[0]), row[1], int(row[2])
        if vehicle not in first_seen:
            first_seen[vehicle] = t  # its first step shows SUMO's own blinker: not set yet
            continue
        want = mask_at(ev.get(vehicle, []), t - 0.1)
        want = 0 if want is None else want
        assert signals & 7 == want, (vehicle, t, signals, want)
        checked += 1
    assert checked > 2000, checked


def main():
    kind, args = sys.argv[1], sys.argv[2:]
    if kind == "junction":
        check_junction(*args)
    elif kind == "roundabout":
        check_roundabout(*args)
    elif kind == "teleport":
        check_teleport(*args)
    elif kind == "observe":
        check_observe(*args)
    elif kind == "samples":
        check_samples(*args)
    elif kind == "rerouted":
        run, vehicle, blinker = args
        assert fleet_summary(run)["vehicles"]["rerouted"] >= 1, fleet_summary(run)["vehicles"]
        got = [(r["blinker"], r["place"]) for r in events(run)[vehicle]]
        assert got == [(blinker, "C"), ("none", "")], (vehicle, got)
    elif kind == "same":
        a, b = (open(d + "/fleet_events.csv", "rb").read() for d in args)
        assert a == b, "fleet_events.csv differ"
    else:
        raise SystemExit("unknown check " + kind)


if __name__ == "__main__":
    main()
