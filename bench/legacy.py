"""The single-figure benchmarks, each chosen with tools/bench --only NAME (not run by default):

  micro      Google Benchmark: one decider step and one speed-planning step on 100 .. 100 000 lanelets
  embedded   intersection_left as a whole process (libsumo in-process)
  gui        the same run in sumo-gui under an Xvfb started here (--gui), when Xvfb is installed
  connect    the same run attached (--connect) to a sumo started here on 127.0.0.1, per run
  routes     a Bologna ego with the net's 8 622-vehicle demand as route files (-r, `routes:`)
  additional the same demand given as additional files (everything loaded at start)

Each prints its row at once: the median wall and CPU time of N runs after one warm-up run (min-max of
the wall time in brackets; connect's CPU includes its sumo server's). Every service started here is stopped by its process id.
"""
import os
import shutil
import socket
import statistics
import subprocess
import time

from measure import children_cpu, run_child

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENARIO = os.path.join(ROOT, "scenarios", "intersection_left.yaml")
ACOSTA = os.path.join(ROOT, "sumo_nets", "bologna_acosta")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def timed(command, runs, env=None, before=None, after=None):
    """Samples of `command` over `runs` runs after one warm-up run. With `before`, each run first calls
    it (not timed) and `command` is a function of what it returned; `after` gets that state back, and
    the CPU time of what it waits for (a server `before` started) counts in the run's."""
    samples = []
    for i in range(runs + 1):
        state = before() if before else None
        argv = command(state) if before else command
        cpu_before = children_cpu()
        try:
            sample = run_child(argv, env=env, ok_codes=(0, 1))
        finally:
            if after:
                after(state)
        sample.cpu = children_cpu() - cpu_before
        if i > 0:
            samples.append(sample)
    return samples


def row(name, what, samples):
    walls = [s.wall for s in samples]
    print("%-10s  %-58s  %7.3f s wall (%.3f-%.3f)  %7.3f s CPU" % (
        name, what, statistics.median(walls), min(walls), max(walls), statistics.median(s.cpu for s in samples)),
        flush=True)


def bench_micro(_runs, _work, _binary, env):
    binary = os.path.join(ROOT, "build", "bench", "signalsim_bench")
    out = subprocess.run([binary, "--benchmark_min_time=0.2"], capture_output=True, text=True, check=True,
                         env=env).stdout
    for line in out.splitlines():
        if line.startswith("BM_"):
            print("micro       " + line, flush=True)


def bench_embedded(runs, work, binary, env):
    row("embedded", "intersection_left, 320 steps",
        timed([binary, "run", SCENARIO, "--out", work + "/e", "--quiet"], runs, env))


def bench_gui(runs, work, binary, env):
    if shutil.which("Xvfb") is None:
        print("gui         skipped: Xvfb is not installed (apt-get install xvfb)")
        return
    display_file = open(work + "/display", "w+")
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(display_file.fileno()), "-nolisten", "tcp"],
                            pass_fds=[display_file.fileno()], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        number = ""
        for _ in range(100):
            display_file.seek(0)
            number = display_file.read().strip()
            if number:
                break
            time.sleep(0.05)
        gui_env = dict(env, DISPLAY=":" + number)
        row("gui", "intersection_left in sumo-gui (start, connect, quit)",
            timed([binary, "run", SCENARIO, "--out", work + "/g", "--quiet", "--gui"], runs, env=gui_env))
    finally:
        xvfb.terminate()
        xvfb.wait()
        display_file.close()


def bench_connect(runs, work, binary, env):
    net = os.path.join(ROOT, "sumo_nets", "cross", "cross.net.xml")

    def start_server():  # a fresh server per run; it ends when signalsim, its only client, leaves
        port = free_port()
        server = subprocess.Popen(["sumo", "-n", net, "--remote-port", str(port), "--step-length", "0.1",
                                   "--seed", "1", "--no-step-log", "true"], env=env,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return port, server

    def stop_server(state):
        try:
            state[1].wait(timeout=30)
        except subprocess.TimeoutExpired:
            state[1].kill()
            state[1].wait()

    row("connect", "intersection_left attached to a sumo on 127.0.0.1",
        timed(lambda state: [binary, "run", SCENARIO, "--out", work + "/c", "--quiet", "--connect",
                             "127.0.0.1:%d" % state[0]], runs, env, before=start_server, after=stop_server))


def write_acosta_scenario(work, key):
    path = os.path.join(work, "acosta_%s.yaml" % key)
    files = ["acosta.rou.xml", "acosta_busses.rou.xml"]
    with open(path, "w") as f:
        f.write("name: acosta_%s\nnet: %s/acosta_buslanes.net.xml\n" % (key, ACOSTA))
        f.write("additional: [%s/acosta_vtypes.add.xml, %s/acosta_tls.add.xml, %s/acosta_bus_stops.add.xml"
                % (ACOSTA, ACOSTA, ACOSTA))
        if key == "additional":
            f.write("".join(", %s/%s" % (ACOSTA, x) for x in files))
        f.write("]\n")
        if key == "routes":
            f.write("routes: [%s]\n" % ", ".join("%s/%s" % (ACOSTA, x) for x in files))
        f.write("duration: 60\nego:\n  route: ['131', '117', '209']\n  depart_speed: 5\n")
    return path


def bench_routes(runs, work, binary, env):
    scenario = write_acosta_scenario(work, "routes")
    row("routes", "bologna/acosta ego, its demand as route files (-r)",
        timed([binary, "run", scenario, "--out", work + "/r", "--quiet"], runs, env))


def bench_additional(runs, work, binary, env):
    scenario = write_acosta_scenario(work, "additional")
    row("additional", "bologna/acosta ego, its demand as additional files (-a)",
        timed([binary, "run", scenario, "--out", work + "/a", "--quiet"], runs, env))


BENCHES = {"micro": bench_micro, "embedded": bench_embedded, "gui": bench_gui, "connect": bench_connect,
           "routes": bench_routes, "additional": bench_additional}
