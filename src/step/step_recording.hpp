// A run's steps as data (docs/run.md "Recorded steps"): every step's observation, the commands the
// core gave on it and SUMO's feedback, one JSON object per line, so that a core can be replayed
// without SUMO on a real run's inputs and must give the same commands and the same record.
//
//   line 1      {"format": "signalsim-steps", "version": 1, "start_time": s}   (the core's start)
//   each step   {"observation": {...}, "commands": {...}, "feedback": {...}}
//
// Field names are those of step_ports.hpp; numbers are written so that they read back exactly.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "step/run_core.hpp"

namespace signalsim {

inline constexpr int kStepRecordingVersion = 1;

struct RecordedStep {
  StepObservation observation;
  Commands commands;
  StepFeedback feedback;
};

struct StepRecording {
  double start_time = 0.0;  ///< [s] SUMO's time when the core was built
  std::vector<RecordedStep> steps;
};

/// A core that passes every call through to `inner` and writes each step to `out` (header first).
class RecordingCore final : public RunCore {
 public:
  RecordingCore(RunCore& inner, std::ostream& out, double start_time);
  ObservationDemand demand(const sumo::EgoState& ego) override { return inner_.demand(ego); }
  Commands step(const StepObservation& seen) override;
  bool record(const StepObservation& seen, const StepFeedback& feedback) override;
  RunRecord finish(int collisions) override { return inner_.finish(collisions); }

 private:
  RunCore& inner_;
  std::ostream& out_;
  Commands last_;
};

/// Reads a recording. Throws InputError naming `source`, the line and the reason.
StepRecording read_step_recording(std::istream& in, const std::string& source);

/// What a replay gave: the record, and the first step whose commands differ from the recording's.
struct Replay {
  RunRecord record;
  std::optional<std::size_t> first_different_commands;
  std::size_t steps = 0;  ///< steps replayed until the core said the run is over
};

/// Drives `core` on the recorded steps (demand, step, record, as the step loop does), with the
/// recorded collision count at the end.
Replay replay(RunCore& core, const StepRecording& recording, int collisions = 0);

}  // namespace signalsim
