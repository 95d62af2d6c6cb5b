// The text of a generated scenario file: a comment block saying how it was generated and where every
// expectation's number comes from, then the scenario (docs/scenario.md) with an expect: list.
// SUMO-free, pure; the same inputs give the same bytes.
#pragma once

#include <string>
#include <vector>

#include "core/vehicle_defaults.hpp"
#include "law/expectation_rules.hpp"

namespace signalsim::generate {
using namespace law;  // the rules: sections, speeds, expectations (src/law)

struct ScenarioDraft {
  std::vector<std::string> header;   ///< comment lines (without "# "), before the keys
  std::string name;
  std::string description;
  std::string net;                   ///< path relative to the file
  std::string country;               ///< empty: none (Autoware's defaults)
  double duration = 60.0;            ///< [s]
  std::vector<std::string> route;    ///< edge ids
  double depart_speed = 0.0;         ///< [m/s]
  double max_speed = vehicle_defaults::kMaxSpeed;  ///< [m/s]
  double length = vehicle_defaults::kLength;  ///< [m]
  double base_link_to_front = vehicle_defaults::kBaseLinkToFront;  ///< [m]
  std::vector<GeneratedExpectation> expect;
};

/// A YAML double-quoted scalar (ids may hold ':', '#', ',', ...).
std::string quoted(const std::string& text);

/// One expectation as its `- kind: {...}` list item (without the leading "  - ").
std::string expectation_yaml(const GeneratedExpectation& e);

std::string scenario_text(const ScenarioDraft& draft);

}  // namespace signalsim::generate
