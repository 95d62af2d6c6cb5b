// libFuzzer target: load_scenario on arbitrary bytes (the file's text), with optional `--set`
// overrides. The bytes after a line "#%set" are the overrides, one "key=value" per line.
// Documented failures: InputError (scenario/input_error.hpp). Anything else is a finding.
//
// The file is written to work_dir()/scenarios/fuzz.yaml (fuzz_common.hpp) beside links to the
// repository's config/, sumo_nets/ and scenarios/lights/, so the bundled scenarios' relative paths
// (the corpus) resolve.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "fuzz_common.hpp"
#include "scenario/input_error.hpp"
#include "scenario/scenario.hpp"

namespace fs = std::filesystem;

namespace {
const std::string& scenario_path() {
  static const std::string path = [] {
    const fs::path root = signalsim::fuzz::work_dir();
    fs::create_directories(root / "scenarios");
    const fs::path src = SIGNALSIM_SOURCE_DIR;
    std::error_code ec;
    fs::create_directory_symlink(src / "config", root / "config", ec);
    fs::create_directory_symlink(src / "sumo_nets", root / "sumo_nets", ec);
    fs::create_directory_symlink(src / "scenarios" / "lights", root / "scenarios" / "lights", ec);
    return (root / "scenarios" / "fuzz.yaml").string();
  }();
  return path;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kSetMarker = "\n#%set\n";
  const std::size_t marker = bytes.find(kSetMarker);
  signalsim::ScenarioOverrides overrides;
  std::size_t text_size = size;
  if (marker != std::string_view::npos) {
    text_size = marker;
    std::string_view rest = bytes.substr(marker + kSetMarker.size());
    while (!rest.empty()) {
      const std::size_t nl = rest.find('\n');
      overrides.set.emplace_back(rest.substr(0, nl));
      rest = nl == std::string_view::npos ? std::string_view{} : rest.substr(nl + 1);
    }
  }
  const std::string path = signalsim::fuzz::write_file(scenario_path(), data, text_size);
  try {
    const signalsim::Scenario s = signalsim::load_scenario(path, overrides);
    FUZZ_ASSERT(s.step_length > 0.0);
    FUZZ_ASSERT(s.duration / s.step_length <= 2e6);
    FUZZ_ASSERT(s.ego.base_link_to_front <= s.ego.length);
  } catch (const signalsim::InputError&) {
  }
  return 0;
}
