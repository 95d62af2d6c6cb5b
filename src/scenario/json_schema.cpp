// Key tables to JSON Schema (draft-07).
#include "scenario/json_schema.hpp"

#include <cmath>

#include "scenario/parameter_json_schema.hpp"

namespace signalsim {
namespace {

// What a loader reads as text: any scalar (ids such as a junction `2` are numbers in YAML).
SchemaJson scalar_schema() { return {{"type", {"string", "number", "boolean"}}}; }

std::string describe(const KeySpec& key) {
  std::string text = key.unit.empty() ? key.description : "[" + key.unit + "] " + key.description;
  if (!key.default_note.empty()) text += " Default: " + key.default_note + ".";
  return text;
}

// `bound` as JSON: an integer for Integer keys.
SchemaJson number_value(const KeySpec& key, double value) {
  if (key.type == KeyType::Integer) return static_cast<long long>(value);
  return value;
}

SchemaJson number_schema(const KeySpec& key) {
  SchemaJson s = {{"type", key.type == KeyType::Integer ? "integer" : "number"}};
  if (std::isfinite(key.min)) s["minimum"] = number_value(key, key.min);
  if (std::isfinite(key.max)) s["maximum"] = number_value(key, key.max);
  // A sentinel default outside the range (pull_out.at -1: "the depart position") is said in words.
  if (key.default_number && std::isfinite(*key.default_number) && *key.default_number >= key.min &&
      *key.default_number <= key.max)
    s["default"] = number_value(key, *key.default_number);
  return s;
}

SchemaJson nullable_list(SchemaJson items) { return {{"type", {"array", "null"}}, {"items", std::move(items)}}; }

// The items of `maneuvers:` and `expect:`: one-key mappings whose key is a kind of `kinds`.
SchemaJson kind_item_schema(const KeyTable& kinds) {
  SchemaJson properties = SchemaJson::object();
  for (const KeySpec& kind : kinds.keys) properties[kind.name] = key_schema(kind);
  return {{"type", "object"},          {"description", kinds.description}, {"minProperties", 1},
          {"maxProperties", 1},         {"properties", properties},         {"additionalProperties", false}};
}

SchemaJson value_schema(const KeySpec& key) {
  switch (key.type) {
    case KeyType::Text:
      if (!key.choices.empty()) return {{"enum", key.choices}};
      return scalar_schema();
    case KeyType::Number:
    case KeyType::Integer:
      return number_schema(key);
    case KeyType::Boolean:
      return {{"type", "boolean"}};
    case KeyType::TextList:
      return nullable_list(scalar_schema());
    case KeyType::Mapping: {
      SchemaJson s = mapping_schema(*key.table);
      if (key.may_be_null) s["type"] = {"object", "null"};
      return s;
    }
    case KeyType::MappingList:
      return nullable_list(mapping_schema(*key.table));
    case KeyType::KindList:
      return nullable_list(kind_item_schema(*key.table));
    case KeyType::NumberMapping:
      return {{"type", "object"}, {"additionalProperties", {{"type", "number"}}}};
    case KeyType::Intervals:
      return nullable_list({{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 2}, {"maxItems", 2}});
    case KeyType::Parameters:
      return {{"anyOf", {{{"$ref", definition_ref("parameters")}}, {{"type", "null"}}}}};
    case KeyType::True:
      return {{"const", true}};
    case KeyType::TextOrTextList:
      return {{"anyOf", {scalar_schema(), {{"type", "array"}, {"minItems", 1}, {"items", scalar_schema()}}}}};
    case KeyType::MappingOrList:
      return {{"anyOf", {mapping_schema(*key.table),
                         {{"type", "array"}, {"minItems", 1}, {"items", mapping_schema(*key.table)}}}}};
    case KeyType::OverrideValues:
      return {{"$ref", definition_ref("override_values")}};
    case KeyType::OverrideLists:
      return {{"$ref", definition_ref("override_lists")}};
    case KeyType::OverrideListGroups:
      return {{"anyOf", {{{"$ref", definition_ref("override_lists")}},
                         {{"type", "array"}, {"minItems", 1}, {"items", {{"$ref", definition_ref("override_lists")}}}}}}};
  }
  return SchemaJson::object();
}

bool uses(const KeyTable& table, bool (*wanted)(KeyType)) {
  for (const KeySpec& key : table.keys)
    if (wanted(key.type) || (key.table && uses(*key.table, wanted))) return true;
  return false;
}

bool is_parameters_or_override(KeyType t) {
  return t == KeyType::Parameters || t == KeyType::OverrideValues || t == KeyType::OverrideLists ||
         t == KeyType::OverrideListGroups;
}
bool is_parameters(KeyType t) { return t == KeyType::Parameters; }
bool is_override(KeyType t) { return t == KeyType::OverrideValues || t == KeyType::OverrideLists || t == KeyType::OverrideListGroups; }

}  // namespace

SchemaJson key_schema(const KeySpec& key) {
  SchemaJson s = {{"description", describe(key)}};
  const SchemaJson value_part = value_schema(key);
  for (const auto& [name, value] : value_part.items()) {
    if (name == "description") continue;  // a mapping's own description gives way to the key's
    s[name] = value;
  }
  if (key.type == KeyType::Text && key.default_text) s["default"] = *key.default_text;
  if (key.type == KeyType::Boolean && key.default_boolean) s["default"] = *key.default_boolean;
  return s;
}

SchemaJson mapping_schema(const KeyTable& table) {
  SchemaJson s = {{"type", "object"}};
  if (!table.description.empty()) s["description"] = table.description;
  SchemaJson properties = SchemaJson::object();
  SchemaJson required = SchemaJson::array();
  SchemaJson dependencies = SchemaJson::object();
  for (const KeySpec& key : table.keys) {
    properties[key.name] = key_schema(key);
    if (key.required) required.push_back(key.name);
    if (!key.needs.empty()) dependencies[key.name] = key.needs;
  }
  s["properties"] = properties;
  if (!required.empty()) s["required"] = required;
  if (!dependencies.empty()) s["dependencies"] = dependencies;
  if (!table.one_of_required.empty()) {
    // Each group: at least one of its keys (draft-07 has no anyOf-required shorthand).
    SchemaJson all = SchemaJson::array();
    for (const std::vector<std::string>& group : table.one_of_required) {
      SchemaJson any = SchemaJson::array();
      for (const std::string& name : group) any.push_back({{"required", {name}}});
      all.push_back({{"anyOf", any}});
    }
    s["allOf"] = all;
  }
  s["additionalProperties"] = false;
  return s;
}

SchemaJson schema_document(const KeyTable& top, const std::string& title) {
  SchemaJson doc = {{"$schema", "http://json-schema.org/draft-07/schema#"},
                    {"title", title},
                    {"$comment", "Generated by `signalsim schema` from the key tables its loaders read; do not edit."}};
  const SchemaJson mapping = mapping_schema(top);
  for (const auto& [name, value] : mapping.items()) doc[name] = value;
  if (uses(top, is_parameters_or_override)) {
    SchemaJson definitions = parameter_definitions();
    if (!uses(top, is_parameters)) definitions.erase("parameters");  // the leaves alone (`--set` keys)
    if (uses(top, is_override)) {
      const SchemaJson overrides = override_definitions();
      for (const auto& [name, value] : overrides.items()) definitions[name] = value;
    }
    doc["definitions"] = definitions;
  }
  return doc;
}

std::string schema_text(const SchemaJson& document) { return document.dump(2) + "\n"; }

}  // namespace signalsim
