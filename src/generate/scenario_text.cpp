// The YAML text of a generated scenario.
#include "generate/scenario_text.hpp"

#include <sstream>

#include "core/number_text.hpp"

namespace signalsim::generate {

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string expectation_yaml(const GeneratedExpectation& e) {
  using Kind = GeneratedExpectation::Kind;
  switch (e.kind) {
    case Kind::ThroughJunction:
      return "blinker_through_junction: {junction: " + quoted(e.target) + ", blinker: " + e.blinker +
             ", lead: " + rounded_fixed(e.lead, 1) + "}";
    case Kind::ThroughLanelet:
      return "blinker_through_lanelet: {lanelet: " + quoted(e.target) + ", blinker: " + e.blinker +
             ", lead: " + rounded_fixed(e.lead, 1) + "}";
    case Kind::BlinkerOn:
      return "blinker_on: {blinker: " + e.blinker + ", from_s: " + rounded_fixed(e.from_s, 1) +
             ", to_s: " + rounded_fixed(e.to_s, 1) + "}";
    case Kind::NoBlinker:
      return "no_blinker: {from_s: " + rounded_fixed(e.from_s, 1) + ", to_s: " + rounded_fixed(e.to_s, 1) + "}";
    case Kind::BlinkerNever: return "blinker_never: " + e.blinker;
    case Kind::NeverRunsRed: return "never_runs_red: true";
    case Kind::Arrives: break;
  }
  return "arrives: true";
}

std::string scenario_text(const ScenarioDraft& d) {
  std::ostringstream out;
  for (const std::string& line : d.header) out << (line.empty() ? "#" : "# " + line) << "\n";
  out << "# Expectations and where their numbers come from:\n";
  for (std::size_t i = 0; i < d.expect.size(); ++i)
    out << "#   expect[" << i << "] " << expectation_yaml(d.expect[i]) << ": " << d.expect[i].why << "\n";
  out << "name: " << quoted(d.name) << "\n";
  out << "description: " << quoted(d.description) << "\n";
  out << "net: " << quoted(d.net) << "\n";
  out << "step_length: " << rounded_fixed(kStepLength, 1) << "\n";
  out << "duration: " << rounded_fixed(d.duration, 0) << "\n";
  out << "seed: 1\n";
  if (!d.country.empty()) out << "country: " << d.country << "\n";
  out << "ego:\n";
  out << "  route: [";
  for (std::size_t i = 0; i < d.route.size(); ++i) out << (i ? ", " : "") << quoted(d.route[i]);
  out << "]\n";
  out << "  depart_pos: 0\n";
  out << "  depart_speed: " << rounded_fixed(d.depart_speed, 1) << "\n";
  out << "  max_speed: " << rounded_fixed(d.max_speed, 2) << "\n";
  out << "  length: " << rounded_fixed(d.length, 1) << "\n";
  out << "  base_link_to_front: " << rounded_fixed(d.base_link_to_front, 1) << "\n";
  out << "expect:\n";
  for (const GeneratedExpectation& e : d.expect) out << "  - " << expectation_yaml(e) << "\n";
  return out.str();
}

}  // namespace signalsim::generate
