// libFuzzer target: ParameterSet::apply_file on arbitrary bytes as an Autoware-style parameter
// file, lenient (as `params.files`) and strict (--strict-params), then the parameter structs every
// module is built from (after check_consistency, as the scenario loader calls it); strict also under
// the name of one of Autoware's files, whose keys data/autoware_keys.yaml lists. Documented
// failures: InputError. Anything else is a finding.
#include <cmath>
#include <cstdint>
#include <filesystem>

#include "fuzz_common.hpp"
#include "scenario/autoware_key_table.hpp"
#include "scenario/input_error.hpp"
#include "scenario/parameters.hpp"
#include "traffic_light/traffic_light_judge.hpp"

namespace {
void check(const std::string& path, bool strict) {
  signalsim::ParameterSet set;
  try {
    set.apply_file(path, strict);
    // The rules between parameters (restart-suppression window, prepare duration) are checked on
    // the final values, after the last apply (parameters.hpp), as load_scenario does.
    set.check_consistency(path);
  } catch (const signalsim::InputError&) {
    return;
  }
  // Strict: a file of no name in the table keeps only signalsim's keys; one of Autoware's names lists
  // only keys Autoware knows in it.
  if (strict)
    for (const signalsim::UnusedParameters& file : set.unused()) {
      const auto& tables = signalsim::autoware_key_tables().files;  // read already: strict listed a key
      const auto entry = tables.find(std::filesystem::path(path).filename().string());
      for (const std::string& key : file.keys) FUZZ_ASSERT(entry != tables.end() && entry->second.knows(key));
    }
  // Whatever the file set, the resolved values are accepted by the modules (no std::invalid_argument
  // from the judge's validate, no bad_variant_access from a getter).
  const signalsim::TrafficLightJudgeParameters tl = signalsim::traffic_light_parameters(set);
  const signalsim::TrafficLightJudge judge(tl);
  const signalsim::TurnSignalParameters decider = signalsim::turn_signal_parameters(set, 3.7);
  (void)signalsim::behavior_parameters(set, decider, 4.5, 1.8);
  for (const auto& [name, value] : set.values()) {
    FUZZ_ASSERT(!set.origin(name).empty());
    if (const double* d = std::get_if<double>(&value)) FUZZ_ASSERT(std::isfinite(*d));
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = signalsim::fuzz::write_file(signalsim::fuzz::work_dir() / "params.param.yaml", data, size);
  check(path, false);
  check(path, true);
  check(signalsim::fuzz::write_file(signalsim::fuzz::work_dir() / "lane_change.param.yaml", data, size), true);
  return 0;
}
