#include "report/expectations.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "scenario/input_error.hpp"

namespace signalsim {
namespace {

constexpr double kRestSpeed = 0.1;  // [m/s] "came to rest" for passes_light

struct Span {
  double enter = 0.0;  // route s where the route enters the junction / lanelet
  double leave = 0.0;  // route s where it leaves
};

// The first stretch of consecutive route lanelets in the junction (or the lanelet itself).
std::optional<Span> span_of(const ExpectBlinkerThrough& e, const RouteMap& route) {
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Lanelet& l = route.at(i);
    const bool match = e.junction.empty() ? l.lane_id == e.lanelet : l.junction_id == e.junction;
    if (!match) continue;
    Span span{l.s_start, l.s_end()};
    while (!e.junction.empty() && i + 1 < route.size() && route.at(i + 1).junction_id == e.junction)
      span.leave = route.at(++i).s_end();
    return span;
  }
  return std::nullopt;
}

std::string at(const TimelineRow& row) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(2);
  out << "t=" << row.time << " s, s_front=" << row.s_front << " m";
  return out.str();
}

ExpectationResult check(const ExpectBlinkerThrough& e, const RouteMap& route, const RunRecord& record) {
  const Span span = *span_of(e, route);
  const double from = span.enter - e.lead;
  std::size_t checked = 0;
  for (const TimelineRow& row : record.rows) {
    const double s_base = row.s_front - record.base_link_to_front;
    if (row.s_front < from || s_base > span.leave) continue;
    ++checked;
    if (row.blinker != e.blinker)
      return {"", false, "blinker " + std::string(to_string(row.blinker)) + " at " + at(row)};
  }
  if (checked == 0) return {"", false, "the ego never drove through the span"};
  const double last_base = record.rows.back().s_front - record.base_link_to_front;
  if (last_base <= span.leave) return {"", false, "the run ended before base_link left the span"};
  std::ostringstream out;
  out << checked << " steps from s_front " << from << " m until base_link passed " << span.leave << " m";
  return {"", true, out.str()};
}

// Every step with the front bumper in [from_s, to_s] shows `wanted`.
ExpectationResult check_range(Blinker wanted, double from_s, double to_s, const RunRecord& record) {
  std::size_t checked = 0;
  for (const TimelineRow& row : record.rows) {
    if (row.s_front < from_s || row.s_front > to_s) continue;
    ++checked;
    if (row.blinker != wanted)
      return {"", false, "blinker " + std::string(to_string(row.blinker)) + " at " + at(row)};
  }
  if (checked == 0) return {"", false, "no step had the front bumper in the range"};
  return {"", true, std::to_string(checked) + " steps with blinker " + std::string(to_string(wanted))};
}

ExpectationResult check(const ExpectNoBlinker& e, const RouteMap&, const RunRecord& record) {
  return check_range(Blinker::None, e.from_s, e.to_s, record);
}

ExpectationResult check(const ExpectBlinkerOn& e, const RouteMap&, const RunRecord& record) {
  return check_range(e.blinker, e.from_s, e.to_s, record);
}

ExpectationResult check(const ExpectBlinkerNever& e, const RouteMap&, const RunRecord& record) {
  for (const TimelineRow& row : record.rows)
    if (row.blinker == e.blinker) return {"", false, "blinker " + std::string(to_string(row.blinker)) + " at " + at(row)};
  if (record.rows.empty()) return {"", false, "the run recorded no step"};
  if (!record.arrived) return {"", false, "the run ended before the ego arrived: the rest of the route is unchecked"};
  return {"", true, std::to_string(record.rows.size()) + " steps checked"};
}

ExpectationResult check(const ExpectLateralFollowsPlan& e, const RouteMap&, const RunRecord& record) {
  std::size_t checked = 0;
  double worst = 0.0;
  for (const TimelineRow& row : record.rows) {
    if (!row.planned_offset) continue;
    ++checked;
    const double error = std::abs(row.lateral_offset - *row.planned_offset);
    worst = std::max(worst, error);
    if (error > e.tolerance) {
      std::ostringstream out;
      out << "lateral offset " << row.lateral_offset << " m against planned " << *row.planned_offset << " m at "
          << at(row);
      return {"", false, out.str()};
    }
  }
  if (checked == 0) return {"", false, "no step drove a lateral plan"};
  std::ostringstream out;
  out << checked << " steps, worst deviation " << worst << " m";
  return {"", true, out.str()};
}

// Route s of the stop line of the first approach to `light`, if the route meets it.
std::optional<double> stop_line_of(const std::string& light, const RouteMap& route) {
  for (const Lanelet& l : route.lanelets())
    if (!l.is_internal && l.traffic_light && l.traffic_light->tls_id == light) return l.stop_line_s();
  return std::nullopt;
}

bool is_stop(JudgeDecision d) { return d == JudgeDecision::Stop || d == JudgeDecision::EmergencyStop; }

ExpectationResult check(const ExpectStopsBeforeLight& e, const RouteMap&, const RunRecord& record) {
  for (const LightStop& stop : record.stops) {
    if (stop.tl_id != e.light) continue;
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(3);
    out << "at rest at t=" << stop.time << " s, " << stop.error << " m from the stop point (";
    if (stop.by_judge) out << to_string(stop.decision) << ", " << to_string(stop.worst_level) << " level)";
    else out << "SUMO stopped on its own)";
    if (!stop.queued_behind.empty()) out << ", in the queue behind vehicle '" << stop.queued_behind << "'";
    if (!stop.waiting_at.empty()) out << ", waiting at junction '" << stop.waiting_at << "' before the light";
    return {"", std::abs(stop.error) <= e.tolerance, out.str()};
  }
  return {"", false, "the ego never came to rest for a stop at light " + e.light};
}

ExpectationResult check(const ExpectPassesLight& e, const RouteMap& route, const RunRecord& record) {
  const double line = *stop_line_of(e.light, route);
  bool crossed = false;
  for (const TimelineRow& row : record.rows) {
    if (row.s_front >= line) {
      crossed = true;
      break;
    }
    if (row.tl_id == e.light && is_stop(row.tl_decision))
      return {"", false, "the judge ordered " + std::string(to_string(row.tl_decision)) + " at " + at(row)};
    if (row.speed < kRestSpeed && row.time > record.rows.front().time)
      return {"", false, "the ego came to rest before the stop line at " + at(row)};
  }
  if (!crossed) return {"", false, "the ego never reached the stop line"};
  return {"", true, "crossed the stop line without a stop"};
}

ExpectationResult check(const ExpectEmergencyStopAtLight& e, const RouteMap&, const RunRecord& record) {
  for (const TimelineRow& row : record.rows)
    if (row.tl_id == e.light && row.tl_decision == JudgeDecision::EmergencyStop)
      return {"", true, "emergency stop ordered at " + at(row) + " (zone " + std::string(to_string(row.zone)) + ")"};
  return {"", false, "no emergency stop was ordered at light " + e.light};
}

ExpectationResult check(const ExpectNeverInDilemmaZone& e, const RouteMap&, const RunRecord& record) {
  std::size_t judged = 0;
  for (const TimelineRow& row : record.rows) {
    if (row.tl_id != e.light || !row.stop_distance) continue;
    ++judged;
    if (row.zone == JudgeZone::DilemmaZone || row.tl_decision == JudgeDecision::EmergencyStop)
      return {"", false, std::string(to_string(row.tl_decision)) + " in zone " + std::string(to_string(row.zone)) +
                             " at " + at(row)};
  }
  if (judged == 0) return {"", false, "the judge never judged light " + e.light};
  return {"", true, std::to_string(judged) + " judged steps, none in the dilemma zone"};
}

ExpectationResult check(const ExpectV2iStopAtLight& e, const RouteMap&, const RunRecord& record) {
  for (const TimelineRow& row : record.rows)
    if (row.tl_id == e.light && row.v2i_stop && is_stop(row.tl_decision)) {
      std::ostringstream out;
      out.setf(std::ios::fixed);
      out.precision(2);
      out << std::string(to_string(row.tl_decision)) << " for V2I at " << at(row) << " (light " << row.tl_state;
      if (row.v2i_time_to_red) out << ", red in " << *row.v2i_time_to_red << " s";
      out << ")";
      return {"", true, out.str()};
    }
  return {"", false, "the judge never stopped for a V2I prediction at light " + e.light};
}

ExpectationResult check(const ExpectNeverRunsRed&, const RouteMap&, const RunRecord& record) {
  if (record.red_violations.empty() && !record.arrived)
    return {"", false, "the run ended before the ego arrived: later stop lines are unchecked"};
  if (record.red_violations.empty()) return {"", true, "no stop line crossed on red"};
  const RedLightViolation& v = record.red_violations.front();
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(2);
  out << "crossed the stop line of " << v.tl_id << " on red at t=" << v.time << " s, s_front=" << v.s_front << " m";
  return {"", false, out.str()};
}

ExpectationResult check(const ExpectArrives&, const RouteMap& route, const RunRecord& record) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(2);
  if (record.rows.empty()) return {"", false, "the run recorded no step"};
  const TimelineRow& last = record.rows.back();
  if (record.arrived) {
    out << "arrived at t=" << last.time << " s";
    return {"", true, out.str()};
  }
  out << "the run ended at t=" << last.time << " s with the front at s=" << last.s_front << " m of "
      << route.length() << " m, before the ego arrived";
  return {"", false, out.str()};
}

}  // namespace

void check_expectations_apply(const Scenario& scenario, const RouteMap& route) {
  for (std::size_t i = 0; i < scenario.expect.size(); ++i) {
    std::string light;
    if (const auto* e = std::get_if<ExpectStopsBeforeLight>(&scenario.expect[i])) light = e->light;
    if (const auto* e = std::get_if<ExpectPassesLight>(&scenario.expect[i])) light = e->light;
    if (const auto* e = std::get_if<ExpectEmergencyStopAtLight>(&scenario.expect[i])) light = e->light;
    if (const auto* e = std::get_if<ExpectNeverInDilemmaZone>(&scenario.expect[i])) light = e->light;
    if (const auto* e = std::get_if<ExpectV2iStopAtLight>(&scenario.expect[i])) light = e->light;
    const std::string key = "expect[" + std::to_string(i) + "]";
    if (!light.empty() && !stop_line_of(light, route))
      throw key_error(scenario, key, key + ": traffic light '" + light + "' is not on the ego's route");
    const auto* through = std::get_if<ExpectBlinkerThrough>(&scenario.expect[i]);
    if (!through || span_of(*through, route)) continue;
    const std::string what = through->junction.empty() ? "lanelet '" + through->lanelet + "'"
                                                        : "junction '" + through->junction + "'";
    throw key_error(scenario, key, key + ": " + what + " is not on the ego's route");
  }
}

std::vector<ExpectationResult> evaluate_expectations(const Scenario& scenario, const RouteMap& route,
                                                     const RunRecord& record) {
  std::vector<ExpectationResult> results;
  for (const Expectation& expectation : scenario.expect) {
    ExpectationResult r = std::visit([&](const auto& e) { return check(e, route, record); }, expectation);
    r.description = describe(expectation);
    results.push_back(std::move(r));
  }
  // Built in: a lane change the scenario needs but the ego gave up is a failure, asked for or not.
  for (const LaneChangeRecord& lc : record.lane_changes)
    if (lc.phase == "missed") {
      std::ostringstream detail;
      detail << "missed: not approved before base_link passed its last start";
      if (lc.blinker_on_time) detail << " (blinker on since t=" << *lc.blinker_on_time << " s)";
      results.push_back({"lane_change on " + lc.edge + " executed", false, detail.str()});
    }
  // Built in: a run the stuck rule ended (step/stuck_watch) cannot arrive: a failure.
  if (record.not_arrived && record.not_arrived->reason == "stuck")
    results.push_back({"ego arrives (not stuck)", false, record.not_arrived->detail});
  return results;
}

}  // namespace signalsim
