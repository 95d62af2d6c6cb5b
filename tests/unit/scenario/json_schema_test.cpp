// The JSON Schemas `signalsim schema scenario|sweep` prints: draft-07 JSON, the same text every time,
// every key of the key tables with its type, default and range, every parameter under each of its
// spellings with the parameter schema's default and range, and the sweep's `--set` keys.
#include <cmath>
#include <algorithm>
#include <string>
#include <utility>
#include <variant>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "batch/sweep_keys.hpp"
#include "scenario/json_schema.hpp"
#include "scenario/parameters.hpp"
#include "scenario/scenario_keys.hpp"

namespace signalsim {
namespace {

using nlohmann::json;

json scenario_schema() { return json::parse(schema_text(schema_document(scenario_keys(), "scenario"))); }
json sweep_schema() { return json::parse(schema_text(schema_document(sweep_keys(), "sweep"))); }

// "#/definitions/x" -> the definition x of `doc`.
const json& resolve(const json& doc, const json& schema) {
  if (!schema.contains("$ref")) return schema;
  const std::string ref = schema["$ref"];
  return doc["definitions"].at(ref.substr(std::string("#/definitions/").size()));
}

// Each key of `table` is a property of `schema` of the table's shape, default and range.
void expect_table(const json& schema, const KeyTable& table) {
  ASSERT_TRUE(schema.contains("properties")) << table.where;
  EXPECT_EQ(schema["additionalProperties"], false) << table.where;
  EXPECT_EQ(schema["properties"].size(), table.keys.size()) << table.where;
  for (const KeySpec& key : table.keys) {
    const std::string name = table.where + "." + key.name;
    ASSERT_TRUE(schema["properties"].contains(key.name)) << name;
    const json& p = schema["properties"][key.name];
    EXPECT_TRUE(p.contains("description")) << name;
    const bool required = schema.contains("required") &&
                          std::find(schema["required"].begin(), schema["required"].end(), key.name) != schema["required"].end();
    EXPECT_EQ(required, key.required) << name;
    switch (key.type) {
      case KeyType::Number:
      case KeyType::Integer:
        EXPECT_EQ(p["type"], key.type == KeyType::Number ? "number" : "integer") << name;
        if (std::isfinite(key.min)) {
          EXPECT_DOUBLE_EQ(p["minimum"].get<double>(), key.min) << name;
        }
        if (std::isfinite(key.max)) {
          EXPECT_DOUBLE_EQ(p["maximum"].get<double>(), key.max) << name;
        }
        if (key.default_number && *key.default_number >= key.min && *key.default_number <= key.max)
          EXPECT_DOUBLE_EQ(p["default"].get<double>(), *key.default_number) << name;
        else
          EXPECT_FALSE(p.contains("default")) << name << ": a sentinel or computed default is said in words";
        break;
      case KeyType::Text:
        if (!key.choices.empty()) {
          EXPECT_EQ(p["enum"], json(key.choices)) << name;
        }
        if (key.default_text) {
          EXPECT_EQ(p["default"], *key.default_text) << name;
        }
        break;
      case KeyType::Mapping:
        expect_table(p, *key.table);
        break;
      case KeyType::MappingList:
        expect_table(p["items"], *key.table);
        break;
      case KeyType::KindList:
        EXPECT_EQ(p["items"]["maxProperties"], 1) << name;
        for (const KeySpec& kind : key.table->keys) {
          ASSERT_TRUE(p["items"]["properties"].contains(kind.name)) << name << " " << kind.name;
          if (kind.table) expect_table(p["items"]["properties"][kind.name], *kind.table);
        }
        break;
      default:
        break;
    }
  }
}

TEST(JsonSchema, IsDraft07JsonAndTheSameEveryTime) {
  for (const auto& [top, title] : {std::pair{&scenario_keys(), "scenario"}, std::pair{&sweep_keys(), "sweep"}}) {
    const std::string text = schema_text(schema_document(*top, title));
    EXPECT_EQ(text, schema_text(schema_document(*top, title)));
    const json doc = json::parse(text);  // throws on invalid JSON
    EXPECT_EQ(doc["$schema"], "http://json-schema.org/draft-07/schema#");
    EXPECT_EQ(doc["type"], "object");
    EXPECT_EQ(text.back(), '\n');
  }
}

TEST(JsonSchema, HoldsEveryScenarioKeyWithItsShapeDefaultAndRange) {
  const json doc = scenario_schema();
  expect_table(doc, scenario_keys());
  EXPECT_EQ(doc["allOf"][0]["anyOf"][1]["required"][0], "sumocfg");  // net or sumocfg
  EXPECT_EQ(doc["allOf"][1]["anyOf"][0]["required"][0], "ego");      // ego, or fleet without one
  EXPECT_EQ(doc["allOf"][1]["anyOf"][1]["required"][0], "fleet");
  EXPECT_EQ(doc["properties"]["maneuvers"]["items"]["properties"]["lane_change"]["dependencies"]["to_lane"][0], "edge");
}

TEST(JsonSchema, HoldsEverySweepKey) { expect_table(sweep_schema(), sweep_keys()); }

TEST(JsonSchema, EveryParameterUnderEachSpellingWithItsDefaultAndRange) {
  const json doc = scenario_schema();
  const json& tree = doc["definitions"]["parameters"];
  for (const ParameterSpec& spec : parameter_schema()) {
    const json& leaf = doc["definitions"]["parameter." + spec.name];
    std::visit(
        [&](const auto& value) {
          using T = std::decay_t<decltype(value)>;
          EXPECT_EQ(leaf["default"].get<T>(), value) << spec.name;
          if constexpr (std::is_same_v<T, int> || std::is_same_v<T, double>) {
            EXPECT_DOUBLE_EQ(leaf["minimum"].get<double>(), spec.min) << spec.name;
            EXPECT_DOUBLE_EQ(leaf["maximum"].get<double>(), spec.max) << spec.name;
          }
        },
        spec.default_value);
    if (!spec.choices.empty()) {
      EXPECT_EQ(leaf["enum"], json(spec.choices)) << spec.name;
    }
    for (const std::string& name : {spec.name, spec.autoware_key}) {
      if (name.empty()) continue;
      // Dotted as one key, and nested one level per dot.
      EXPECT_EQ(resolve(doc, tree["properties"][name]), leaf) << name;
      const json* level = &tree;
      std::string rest = name;
      for (std::size_t dot; (dot = rest.find('.')) != std::string::npos; rest = rest.substr(dot + 1)) {
        ASSERT_TRUE((*level)["properties"].contains(rest.substr(0, dot))) << name;
        level = &(*level)["properties"][rest.substr(0, dot)];
      }
      EXPECT_EQ(resolve(doc, (*level)["properties"][rest]), leaf) << name;
    }
  }
}

TEST(JsonSchema, TheSweepsSetKeysAreScenarioPathsAndParameterNames) {
  const json doc = sweep_schema();
  const json& values = doc["definitions"]["override_values"];
  const json& lists = doc["definitions"]["override_lists"];
  EXPECT_EQ(values["additionalProperties"], false);
  EXPECT_DOUBLE_EQ(resolve(doc, values["properties"]["ego.max_speed"])["maximum"].get<double>(), 100.0);
  EXPECT_EQ(resolve(doc, lists["properties"]["ego.max_speed"]["items"]), resolve(doc, values["properties"]["ego.max_speed"]));
  EXPECT_EQ(resolve(doc, values["properties"]["perception.v2i.latency"])["type"], "number");
  const std::pair<const char*, const char*> parameters[] = {
      {"turn_signal_search_time", "turn_signal_search_time"},
      {"params.set.turn_signal_search_time", "turn_signal_search_time"},
      {"traffic_light.stop_margin", "stop_margin"},  // Autoware's place
      {"params.set.traffic_light.stop_margin", "stop_margin"}};
  for (const auto& [key, parameter] : parameters)
    EXPECT_EQ(resolve(doc, values["properties"][key]), doc["definitions"][std::string("parameter.") + parameter]) << key;
  EXPECT_TRUE(values["patternProperties"].contains("^light_offsets\\.[^.]+$"));
  EXPECT_FALSE(values["properties"].contains("ego"));  // a mapping: its keys are the --set keys
  EXPECT_FALSE(doc["definitions"].contains("parameters"));  // no parameter mapping in a sweep file
}

}  // namespace
}  // namespace signalsim
