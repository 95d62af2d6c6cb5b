// Reading obstacles and maneuvers through their key tables (scenario_keys.hpp).
#include "scenario/maneuver_reading.hpp"

#include "scenario/input_error.hpp"
#include "scenario/scenario_keys.hpp"

namespace signalsim {
namespace {

AvoidManeuver read_avoid(const YamlFields& fields) {
  AvoidManeuver a;
  a.obstacle = fields.text("obstacle");
  a.clearance = fields.number("clearance");
  a.side = fields.choice("side");
  a.length = fields.number("length");
  a.approval_delay = fields.number("approval_delay");
  fields.finish();
  return a;
}

PullOutManeuver read_pull_out(const YamlFields& fields) {
  PullOutManeuver m;
  m.offset = fields.required_number("offset");
  m.length = fields.number("length");
  m.at = fields.number("at");
  m.backward = fields.number("backward");
  m.engage_delay = fields.number("engage_delay");
  fields.finish();
  return m;
}

PullOverManeuver read_pull_over(const YamlFields& fields) {
  PullOverManeuver m;
  m.edge = fields.text("edge");
  m.pos = fields.required_number("pos");
  m.offset = fields.required_number("offset");
  m.length = fields.number("length");
  fields.finish();
  return m;
}

LaneChangeManeuver read_lane_change(const YamlFields& fields) {
  LaneChangeManeuver m;
  m.edge = fields.text_or("edge");
  if (!m.edge.empty()) m.to_lane = static_cast<int>(fields.required_number("to_lane"));
  m.at = fields.required_number("at");
  m.length = fields.number("length");
  m.approval_delay = fields.number("approval_delay");
  fields.finish();
  return m;
}

}  // namespace

void read_obstacles(const YamlFields& top, const std::string& path, Scenario& s) {
  const YAML::Node obstacles = top.node("obstacles");
  if (!obstacles || obstacles.IsNull()) return;
  if (!obstacles.IsSequence()) top.fail("obstacles", "expected a list of obstacles");
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    YamlFields fields(obstacles[i], path, "obstacles[" + std::to_string(i) + "]", obstacle_keys());
    ObstacleSpec o;
    o.id = fields.text("id");
    o.edge = fields.text("edge");
    o.lane = fields.integer("lane");
    o.pos = fields.required_number("pos");
    o.length = fields.number("length");
    fields.finish();
    for (const ObstacleSpec& other : s.obstacles)
      if (other.id == o.id) fields.fail("id", "'" + o.id + "' is declared twice");
    s.obstacles.push_back(o);
  }
}

void read_maneuvers(const YamlFields& top, const std::string& path, Scenario& s) {
  const YAML::Node maneuvers = top.node("maneuvers");
  if (!maneuvers || maneuvers.IsNull()) return;
  if (!maneuvers.IsSequence()) top.fail("maneuvers", "expected a list of maneuvers");
  const KeyTable& kinds = maneuver_kinds();
  for (std::size_t i = 0; i < maneuvers.size(); ++i) {
    const YAML::Node item = maneuvers[i];
    const std::string where = "maneuvers[" + std::to_string(i) + "]";
    if (!item.IsMap() || item.size() != 1)
      throw InputError(path, yaml_line(item), where + ": each maneuver is a one-key mapping, e.g. "
                                                      "'- lane_change: {at: 40, length: 50}'", where);
    const std::string kind = item.begin()->first.Scalar();
    const YAML::Node body = item.begin()->second;
    if (!kinds.find(kind))
      throw InputError(path, yaml_line(item.begin()->first),
                       where + ": unknown maneuver '" + kind + "' (known: " + kinds.names() + ")", where);
    if ((kind == "pull_out" && s.pull_out) || (kind == "pull_over" && s.pull_over))
      throw InputError(path, yaml_line(item), where + ": at most one " + kind, where);
    const YamlFields fields(body, path, where + "." + kind, kinds.table_of(kind));
    if (kind == "avoid") {
      s.avoids.push_back(read_avoid(fields));
      s.avoids.back().key = where;
    } else if (kind == "pull_out") {
      s.pull_out = read_pull_out(fields);
      s.pull_out->line = yaml_line(item);
      s.pull_out->key = where;
    } else if (kind == "pull_over") {
      s.pull_over = read_pull_over(fields);
      s.pull_over->key = where;
    } else {
      LaneChangeManeuver m = read_lane_change(fields);
      m.key = where;
      for (const LaneChangeManeuver& other : s.lane_changes)
        if (other.edge == m.edge)
          throw InputError(path, yaml_line(item), where + ": a second lane_change on " +
                                                      (m.edge.empty() ? std::string("the first edge") : "edge '" + m.edge + "'") +
                                                      " (at most one per edge)", where);
      s.lane_changes.push_back(m);
    }
  }
}

}  // namespace signalsim
