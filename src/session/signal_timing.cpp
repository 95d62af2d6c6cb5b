#include "session/signal_timing.hpp"

namespace signalsim::sumo {

ProgramKind program_kind_of(int traci_type) {
  switch (traci_type) {
    case 0: return ProgramKind::Static;      // TRAFFICLIGHT_TYPE_STATIC
    case 3: return ProgramKind::Actuated;    // TRAFFICLIGHT_TYPE_ACTUATED
    case 4: return ProgramKind::DelayBased;  // TRAFFICLIGHT_TYPE_DELAYBASED
    default: return ProgramKind::Other;
  }
}

int static_successor(const LightProgram& program, int phase) {
  const int n = static_cast<int>(program.phases.size());
  if (phase < 0 || phase >= n) return -1;
  const std::vector<int>& next = program.phases[static_cast<std::size_t>(phase)].next;
  // MSSimpleTrafficLightLogic::trySwitch: the first `next` entry, else the following phase.
  int k = !next.empty() && next.front() >= 0 ? next.front() : phase + 1;
  if (k >= n) k = 0;
  return k;
}

namespace {

// The phase a non-static logic switches to when it switches, if that is known: a single `next`
// target, or none (the following phase). Several targets: chosen by demand, unknown (-1).
int known_successor(const LightProgram& program, int phase) {
  const int n = static_cast<int>(program.phases.size());
  const std::vector<int>& next = program.phases[static_cast<std::size_t>(phase)].next;
  if (next.size() > 1 && next.front() >= 0) return -1;
  const int k = next.size() == 1 && next.front() >= 0 ? next.front() : (phase + 1) % n;
  return k < n ? k : -1;
}

}  // namespace

std::vector<PhasePrediction> predict_phases(const LightProgram& program, int current_phase, double next_switch) {
  std::vector<PhasePrediction> out;
  const int n = static_cast<int>(program.phases.size());
  if (current_phase < 0 || current_phase >= n) return out;
  if (program.kind != ProgramKind::Static) {
    const int k = known_successor(program, current_phase);
    if (k >= 0) out.push_back({next_switch, k, program.phases[static_cast<std::size_t>(k)].state});
    return out;
  }
  // Static: one cycle, each phase once (a `next` chain may skip phases or loop early).
  double t = next_switch;
  int k = static_successor(program, current_phase);
  for (int i = 0; i < n && k >= 0; ++i) {
    const LightPhase& phase = program.phases[static_cast<std::size_t>(k)];
    out.push_back({t, k, phase.state});
    if (k == current_phase) break;  // the cycle is complete
    t += phase.duration;
    k = static_successor(program, k);
  }
  return out;
}

const LightProgram* find_program(const std::vector<LightProgram>& programs, const std::string& id) {
  for (const LightProgram& p : programs)
    if (p.id == id) return &p;
  return nullptr;
}

}  // namespace signalsim::sumo
