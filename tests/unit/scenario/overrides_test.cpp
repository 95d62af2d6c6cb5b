// Overrides of a scenario's YAML tree (--set, --params): `key=value` sets, `key+=value` appends to a
// list of the scenario, creating it when missing; += on a parameter or on a value that is no list is
// refused in one line.
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "scenario/input_error.hpp"
#include "scenario/overrides.hpp"
#include "test_files.hpp"

namespace signalsim {
namespace {

using test::error_of;

std::vector<std::string> files_of(const YAML::Node& root) {
  std::vector<std::string> out;
  for (const YAML::Node& f : root["params"]["files"]) out.push_back(f.Scalar());
  return out;
}

TEST(Overrides, AppendingAddsToTheListAfterTheFilesOwn) {
  YAML::Node parameters;
  const YAML::Node root = apply_overrides(YAML::Load("name: s\nparams:\n  files: [a.yaml]\n"),
                                          ScenarioOverrides{{"params.files+=/x/b.yaml", "params.files+=[c.yaml, d.yaml]"}},
                                          parameters);
  EXPECT_EQ(files_of(root), (std::vector<std::string>{"a.yaml", "/x/b.yaml", "c.yaml", "d.yaml"}));
  EXPECT_EQ(parameters.size(), 0u);
}

TEST(Overrides, AppendingCreatesTheListWhenMissing) {
  YAML::Node parameters;
  const YAML::Node root = apply_overrides(YAML::Load("name: s\n"),
                                          ScenarioOverrides{{"params.files+=\"/x/a b #1.yaml\""}}, parameters);
  EXPECT_EQ(files_of(root), (std::vector<std::string>{"/x/a b #1.yaml"}));
}

TEST(Overrides, AppendingRefusesAParameterAndAValueThatIsNoList) {
  YAML::Node parameters;
  EXPECT_EQ(error_of([&] { apply_overrides(YAML::Load("name: s\n"), ScenarioOverrides{{"stop_margin+=1"}}, parameters); }),
            "--set: 'stop_margin+=1': += appends to a list of the scenario, and 'stop_margin' is a parameter");
  EXPECT_EQ(error_of([&] { apply_overrides(YAML::Load("name: s\n"), ScenarioOverrides{{"name+=t"}}, parameters); }),
            "--set: 'name+=t': 'name' is not a list");
  EXPECT_EQ(error_of([&] { apply_overrides(YAML::Load("name: s\n"), ScenarioOverrides{{"+=x"}}, parameters); }),
            "--set: '+=x' is not of the form key=value");
  EXPECT_EQ(error_of([&] { apply_overrides(YAML::Load("name: s\n"), ScenarioOverrides{{"params.files+="}}, parameters); }),
            "--set: 'params.files+=': empty value (write params.files+=VALUE)");
}

}  // namespace
}  // namespace signalsim
