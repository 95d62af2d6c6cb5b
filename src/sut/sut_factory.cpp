// Turning a scenario's SUT names into adapters; see sut_factory.hpp.
#include "sut/sut_factory.hpp"

#include "scenario/input_error.hpp"
#include "sut/sut_exec.hpp"

namespace signalsim {
namespace {

// An exec: adapter, or InputError naming the key when its command cannot be run.
template <typename Adapter>
std::shared_ptr<Adapter> exec_adapter(const Scenario& scenario, const SutSpec& spec, const char* key) {
  try {
    return std::make_shared<Adapter>(spec);
  } catch (const SutProcessError& e) {
    throw InputError(scenario.path, 0, std::string("key '") + key + "': " + spec.text + ": " + e.what());
  }
}

}  // namespace

SystemsUnderTest make_systems_under_test(const Scenario& scenario) {
  SystemsUnderTest suts;
  if (scenario.decider.kind != SutSpec::Kind::Reference) {
    suts.decider_name = scenario.decider.text;
    if (scenario.decider.kind == SutSpec::Kind::Exec)
      suts.decider = exec_adapter<ExecDecider>(scenario, scenario.decider, "decider");
    else
      throw InputError(scenario.path, 0, "decider '" + scenario.decider.text + "' is not available in this build");
  }
  if (scenario.light_judge.kind != SutSpec::Kind::Reference) {
    suts.light_judge_name = scenario.light_judge.text;
    if (scenario.light_judge.kind == SutSpec::Kind::Exec)
      suts.light_judge = exec_adapter<ExecLightJudge>(scenario, scenario.light_judge, "light_judge");
    else
      throw InputError(scenario.path, 0, "light_judge '" + scenario.light_judge.text + "' is not available in this build");
  }
  return suts;
}

}  // namespace signalsim
