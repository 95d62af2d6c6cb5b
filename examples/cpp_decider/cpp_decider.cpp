// An example plugin for signalsim (docs/decider.md "The C ABI"): a turn-signal decider and a
// traffic-light judge in plain C++, with nothing but include/signalsim/decider_plugin.h and the
// standard library.
//
// The decider keeps only the intersection rule of docs/behaviour.md §T4 (no roundabouts, no
// lane-change or other maneuver requests):
//   - consecutive route lanelets turning the same way (left or right) form a group;
//   - a group is within reach when its first lanelet starts less than the search distance ahead of
//     the front bumper: the lanelet's turn_signal_distance if it has one, else
//     turn_signal_search_time * speed + turn_signal_intersection_search_distance;
//   - the first cycle a group comes within reach, base_link's position is remembered as its
//     desired start; the blinker may be on from there until base_link leaves the group (desired end);
//   - of the groups within reach, the first whose end base_link has not passed decides.
// On the bundled scenarios whose only signal sections are intersection turns it decides exactly as
// signalsim's reference (tests/integration/sut_example_plugin_test.sh).
//
// The light judge is a simple rule, not Autoware's: stop while the last message perception delivered
// for the light shows a red or amber circle, and while messages without any element follow such a
// message (a light seen red and then not recognised is still red); go otherwise.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "signalsim/decider_plugin.h"

namespace {

struct Decider {
  std::vector<ss_lanelet> lanelets;
  std::vector<std::vector<ss_point>> centerlines;
  std::vector<double> ends;  // [m] s_end per lanelet
  double search_time = 3.0, search_distance = 30.0, angle_threshold = 15.0;  // [s], [m], [deg]
  std::map<size_t, double> desired_starts;  // group's first lanelet -> base_link s when it came within reach
};

// The group's required end (docs/behaviour.md §T7, without the reference's resampling): along the
// group's joined centre line, the last point whose heading still differs from the final heading by
// the angle threshold, as route s.
double required_end(const Decider& d, size_t first, size_t last) {
  std::vector<ss_point> line;
  for (size_t i = first; i <= last; ++i)
    for (const ss_point& p : d.centerlines[i]) {
      bool taken = false;
      for (const ss_point& q : line) taken = taken || std::hypot(p.x - q.x, p.y - q.y) < 0.01;
      if (!taken) line.push_back(p);
    }
  const double s_first = d.lanelets[first].s_start, s_last = d.lanelets[last].s_end;
  if (line.size() < 2) return s_first;
  std::vector<double> arc(line.size(), 0.0), yaw(line.size(), 0.0);
  for (size_t i = 1; i < line.size(); ++i) arc[i] = arc[i - 1] + std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
  for (size_t i = 0; i + 1 < line.size(); ++i) yaw[i] = std::atan2(line[i + 1].y - line[i].y, line[i + 1].x - line[i].x);
  yaw.back() = yaw[line.size() - 2];
  const double scale = arc.back() > 0.0 ? (s_last - s_first) / arc.back() : 1.0;
  const double pi = std::acos(-1.0), threshold = d.angle_threshold * pi / 180.0;
  for (size_t i = line.size(); i-- > 0;) {
    const double diff = std::remainder(yaw[i] - yaw.back(), 2.0 * pi);
    if (std::abs(diff) >= threshold) return s_first + arc[i] * scale;
  }
  return s_first + arc.back() * scale;
}

bool is_turn(ss_turn_direction d) { return d == SS_TURN_LEFT || d == SS_TURN_RIGHT; }

double parameter(const ss_run* run, const char* name, double fallback) {
  for (size_t i = 0; i < run->parameter_count; ++i)
    if (std::strcmp(run->parameters[i].key, name) == 0) return std::strtod(run->parameters[i].value, nullptr);
  return fallback;
}

// One cycle of the intersection rule: the blinker for the ego at this step.
ss_blinker decide(Decider& d, const ss_step& step) {
  const double speed = step.ego.speed, front = step.ego.s_front, base = step.ego.s_base;
  const double base_search = d.search_time * speed + d.search_distance;
  for (size_t i = step.window_first; i < step.window_last && i < d.lanelets.size(); ++i) {
    const ss_lanelet& first = d.lanelets[i];
    if (first.roundabout_role != SS_ROUNDABOUT_NONE || !is_turn(first.turn_direction)) continue;
    size_t last = i;  // the group: following lanelets turning the same way (beyond the window too)
    while (last + 1 < d.lanelets.size() && d.lanelets[last + 1].turn_direction == first.turn_direction) ++last;
    const size_t group = i;
    i = last;  // the next group starts after this one
    if (d.ends[last] - base < 0.0) {  // base_link has left the group
      d.desired_starts.erase(group);
      continue;
    }
    const double search = std::isnan(first.turn_signal_distance) ? base_search : first.turn_signal_distance;
    if (search <= first.s_start - front) continue;  // not within reach yet
    const double desired_start = d.desired_starts.try_emplace(group, base).first->second;
    // Of the groups within reach, the first whose required end base_link has not passed decides (the
    // last one in any case).
    bool later_in_reach = false;
    for (size_t k = last + 1; k < step.window_last && k < d.lanelets.size() && !later_in_reach; ++k)
      later_in_reach = is_turn(d.lanelets[k].turn_direction) && d.lanelets[k].roundabout_role == SS_ROUNDABOUT_NONE &&
                       (std::isnan(d.lanelets[k].turn_signal_distance) ? base_search : d.lanelets[k].turn_signal_distance) >
                           d.lanelets[k].s_start - front;
    if (later_in_reach && required_end(d, group, last) - base < 0.0) continue;
    if (desired_start - front > 0.0) return SS_BLINKER_NONE;  // the front has not reached it
    return first.turn_direction == SS_TURN_LEFT ? SS_BLINKER_LEFT : SS_BLINKER_RIGHT;
  }
  return SS_BLINKER_NONE;
}

// The light judge's memory: per light (tls id and link), whether it was last seen red or amber.
struct Judge {
  std::map<std::pair<std::string, int>, bool> stop;
};

bool shows_stop(const ss_light& light) {
  for (size_t i = 0; i < light.element_count; ++i) {
    const ss_signal_element& e = light.elements[i];
    if (std::strcmp(e.shape, "circle") == 0 && (std::strcmp(e.color, "red") == 0 || std::strcmp(e.color, "amber") == 0))
      return true;
  }
  return false;
}

}  // namespace

extern "C" {

uint32_t signalsim_plugin_abi_version(void) { return SIGNALSIM_PLUGIN_ABI_VERSION; }

const char* signalsim_plugin_name(void) { return "cpp_decider example 1.0"; }

void* signalsim_decider_create(const ss_run* run, char* error, size_t error_size) {
  Decider* d = new (std::nothrow) Decider;
  if (!d) {
    std::snprintf(error, error_size, "out of memory");
    return nullptr;
  }
  // The lanelets are copied without what they point to: this decider reads only numbers of them.
  d->lanelets.assign(run->lanelets, run->lanelets + run->lanelet_count);
  for (ss_lanelet& l : d->lanelets) {
    l.id = l.edge_id = l.junction_id = l.roundabout_id = "";
    d->centerlines.emplace_back(l.centerline, l.centerline + l.centerline_size);
    l.tags = nullptr, l.tag_count = 0, l.centerline = nullptr, l.centerline_size = 0;
    l.successor_turn_directions = nullptr, l.successor_turn_direction_count = 0;
    d->ends.push_back(l.s_end);
  }
  d->search_time = parameter(run, "turn_signal_search_time", 3.0);
  d->search_distance = parameter(run, "turn_signal_intersection_search_distance", 30.0);
  d->angle_threshold = parameter(run, "turn_signal_intersection_angle_threshold_deg", 15.0);
  return d;
}

int signalsim_decider_step(void* decider, const ss_step* step, ss_blinker* blinker, char* error, size_t error_size) {
  (void)error, (void)error_size;
  *blinker = decide(*static_cast<Decider*>(decider), *step);
  return 0;
}

void signalsim_decider_destroy(void* decider) { delete static_cast<Decider*>(decider); }

void* signalsim_light_judge_create(const ss_run* run, char* error, size_t error_size) {
  (void)run;
  Judge* j = new (std::nothrow) Judge;
  if (!j) std::snprintf(error, error_size, "out of memory");
  return j;
}

int signalsim_light_judge_step(void* judge, const ss_step* step, ss_light_answer* answers, char* error,
                               size_t error_size) {
  (void)error, (void)error_size;
  Judge& j = *static_cast<Judge*>(judge);
  for (size_t i = 0; i < step->light_count; ++i) {
    const ss_light& light = step->lights[i];
    bool& stop = j.stop[{light.tls_id, light.link_index}];
    if (light.delivered && light.element_count > 0) stop = shows_stop(light);
    answers[i].decision = stop ? SS_LIGHT_STOP : SS_LIGHT_GO;
    std::snprintf(answers[i].reason, sizeof answers[i].reason, "%s", stop ? "red or amber circle" : "no red");
  }
  return 0;
}

void signalsim_light_judge_destroy(void* judge) { delete static_cast<Judge*>(judge); }

}  // extern "C"
