#include "scenario/yaml_fields.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "core/file_paths.hpp"
#include "scenario/input_error.hpp"
#include "scenario/utf8_text.hpp"
#include "scenario/yaml_text.hpp"

namespace signalsim {

namespace {

std::string read_yaml_text(const std::string& path, const std::string& what) {
  if (const std::string problem = input_file_problem(path); !problem.empty())
    throw InputError(path, 0, what + " " + problem);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot read the " + what);
  std::stringstream bytes;
  bytes << in.rdbuf();
  std::string text = bytes.str();
  // Every string of the file may end up in summary.json (UTF-8 JSON): check the text now, at its line.
  if (const auto bad = find_invalid_utf8(text)) throw InputError(path, bad->line, describe_invalid_utf8(text, *bad) + "; save the file as UTF-8");
  check_yaml_text(text, path, what);
  return text;
}

YAML::Node parse_yaml_text(const std::string& text, const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.line + 1, "malformed YAML: " + e.msg);
  }
  check_yaml_texts(root, text, path);
  return root;
}

}  // namespace

YAML::Node load_yaml_file(const std::string& path, const std::string& what) {
  return parse_yaml_text(read_yaml_text(path, what), path);
}

YAML::Node load_shared_yaml_file(const std::string& path, const std::string& what) {
  // A batch's parent and each of its workers read every scenario's parameter files: yaml-cpp's
  // parse of autoware_defaults.yaml is most of a scenario's load. A hit needs the same bytes, so an
  // edited file is parsed again; a few files are kept (a sweep over many parameter files would
  // otherwise hold them all). (YAML::Clone would lose the marks, the lines errors name.)
  struct Parsed {
    std::string text;
    YAML::Node root;
  };
  static std::map<std::string, Parsed> parsed;
  constexpr std::size_t kKept = 16;
  std::string text = read_yaml_text(path, what);
  if (const auto hit = parsed.find(path); hit != parsed.end() && hit->second.text == text) return hit->second.root;
  YAML::Node root = parse_yaml_text(text, path);
  if (parsed.size() >= kKept) parsed.clear();
  parsed[path] = Parsed{std::move(text), root};
  return root;
}

std::optional<double> yaml_number(const YAML::Node& node, std::string& reason) {
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
    reason = "expected a number, got '" + (node.IsScalar() ? node.Scalar() : std::string("a list or map")) + "'";
    return std::nullopt;
  }
  // SUMO reads numbers with strtod and refuses one that underflows (a subnormal such as 1e-308):
  // such a value would pass here and fail in SUMO with its own two-line message.
  if (value != 0.0 && std::abs(value) < std::numeric_limits<double>::min()) {
    reason = "value " + node.Scalar() + " is too small to be a number SUMO can read (below 2.2e-308); write 0";
    return std::nullopt;
  }
  return value;
}

int yaml_line(const YAML::Node& node) { return node && node.Mark().line >= 0 ? node.Mark().line + 1 : 0; }

YamlFields::YamlFields(const YAML::Node& mapping, std::string file, std::string where)
    : mapping_(mapping), file_(std::move(file)), where_(std::move(where)) {
  if (!mapping_.IsMap())
    throw InputError(file_, yaml_line(mapping_),
                     (where_.empty() ? std::string("the file") : "'" + where_ + "'") + " must be a mapping of key: value",
                     where_);
  reject_duplicate_keys(mapping_, file_, where_);
}

YamlFields::YamlFields(const YAML::Node& mapping, std::string file, std::string where, const KeyTable& keys)
    : YamlFields(mapping, std::move(file), std::move(where)) {
  keys_ = &keys;
}

const KeySpec* YamlFields::spec(const std::string& key, std::optional<KeyType> type) const {
  if (!keys_) return nullptr;
  const KeySpec& entry = keys_->at(key);
  if (type && entry.type != *type)
    throw std::logic_error("key table '" + keys_->where + "': key '" + key + "' is not read as its table says");
  return &entry;
}

const KeySpec& YamlFields::listed(const std::string& key, KeyType type) const {
  if (!keys_) throw std::logic_error("'" + qualified(key) + "': read through a key table, but there is none");
  return *spec(key, type);
}

void reject_duplicate_keys(const YAML::Node& mapping, const std::string& file, const std::string& where) {
  // yaml-cpp keeps both entries of a repeated key and lookups see only one: reject it.
  std::set<std::string> seen;
  for (const auto& entry : mapping) {
    const std::string key = entry.first.Scalar();
    if (!seen.insert(key).second)
      throw InputError(file, yaml_line(entry.first),
                       "duplicate key '" + (where.empty() ? key : where + "." + key) + "'", where.empty() ? key : where + "." + key);
  }
}

std::string YamlFields::qualified(const std::string& key) const { return where_.empty() ? key : where_ + "." + key; }

int YamlFields::line_of(const std::string& key) const {
  for (const auto& entry : mapping_)
    if (entry.first.Scalar() == key) return yaml_line(entry.first);
  return yaml_line(mapping_);
}

void YamlFields::fail(const std::string& key, const std::string& reason) const {
  throw InputError(file_, line_of(key), "key '" + qualified(key) + "': " + reason, qualified(key));
}

bool YamlFields::has(const std::string& key) const {
  (void)spec(key);
  return static_cast<bool>(mapping_[key]);
}

YAML::Node YamlFields::node(const std::string& key) const {
  (void)spec(key);
  read_.insert(key);
  return mapping_[key];
}

std::string YamlFields::text(const std::string& key) const {
  (void)spec(key, KeyType::Text);
  const YAML::Node n = node(key);
  if (!n) throw InputError(file_, yaml_line(mapping_), "missing required key '" + qualified(key) + "'", where_);
  if (!n.IsScalar()) fail(key, "expected a text value");
  return n.Scalar();
}

std::string YamlFields::text_or(const std::string& key, const std::string& fallback) const {
  return has(key) ? text(key) : (read_.insert(key), fallback);
}

double YamlFields::number(const std::string& key, double fallback, double min, double max) const {
  (void)spec(key, KeyType::Number);
  if (!has(key)) {
    read_.insert(key);
    return fallback;
  }
  return required_number(key, min, max);
}

double YamlFields::required_number(const std::string& key, double min, double max) const {
  (void)spec(key, KeyType::Number);
  const YAML::Node n = node(key);
  if (!n) throw InputError(file_, yaml_line(mapping_), "missing required key '" + qualified(key) + "'", where_);
  if (n.IsNull()) fail(key, "empty value (expected a number)");
  std::string reason;
  const std::optional<double> number = yaml_number(n, reason);
  if (!number) fail(key, reason);
  const double value = *number;
  if (value < min || value > max) {
    std::ostringstream out;
    out << "value " << n.Scalar() << " is out of range [" << min << ", " << max << "]";
    fail(key, out.str());
  }
  return value;
}

int YamlFields::integer(const std::string& key, int fallback, int min, int max) const {
  (void)spec(key, KeyType::Integer);
  if (!has(key)) {
    read_.insert(key);
    return fallback;
  }
  const YAML::Node n = node(key);
  int value = 0;
  if (n.IsNull()) fail(key, "empty value (expected an integer)");
  if (!n.IsScalar() || !YAML::convert<int>::decode(n, value))
    fail(key, "expected an integer, got '" + (n.IsScalar() ? n.Scalar() : std::string("a list or map")) + "'");
  if (value < min || value > max) {
    std::ostringstream out;
    out << "value " << value << " is out of range [" << min << ", " << max << "]";
    fail(key, out.str());
  }
  return value;
}

std::vector<std::string> YamlFields::text_list(const std::string& key) const {
  (void)spec(key, KeyType::TextList);
  const YAML::Node n = node(key);
  std::vector<std::string> out;
  if (!n || n.IsNull()) return out;
  if (!n.IsSequence()) fail(key, "expected a list");
  for (const auto& item : n) {
    if (!item.IsScalar()) fail(key, "expected a list of text values");
    out.push_back(item.Scalar());
  }
  return out;
}

void YamlFields::finish() const {
  for (const auto& entry : mapping_) {
    const std::string key = entry.first.Scalar();
    if (!read_.count(key) || (keys_ && !keys_->find(key)))
      throw InputError(file_, yaml_line(entry.first), "unknown key '" + qualified(key) + "'", qualified(key));
  }
}

std::string YamlFields::text_or(const std::string& key) const {
  return text_or(key, listed(key, KeyType::Text).default_text.value());
}

std::string YamlFields::choice(const std::string& key) const {
  const KeySpec& entry = listed(key, KeyType::Text);
  const std::string value = entry.default_text ? text_or(key) : text(key);
  for (const std::string& allowed : entry.choices)
    if (value == allowed) return value;
  std::string allowed;
  for (const std::string& c : entry.choices) allowed += (allowed.empty() ? "" : ", ") + c;
  fail(key, "'" + value + "' is not one of " + allowed);
}

double YamlFields::number(const std::string& key) const {
  return number(key, listed(key, KeyType::Number).default_number.value());
}

double YamlFields::number(const std::string& key, double fallback) const {
  const KeySpec& entry = listed(key, KeyType::Number);
  return number(key, fallback, entry.min, entry.max);
}

double YamlFields::required_number(const std::string& key) const {
  const KeySpec& entry = listed(key, KeyType::Number);
  return required_number(key, entry.min, entry.max);
}

int YamlFields::integer(const std::string& key) const {
  return integer(key, static_cast<int>(listed(key, KeyType::Integer).default_number.value()));
}

int YamlFields::integer(const std::string& key, int fallback) const {
  const KeySpec& entry = listed(key, KeyType::Integer);
  return integer(key, fallback, static_cast<int>(entry.min), static_cast<int>(entry.max));
}

}  // namespace signalsim
