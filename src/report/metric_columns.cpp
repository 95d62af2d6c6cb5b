// Flattening the metrics JSON into results.csv cells, and the columns' fixed order (see metric_columns.hpp).
#include "report/metric_columns.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <tuple>

namespace signalsim {
namespace {

// Column order (see metric_column_less).
int rank_in(const std::vector<std::string>& list, const std::string& name) {
  const auto it = std::find(list.begin(), list.end(), name);
  return it == list.end() ? static_cast<int>(list.size()) : static_cast<int>(it - list.begin());
}

const std::vector<std::string>& run_level_order() {
  static const std::vector<std::string> order = {"decider",        "decider_agreement", "light_judge",
                                                 "light_judge_agreement",
                                                 "max_decel",      "max_jerk",       "p95_decel",
                                                 "p95_jerk",       "collisions",
                                                 "blinker_events", "flickers",       "missed_signals",
                                                 "red_light_violations"};
  return order;
}
const std::vector<std::string>& group_order() {
  static const std::vector<std::string> order = {"turn",     "roundabout_entry", "roundabout_exit", "lane_change",
                                                 "avoidance", "pull_out",        "pull_over",       "light"};
  return order;
}
const std::vector<std::string>& field_order() {
  static const std::vector<std::string> order = {
      "id",       "blinker", "blinker_at_start", "lead_distance", "lead_time",           "time_on",
      "flickers", "missed",  "state_at_line", "red_light_violation", "stop_position_error",
      "decision", "zone",    "emergency_stop"};
  return order;
}

using ColumnKey = std::tuple<int, int, std::string, long, int, std::string>;

ColumnKey column_key(const std::string& column) {
  const auto dot = column.find('.');
  if (dot == std::string::npos) return {0, rank_in(run_level_order(), column), column, 0, 0, ""};
  const std::string item = column.substr(0, dot), field = column.substr(dot + 1);
  std::size_t digits = item.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(item[digits - 1]))) --digits;
  const std::string group = item.substr(0, digits);
  const long number = digits < item.size() ? std::stol(item.substr(digits)) : 0;
  return {1, rank_in(group_order(), group), group, number, rank_in(field_order(), field), field};
}

std::string cell_text(const nlohmann::ordered_json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  return v.dump();
}

bool skipped_field(const std::string& key) {
  static const char* const skip[] = {"kind", "s_start", "s_end", "lanelets", "reached", "link_index", "stop_line_s"};
  return std::any_of(std::begin(skip), std::end(skip), [&](const char* s) { return key == s; });
}

}  // namespace

bool is_run_metric_column(const std::string& name) {
  if (name == "decider" || name == "light_judge") return false;
  return rank_in(run_level_order(), name) < static_cast<int>(run_level_order().size());
}

std::vector<std::pair<std::string, std::string>> flatten_metrics(const nlohmann::ordered_json& metrics) {
  std::vector<std::pair<std::string, std::string>> out;
  if (!metrics.is_object()) return out;
  std::map<std::string, int> counters;  // kind -> sections seen
  for (const auto& [key, value] : metrics.items()) {
    if (value.is_primitive()) {
      if (!value.is_null()) out.emplace_back(key, cell_text(value));
      continue;
    }
    if (!value.is_array()) continue;
    for (const auto& item : value) {
      if (!item.is_object()) continue;
      std::string prefix = key == "lights" ? "light" : key;
      if (item.contains("kind") && item["kind"].is_string()) prefix = item["kind"].get<std::string>();
      const std::string name = prefix + std::to_string(++counters[prefix]);
      for (const auto& [field, v] : item.items())
        if (v.is_primitive() && !v.is_null() && !skipped_field(field)) out.emplace_back(name + "." + field, cell_text(v));
    }
  }
  return out;
}

bool metric_column_less(const std::string& a, const std::string& b) { return column_key(a) < column_key(b); }

}  // namespace signalsim
