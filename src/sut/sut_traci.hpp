// The traci systems under test (docs/decider.md "Another TraCI client"): a decider or light judge that
// is another TraCI client of the same SUMO (--connect). The decider's blinker is the ego's signal mask
// as that client set it (Vehicle::setSignals), read at signalsim's turn of the step's round; the
// light judge's answers are ego parameters it set (Vehicle::setParameter), one per light:
// kTraciLightParameterPrefix + the light's id, "stop" or "go", optionally ":" and a reason.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sut/system_under_test.hpp"

namespace signalsim {

/// The ego parameter that carries a traci light judge's answer for a light: this prefix + its tls id.
inline constexpr const char* kTraciLightParameterPrefix = "signalsim.light.";
/// The reason recorded for a light whose parameter was never set (the answer is then go).
inline constexpr const char* kTraciUnanswered = "unanswered";

class TraciDecider final : public BlinkerSut {
 public:
  void start(const SutRun& run) override { (void)run; }
  /// The blinker SutStep::sumo_signals shows (core/blinker_signals.hpp blinker_of_signals: hazard for
  /// the emergency bit or both direction bits); none when the mask was not read.
  Blinker decide(const SutStep& step) override;
  bool reads_sumo_signals() const override { return true; }
};

class TraciLightJudge final : public LightJudgeSut {
 public:
  void start(const SutRun& run) override { (void)run; }
  /// One answer per light from the ego parameters read this step: "stop" or "go" (with an optional
  /// ":REASON"); a parameter never set is go with reason kTraciUnanswered. Throws SutError naming
  /// the light, the parameter and its value for any other value.
  std::vector<SutLightAnswer> judge(const SutStep& step) override;
  /// kTraciLightParameterPrefix + tls id for each light of step.lights (each id once, in order).
  std::vector<std::string> ego_parameters(const SutStep& step) const override;
};

/// A light judge's answer as text: "stop" or "go", optionally ":" and a reason; "" (never set) is go
/// with reason kTraciUnanswered. Empty optional for any other text.
std::optional<SutLightAnswer> parse_traci_light_answer(const std::string& value);

}  // namespace signalsim
