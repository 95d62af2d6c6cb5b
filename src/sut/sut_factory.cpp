// Turning a scenario's SUT names into adapters; see sut_factory.hpp.
#include "sut/sut_factory.hpp"

#include <memory>

#include "scenario/input_error.hpp"
#include "sut/bundled_plugins.hpp"
#include "sut/plugin_crash_note.hpp"
#include "sut/plugin_library.hpp"
#include "sut/sut_library.hpp"
#include "sut/sut_exec.hpp"
#include "sut/sut_traci.hpp"

namespace signalsim {
namespace {

// An exec: adapter, or InputError naming the key when its command cannot be run.
template <typename Adapter>
std::shared_ptr<Adapter> exec_adapter(const Scenario& scenario, const SutSpec& spec, const char* key) {
  try {
    return std::make_shared<Adapter>(spec);
  } catch (const SutProcessError& e) {
    throw key_error(scenario, key, std::string("key '") + key + "': " + spec.text + ": " + e.what());
  }
}

constexpr const char* kAutowareCorePlugin = "libsignalsim_autoware_core.so";

// The library a lib: or autoware_core spec names, loaded and checked for the role. Throws InputError
// naming the scenario file and the key.
std::shared_ptr<const PluginLibrary> load(const Scenario& scenario, const char* key, const SutSpec& spec,
                                          PluginRole role) {
  std::string path = spec.target;
  try {
    if (spec.kind == SutSpec::Kind::AutowareCore) path = bundled_plugin(kAutowareCorePlugin);
    return std::make_shared<const PluginLibrary>(path, role);
  } catch (const PluginLoadError& e) {
    throw key_error(scenario, key, std::string(key) + " '" + spec.text + "': " + e.what());
  }
}

bool is_plugin(const SutSpec& spec) {
  return spec.kind == SutSpec::Kind::Library || spec.kind == SutSpec::Kind::AutowareCore;
}

std::shared_ptr<BlinkerSut> make_decider(const Scenario& scenario) {
  const SutSpec& spec = scenario.decider;
  if (is_plugin(spec))
    return std::make_shared<LibraryDecider>(load(scenario, "decider", spec, PluginRole::Decider), spec.text);
  if (spec.kind == SutSpec::Kind::Exec) return exec_adapter<ExecDecider>(scenario, spec, "decider");
  if (spec.kind == SutSpec::Kind::Traci) return std::make_shared<TraciDecider>();
  throw key_error(scenario, "decider", "decider '" + spec.text + "' is not available in this build");
}

std::shared_ptr<LightJudgeSut> make_light_judge(const Scenario& scenario) {
  const SutSpec& spec = scenario.light_judge;
  if (spec.kind == SutSpec::Kind::Library)
    return std::make_shared<LibraryLightJudge>(load(scenario, "light_judge", spec, PluginRole::LightJudge), spec.text);
  if (spec.kind == SutSpec::Kind::Exec) return exec_adapter<ExecLightJudge>(scenario, spec, "light_judge");
  if (spec.kind == SutSpec::Kind::Traci) return std::make_shared<TraciLightJudge>();
  throw key_error(scenario, "light_judge", "light_judge '" + spec.text + "' is not available in this build");
}

}  // namespace

SystemsUnderTest make_systems_under_test(const Scenario& scenario) {
  SystemsUnderTest suts;
  if (scenario.decider.kind != SutSpec::Kind::Reference) {
    suts.decider_name = scenario.decider.text;
    suts.decider = make_decider(scenario);
  }
  if (scenario.light_judge.kind != SutSpec::Kind::Reference) {
    suts.light_judge_name = scenario.light_judge.text;
    suts.light_judge = make_light_judge(scenario);
  }
  return suts;
}

void check_systems_under_test(const Scenario& scenario) {
  if (is_plugin(scenario.decider) || is_plugin(scenario.light_judge)) keep_stderr_for_crash_notes();
  make_systems_under_test(scenario);  // loads the libraries, finds the commands; starts nothing
}

}  // namespace signalsim
