#!/usr/bin/env python3
"""The cost of one ego-only step, counted by valgrind's callgrind (docs/performance.md "One step, measured").

Runs `signalsim run` twice under callgrind on the same scenario, slowed so that it takes many steps
(intersection_left at 3 m/s: 50 and 1 300 steps), and prints
  - the instructions a step: (total of the long run - total of the short run) / the steps between,
    so that the start-up (nearly all of a short run) cancels out;
  - the calls a step into SUMO's library (libsumo, or libtraci with --connect) that signalsim's session
    makes, by function, from the long run's call graph (start-up and shut-down callers left out).
With --connect HOST:PORT the long run attaches to that SUMO instead (start it with --remote-port, the
scenario's net and step length); each libtraci call but getSubscriptionResults is one TraCI message.
The runs end with exit code 1 (at 3 m/s the scenario's expectations do not hold); that is expected.

Usage: tools/bench step-cost [--bin SIGNALSIM] [--scenario YAML] [--out DIR] [--set KEY=VALUE] [--connect HOST:PORT]
Needs valgrind (Debian package valgrind). Takes about a minute.
"""
import argparse
import collections
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SLOW = ["--set", "ego.max_speed=3", "--set", "ego.depart_speed=3"]
# Session functions that run once a run, not once a step.
ONCE = re.compile(r"insert_ego|add_ego|take_control|wait_for_departure|move_to_depart_offset|release_ego|"
                  r"program_states|light_programs|shift_light_program|delta_t|Session::|Session\(|~|"
                  r"open_embedded|open_traci|net_load_error|core_setup|attach|start_gui|try_connect")


def run(args, duration, out_dir, connect=None):
    """Runs one scenario under callgrind; returns (instructions, steps, callgrind file)."""
    name = f"step_cost_{duration}" + ("_connect" if connect else "")
    cg_file = os.path.join(out_dir, name + ".callgrind")
    command = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={cg_file}", args.bin, "run", args.scenario,
               "--out", os.path.join(out_dir, name), "--quiet", "--set", f"duration={duration}"] + SLOW
    for value in args.set:
        command += ["--set", value]
    if connect:
        command += ["--connect", connect]
    done = subprocess.run(command, capture_output=True, text=True)
    found = re.search(r"Collected : (\d+)", done.stderr)
    if not found:
        sys.exit(f"step_cost: valgrind did not report a total:\n{done.stderr[-2000:]}")
    with open(os.path.join(out_dir, name, "summary.json")) as f:
        steps = json.load(f)["counts"]["steps"]
    return int(found.group(1)), steps, cg_file


def library_calls(cg_file, library):
    """Calls from signalsim's code into `library`:: functions, by (callee, calling session function)."""
    names, objects = {}, {}
    counts = collections.Counter()
    caller = caller_object = callee = None

    def resolve(table, text):  # callgrind's name compression: "(id) name" once, "(id)" after
        m = re.match(r"\((\d+)\)(?:\s+(.*))?", text)
        if not m:
            return text
        if m.group(2) is not None:
            table[m.group(1)] = m.group(2)
        return table.get(m.group(1), "?")

    with open(cg_file) as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("ob="):
                caller_object = resolve(objects, line[3:])
            elif line.startswith("fn="):
                caller = resolve(names, line[3:])
            elif line.startswith("cob="):
                resolve(objects, line[4:])
            elif line.startswith("cfn="):
                callee = resolve(names, line[4:])
            elif line.startswith("calls=") and callee and callee.startswith(library + "::"):
                if "signalsim" not in os.path.basename(caller_object or "") or ONCE.search(caller or ""):
                    continue
                plain = (caller or "?").replace("(anonymous namespace)", "")
                short_caller = re.sub(r"<.*?>|\(.*", "", plain).split("::")[-1]
                counts[(re.sub(r"\(.*|\[abi:cxx11\]", "", callee), short_caller)] += int(line[6:].split()[0])
    return counts


def main():
    parser = argparse.ArgumentParser(prog="tools/bench step-cost", description=__doc__.split("\n")[0])
    parser.add_argument("--bin", default=os.path.join(ROOT, "build/src/app/signalsim"))
    parser.add_argument("--scenario", default=os.path.join(ROOT, "scenarios/intersection_left.yaml"))
    parser.add_argument("--out", default=os.path.join(ROOT, "out/step_cost"))
    parser.add_argument("--set", action="append", default=[],
                        help="one more --set of both runs (e.g. decider=lib:PATH.so: a decider under test)")
    parser.add_argument("--connect", help="HOST:PORT of a SUMO started with --remote-port (the long run only)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if not args.connect:
        short_total, short_steps, _ = run(args, 5, args.out)
    long_total, long_steps, cg_file = run(args, 130, args.out, args.connect)
    if not args.connect:
        print(f"instructions a step: {(long_total - short_total) / (long_steps - short_steps):,.0f} "
              f"({short_steps} and {long_steps} steps: {short_total:,} and {long_total:,})")
    library = "libtraci" if args.connect else "libsumo"
    counts = library_calls(cg_file, library)
    print(f"{library} calls a step ({long_steps} steps):")
    for (callee, caller), n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])):
        print(f"  {n / long_steps:6.3f}  {callee}  (from {caller})")
    print(f"  {sum(counts.values()) / long_steps:6.3f}  in all")


if __name__ == "__main__":
    sys.exit(main())
