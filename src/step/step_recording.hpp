// A run's steps as data (docs/run.md "Recorded steps"): every step's observation, the commands the
// core gave on it and SUMO's feedback, one JSON object per line, so that a core can be replayed
// without SUMO on a real run's inputs and must give the same commands and the same record.
//
//   line 1      {"format": "signalsim-steps", "version": 1, "start_time": s, "arrows": [bool, ...]}
//               (the core's start: SUMO's time, and each approach light's arrow bulbs, in route order)
//   each step   {"observation": {...}, "commands": {...}, "feedback": {...}}
//   last line   {"collisions": n}   (SUMO's count at the end; absent when the run did not finish)
//
// Field names are those of step_ports.hpp; numbers are written so that they read back exactly.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "route/approach_lights.hpp"
#include "step/run_core.hpp"
#include "step/step_core.hpp"

namespace signalsim {

inline constexpr int kStepRecordingVersion = 1;

struct RecordedStep {
  StepObservation observation;
  Commands commands;
  StepFeedback feedback;
};

struct StepRecording {
  std::string source;       ///< where it was read from (messages)
  double start_time = 0.0;  ///< [s] SUMO's time when the core was built
  std::vector<bool> arrows; ///< each approach light's has_arrow, in route order
  std::vector<RecordedStep> steps;
  int collisions = 0;       ///< SUMO's count of the ego's collisions at the end
};

/// Writes the recording's first line for a core built from `setup` (before the core takes it).
void write_recording_header(std::ostream& out, const CoreSetup& setup);

/// A core that passes every call through to `inner` and writes each step to `out`, and the collision
/// count at the end (the header is written before, write_recording_header).
class RecordingCore final : public RunCore {
 public:
  RecordingCore(RunCore& inner, std::ostream& out) : inner_(inner), out_(out) {}
  ObservationDemand demand(const sumo::EgoState& ego) override { return inner_.demand(ego); }
  Commands step(const StepObservation& seen) override;
  bool record(const StepObservation& seen, const StepFeedback& feedback) override;
  RunRecord finish(int collisions) override;

 private:
  RunCore& inner_;
  std::ostream& out_;
  Commands last_;
};

/// Reads a recording (blank lines skipped). Throws InputError naming `source`, the line and the reason.
StepRecording read_step_recording(std::istream& in, const std::string& source);

/// `lights` (the route's approach lights from the net) with the arrow bulbs the recorded run had.
/// Throws InputError when the recording names another number of lights.
std::vector<sumo::ApproachLight> with_recorded_arrows(std::vector<sumo::ApproachLight> lights,
                                                      const StepRecording& recording);

/// What of `want` `seen` does not hold ("" when it holds all): a light, its timing or programs, the
/// lateral offset or the signal mask the core asked for (the leader and lane traffic may be absent).
std::string unrecorded(const ObservationDemand& want, const StepObservation& seen);

/// What a replay gave: the record, the first step whose commands differ from the recording's, and
/// where the core asked for something the recording does not hold (the replay stops there).
struct Replay {
  RunRecord record;
  std::optional<std::size_t> first_different_commands;
  std::size_t steps = 0;  ///< steps replayed until the core said the run is over
  std::string unrecorded; ///< "step N at t s: <what>", empty when every demand was recorded
};

/// Drives `core` on the recorded steps (demand, step, record, as the step loop does), with the
/// recorded collision count at the end.
Replay replay(RunCore& core, const StepRecording& recording);

}  // namespace signalsim
