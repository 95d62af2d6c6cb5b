"""The generated schemas (WORK/scenario.schema.json, WORK/sweep.schema.json) against the bundled files
and the loader: python3 schema_validation.py SIGNALSIM SOURCE_DIR WORK. Exit 1 on any failure."""
import copy
import glob
import json
import os
import subprocess
import sys

import jsonschema
import yaml

signalsim, src, work = sys.argv[1:4]
failures = 0


def fail(message):
    global failures
    failures += 1
    print("FAIL " + message)


def validator(kind):
    schema = json.load(open(os.path.join(work, kind + ".schema.json"), encoding="utf-8"))
    jsonschema.Draft7Validator.check_schema(schema)  # raises on a schema that is not draft-07
    return jsonschema.Draft7Validator(schema)


def errors(v, doc):
    return sorted(v.iter_errors(doc), key=lambda e: list(map(str, e.absolute_path)))


scenario, sweep = validator("scenario"), validator("sweep")

# Every bundled file validates: the suite, its sweeps, and the test data that loads.
scenario_files = ["/scenarios/*.yaml", "/tests/data/schema/*.yaml", "/tests/data/scenarios/*.yaml",
                  "/tests/data/user_sumo/*.yaml", "/tests/data/compare/*.yaml", "/tests/batch/data/[rt]*.yaml",
                  "/tests/data/fleet/cross_traffic_egoless.yaml"]
sweep_files = ["/scenarios/sweeps/*.yaml", "/tests/data/sweeps/*.yaml", "/tests/batch/data/sweep_*.yaml"]
bundled = [(scenario, p) for pattern in scenario_files for p in glob.glob(src + pattern)]
bundled += [(sweep, p) for pattern in sweep_files for p in glob.glob(src + pattern)]
for v, path in sorted(bundled, key=lambda b: b[1]):
    for e in errors(v, yaml.safe_load(open(path, encoding="utf-8"))):
        fail("%s: %s: %s" % (os.path.relpath(path, src), "/".join(map(str, e.absolute_path)), e.message))
print("ok   %d bundled files validate (%d scenarios, %d sweeps)" % (len(bundled), sum(v is scenario for v, _ in bundled), sum(v is sweep for v, _ in bundled)))

# Mutants of every_key.yaml (paths made absolute, written to WORK): each is refused by the schema and
# by the loader (`signalsim run`: exit 2, the loader's message).
here = src + "/tests/data/schema/"
base = yaml.safe_load(open(here + "every_key.yaml", encoding="utf-8"))
base["net"] = here + base["net"]
for key in ("routes", "additional"):
    base[key] = [here + p for p in base[key]]
base["ego"]["vehicle_info"] = here + base["ego"]["vehicle_info"]
base["params"]["files"] = [here + p for p in base["params"]["files"]]


def mutant(change):
    doc = copy.deepcopy(base)
    change(doc)
    return doc


def write(name, doc):
    path = os.path.join(work, name + ".yaml")
    with open(path, "w", encoding="utf-8") as f:
        yaml.safe_dump(doc, f, sort_keys=False)
    return path


# The unchanged file validates and loads (sweep --list loads its scenarios, no SUMO).
if errors(scenario, base):
    fail("every_key (absolute paths) does not validate: %s" % errors(scenario, base)[0].message)
listing = write("list_sweep", {"scenarios": [write("every_key", base)]})
done = subprocess.run([signalsim, "sweep", listing, "--list"], capture_output=True, text=True)
if done.returncode != 0:
    fail("every_key does not load: " + done.stderr.strip())

cases = [
    ("unknown_top_key", lambda d: d.update(colour="red"), "unknown key 'colour'"),
    ("unknown_ego_key", lambda d: d["ego"].update(top_speed=3), "unknown key 'ego.top_speed'"),
    ("unknown_v2i_key", lambda d: d["perception"]["v2i"].update(range=3), "unknown key 'perception.v2i.range'"),
    ("unknown_maneuver_key", lambda d: d["maneuvers"][1]["avoid"].update(gap=1), "unknown key 'maneuvers[1].avoid.gap'"),
    ("unknown_obstacle_key", lambda d: d["obstacles"][0].update(speed=1), "unknown key 'obstacles[0].speed'"),
    ("unknown_expectation", lambda d: d["expect"].append({"blinker_always": {"blinker": "left"}}), "unknown expectation 'blinker_always'"),
    ("unknown_parameter", lambda d: d["params"]["set"].update(turn_signal_serch_time=3.0),
     "unknown parameter 'turn_signal_serch_time' (did you mean 'turn_signal_search_time'?)"),
    ("number_as_text", lambda d: d["ego"].update(max_speed="fast"), "key 'ego.max_speed': expected a number, got 'fast'"),
    ("route_not_a_list", lambda d: d["ego"].update(route="in_S"), "key 'ego.route': expected a list"),
    ("integer_as_number", lambda d: d["perception"].update(detections_per_light=1.5),
     "key 'perception.detections_per_light': expected an integer, got '1.5'"),
    ("out_of_range", lambda d: d["perception"].update(dropout_probability=1.5),
     "key 'perception.dropout_probability': value 1.5 is out of range [0, 1]"),
    ("not_a_choice", lambda d: d["maneuvers"][1]["avoid"].update(side="up"),
     "key 'maneuvers[1].avoid.side': 'up' is not one of auto, left, right"),
    ("parameter_type", lambda d: d["params"]["set"].update(turn_signal_on_swerving=3),
     "parameter 'turn_signal_on_swerving': expected true or false, got '3'"),
    ("parameter_range", lambda d: d["params"]["set"]["v2i"].update(last_time_allowed_to_pass=99),
     "parameter 'v2i.last_time_allowed_to_pass': value 99 is out of range [0, 60]"),
    ("missing_name", lambda d: d.pop("name"), "missing required key 'name'"),
    ("missing_ego_and_fleet", lambda d: (d.pop("ego"), d.pop("fleet")), "missing required key 'ego'"),
    ("lists_not_a_mapping", lambda d: d.update(params=[1]), "'params' must be a mapping of key: value"),
]
for name, change, message in cases:
    doc = mutant(change)
    if not errors(scenario, doc):
        fail("%s: the schema accepts it" % name)
    done = subprocess.run([signalsim, "run", write(name, doc), "--out", os.path.join(work, "out_" + name)],
                          capture_output=True, text=True)
    if done.returncode != 2 or message not in done.stderr:
        fail("%s: the loader gives exit %d, %r (want 2, %r)" % (name, done.returncode, done.stderr.strip(), message))
print("ok   %d scenario mutants refused by the schema and the loader" % len(cases))

# Sweeps: an unknown key, a swept value out of its key's range, an unknown --set key.
scenario_file = write("every_key", base)
sweep_cases = [
    ("sweep_unknown_key", {"scenarios": [scenario_file], "grids": {"seed": [1]}}, "unknown key 'grids'"),
    ("sweep_value_range", {"scenarios": [scenario_file], "grid": {"ego.max_speed": [200]}},
     "key 'ego.max_speed': value 200 is out of range [0.1, 100]"),
    ("sweep_unknown_set_key", {"scenarios": [scenario_file], "set": {"ego.top_speed": 3}}, "unknown key 'ego.top_speed'"),
    ("sweep_timeout_type", {"scenarios": [scenario_file], "timeout": "long"}, "key 'timeout': expected a number"),
]
for name, doc, message in sweep_cases:
    if not errors(sweep, doc):
        fail("%s: the schema accepts it" % name)
    done = subprocess.run([signalsim, "sweep", write(name, doc), "--list"], capture_output=True, text=True)
    if done.returncode != 2 or message not in done.stderr:
        fail("%s: signalsim sweep gives exit %d, %r (want 2, %r)" % (name, done.returncode, done.stderr.strip(), message))
print("ok   %d sweep mutants refused by the schema and by signalsim sweep" % len(sweep_cases))

sys.exit(1 if failures else 0)
