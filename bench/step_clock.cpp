// The step clock: an LD_PRELOAD library with which tools/bench measures a whole process's cost per
// simulation step without its start-up (docs/performance.md). It wraps libsumo's Simulation::step and
// Simulation::close, forwarding every call unchanged to libsumocpp.so (dlsym RTLD_NEXT), and records
// the process's CPU time (CLOCK_PROCESS_CPUTIME_ID) when the first step starts, when step number
// SIGNALSIM_STEP_CLOCK_FROM (default 1) has returned, at close and at exit, and the number of step
// calls. At exit it writes them as one JSON line to the file named by SIGNALSIM_STEP_CLOCK:
//   {"first_step_cpu": s, "from": n, "from_cpu": s, "close_cpu": s, "exit_cpu": s, "step_calls": n}
// first_step_cpu is the start-up (process start, net index, SUMO's load, adding the ego);
// (close_cpu - from_cpu) / (step_calls - from) the cost of a step, SUMO's and signalsim's (its rows
// are kept in memory and written after close); exit_cpu - close_cpu what follows (SUMO's close, the
// expectations, the outputs, freeing the net).
// Why the first steps can be left out: after SUMO loads a big net, glibc's malloc sorts the many
// chunks the XML parse freed on the next allocations; on a 95 x 95 grid that is about 50 ms, a
// start-up cost that lands in whatever allocates first (signalsim's set-up, or SUMO's first 20 steps).
// With SIGNALSIM_STEP_CLOCK_SPLIT=1 it also splits the steps after step FROM into SUMO's part and
// the caller's: the wall time (CLOCK_MONOTONIC, a vDSO read of about 30 ns, twice a step) spent inside
// Simulation::step, and the wall time from step FROM to close, added to the line as
//   "in_step_wall": s, "from_wall": s, "close_wall": s
// On an idle machine their ratio is the share of a step's CPU time that is SUMO's own; the reads add
// to the step, so tools/bench takes the step's cost from runs without the split.
// Nothing of signalsim changes: its libsumo module calls libsumo through the dynamic linker, which finds
// these first (a preloaded library comes before the module's own libraries).
#include <dlfcn.h>
#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <string>

// The two libsumo functions, declared as libsumo/Simulation.h declares them (same mangled names).
namespace libsumo {
class Simulation {
 public:
  static void step(const double time);
  static void close(const std::string& reason);
};
}  // namespace libsumo

namespace {

double first_step_cpu = -1.0;
double from_cpu = -1.0;
double close_cpu = -1.0;
long step_calls = 0;
long from_step = 1;
bool split = false;
double in_step_wall = 0.0;
double from_wall = -1.0;
double close_wall = -1.0;

double process_cpu() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double wall() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

template <class Function>
Function next_definition(const char* mangled) {
  void* found = dlsym(RTLD_NEXT, mangled);
  // signalsim loads libsumo with its module (RTLD_LOCAL, src/session/session_factory.hpp): libsumocpp.so is
  // then loaded, but not among the libraries after this one; ask it by name.
  if (void* library = found ? nullptr : dlopen("libsumocpp.so", RTLD_NOW | RTLD_NOLOAD)) found = dlsym(library, mangled);
  if (found == nullptr) {
    std::fprintf(stderr, "signalsim step clock: %s not found after this library (is libsumocpp.so loaded?)\n",
                 mangled);
    std::abort();
  }
  return reinterpret_cast<Function>(found);
}

// Run at exit, after the program's own static destructors (this library was loaded first).
__attribute__((destructor)) void write_clock() {
  const double exit_cpu = process_cpu();
  const char* path = std::getenv("SIGNALSIM_STEP_CLOCK");
  if (path == nullptr || *path == '\0') return;
  if (std::FILE* out = std::fopen(path, "w")) {
    std::fprintf(out,
                 "{\"first_step_cpu\": %.9f, \"from\": %ld, \"from_cpu\": %.9f, \"close_cpu\": %.9f, "
                 "\"exit_cpu\": %.9f, \"step_calls\": %ld",
                 first_step_cpu, from_step, from_cpu, close_cpu, exit_cpu, step_calls);
    if (split)
      std::fprintf(out, ", \"in_step_wall\": %.9f, \"from_wall\": %.9f, \"close_wall\": %.9f", in_step_wall,
                   from_wall, close_wall);
    std::fprintf(out, "}\n");
    std::fclose(out);
  }
}

}  // namespace

void libsumo::Simulation::step(const double time) {
  using Step = void (*)(double);
  static const Step real_step = next_definition<Step>("_ZN7libsumo10Simulation4stepEd");
  if (step_calls++ == 0) {
    first_step_cpu = process_cpu();
    const char* from = std::getenv("SIGNALSIM_STEP_CLOCK_FROM");
    if (from != nullptr && std::atol(from) > 0) from_step = std::atol(from);
    const char* split_wanted = std::getenv("SIGNALSIM_STEP_CLOCK_SPLIT");
    split = split_wanted != nullptr && std::string(split_wanted) == "1";
  }
  if (split && step_calls > from_step) {
    const double started = wall();
    real_step(time);
    in_step_wall += wall() - started;
    return;
  }
  real_step(time);
  if (step_calls == from_step) {
    from_cpu = process_cpu();
    if (split) from_wall = wall();
  }
}

void libsumo::Simulation::close(const std::string& reason) {
  using Close = void (*)(const std::string&);
  static const Close real_close =
      next_definition<Close>("_ZN7libsumo10Simulation5closeERKNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEE");
  close_cpu = process_cpu();
  if (split) close_wall = wall();
  real_close(reason);
}
