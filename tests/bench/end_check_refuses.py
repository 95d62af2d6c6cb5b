#!/usr/bin/python3
"""tools/bench's end check (bench/scenarios.py) on real runs of intersection_left: the sumo
binary alone and the Python TraCI controller pass when they end where signalsim's run ends, and are
refused, naming both times, when they stop one step short.

  tests/bench/end_check_refuses.py SIGNALSIM
"""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(ROOT, "bench"))
import scenarios  # noqa: E402
from measure import BenchError  # noqa: E402


def refused(check, *args):
    try:
        check(*args)
    except BenchError as e:
        return str(e)
    return None


def main():
    binary = os.path.abspath(sys.argv[1])
    env = dict(os.environ, SUMO_HOME=scenarios.SUMO_HOME)
    failures = []
    with tempfile.TemporaryDirectory() as work:
        s = scenarios.BenchScenario("test", os.path.join(ROOT, "scenarios", "intersection_left.yaml"), work)
        s.calibrate(binary, env)
        if abs(s.runs["full"]["end"] - 32.8) > 1e-9 or s.runs["full"]["steps"] != 327:
            failures.append("signalsim's run: end %g, %d steps (want 32.8, 327)" % (s.runs["full"]["end"],
                                                                                 s.runs["full"]["steps"]))
        log = os.path.join(work, "sumo.log")
        for shift, want_refused in ((0.0, False), (-s.step_length, True)):
            end = s.runs["full"]["end"]
            s.runs["full"]["end"] = round(end + shift, 6)  # the contestants are started with a shifted end
            sumo_argv, controller_argv = s.sumo_argv("full", log), s.controller_argv("full")
            s.runs["full"]["end"] = end
            subprocess.run(sumo_argv, env=env, check=True)
            controller = subprocess.run(controller_argv, env=env, check=True, capture_output=True, text=True)
            for who, message in (("sumo alone", refused(s.check_sumo, "full", log)),
                                 ("controller", refused(s.check_controller, "full", controller.stdout))):
                if want_refused and (message is None or "t=32.7" not in message or "t=32.8" not in message):
                    failures.append("%s one step short: %s" % (who, message or "not refused"))
                if not want_refused and message is not None:
                    failures.append("%s at signalsim's end: refused: %s" % (who, message))
    for f in failures:
        print("FAIL: " + f)
    if not failures:
        print("ok: sumo alone and the controller at t=32.8 pass, one step short (t=32.7) refused")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
