// SUMO alone, in-process, with the library signalsim embeds (libsumocpp.so): how tools/bench
// measures SUMO's own cost per step without its start-up (docs/performance.md).
//
//   build/bench/sumo_steps FROM END SUMO-ARGUMENT...
//
// Loads the simulation with the sumo binary's own arguments (the ego a plain vehicle of a route
// file), runs FROM steps one by one (the first inserts the ego), then every further step up to the
// simulated time END in one Simulation::step(END), so that nothing runs between SUMO's steps. Prints
// one JSON line:
//   {"load_cpu": s, "first_steps_cpu": s, "step_cpu": s, "steps": n, "end_time": t}
// load_cpu is this process's CPU time (CLOCK_PROCESS_CPUTIME_ID) once SUMO has loaded,
// first_steps_cpu that of the FROM steps, step_cpu that of the `steps` steps after them. Why the
// first steps are apart: see bench/step_clock.cpp. Exit 2 with one line when SUMO refuses.
#include <libsumo/libsumo.h>
#include <time.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace {

double process_cpu() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: sumo_steps FROM END SUMO-ARGUMENT...\n");
    return 2;
  }
  char* rest = nullptr;
  const long from = std::strtol(argv[1], &rest, 10);
  if (rest == argv[1] || *rest != '\0' || from < 1) {
    std::fprintf(stderr, "sumo_steps: FROM '%s' is not a whole number of at least 1\n", argv[1]);
    return 2;
  }
  const double end = std::strtod(argv[2], &rest);
  if (rest == argv[2] || *rest != '\0' || !std::isfinite(end)) {
    std::fprintf(stderr, "sumo_steps: END '%s' is not a number\n", argv[2]);
    return 2;
  }
  std::vector<std::string> arguments = {"sumo"};
  arguments.insert(arguments.end(), argv + 3, argv + argc);
  try {
    libsumo::Simulation::start(arguments);
    const double loaded = process_cpu();
    for (long i = 0; i < from; ++i) libsumo::Simulation::step();
    const double first_step = process_cpu();
    const double after_first = libsumo::Simulation::getTime();
    libsumo::Simulation::step(end);
    const double stepped = process_cpu();
    const double end_time = libsumo::Simulation::getTime();
    const long steps = std::lround((end_time - after_first) / libsumo::Simulation::getDeltaT());
    libsumo::Simulation::close();
    std::printf("{\"load_cpu\": %.9f, \"first_steps_cpu\": %.9f, \"step_cpu\": %.9f, \"steps\": %ld, \"end_time\": %.6f}\n",
                loaded, first_step - loaded, stepped - first_step, steps, end_time);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sumo_steps: SUMO refused: %s\n", e.what());
    return 2;
  }
  return 0;
}
