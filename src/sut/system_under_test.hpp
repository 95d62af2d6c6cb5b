// The systems under test (docs/decider.md): a user's turn-signal decider and traffic-light judge in
// the loop in place of signalsim's own, which then run in shadow as the reference. One interface per
// role; the adapters are lib: (a C ABI plugin, sut_library.hpp), exec: (a JSON-lines process,
// sut_process.hpp), traci (another TraCI client's settings on the ego, sut_traci.hpp) and the bundled
// autoware_core plugin. A SUT that fails (a crash, a reply that is not one, a timeout) throws
// SutError: the run ends as an error naming the SUT and the step.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "sut/sut_values.hpp"

namespace signalsim {

/// A SUT failed; the message names the SUT and the step ("decider exec:python3 d.py at t=12.30 s: ...").
class SutError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class BlinkerSut {
 public:
  virtual ~BlinkerSut() = default;
  /// Before SUMO starts, with the run's output folder: an exec: process starts here, so that its own
  /// start-up overlaps SUMO's. Throws SutError.
  virtual void launch(const std::string& out_dir) { (void)out_dir; }
  /// Before the first step (the C ABI's create, JSON lines' hello; launches first if not launched).
  /// Throws SutError.
  virtual void start(const SutRun& run) = 0;
  /// After the last step (JSON lines' bye). Throws SutError.
  virtual void finish() {}
  /// The blinker for this step. Throws SutError.
  virtual Blinker decide(const SutStep& step) = 0;
  /// Reads the ego's SUMO signal mask (SutStep::sumo_signals) instead of commanding it (traci).
  virtual bool reads_sumo_signals() const { return false; }
};

class LightJudgeSut {
 public:
  virtual ~LightJudgeSut() = default;
  virtual void launch(const std::string& out_dir) { (void)out_dir; }  ///< as BlinkerSut::launch
  virtual void start(const SutRun& run) = 0;
  virtual void finish() {}
  /// One answer per light of step.lights, in that order. Throws SutError.
  virtual std::vector<SutLightAnswer> judge(const SutStep& step) = 0;
  /// The ego parameters this judge reads from SUMO each step (traci: one per light of the window).
  virtual std::vector<std::string> ego_parameters(const SutStep& step) const {
    (void)step;
    return {};
  }
};

/// The SUTs of one run: empty pointers run signalsim's own modules (the reference) alone. Shared so that
/// a core's setup can be copied (a replay builds a second core); a SUT serves one core at a time.
struct SystemsUnderTest {
  std::shared_ptr<BlinkerSut> decider;
  std::shared_ptr<LightJudgeSut> light_judge;
  std::string decider_name;      ///< the spec as given ("exec:python3 d.py"), "" for the reference
  std::string light_judge_name;
};

}  // namespace signalsim
