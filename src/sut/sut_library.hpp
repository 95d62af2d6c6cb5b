// The lib: systems under test (docs/decider.md "The C ABI"): a decider or a light judge in a shared
// library with the C ABI of include/signalsim/decider_plugin.h. The run is converted once at start
// (c_abi_values.hpp), each step into reused buffers. A create that fails or a step that returns
// non-zero (or answers a value outside the ABI's) throws SutError naming the SUT and the step.
#pragma once

#include <memory>
#include <string>

#include "sut/c_abi_values.hpp"
#include "sut/plugin_library.hpp"
#include "sut/system_under_test.hpp"

namespace signalsim {

class LibraryDecider final : public BlinkerSut {
 public:
  /// `label`: how messages name it ("lib:./d.so", "autoware_core").
  LibraryDecider(std::shared_ptr<const PluginLibrary> library, const std::string& label);
  ~LibraryDecider() override;
  void start(const SutRun& run) override;
  Blinker decide(const SutStep& step) override;

 private:
  std::shared_ptr<const PluginLibrary> library_;
  std::string who_;  // "decider lib:./d.so"
  std::unique_ptr<CRun> run_;
  CStep step_;
  void* instance_ = nullptr;
  char error_[512] = {};
};

class LibraryLightJudge final : public LightJudgeSut {
 public:
  LibraryLightJudge(std::shared_ptr<const PluginLibrary> library, const std::string& label);
  ~LibraryLightJudge() override;
  void start(const SutRun& run) override;
  std::vector<SutLightAnswer> judge(const SutStep& step) override;

 private:
  std::shared_ptr<const PluginLibrary> library_;
  std::string who_;  // "light_judge lib:./j.so"
  std::unique_ptr<CRun> run_;
  CStep step_;
  std::vector<ss_light_answer> answers_;
  void* instance_ = nullptr;
  char error_[512] = {};
};

}  // namespace signalsim
