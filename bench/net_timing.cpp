// signalsim_net_timing: what signalsim's own start-up of a run costs on a scenario's net, and what
// one step costs (docs/performance.md "Start-up on big nets"). CPU time of this process, medians.
//
//   build/bench/signalsim_net_timing SCENARIO [--set KEY=VALUE]... [--repeat N] [--steps]
//
// Start-up: the net index as a run reads it (NetReading::OnDemand) and the run's plan (plan_run: the
// route's elements read, lanelets, lane plan); for comparison the whole net read at load (what
// `inspect` and `generate` do), and a second NetIndex::load_shared of the net (a batch worker's next
// run on it). `--set` as in `signalsim run` (`--set net=PATH`: the same route on another net). --steps then drives the scenario once in libsumo (one simulation
// per process) and prints the CPU per step of the step loop, SUMO's step included, start-up not.
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "sim/session_setup.hpp"
#include "sim/step_loop.hpp"
#include "net/net_index.hpp"

namespace {

using namespace signalsim;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int run(const std::string& scenario_path, const std::vector<std::string>& set, int repeat, bool steps) {
  const Scenario scenario = load_scenario(scenario_path, ScenarioOverrides{set});
  std::vector<double> on_demand, plan, whole;
  std::size_t edges = 0, lanelets = 0;
  for (int i = 0; i < repeat; ++i) {
    const double t0 = cpu_seconds();
    const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
    const double t1 = cpu_seconds();
    const PlannedRun planned = plan_run(scenario, net);
    const double t2 = cpu_seconds();
    on_demand.push_back(t1 - t0);
    plan.push_back(t2 - t1);
    edges = net.edge_count();
    lanelets = planned.plan.map.size();
  }
  const double rss_after_start = peak_rss_mib();
  for (int i = 0; i < repeat; ++i) {
    const double t0 = cpu_seconds();
    const sumo::NetIndex net = sumo::NetIndex::load(scenario.net, sumo::NetReading::Whole);
    whole.push_back(cpu_seconds() - t0);
  }
  std::printf("net %s: %zu edges; route: %zu lanelets\n", scenario.net.c_str(), edges, lanelets);
  std::printf("start-up, CPU, median of %d: net index (on demand) %.4f s + route plan %.4f s = %.4f s; "
              "peak RSS %.0f MiB\n",
              repeat, median(on_demand), median(plan), median(on_demand) + median(plan), rss_after_start);
  std::printf("whole net read at load (inspect, generate), CPU, median of %d: %.4f s\n", repeat, median(whole));
  const auto shared = sumo::NetIndex::load_shared(scenario.net);
  std::vector<double> again;
  for (int i = 0; i < repeat; ++i) {
    const double t0 = cpu_seconds();
    const auto same = sumo::NetIndex::load_shared(scenario.net);
    again.push_back(cpu_seconds() - t0);
    if (same != shared) std::printf("load_shared loaded the net again\n");
  }
  std::printf("load_shared of a loaded net, CPU, median of %d: %.1f us\n", repeat, median(again) * 1e6);
  if (!steps) return 0;

  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  StartedRun started = start_run(plan_run(scenario, net), net, RunContext{});
  const double t0 = cpu_seconds();
  const RunRecord record = drive(started, net);
  const double per_step = (cpu_seconds() - t0) / static_cast<double>(std::max<std::size_t>(record.rows.size(), 1));
  std::printf("steps: %zu, %.2f us CPU per step (the step loop, SUMO's step included)\n", record.rows.size(),
              per_step * 1e6);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scenario;
  std::vector<std::string> set;
  int repeat = 7;
  bool steps = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--set") == 0 && i + 1 < argc) set.emplace_back(argv[++i]);
    else if (std::strcmp(argv[i], "--steps") == 0) steps = true;
    else if (scenario.empty() && argv[i][0] != '-') scenario = argv[i];
    else {
      std::fprintf(stderr, "usage: signalsim_net_timing SCENARIO [--set KEY=VALUE]... [--repeat N] [--steps]\n");
      return 2;
    }
  }
  if (scenario.empty()) {
    std::fprintf(stderr, "usage: signalsim_net_timing SCENARIO [--set KEY=VALUE]... [--repeat N] [--steps]\n");
    return 2;
  }
  try {
    return run(scenario, set, repeat, steps);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
