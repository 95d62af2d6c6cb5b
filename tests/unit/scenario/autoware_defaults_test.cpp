// config/autoware_defaults.yaml against the parameter schema (scenario/parameter_schema.cpp): both
// are written by hand, so this test holds them together. Read as the loader reads it (its nesting
// flattened to dotted names), the file gives every parameter of the schema exactly once, under
// signalsim's name, with the schema's default written in the schema's type, the unit first in its
// comment, and nothing else.
#include <fstream>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "scenario/parameter_keys.hpp"
#include "scenario/parameters.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {
namespace {

const std::string kFile = std::string(SIGNALSIM_SOURCE_DIR) + "/config/autoware_defaults.yaml";

std::vector<FlatParameter> file_parameters() { return document_parameters(load_yaml_file(kFile, "parameter file"), kFile); }

std::vector<std::string> file_lines() {
  std::ifstream in(kFile);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// "" when `value` (as written in the file) is `spec`'s default in `spec`'s type, else why not.
std::string default_problem(const ParameterSpec& spec, const YAML::Node& value) {
  if (!value.IsScalar()) return "not a single value";
  const std::string raw = value.Scalar();
  return std::visit(
      [&](const auto& fallback) -> std::string {
        using T = std::decay_t<decltype(fallback)>;
        T read{};
        if (!YAML::convert<T>::decode(value, read)) return "'" + raw + "' is not of the schema's type";
        if (read != fallback) return "'" + raw + "' is not the schema's default";
        // A ROS 2 parameter's type is its literal's: a double is written with a decimal point, an
        // integer without (Autoware's launch would refuse 50.0 for an integer, 0 for a double).
        const bool decimal = raw.find_first_of(".eE") != std::string::npos;
        if (std::is_same_v<T, double> && !decimal) return "'" + raw + "' reads as an integer; write it as a double";
        if (std::is_same_v<T, int> && decimal) return "'" + raw + "' reads as a double; write it as an integer";
        return "";
      },
      spec.default_value);
}

TEST(AutowareDefaults, EveryParameterOnceWithTheSchemasDefault) {
  std::set<std::string> seen;
  for (const FlatParameter& entry : file_parameters()) {
    const ParameterSpec* spec = find_parameter(entry.name);
    ASSERT_NE(spec, nullptr) << "line " << entry.line << ": '" << entry.name << "' is not in the parameter schema";
    EXPECT_EQ(spec->name, entry.name) << "line " << entry.line << ": written under Autoware's place, not signalsim's name";
    EXPECT_TRUE(seen.insert(spec->name).second) << "line " << entry.line << ": '" << entry.name << "' given twice";
    EXPECT_EQ(default_problem(*spec, entry.value), "") << "line " << entry.line << ": " << entry.name;
  }
  for (const ParameterSpec& spec : parameter_schema())
    EXPECT_TRUE(seen.count(spec.name)) << spec.name << " (in the schema) is missing from " << kFile;
}

TEST(AutowareDefaults, EachCommentStartsWithTheUnit) {
  const std::vector<std::string> lines = file_lines();
  for (const FlatParameter& entry : file_parameters()) {
    const ParameterSpec* spec = find_parameter(entry.name);
    ASSERT_NE(spec, nullptr) << entry.name;
    if (spec->unit == "-") continue;  // true/false, a choice: no unit
    ASSERT_GT(entry.line, 0);
    const std::string& line = lines.at(static_cast<std::size_t>(entry.line - 1));
    const auto hash = line.find('#');
    ASSERT_NE(hash, std::string::npos) << "line " << entry.line << ": " << entry.name << " has no comment with its unit";
    const std::string comment = line.substr(line.find_first_not_of(' ', hash + 1));
    const std::string unit = comment.substr(0, comment.find_first_of(" ,("));
    EXPECT_EQ(unit, spec->unit) << "line " << entry.line << ": " << entry.name;
  }
}

TEST(AutowareDefaults, LoadsStrictlyAndChangesNothing) {
  ParameterSet set;
  ASSERT_NO_THROW(set.apply_file(kFile, /*strict=*/true));
  EXPECT_TRUE(set.unused().empty());
  EXPECT_EQ(set.values(), ParameterSet().values());
  for (const ParameterSpec& spec : parameter_schema())
    EXPECT_EQ(set.origin(spec.name).rfind(kFile + ":", 0), 0u) << spec.name << " from " << set.origin(spec.name);
}

}  // namespace
}  // namespace signalsim
