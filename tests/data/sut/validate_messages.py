#!/usr/bin/env python3
"""Real messages against `signalsim schema`: every line of LOG validates against REQUEST_SCHEMA, the
first is hello, the last bye, the rest steps; each of REPLIES (JSON texts) validates against
REPLY_SCHEMA and each of BAD_REPLIES does not. Exit 1 on any failure.
usage: python3 validate_messages.py REQUEST_SCHEMA LOG REPLY_SCHEMA 'GOOD;GOOD' 'BAD;BAD'"""
import json
import sys

import jsonschema

request_schema, log, reply_schema, good, bad = sys.argv[1:6]
failures = 0


def check(schema_path):
    schema = json.load(open(schema_path, encoding="utf-8"))
    jsonschema.Draft7Validator.check_schema(schema)
    return jsonschema.Draft7Validator(schema)


requests, replies = check(request_schema), check(reply_schema)
lines = [json.loads(l) for l in open(log, encoding="utf-8")]
kinds = [m["type"] for m in lines]
if len(lines) < 3 or kinds[0] != "hello" or kinds[-1] != "bye" or set(kinds[1:-1]) != {"step"}:
    print("FAIL %s: not hello, steps, bye: %s ..." % (log, kinds[:3]))
    failures += 1
for i, m in enumerate(lines):
    for e in requests.iter_errors(m):
        print("FAIL %s line %d: %s: %s" % (log, i + 1, "/".join(map(str, e.absolute_path)), e.message[:200]))
        failures += 1
        break
for text in filter(None, good.split(";")):
    if not replies.is_valid(json.loads(text)):
        print("FAIL reply %s is refused by %s" % (text, reply_schema))
        failures += 1
for text in filter(None, bad.split(";")):
    if replies.is_valid(json.loads(text)):
        print("FAIL reply %s is accepted by %s" % (text, reply_schema))
        failures += 1
print("%s %d messages of %s (%d steps)" % ("FAIL" if failures else "ok  ", len(lines), log, kinds.count("step")))
sys.exit(1 if failures else 0)
