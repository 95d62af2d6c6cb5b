// The C ABI's values (include/signalsim/decider_plugin.h) made from the SUT values (sut_values.hpp):
// the run once, with storage of its own that lives as long as the plugin instance; each step into
// buffers reused from step to step (a decider's step allocates nothing once the buffers are warm).
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "core/blinker_signals.hpp"
#include <signalsim/decider_plugin.h>
#include "sut/sut_values.hpp"

namespace signalsim {

/// An ss_run and everything it points to, copied from a SutRun (which may go away after start).
class CRun {
 public:
  explicit CRun(const SutRun& run);
  CRun(const CRun&) = delete;  // run_ points into the members
  CRun& operator=(const CRun&) = delete;
  const ss_run& get() const { return run_; }

 private:
  const char* keep(const std::string& text);

  std::deque<std::string> texts_;  // stable addresses
  std::vector<ss_key_value> parameters_;
  std::vector<std::vector<ss_key_value>> tags_;
  std::vector<std::vector<ss_point>> centerlines_;
  std::vector<std::vector<ss_turn_direction>> successors_;
  std::vector<ss_lanelet> lanelets_;
  std::vector<ss_shift_line> shift_lines_;
  ss_run run_{};
};

/// The ss_step of each step: valid until the next fill (its strings point into `step`).
class CStep {
 public:
  const ss_step& fill(const SutStep& step);

 private:
  std::vector<ss_light> lights_;
  std::vector<ss_signal_element> elements_;
  ss_step step_{};
};

ss_turn_direction c_turn_direction(TurnDirection d);
/// The project's blinker for a plugin's answer; false for a value outside ss_blinker.
bool blinker_from_c(int value, Blinker& out);

}  // namespace signalsim
