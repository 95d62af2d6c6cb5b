// Measuring each light of a run: state at the line, violation, the judge's decision and zone, the
// stop position error (see light_metrics.hpp).
#include "report/light_metrics.hpp"

#include <algorithm>
#include <limits>
#include <map>

#include "core/number_text.hpp"

namespace signalsim {

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
    m.stop_line_s = rounded(l.stop_line_s(), 3);
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
        m.stop_position_error = rounded(stop.error, 3);
        break;
      }
    for (const RedLightViolation& v : record.red_violations)
      if (v.tl_id == m.id && v.time >= t_from && v.time <= t_to) m.red_light_violation = true;
    from_row = std::min(k, rows.size());
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace signalsim
