// The traci systems under test; see sut_traci.hpp.
#include "sut/sut_traci.hpp"

#include <algorithm>
#include <cstdio>

namespace signalsim {

Blinker TraciDecider::decide(const SutStep& step) {
  const int mask = step.sumo_signals.value_or(0);
  return mask < 0 ? Blinker::None : blinker_of_signals(mask);
}

std::vector<std::string> TraciLightJudge::ego_parameters(const SutStep& step) const {
  std::vector<std::string> keys;
  for (const SutLight& light : step.lights) {
    std::string key = kTraciLightParameterPrefix + light.tls_id;
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(std::move(key));
  }
  return keys;
}

std::optional<SutLightAnswer> parse_traci_light_answer(const std::string& value) {
  if (value.empty()) return SutLightAnswer{false, kTraciUnanswered};
  const std::size_t colon = value.find(':');
  const std::string word = value.substr(0, colon);
  if (word != "stop" && word != "go") return std::nullopt;
  return SutLightAnswer{word == "stop", colon == std::string::npos ? std::string() : value.substr(colon + 1)};
}

std::vector<SutLightAnswer> TraciLightJudge::judge(const SutStep& step) {
  std::vector<SutLightAnswer> answers;
  for (const SutLight& light : step.lights) {
    const std::string key = kTraciLightParameterPrefix + light.tls_id;
    const auto read = std::find_if(step.ego_parameters.begin(), step.ego_parameters.end(),
                                   [&](const auto& p) { return p.first == key; });
    const std::string value = read == step.ego_parameters.end() ? std::string() : read->second;
    const std::optional<SutLightAnswer> answer = parse_traci_light_answer(value);
    if (!answer) {
      char at[48];
      std::snprintf(at, sizeof at, "at t=%.2f s", step.time);
      throw SutError("light_judge traci " + std::string(at) + ": the ego's parameter " + key + " is '" + value +
                     "', not stop or go (optionally followed by :REASON)");
    }
    answers.push_back(*answer);
  }
  return answers;
}

}  // namespace signalsim
