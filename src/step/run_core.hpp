// The logic of one run between SUMO's ports (docs/architecture.md "The step as a system"): the part
// of a run that reads nothing from SUMO and writes nothing to it. Each step the loop (sim/step_loop)
//   1. reads the ego and asks the core what else the step needs     demand(ego)
//   2. reads exactly that                                              sim/session_ports observe
//   3. hands the observation to the core, which decides               step(observation) -> Commands
//   4. writes the commands and advances SUMO one step                 sim/session_ports apply
//   5. hands what SUMO said back to the core, which records the row    record(observation, feedback)
// until record says the run is over. Two cores: StepCore (signalsim drives, step_core.hpp) and
// SumoDrivenCore (SUMO drives and signalsim observes, sumo_driven_core.hpp). A recorded sequence
// of observations and feedback replays a core without SUMO (step/step_recording.hpp).
#pragma once

#include "report/timeline.hpp"
#include "session/sumo_session.hpp"
#include "step/step_ports.hpp"

namespace signalsim {

class RunCore {
 public:
  virtual ~RunCore() = default;
  /// The first half of a step: the ego as SUMO reports it at the step's start; returns what the
  /// step reads of SUMO besides the ego.
  virtual ObservationDemand demand(const sumo::EgoState& ego) = 0;
  /// The step's decisions on the observation demand() asked for (its `ego` is the one passed there).
  virtual Commands step(const StepObservation& seen) = 0;
  /// The step's row and what follows from it, once SUMO has executed the commands. Returns true when
  /// the run is over (arrived, stuck, or out of time).
  virtual bool record(const StepObservation& seen, const StepFeedback& feedback) = 0;
  /// The record, completed with SUMO's count of the ego's collisions. Call once, after the last step.
  virtual RunRecord finish(int collisions) = 0;
};

}  // namespace signalsim
