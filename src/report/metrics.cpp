#include "report/metrics.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "report/outputs.hpp"

namespace signalsim {
namespace {

double round3(double v) {
  const double r = std::round(v * 1000.0) / 1000.0;
  return r == 0.0 ? 0.0 : r;  // no "-0"
}

Blinker blinker_of(TurnDirection d) {
  return d == TurnDirection::Left ? Blinker::Left : d == TurnDirection::Right ? Blinker::Right : Blinker::None;
}

Blinker blinker_of_parameter(const std::string& value) {  // "None" / "Left" / "Right"
  return value == "Left" ? Blinker::Left : value == "Right" ? Blinker::Right : Blinker::None;
}

// True when a lanelet param (e.g. exit_turn_signal_left="[a, b]") lists `lane_id`; brackets,
// commas and spaces all separate (spec TSD §5.2).
bool param_lists(const Lanelet& lanelet, const std::string& key, const std::string& lane_id) {
  const auto it = lanelet.params.find(key);
  if (it == lanelet.params.end()) return false;
  std::string token;
  for (const char c : it->second + ' ') {
    if (c == ',' || c == ' ' || c == '[' || c == ']') {
      if (token == lane_id) return true;
      token.clear();
    } else {
      token += c;
    }
  }
  return false;
}

std::string id_of(const Lanelet& l) { return l.junction_id.empty() ? l.lane_id : l.junction_id; }

// A run of consecutive rows with the same blinker: rows [first, last].
struct Stretch {
  Blinker blinker = Blinker::None;
  std::size_t first = 0;
  std::size_t last = 0;
};

std::vector<Stretch> stretches_of(const std::vector<TimelineRow>& rows) {
  std::vector<Stretch> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (out.empty() || rows[i].blinker != out.back().blinker) out.push_back({rows[i].blinker, i, i});
    else out.back().last = i;
  }
  return out;
}

// How long a stretch lasted: until the next row's time, or one step past its last row.
double duration_of(const std::vector<TimelineRow>& rows, std::size_t first, std::size_t last, double step) {
  const double end = last + 1 < rows.size() ? rows[last + 1].time : rows[last].time + step;
  return end - rows[first].time;
}

// Flickers: stretches with a change on both sides shorter than kFlickerSeconds.
bool is_flicker(const std::vector<TimelineRow>& rows, const std::vector<Stretch>& stretches, std::size_t i,
                double step) {
  if (i == 0 || i + 1 >= stretches.size()) return false;
  return duration_of(rows, stretches[i].first, stretches[i].last, step) < kFlickerSeconds - 1e-9;
}

SectionMetrics measure(const SignalSection& section, const RunRecord& record, const std::vector<Stretch>& stretches,
                       double step, double window_from, double window_to) {
  const auto& rows = record.rows;
  SectionMetrics m;
  m.section = section;
  for (std::size_t i = 0; i < stretches.size(); ++i) {
    const double s = rows[stretches[i].first].s_front;
    if (s > window_from && s <= window_to && is_flicker(rows, stretches, i, step)) ++m.flickers;
  }
  // The front has reached the section once it is beyond its start: a front exactly at the start is
  // still on the lane before (SUMO holds a vehicle at a lane's end while a link is not yet open), and
  // the reference's "front has reached it" test is strict too (spec TSD §5.3: DIST - b2f >= 0 is "not yet").
  const auto enter = std::find_if(rows.begin(), rows.end(),
                                  [&](const TimelineRow& r) { return r.s_front > section.s_start; });
  if (enter == rows.end()) return m;
  m.reached = true;
  if (section.blinker == Blinker::None) return m;
  const std::size_t k = static_cast<std::size_t>(enter - rows.begin());
  // The stretch of the expected blinker around row i, if row i shows it.
  const auto stretch_at = [&](std::size_t i) -> std::optional<std::pair<std::size_t, std::size_t>> {
    if (rows[i].blinker != section.blinker) return std::nullopt;
    std::size_t first = i, last = i;
    while (first > 0 && rows[first - 1].blinker == section.blinker) --first;
    while (last + 1 < rows.size() && rows[last + 1].blinker == section.blinker) ++last;
    return std::make_pair(first, last);
  };
  // Serving stretch: on just before the front reached the start, or at that step; else the first
  // one that began later while base_link was still in the section (a late blinker).
  auto serving = k > 0 ? stretch_at(k - 1) : std::nullopt;
  if (!serving) serving = stretch_at(k);
  m.missed = !serving;
  const double end_front = section.s_end + record.base_link_to_front;
  for (std::size_t i = k + 1; !serving && i < rows.size() && rows[i].s_front <= end_front; ++i) serving = stretch_at(i);
  if (!serving) {
    m.time_on = 0.0;
    return m;
  }
  const auto [first, last] = *serving;
  double t_enter = rows[k].time;  // the front reached s_start: interpolate between the two rows
  if (k > 0 && rows[k].s_front > rows[k - 1].s_front)
    t_enter = rows[k - 1].time + (section.s_start - rows[k - 1].s_front) /
                                     (rows[k].s_front - rows[k - 1].s_front) * (rows[k].time - rows[k - 1].time);
  m.lead_distance = round3(section.s_start - rows[first].s_front);
  m.lead_time = round3(t_enter - rows[first].time);
  m.time_on = round3(duration_of(rows, first, last, step));
  return m;
}

std::vector<LightMetrics> measure_lights(const RouteMap& route, const RunRecord& record) {
  const auto& rows = record.rows;
  std::vector<LightMetrics> out;
  // Per light (approach lanelet), what its own judge saw at each step (signalsim-driven runs); a
  // run without the log (SUMO driving, a timeline read back from files) has the light rows show.
  std::map<std::size_t, std::vector<const LightObservation*>> log;
  for (const LightObservation& o : record.light_log) log[o.route_index].push_back(&o);
  std::size_t from_row = 0;  // rows after the previous light's stop line
  for (std::size_t index = 0; index < route.size(); ++index) {
    const Lanelet& l = route.at(index);
    if (l.is_internal || !l.traffic_light) continue;
    LightMetrics m;
    m.id = l.traffic_light->tls_id;
    m.link_index = l.traffic_light->link_index;
    m.stop_line_s = round3(l.stop_line_s());
    std::size_t k = from_row;  // the first row at or beyond the stop line
    while (k < rows.size() && rows[k].s_front < m.stop_line_s) ++k;
    m.reached = k < rows.size() && k > 0;
    const auto own = log.find(index);
    const bool logged = own != log.end();
    // The light's state at the last row before the line, and its judge's rows on the approach.
    char state_at_line = 0;
    struct Judged {
      JudgeDecision decision;
      JudgeZone zone;
    };
    std::vector<Judged> judged_rows;
    if (logged) {
      for (const LightObservation* o : own->second) {
        if (o->row >= k) break;
        if (o->row < from_row) continue;
        judged_rows.push_back({o->decision, o->zone});
        if (m.reached && o->row == k - 1) state_at_line = o->state;
      }
    } else {
      if (m.reached && rows[k - 1].tl_id == m.id) state_at_line = rows[k - 1].tl_state;
      for (std::size_t i = from_row; i < k && i < rows.size(); ++i)
        if (rows[i].tl_id == m.id) judged_rows.push_back({rows[i].tl_decision, rows[i].zone});
    }
    if (state_at_line != 0) {
      m.state_at_line = std::string(1, state_at_line);
      m.red_light_violation = state_at_line == 'r' || state_at_line == 'u';
    }
    // The judge on this approach: its most restrictive decision, the zone it was taken in (else the
    // last zone the pass judge gave), whether it ordered an emergency stop.
    const double t_from = from_row < rows.size() ? rows[from_row].time : 0.0;
    const double t_to = k < rows.size() ? rows[k].time : std::numeric_limits<double>::infinity();
    JudgeDecision worst = JudgeDecision::None;
    JudgeZone decisive_zone = JudgeZone::None, last_zone = JudgeZone::None;
    for (const Judged& j : judged_rows) {
      if (j.zone != JudgeZone::None) last_zone = j.zone;
      if (j.decision > worst) {
        worst = j.decision;
        decisive_zone = j.zone;
      }
    }
    if (worst != JudgeDecision::None) {
      m.decision = std::string(to_string(worst));
      const JudgeZone zone = decisive_zone != JudgeZone::None ? decisive_zone : last_zone;
      if (zone != JudgeZone::None) m.zone = std::string(to_string(zone));
      m.emergency_stop = worst == JudgeDecision::EmergencyStop;
    }
    // A rest in the queue before the light says where the queue ended: no stop position error.
    for (const LightStop& stop : record.stops)
      if (stop.tl_id == m.id && stop.time >= t_from && stop.time <= t_to && stop.queued_behind.empty() &&
          stop.waiting_at.empty()) {
        m.stop_position_error = round3(stop.error);
        break;
      }
    for (const RedLightViolation& v : record.red_violations)
      if (v.tl_id == m.id && v.time >= t_from && v.time <= t_to) m.red_light_violation = true;
    from_row = std::min(k, rows.size());
    out.push_back(std::move(m));
  }
  return out;
}

template <typename T>
nlohmann::ordered_json optional_json(const std::optional<T>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

// Column order (see metric_column_less).
int rank_in(const std::vector<std::string>& list, const std::string& name) {
  const auto it = std::find(list.begin(), list.end(), name);
  return it == list.end() ? static_cast<int>(list.size()) : static_cast<int>(it - list.begin());
}

const std::vector<std::string>& run_level_order() {
  static const std::vector<std::string> order = {"max_decel",      "max_jerk",       "collisions",
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
      "id",       "blinker", "lead_distance", "lead_time",           "time_on",
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

std::vector<SignalSection> signal_sections(const RouteMap& route, const ParameterSet& params) {
  std::vector<SignalSection> out;
  const Blinker on_entry = blinker_of_parameter(params.text("turn_signal_roundabout_on_entry"));
  const Blinker on_exit = blinker_of_parameter(params.text("turn_signal_roundabout_on_exit"));
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Lanelet& l = route.at(i);
    if (l.roundabout_role == RoundaboutRole::Entry || l.roundabout_role == RoundaboutRole::Exit) {
      SignalSection s{l.roundabout_role == RoundaboutRole::Entry ? "roundabout_entry" : "roundabout_exit", id_of(l),
                      on_exit, l.s_start, l.s_end(), {l.lane_id}};
      if (l.roundabout_role == RoundaboutRole::Entry) {
        s.blinker = on_entry;
        // The exit the route takes: the last lanelet of this roundabout after the entry.
        const Lanelet* exit = nullptr;
        for (std::size_t j = i + 1; j < route.size() && route.at(j).roundabout_role != RoundaboutRole::None &&
                                    route.at(j).roundabout_id == l.roundabout_id;
             ++j)
          exit = &route.at(j);
        if (exit && param_lists(l, "exit_turn_signal_left", exit->lane_id)) s.blinker = Blinker::Left;
        else if (exit && param_lists(l, "exit_turn_signal_right", exit->lane_id)) s.blinker = Blinker::Right;
      }
      out.push_back(std::move(s));
      continue;
    }
    if (l.roundabout_role != RoundaboutRole::None) continue;
    const Blinker b = blinker_of(l.turn_direction);
    if (b == Blinker::None) continue;
    SignalSection s{"turn", id_of(l), b, l.s_start, l.s_end(), {l.lane_id}};
    while (i + 1 < route.size() && route.at(i + 1).roundabout_role == RoundaboutRole::None &&
           route.at(i + 1).turn_direction == l.turn_direction) {
      ++i;
      s.s_end = route.at(i).s_end();
      s.lanelets.push_back(route.at(i).lane_id);
    }
    out.push_back(std::move(s));
  }
  return out;
}

RunMetrics compute_metrics(const Scenario& scenario, const RouteMap& route, const RunRecord& record) {
  RunMetrics m;
  const auto& rows = record.rows;
  // The acceleration as timeline.csv has it, so that metrics recomputed from the files (batch's
  // fallback) are the run's own: the jerk divides its rounding by the step.
  const auto written = [](double v) { return std::stod(fixed(v, 3)); };
  double min_accel = 0.0, max_jerk = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    min_accel = std::min(min_accel, written(rows[i].accel));
    if (i > 0 && rows[i].time > rows[i - 1].time)
      max_jerk = std::max(max_jerk, std::abs(written(rows[i].accel) - written(rows[i - 1].accel)) /
                                        (rows[i].time - rows[i - 1].time));
  }
  m.max_decel = round3(-min_accel);
  m.max_jerk = round3(max_jerk);
  m.collisions = record.collisions;
  m.blinker_events = static_cast<int>(std::count_if(record.events.begin(), record.events.end(),
                                                    [](const TimelineEvent& e) { return e.kind == "blinker"; }));
  const std::vector<Stretch> stretches = stretches_of(rows);
  for (std::size_t i = 0; i < stretches.size(); ++i) m.flickers += is_flicker(rows, stretches, i, scenario.step_length);

  // The route's sections and the maneuvers' lateral motions (front bumper at base_link's start), by start.
  std::vector<SignalSection> sections = signal_sections(route, scenario.params);
  for (const ManeuverLine& line : record.maneuver_lines)
    sections.push_back({line.kind, line.id, line.blinker, line.s_start + record.base_link_to_front, line.s_end, {}});
  std::stable_sort(sections.begin(), sections.end(),
                   [](const SignalSection& a, const SignalSection& b) { return a.s_start < b.s_start; });
  double window_from = -std::numeric_limits<double>::infinity();
  for (const SignalSection& section : sections) {
    const double window_to = section.s_end + record.base_link_to_front;
    m.sections.push_back(measure(section, record, stretches, scenario.step_length, window_from, window_to));
    window_from = window_to;
    m.missed_signals += m.sections.back().missed.value_or(false);
  }
  m.lights = measure_lights(route, record);
  for (const LightMetrics& l : m.lights) m.red_light_violations += l.red_light_violation.value_or(false);
  return m;
}

nlohmann::ordered_json to_json(const RunMetrics& m) {
  nlohmann::ordered_json out;
  out["max_decel"] = m.max_decel;
  out["max_jerk"] = m.max_jerk;
  out["collisions"] = m.collisions;
  out["blinker_events"] = m.blinker_events;
  out["flickers"] = m.flickers;
  out["missed_signals"] = m.missed_signals;
  out["red_light_violations"] = m.red_light_violations;
  nlohmann::ordered_json sections = nlohmann::ordered_json::array();
  for (const SectionMetrics& s : m.sections) {
    nlohmann::ordered_json j;
    j["kind"] = s.section.kind;
    j["id"] = s.section.id;
    j["blinker"] = to_string(s.section.blinker);
    j["s_start"] = round3(s.section.s_start);
    j["s_end"] = round3(s.section.s_end);
    j["lanelets"] = s.section.lanelets;
    j["reached"] = s.reached;
    j["lead_distance"] = optional_json(s.lead_distance);
    j["lead_time"] = optional_json(s.lead_time);
    j["time_on"] = optional_json(s.time_on);
    j["flickers"] = s.flickers;
    j["missed"] = optional_json(s.missed);
    sections.push_back(std::move(j));
  }
  out["sections"] = std::move(sections);
  nlohmann::ordered_json lights = nlohmann::ordered_json::array();
  for (const LightMetrics& l : m.lights) {
    nlohmann::ordered_json j;
    j["id"] = l.id;
    j["link_index"] = l.link_index;
    j["stop_line_s"] = l.stop_line_s;
    j["reached"] = l.reached;
    j["state_at_line"] = l.state_at_line;
    j["red_light_violation"] = optional_json(l.red_light_violation);
    j["stop_position_error"] = optional_json(l.stop_position_error);
    j["decision"] = optional_json(l.decision);
    j["zone"] = optional_json(l.zone);
    j["emergency_stop"] = optional_json(l.emergency_stop);
    lights.push_back(std::move(j));
  }
  out["lights"] = std::move(lights);
  return out;
}

nlohmann::ordered_json metrics_json(const Scenario& scenario, const RouteMap& route, const RunRecord& record) {
  return to_json(compute_metrics(scenario, route, record));
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
