#include "batch/run_outputs.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "core/csv.hpp"
#include "step/behavior_stage.hpp"
#include "report/metrics.hpp"
#include "step/route_planning.hpp"
#include "net/net_index.hpp"
#include "report/run_files.hpp"
#include "route/route_builder.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

using Table = std::vector<std::vector<std::string>>;

double number(const std::string& text, const std::string& path, std::size_t line) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  throw std::runtime_error(path + ":" + std::to_string(line) + ": '" + text + "' is not a number");
}

// An event's time and position: a golden file edited to nan or inf would compare as no number does.
double finite_number(const std::string& text, const std::string& path, std::size_t line) {
  const double v = number(text, path, line);
  if (!std::isfinite(v)) throw std::runtime_error(path + ":" + std::to_string(line) + ": '" + text + "' is not a finite number");
  return v;
}

Blinker parse_blinker(const std::string& text) {
  for (const Blinker b : {Blinker::None, Blinker::Left, Blinker::Right, Blinker::Hazard})
    if (to_string(b) == text) return b;
  return Blinker::None;
}

template <typename Enum>
Enum parse_enum(const std::string& text, Enum last, Enum fallback) {
  for (int i = 0; i <= static_cast<int>(last); ++i)
    if (to_string(static_cast<Enum>(i)) == text) return static_cast<Enum>(i);
  return fallback;
}

RequestSource parse_source(const std::string& text) {
  for (int i = 0; i <= static_cast<int>(RequestSource::Sut); ++i)
    if (to_string(static_cast<RequestSource>(i)) == text) return static_cast<RequestSource>(i);
  return RequestSource::None;
}

// Column index by name; -1 when absent.
std::map<std::string, int> header_of(const Table& table, const std::string& path) {
  if (table.empty()) throw std::runtime_error(path + ": empty file");
  std::map<std::string, int> out;
  for (std::size_t i = 0; i < table.front().size(); ++i) out[table.front()[i]] = static_cast<int>(i);
  return out;
}

}  // namespace

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

nlohmann::ordered_json read_json_file(const std::string& path) {
  try {
    return nlohmann::ordered_json::parse(read_text_file(path));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": not valid JSON: " + e.what());
  }
}

std::vector<TimelineEvent> read_events_csv(const std::string& path) {
  const Table table = parse_csv(read_text_file(path));
  const auto header = header_of(table, path);
  for (const char* column : {"time", "s_front", "kind", "from", "to", "source"})
    if (!header.count(column)) throw std::runtime_error(path + ": no '" + column + "' column");
  std::vector<TimelineEvent> events;
  for (std::size_t r = 1; r < table.size(); ++r) {
    const auto& row = table[r];
    if (row.size() == 1 && row[0].empty()) continue;
    if (row.size() != table.front().size())
      throw std::runtime_error(path + ":" + std::to_string(r + 1) + ": wrong number of fields");
    TimelineEvent e;
    e.time = finite_number(row[header.at("time")], path, r + 1);
    e.s_front = finite_number(row[header.at("s_front")], path, r + 1);
    e.kind = row[header.at("kind")];
    e.from = row[header.at("from")];
    e.to = row[header.at("to")];
    e.source = row[header.at("source")];
    events.push_back(std::move(e));
  }
  return events;
}

std::vector<TimelineRow> read_timeline_csv(const std::string& path) {
  const Table table = parse_csv(read_text_file(path));
  const auto header = header_of(table, path);
  for (const char* column : {"time", "s_front", "speed", "accel", "blinker"})
    if (!header.count(column)) throw std::runtime_error(path + ": no '" + column + "' column");
  const auto col = [&](const char* name) { return header.count(name) ? header.at(name) : -1; };
  const int c_x = col("x"), c_y = col("y"), c_edge = col("edge"), c_lane = col("lane"), c_lat = col("lateral_offset"),
            c_source = col("blinker_source"), c_signals = col("sumo_signals"), c_tl = col("tl_id"),
            c_state = col("tl_state"), c_decision = col("tl_decision"), c_zone = col("zone"),
            c_planned = col("planned_offset"), c_v2i = col("v2i_time_to_red"), c_ref = col("ref_blinker"),
            c_ref_source = col("ref_blinker_source"), c_ref_tl = col("ref_tl_decision"), c_reason = col("tl_reason");
  std::vector<TimelineRow> rows;
  for (std::size_t r = 1; r < table.size(); ++r) {
    const auto& f = table[r];
    if (f.size() == 1 && f[0].empty()) continue;
    if (f.size() != table.front().size())
      throw std::runtime_error(path + ":" + std::to_string(r + 1) + ": wrong number of fields");
    TimelineRow row;
    row.time = number(f[header.at("time")], path, r + 1);
    row.s_front = number(f[header.at("s_front")], path, r + 1);
    row.speed = number(f[header.at("speed")], path, r + 1);
    row.accel = number(f[header.at("accel")], path, r + 1);
    row.blinker = parse_blinker(f[header.at("blinker")]);
    if (c_x >= 0 && !f[c_x].empty()) row.x = number(f[c_x], path, r + 1);
    if (c_y >= 0 && !f[c_y].empty()) row.y = number(f[c_y], path, r + 1);
    if (c_lat >= 0 && !f[c_lat].empty()) row.lateral_offset = number(f[c_lat], path, r + 1);
    if (c_edge >= 0) row.edge = f[c_edge];
    if (c_lane >= 0) row.lane = f[c_lane];
    if (c_source >= 0) row.blinker_source = parse_source(f[c_source]);
    if (c_signals >= 0) row.sumo_signals = f[c_signals].empty() ? -1 : static_cast<int>(number(f[c_signals], path, r + 1));
    if (c_tl >= 0) row.tl_id = f[c_tl];
    if (c_state >= 0 && !f[c_state].empty()) row.tl_state = f[c_state][0];
    if (c_decision >= 0)
      row.tl_decision = parse_enum(f[c_decision], JudgeDecision::EmergencyStop, JudgeDecision::None);
    if (c_zone >= 0) row.zone = parse_enum(f[c_zone], JudgeZone::Slow, JudgeZone::None);
    if (c_planned >= 0 && !f[c_planned].empty()) row.planned_offset = number(f[c_planned], path, r + 1);
    if (c_v2i >= 0 && !f[c_v2i].empty()) row.v2i_time_to_red = number(f[c_v2i], path, r + 1);  // V2I runs only
    // A decider / light judge under test: the reference's decisions in shadow, the SUT's reason.
    if (c_ref >= 0 && !f[c_ref].empty()) row.ref_blinker = parse_blinker(f[c_ref]);
    if (c_ref_source >= 0) row.ref_blinker_source = parse_source(f[c_ref_source]);
    if (c_ref_tl >= 0 && !f[c_ref_tl].empty())
      row.ref_tl_decision = parse_enum(f[c_ref_tl], JudgeDecision::EmergencyStop, JudgeDecision::None);
    if (c_reason >= 0) row.tl_reason = f[c_reason];
    rows.push_back(std::move(row));
  }
  return rows;
}

nlohmann::ordered_json metrics_from_run_dir(const std::string& run_dir, const std::string& scenario_file,
                                            const std::vector<std::string>& set) {
  // Routes are rebuilt once per (net, edges): a sweep runs the same route many times.
  struct Route {
    std::shared_ptr<const sumo::NetIndex> net;
    sumo::RoutePlan plan;
  };
  static std::map<std::string, std::shared_ptr<const Route>> routes;
  Scenario scenario = load_scenario(scenario_file, ScenarioOverrides{set});
  const fs::path dir(run_dir);
  const auto summary = read_json_file((dir / run_files::kSummary).string());
  // The ego as the run had it (a taken-over vehicle's route and length are SUMO's).
  if (summary.contains("route") && summary["route"].contains("edges"))
    scenario.ego.route = summary["route"]["edges"].get<std::vector<std::string>>();
  if (summary.contains("ego") && summary["ego"].contains("base_link_to_front"))
    scenario.ego.base_link_to_front = summary["ego"]["base_link_to_front"].get<double>();
  std::string key = scenario.net;
  for (const std::string& edge : scenario.ego.route) key += "\n" + edge;
  for (int lane : required_exit_lanes(scenario)) key += "\n" + std::to_string(lane);
  // The lane plan depends on what limits the ego's lane changes (lane_change_ego).
  const sumo::LaneChangeEgo ego = lane_change_ego(scenario);
  for (double v : {ego.base_link_to_front, ego.depart_pos, ego.max_speed, ego.max_lateral_accel})
    key += "\n" + std::to_string(v);
  auto& route = routes[key];
  if (!route) {
    auto net = std::make_shared<const sumo::NetIndex>(sumo::NetIndex::load(scenario.net));
    sumo::RoutePlan plan = build_scenario_route(scenario, *net);
    route = std::make_shared<const Route>(Route{std::move(net), std::move(plan)});
  }
  RunRecord record;
  record.rows = read_timeline_csv((dir / run_files::kTimeline).string());
  record.events = read_events_csv((dir / run_files::kEvents).string());
  record.base_link_to_front = scenario.ego.base_link_to_front;
  if (summary.contains("counts")) {
    record.collisions = summary["counts"].value("collisions", 0);
    record.arrived = summary["counts"].value("arrived", false);
  }
  if (summary.contains("lights") && summary["lights"].is_object()) {
    const auto& lights = summary["lights"];
    if (lights.contains("stops"))
      for (const auto& s : lights["stops"]) {
        LightStop stop;
        stop.tl_id = s.value("light", "");
        stop.time = s.value("time", 0.0);
        stop.stop_s = s.value("stop_s", 0.0);
        stop.rest_s = s.value("rest_s", 0.0);
        stop.error = s.value("error", 0.0);
        stop.decision = parse_enum(s.value("decision", ""), JudgeDecision::EmergencyStop, JudgeDecision::Stop);
        stop.worst_level = parse_enum(s.value("level", ""), StopLevel::Emergency, StopLevel::Normal);
        if (s.contains("queued_behind") && s["queued_behind"].is_string()) stop.queued_behind = s["queued_behind"];
        if (s.contains("waiting_at") && s["waiting_at"].is_string()) stop.waiting_at = s["waiting_at"];
        record.stops.push_back(stop);
      }
    if (lights.contains("red_light_violations"))
      for (const auto& v : lights["red_light_violations"])
        record.red_violations.push_back({v.value("light", ""), v.value("time", 0.0), v.value("s_front", 0.0)});
  }
  // The maneuvers' lateral motions: the plan's lines, each lane change's as summary.json recorded it.
  if (summary.contains("lane_changes") && summary["lane_changes"].is_array())
    for (const auto& lc : summary["lane_changes"]) {
      LaneChangeRecord r;
      r.edge = lc.value("edge", "");
      if (lc.contains("lateral_start_s") && lc["lateral_start_s"].is_number()) r.start = lc["lateral_start_s"].get<double>();
      if (lc.contains("lateral_end_s") && lc["lateral_end_s"].is_number()) r.end = lc["lateral_end_s"].get<double>();
      record.lane_changes.push_back(std::move(r));
    }
  record.maneuver_lines = maneuver_lines(plan_lateral(scenario, route->plan, *route->net), record.lane_changes,
                                         scenario.run_params.decider.turn_signal_shift_length_threshold);
  return metrics_json(scenario, route->plan.map, record);
}

}  // namespace signalsim
