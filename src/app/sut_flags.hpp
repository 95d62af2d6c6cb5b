// --decider, --light-judge and --sut-timeout: the command-line form of the scenario keys `decider:`,
// `light_judge:` and `sut_timeout:` (docs/decider.md "Naming the system under test") for every scenario
// of run, batch, check, compare and sweep. Each becomes an override, so batch workers inherit it; a
// lib: path or an exec: command given here is relative to the current directory (sut_override), not
// to the scenario file. A bad value is refused while the command line is parsed: one line naming the flag.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli_numbers.hpp"
#include "scenario/sut_spec.hpp"

namespace signalsim::app {

/// What the flags named, beside the overrides they add (compare runs its three drivers from them).
struct SutFlags {
  std::string decider;      ///< as given; empty when the flag is absent
  std::string light_judge;  ///< as given; empty when the flag is absent
  bool any() const { return !decider.empty() || !light_judge.empty(); }
};

namespace sut_flags_detail {

// "" when `text` names a SUT for the role, else the reason.
inline std::string problem(const std::string& text, bool light_judge) {
  SutSpec spec;
  const std::string reason = parse_sut_spec(text, std::filesystem::current_path().string(), spec);
  if (!reason.empty()) return reason;
  if (light_judge && spec.kind == SutSpec::Kind::AutowareCore)
    return "autoware_core is a decider (its path_generator has no traffic-light judge)";
  return "";
}

}  // namespace sut_flags_detail

/// Adds the three flags to `sub`; each pushes its override onto `overrides` in command-line order
/// (after or before --set items as given: the later wins) and records its value in `flags`.
inline void add_sut_flags(CLI::App* sub, std::vector<std::string>& overrides, SutFlags& flags) {
  for (const bool judge : {false, true}) {
    const std::string key = judge ? "light_judge" : "decider";
    std::string& named = judge ? flags.light_judge : flags.decider;
    sub->add_option_function<std::string>(
           judge ? "--light-judge" : "--decider",
           [&overrides, &named, key](const std::string& text) {
             named = text;
             overrides.push_back(sut_override(key, text, std::filesystem::current_path().string()));
           },
           judge ? "The traffic-light judge under test for every scenario: reference, traci, lib:PATH.so or "
                   "exec:COMMAND (relative to the current directory; docs/decider.md)"
                 : "The turn-signal decider under test for every scenario: reference, autoware_core, traci, "
                   "lib:PATH.so or exec:COMMAND (relative to the current directory; docs/decider.md)")
        ->check(CLI::Validator(
            [judge](std::string& text) { return sut_flags_detail::problem(text, judge); }, "SUT"));
  }
  sub->add_option_function<std::string>(
         "--sut-timeout", [&overrides](const std::string& text) { overrides.push_back("sut_timeout=" + text); },
         "Seconds a decider or light judge under test may take to answer one step (default 5)")
      ->check(number_between(0.01, 3600.0));
}

}  // namespace signalsim::app
