// SUMO's light programs as plain values, and what they let V2I predict (docs/behaviour.md §L1.7): from the
// program's phases, the current phase and SUMO's next switch (TrafficLight::getNextSwitch), the
// phases to come with the times they come on. No libsumo here: the session (sumo_session.hpp) reads
// the programs once per light and the timing every step; this file only computes.
//
// What SUMO can tell (read in SUMO's source, MSTrafficLightLogic::getNextSwitchTime: the time of the
// logic's next scheduled SwitchCommand, i.e. the next call of trySwitch):
//  - static: trySwitch always switches, to `next` (its first entry) or else to the following phase,
//    and every phase lasts its `duration`. The next switch is exact (also after setPhaseDuration, as
//    light_offsets do), and so is the whole cycle: one cycle of phases is predicted.
//  - actuated, delay_based (and any other non-static type, e.g. NEMA): at the next switch the
//    controller decides (MSActuatedTrafficLightLogic::trySwitch): a green phase with detected traffic
//    may be extended (gap control, up to maxDur) and a phase with several `next` targets picks one
//    by demand. So only the next switch is predicted, as the earliest time the next phase can come
//    on, and only when that phase is known (one `next` target, or none: the following phase);
//    nothing beyond it, which depends on detectors.
#pragma once

#include <string>
#include <vector>

namespace signalsim::sumo {

/// One phase of a program (libsumo TraCIPhase).
struct LightPhase {
  double duration = 0.0;   ///< [s]
  std::string state;       ///< one character per link index
  std::vector<int> next;   ///< SUMO's `next` phase indices (empty: the following phase)
};

/// How SUMO runs a program (libsumo TraCILogic::type).
enum class ProgramKind { Static, Actuated, DelayBased, Other };

/// libsumo's TRAFFICLIGHT_TYPE_* value -> ProgramKind (0 static, 3 actuated, 4 delay_based).
ProgramKind program_kind_of(int traci_type);

/// One program SUMO loaded for a light (TrafficLight::getAllProgramLogics).
struct LightProgram {
  std::string id;
  ProgramKind kind = ProgramKind::Static;
  std::vector<LightPhase> phases;
};

/// A light's live timing (TrafficLight::getProgram, getPhase, getNextSwitch).
struct LightTiming {
  std::string program;      ///< the running program's id
  int phase = -1;           ///< index of the current phase
  double next_switch = 0.0; ///< [s] absolute simulation time of the next switch
};

/// A phase predicted to come on at `stamp`.
struct PhasePrediction {
  double stamp = 0.0;  ///< [s] absolute
  int phase = -1;      ///< its index in the program
  std::string state;   ///< its link states

  friend bool operator==(const PhasePrediction&, const PhasePrediction&) = default;
};

/// The phase a static program switches to after `phase`: next[0] when given and >= 0, else the
/// following one (wrapping to 0). -1 for an index out of range.
int static_successor(const LightProgram& program, int phase);

/// The phases to come (rules at the top of this file), in time order: for a static program one
/// cycle (each phase once, ending with the current phase's return); for any other kind the next
/// phase at `next_switch` if it is known, else nothing. Empty for an empty program or a current phase
/// out of range. Never throws.
std::vector<PhasePrediction> predict_phases(const LightProgram& program, int current_phase, double next_switch);

/// The program with id `id` among `programs`, or nullptr.
const LightProgram* find_program(const std::vector<LightProgram>& programs, const std::string& id);

}  // namespace signalsim::sumo
