#!/usr/bin/env python3
"""A JSON-lines SUT for the protocol tests: writes every line signalsim sends to LOG and answers each
step with REPLY's decision (decider: blinker none; light_judge: go for every light).
usage: python3 record.py decider|light_judge LOG"""
import json
import sys

role, log = sys.argv[1], sys.argv[2]
with open(log, "w", encoding="utf-8") as out:
    for line in sys.stdin:
        out.write(line)
        message = json.loads(line)
        if message["type"] == "step":
            if role == "decider":
                reply = {"blinker": "none"}
            else:
                reply = {"lights": [{"tls_id": l["tls_id"], "decision": "go"} for l in message["lights"]]}
            sys.stdout.write(json.dumps(reply) + "\n")
            sys.stdout.flush()
        elif message["type"] == "bye":
            break
