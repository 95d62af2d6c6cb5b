// Key tables: lookup and the one-line constructors of their entries.
#include "scenario/key_table.hpp"

#include <stdexcept>
#include <utility>

namespace signalsim {

KeyTable::KeyTable(std::string where_, std::string description_, std::vector<KeySpec> keys_,
                   std::vector<std::vector<std::string>> one_of_required_)
    : where(std::move(where_)),
      description(std::move(description_)),
      keys(std::move(keys_)),
      one_of_required(std::move(one_of_required_)) {}

const KeySpec* KeyTable::find(const std::string& name) const {
  for (const KeySpec& key : keys)
    if (key.name == name) return &key;
  return nullptr;
}

const KeySpec& KeyTable::at(const std::string& name) const {
  if (const KeySpec* key = find(name)) return *key;
  throw std::logic_error("key table '" + where + "' has no key '" + name + "'");
}

const KeyTable& KeyTable::table_of(const std::string& name) const {
  const KeySpec& key = at(name);
  if (!key.table) throw std::logic_error("key '" + name + "' of table '" + where + "' has no inner table");
  return *key.table;
}

std::string KeyTable::names() const {
  std::string out;
  for (const KeySpec& key : keys) out += (out.empty() ? "" : ", ") + key.name;
  return out;
}

KeySpec text_key(std::string name, std::string description, std::vector<std::string> choices) {
  KeySpec k;
  k.name = std::move(name);
  k.type = KeyType::Text;
  k.description = std::move(description);
  k.choices = std::move(choices);
  return k;
}

KeySpec required_text_key(std::string name, std::string description, std::vector<std::string> choices) {
  return as_required(text_key(std::move(name), std::move(description), std::move(choices)));
}

KeySpec text_key_or(std::string name, std::string fallback, std::string description, std::vector<std::string> choices) {
  KeySpec k = text_key(std::move(name), std::move(description), std::move(choices));
  k.default_text = std::move(fallback);
  return k;
}

KeySpec number_key(std::string name, double fallback, double min, double max, std::string unit, std::string description) {
  KeySpec k = required_number_key(std::move(name), min, max, std::move(unit), std::move(description));
  k.required = false;
  k.default_number = fallback;
  return k;
}

KeySpec required_number_key(std::string name, double min, double max, std::string unit, std::string description) {
  KeySpec k;
  k.name = std::move(name);
  k.type = KeyType::Number;
  k.description = std::move(description);
  k.unit = std::move(unit);
  k.required = true;
  k.min = min;
  k.max = max;
  return k;
}

KeySpec computed_number_key(std::string name, double min, double max, std::string unit, std::string note,
                            std::string description) {
  KeySpec k = required_number_key(std::move(name), min, max, std::move(unit), std::move(description));
  k.required = false;
  k.default_note = std::move(note);
  return k;
}

KeySpec integer_key(std::string name, int fallback, int min, int max, std::string description) {
  KeySpec k = required_integer_key(std::move(name), min, max, std::move(description));
  k.required = false;
  k.default_number = fallback;
  return k;
}

KeySpec required_integer_key(std::string name, int min, int max, std::string description) {
  KeySpec k = required_number_key(std::move(name), min, max, "", std::move(description));
  k.type = KeyType::Integer;
  return k;
}

KeySpec boolean_key(std::string name, bool fallback, std::string description) {
  KeySpec k = shape_key(std::move(name), KeyType::Boolean, std::move(description));
  k.default_boolean = fallback;
  return k;
}

KeySpec text_list_key(std::string name, std::string description) {
  return shape_key(std::move(name), KeyType::TextList, std::move(description));
}

KeySpec table_key(std::string name, KeyType type, const KeyTable& table, std::string description) {
  KeySpec k = shape_key(std::move(name), type, std::move(description));
  k.table = &table;
  return k;
}

KeySpec shape_key(std::string name, KeyType type, std::string description) {
  KeySpec k;
  k.name = std::move(name);
  k.type = type;
  k.description = std::move(description);
  return k;
}

KeySpec with_default_note(KeySpec spec, std::string note) {
  spec.default_note = std::move(note);
  return spec;
}

KeySpec as_required(KeySpec spec) {
  spec.required = true;
  return spec;
}

KeySpec as_nullable(KeySpec spec) {
  spec.may_be_null = true;
  return spec;
}

}  // namespace signalsim
