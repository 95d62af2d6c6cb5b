#!/usr/bin/env python3
"""A traffic-light judge for signalsim's JSON-lines protocol (docs/decider.md "JSON lines"), Python
standard library only: stop for a light whose delivered elements show a red or amber circle, go
otherwise. Without a delivery this step, the last delivered elements of that light count.

Run: signalsim run scenarios/tl_red_stop_then_go.yaml --light-judge "exec:python3 examples/python_light_judge/judge.py"
"""
import json
import sys


def main():
    last = {}  # tls_id -> the last delivered elements
    for line in sys.stdin:
        message = json.loads(line)
        if message["type"] == "bye":
            break
        if message["type"] != "step":
            continue
        answers = []
        for light in message["lights"]:
            if light["delivered"]:
                last[light["tls_id"]] = light["elements"]
            elements = last.get(light["tls_id"], [])
            stop = any(e["shape"] == "circle" and e["color"] in ("red", "amber") and e["status"] != "solid_off"
                       for e in elements)
            answers.append({"tls_id": light["tls_id"], "decision": "stop" if stop else "go",
                            "reason": "red or amber circle" if stop else "no red or amber circle"})
        sys.stdout.write(json.dumps({"lights": answers}) + "\n")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
