#include "report/outputs.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "report/atomic_file.hpp"
#include "core/number_text.hpp"
#include "report/judge_curves.hpp"
#include "report/metrics.hpp"
#include "report/run_files.hpp"
#include "report/summary_sections.hpp"
#include "report/sut_agreement.hpp"
#include "report/fleet_outputs.hpp"
#include "scenario/take_over.hpp"
#include "session/sumo_session.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

void write_atomically(const std::string& path, const std::string& content) { write_file_atomically(path, content); }

// Input text is checked to be UTF-8 when it is loaded; anything else that reaches a summary (a net's
// ids, SUMO's messages) is written with U+FFFD in place of a bad byte rather than losing the run.
std::string json_text(const nlohmann::ordered_json& summary) {
  return summary.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

nlohmann::ordered_json parameters_json(const ParameterSet& set) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const ParameterSpec& spec : parameter_schema()) {
    std::visit([&](const auto& v) { out[spec.name] = v; }, set.values().at(spec.name));
  }
  return out;
}

// Every parameter's value and where it came from ("default", "<file>:<line>", "country jp", "set",
// "--set"), with its Autoware place when that differs from its name.
nlohmann::ordered_json parameter_sources_json(const ParameterSet& set) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const ParameterSpec& spec : parameter_schema()) {
    nlohmann::ordered_json entry;
    std::visit([&](const auto& v) { entry["value"] = v; }, set.values().at(spec.name));
    entry["from"] = set.origin(spec.name);
    if (!spec.autoware_key.empty()) entry["autoware_key"] = spec.autoware_key;
    out[spec.name] = entry;
  }
  return out;
}

// The parameter files with keys signalsim does not use, and those keys.
nlohmann::ordered_json parameter_files_json(const ParameterSet& set) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const UnusedParameters& file : set.unused()) out.push_back({{"file", file.file}, {"unused_keys", file.keys}});
  return out;
}

// Which SUMO ran with which files and options, and what it said (counted from its log).
nlohmann::ordered_json sumo_json(const Scenario& scenario, const RunSumoInfo& info) {
  nlohmann::ordered_json out;
  out["backend"] = std::string(sumo::to_string(info.backend));
  if (!info.endpoint.empty()) out["endpoint"] = info.endpoint;
  out["sumocfg"] = scenario.sumo.sumocfg;
  out["route_files"] = scenario.sumo.route_files;
  out["additional"] = scenario.additional;
  // Paths in the run's own directory are written relative to it: the summary is the same whatever
  // --out (a batch's run folder or a run of its own).
  nlohmann::ordered_json options = nlohmann::ordered_json::array();
  const std::string prefix = info.out_dir.empty() ? std::string() : fs::path(info.out_dir).lexically_normal().string() + "/";
  for (const std::string& a : info.args)
    options.push_back(!prefix.empty() && a.rfind(prefix, 0) == 0 ? a.substr(prefix.size()) : a);
  out["options"] = options;
  if (!info.server_options.empty()) {
    nlohmann::ordered_json server = nlohmann::ordered_json::object();
    for (const auto& [name, value] : info.server_options) server[name] = value;
    out["server_options"] = server;
  }
  if (!info.notes.empty()) out["notes"] = info.notes;
  if (!scenario.sumo.sumocfg.empty())
    out["sumocfg_used"] = {{"used", scenario.sumo.cfg_used},
                           {"replaced_by_scenario", scenario.sumo.cfg_overridden},
                           {"ignored", scenario.sumo.cfg_ignored}};
  out["log"] = info.log.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(fs::path(info.log).filename().string());
  if (info.log_counts.read)
    out["messages"] = {{"warnings", info.log_counts.warnings},
                       {"errors", info.log_counts.errors},
                       {"teleports", info.log_counts.teleports},
                       {"emergency_braking", info.log_counts.emergency_braking},
                       {"ego_emergency_braking", info.log_counts.ego_emergency_braking},
                       {"collisions", info.log_counts.collisions}};
  return out;
}

// The ego as it ran: the scenario's vehicle with what SUMO departed (id, type, width, departure).
nlohmann::ordered_json ego_json(const Scenario& scenario, const sumo::EgoVehicle& departed) {
  nlohmann::ordered_json ego;
  ego["id"] = departed.id.empty() ? std::string(sumo::kDefaultEgoId) : departed.id;
  ego["taken_over"] = !scenario.ego.id.empty();
  ego["type"] = departed.type;
  ego["length"] = as_written(scenario.ego.length, 3);
  ego["width"] = departed.width;
  ego["base_link_to_front"] = as_written(scenario.ego.base_link_to_front, 3);
  ego["base_link_to_rear"] = as_written(scenario.ego.length - scenario.ego.base_link_to_front, 3);
  if (!scenario.ego.vehicle_info.empty()) {
    ego["vehicle_info"] = scenario.ego.vehicle_info;
    ego["vehicle_info_unused_keys"] = scenario.ego.vehicle_info_unused;
  }
  ego["max_speed"] = scenario.ego.max_speed;
  ego["accel"] = scenario.ego.accel;
  ego["decel"] = scenario.ego.decel;
  ego["type_decel"] = departed.decel;
  ego["emergency_decel"] = scenario.ego.emergency_decel;
  ego["depart_time"] = as_written(departed.depart_time, 3);
  ego["depart_lane"] = departed.depart_lane;
  ego["depart_pos"] = as_written(departed.depart_pos, 3);
  ego["depart_speed"] = as_written(departed.depart_speed, 3);
  ego["source"] = ego_sources(scenario, departed.type);
  return ego;
}

}  // namespace

std::string_view to_string(RunStatus status) {
  switch (status) {
    case RunStatus::Passed: return "passed";
    case RunStatus::Failed: return "failed";
    case RunStatus::NoExpectations: return "no_expectations";
    case RunStatus::Error: break;
  }
  return "error";
}


RunStatus run_status(const std::vector<ExpectationResult>& results) {
  if (results.empty()) return RunStatus::NoExpectations;
  for (const ExpectationResult& r : results)
    if (!r.passed) return RunStatus::Failed;
  return RunStatus::Passed;
}

RunStatus run_status(const std::vector<ExpectationResult>& results, const std::vector<LawVerdict>& law) {
  return law_failed(law) > 0 ? RunStatus::Failed : run_status(results);
}

// One row a step: numbers appended in place (core/number_text.hpp), no temporary strings.
void write_timeline_csv(const std::string& path, const std::vector<TimelineRow>& rows, TimelineColumns columns) {
  std::string out =
      "time,s_front,x,y,speed,accel,edge,lane,lateral_offset,blinker,blinker_source,sumo_signals,"
      "tl_id,tl_state,tl_observed,tl_decision,stop_distance,judge_distance,yellow_lamp_line,zone,stop_s,"
      "stop_level,planned_offset,planned_speed,speed_limited_by,sumo_speed,sumo_limited_by,leader,leader_gap";
  if (columns.v2i) out += ",v2i_time_to_red";
  if (columns.decider) out += ",ref_blinker,ref_blinker_source";
  if (columns.light_judge) out += ",ref_tl_decision,tl_reason";
  out += '\n';
  out.reserve(out.size() + rows.size() * 160);
  const auto number = [&out](double v) {
    append_fixed(out, v, 3);
    out += ',';
  };
  const auto optional_number = [&out](const std::optional<double>& v) {
    if (v) append_fixed(out, *v, 3);
  };
  const auto text = [&out](std::string_view v) {
    out += v;
    out += ',';
  };
  for (const TimelineRow& r : rows) {
    number(r.time);
    number(r.s_front);
    number(r.x);
    number(r.y);
    number(r.speed);
    number(r.accel);
    text(r.edge);
    text(r.lane);
    number(r.lateral_offset);
    text(to_string(r.blinker));
    text(to_string(r.blinker_source));
    if (r.sumo_signals >= 0) append_integer(out, r.sumo_signals);
    out += ',';
    text(r.tl_id);
    if (r.tl_state) out += r.tl_state;
    out += ',';
    text(r.tl_observed);
    text(r.tl_id.empty() ? std::string_view() : to_string(r.tl_decision));
    if (r.stop_distance) {
      number(*r.stop_distance);
      number(r.judge_distance);
      number(r.yellow_lamp_line);
    } else {
      out += ",,,";
    }
    text(r.zone == JudgeZone::None ? std::string_view() : to_string(r.zone));
    optional_number(r.stop_s);
    out += ',';
    text(r.stop_level ? to_string(*r.stop_level) : std::string_view());
    optional_number(r.planned_offset);
    out += ',';
    optional_number(r.planned_speed);
    out += ',';
    text(r.speed_limited_by);
    optional_number(r.sumo_speed);
    out += ',';
    text(r.sumo_limited_by);
    text(r.leader);
    optional_number(r.leader_gap);
    if (columns.v2i) {
      out += ',';
      optional_number(r.v2i_time_to_red);
    }
    if (columns.decider) {
      out += ',';
      if (r.ref_blinker) out += to_string(*r.ref_blinker);
      out += ',';
      if (r.ref_blinker) out += to_string(r.ref_blinker_source);
    }
    if (columns.light_judge) {
      out += ',';
      if (r.ref_tl_decision) out += to_string(*r.ref_tl_decision);
      out += ',';
      out += r.tl_reason;  // the SUT's text, cleaned by the step core: no comma, quote or line break
    }
    out += '\n';
  }
  write_atomically(path, out);
}

void write_events_csv(const std::string& path, const std::vector<TimelineEvent>& events) {
  std::string out = "time,s_front,kind,from,to,source\n";
  for (const TimelineEvent& e : events) {
    append_fixed(out, e.time, 3);
    out += ',';
    append_fixed(out, e.s_front, 3);
    for (const std::string* field : {&e.kind, &e.from, &e.to, &e.source}) {
      out += ',';
      out += *field;
    }
    out += '\n';
  }
  write_atomically(path, out);
}

void write_run_outputs(const std::string& dir, const Scenario& scenario, const sumo::RoutePlan& plan,
                       const RunRecord& record, const std::vector<ExpectationResult>& results,
                       RunStatus status, const std::vector<LawVerdict>* law) {
  fs::create_directories(dir);
  fs::remove(fs::path(dir) / run_files::kSummary);  // a stale summary must never describe new files
  write_timeline_csv((fs::path(dir) / run_files::kTimeline).string(), record.rows,
                     {record.v2i, !record.decider_sut.empty(), !record.light_judge_sut.empty()});
  write_events_csv((fs::path(dir) / run_files::kEvents).string(), record.events);
  // The judge's curves as this run's parameters give them, when a light was ahead (dilemma.png reads them).
  const bool light_ahead =
      std::any_of(record.rows.begin(), record.rows.end(), [](const TimelineRow& r) { return !r.tl_id.empty(); });
  if (light_ahead)
    write_atomically((fs::path(dir) / run_files::kJudgeCurves).string(), judge_curves_csv(scenario.run_params.judge));
  if (record.fleet) write_fleet_events_csv((fs::path(dir) / run_files::kFleetEvents).string(), *record.fleet);

  nlohmann::ordered_json summary;
  summary["scenario"] = scenario.name;
  summary["file"] = scenario.path;
  summary["net"] = scenario.net;
  summary["status"] = to_string(status);
  summary["driver"] = to_string(record.driver);
  if (!scenario.warnings.empty()) summary["notes"] = scenario.warnings;  // only then: other summaries as they were
  summary["seed"] = scenario.seed;
  summary["country"] = scenario.country;
  summary["step_length"] = scenario.step_length;
  summary["duration"] = scenario.duration;
  // Without an ego (docs/fleet.md "Without an ego"): no ego and no route; how long the traffic ran.
  summary["ego"] = scenario.has_ego ? ego_json(scenario, record.sumo.ego) : nlohmann::ordered_json();
  if (scenario.has_ego)
    summary["route"] = {{"edges", scenario.ego.route},
                        {"lanelets", plan.map.size()},
                        {"length", as_written(plan.map.length(), 3)},
                        {"lane_changes", plan.lane_changes}};
  else
    summary["route"] = nullptr;
  if (record.egoless)
    summary["egoless"] = {{"steps", record.egoless->steps},
                          {"end_time", as_written(record.egoless->end_time, 3)},
                          {"ended", record.egoless->ended}};
  summary["counts"] = counts_json(record, scenario.sumo.begin);
  summary["not_arrived"] = not_arrived_json(record);
  summary["off_plan"] = off_plan_json(record);
  summary["lights"] = lights_json(record);
  summary["lane_changes"] = lane_changes_json(record);
  summary["metrics"] = metrics_json(scenario, plan.map, record);
  // Only with a system under test of the role (docs/decider.md): every other summary stays as it was.
  if (!record.decider_sut.empty()) summary["decider"] = decider_agreement_json(scenario, plan.map, record);
  if (!record.light_judge_sut.empty()) summary["light_judge"] = light_judge_agreement_json(record);
  if (record.fleet) summary["fleet"] = fleet_json(*record.fleet);  // fleet mode only (docs/fleet.md)
  nlohmann::ordered_json expectations = nlohmann::ordered_json::array();
  for (const ExpectationResult& r : results)
    expectations.push_back({{"expectation", r.description}, {"passed", r.passed}, {"detail", r.detail}});
  summary["expectations"] = expectations;
  summary["law"] = law ? law_json(record, *law) : law_json(record, law_verdicts(scenario, plan.map, record));
  summary["parameters"] = parameters_json(scenario.params);
  summary["parameter_sources"] = parameter_sources_json(scenario.params);
  summary["parameter_files"] = parameter_files_json(scenario.params);
  summary["sumo"] = sumo_json(scenario, record.sumo);
  write_atomically((fs::path(dir) / run_files::kSummary).string(), json_text(summary));
}

void clear_run_outputs(const std::string& dir) {
  fs::create_directories(dir);
  for (const char* name : run_files::kRunOutputs) fs::remove(fs::path(dir) / name);
}

void write_error_summary(const std::string& dir, const Scenario* scenario, const std::string& message,
                         const std::string& status) {
  fs::create_directories(dir);
  for (const char* name : run_files::kRunOutputs) fs::remove(fs::path(dir) / name);
  nlohmann::ordered_json summary;
  summary["scenario"] = scenario ? scenario->name : "";
  summary["file"] = scenario ? scenario->path : "";
  summary["status"] = status;
  summary["error"] = message;
  write_atomically((fs::path(dir) / run_files::kSummary).string(), json_text(summary));
}

}  // namespace signalsim
