// Which implementations made a golden events file of `signalsim check` (docs/batch.md "Golden files
// of a system under test"): DIR/<stem>.events.csv holds the events of the decider and light judge that
// ran, so a golden file made with a SUT is kept with a side file DIR/<stem>.suts.json naming them as
// given ({"decider": "lib:build/my.so", "light_judge": "reference"}). No side file: both were the
// reference. `check` compares the run's pair (summary.json "decider"/"light_judge" names) with it
// before comparing events: a different pair fails the case.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace signalsim {

struct GoldenSuts {
  std::string decider = "reference";
  std::string light_judge = "reference";
  bool operator==(const GoldenSuts&) const = default;
};

/// DIR/<stem>.suts.json beside DIR/<stem>.events.csv (`golden_events` is the latter's path).
std::string golden_suts_path(const std::string& golden_events);

/// The implementations of a finished run, from its summary.json.
GoldenSuts run_suts(const nlohmann::ordered_json& summary);

/// The golden file's (the reference pair without a side file). Throws std::runtime_error for a side
/// file that is not a JSON object of texts.
GoldenSuts read_golden_suts(const std::string& golden_events);

/// Writes the side file for a SUT pair, removes it for the reference pair (--update).
void write_golden_suts(const std::string& golden_events, const GoldenSuts& suts);

/// "decider lib:x.so, light_judge reference".
std::string describe(const GoldenSuts& suts);

}  // namespace signalsim
