// The exec: adapters (docs/decider.md "JSON lines"): a decider or light judge that is an external
// process speaking JSON lines. The command is split and its program found when the adapter is made
// (before the run's first step); the process is launched before SUMO starts, gets hello before the
// first step, answers one line per step and ends after bye. Every fault is a SutError naming the SUT
// and the step.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scenario/sut_spec.hpp"
#include "sut/sut_process.hpp"
#include "sut/system_under_test.hpp"

namespace signalsim {

/// The process of one role, as the adapters share it.
class ExecChannel {
 public:
  /// `role` "decider" or "light_judge"; throws SutProcessError when the command has no program.
  ExecChannel(const SutSpec& spec, std::string role);
  /// Spawns the process (stderr to <out_dir>/<role>.stderr.txt).
  void launch(const std::string& out_dir);
  /// Sends hello (launching first when launch was not called).
  void start(const SutRun& run);
  /// Sends a step and returns its reply line.
  std::string exchange(const SutStep& step);
  /// Sends bye and waits for the end.
  void finish();
  /// A SutError naming the SUT and the moment ("decider exec:python3 d.py at t=12.30 s: <reason>").
  SutError error(const std::string& when, const std::string& reason) const;
  std::string step_when(const SutStep& step) const;

 private:
  SutSpec spec_;
  std::string role_;
  std::vector<std::string> argv_;
  std::string program_;
  double timeout_ = 5.0;
  const RouteMap* route_ = nullptr;
  std::unique_ptr<SutProcess> process_;
  std::string last_step_;  // when the last reply was read ("" before any)
};

class ExecDecider final : public BlinkerSut {
 public:
  explicit ExecDecider(const SutSpec& spec) : channel_(spec, "decider") {}
  void launch(const std::string& out_dir) override { channel_.launch(out_dir); }
  void start(const SutRun& run) override { channel_.start(run); }
  void finish() override { channel_.finish(); }
  Blinker decide(const SutStep& step) override;

 private:
  ExecChannel channel_;
};

class ExecLightJudge final : public LightJudgeSut {
 public:
  explicit ExecLightJudge(const SutSpec& spec) : channel_(spec, "light_judge") {}
  void launch(const std::string& out_dir) override { channel_.launch(out_dir); }
  void start(const SutRun& run) override { channel_.start(run); }
  void finish() override { channel_.finish(); }
  std::vector<SutLightAnswer> judge(const SutStep& step) override;

 private:
  ExecChannel channel_;
};

}  // namespace signalsim
