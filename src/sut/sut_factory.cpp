// Turning a scenario's SUT names into adapters; see sut_factory.hpp.
#include "sut/sut_factory.hpp"

#include "scenario/input_error.hpp"

namespace signalsim {

SystemsUnderTest make_systems_under_test(const Scenario& scenario) {
  SystemsUnderTest suts;
  if (scenario.decider.kind != SutSpec::Kind::Reference) {
    suts.decider_name = scenario.decider.text;
    throw InputError(scenario.path, 0, "decider '" + scenario.decider.text + "' is not available in this build");
  }
  if (scenario.light_judge.kind != SutSpec::Kind::Reference) {
    suts.light_judge_name = scenario.light_judge.text;
    throw InputError(scenario.path, 0, "light_judge '" + scenario.light_judge.text + "' is not available in this build");
  }
  return suts;
}

}  // namespace signalsim
