// The expectation rules: windows per section, their narrowing by the others, emission.
#include "law/expectation_rules.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/number_text.hpp"

namespace signalsim::law {
namespace {

constexpr double kScanStep = 0.1;      // [m] resolution of the activation scan
constexpr double kMinBlinkerOn = 1.0;  // [m] a shorter guaranteed stretch is not stated
constexpr double kMinEntryQuiet = 2.0; // [m] a shorter no-entry-signal stretch is not stated
// (and neither is a stretch shorter than the step's travel, step_room)

std::string name_of(const Section& s) {
  std::string what = s.maneuver.empty() ? to_string(s.kind) : s.maneuver;
  std::replace(what.begin(), what.end(), '_', ' ');
  if (s.kind == SectionKind::Turn) what = std::string(to_string(s.side)) + " turn";
  return what + " " + (s.kind == SectionKind::LaneChange ? "on edge " : "at ") + s.id;
}

// Upper bound of the search distance of a turn or an entry (docs/behaviour.md §T4.1, §T5.1).
double search_upper(const Section& s, const SpeedBounds& speed, const RuleParameters& p) {
  if (s.search_override) return *s.search_override;
  const double reach = p.search_time * 40.0 + s.search_distance;  // beyond any speed the planner gives
  return p.search_time * (speed.max_planned(s.start - reach, s.start) + kSpeedSlack) + s.search_distance;
}

struct Activation {
  double from = 0.0;
  std::string why;
};

// The front position from which the request of a turn or an entry is certainly stored (§T4.4): the
// lowest s such that start - s' < search(lower speed at s') for every s' in [s, start].
Activation guaranteed_activation(const Section& s, const SpeedBounds& speed, const RuleParameters& p,
                                 double depart) {
  const auto search_at = [&](double pos) {
    return s.search_override ? *s.search_override : p.search_time * speed.lower(pos) + s.search_distance;
  };
  // Scan back from the start on a 0.1 m grid (positions start - k * step, no accumulated error).
  std::size_t k = 0;
  const auto grid = [&](std::size_t i) { return s.start - static_cast<double>(i) * kScanStep; };
  while (grid(k + 1) >= depart && s.start - grid(k + 1) < search_at(grid(k + 1))) ++k;
  Activation a;
  a.from = grid(k);
  if (grid(k + 1) < depart) {
    a.from = depart;
    a.why = "within its search distance from the departure (the first step stores the desired start, docs/behaviour.md §T4.4)";
    return a;
  }
  const double failing = grid(k + 1);
  if (s.search_override) {
    a.why =
        "the lanelet's turn_signal_distance " + rounded_fixed(*s.search_override, 1) + " m (docs/behaviour.md §T4.3)";
  } else {
    const double v = speed.lower(failing);
    a.why = "search " + rounded_fixed(p.search_time, 1) + " s x " + rounded_fixed(v, 1) + " m/s + " +
            rounded_fixed(s.search_distance, 1) + " m = " + rounded_fixed(search_at(failing), 1) +
            " m (docs/behaviour.md §T4.1/§T5.1) at the lowest speed the ego can have there (" +
            speed.lower_reason(failing) + ")";
  }
  return a;
}

struct Window {
  double possible_from = 0.0, possible_to = 0.0;  // P
  double from = 0.0, to = 0.0;                    // G
  std::string from_why, to_why;
};

// A lane change (or a run's other maneuver): possible from max(v * search_time,
// minimum_search_distance) before its earliest start until the motion ends; the generator's are never
// guaranteed, a run's approved lane change from its approval until base_link ends the motion.
Window maneuver_window(const Section& s, const SpeedBounds& speed, const RuleParameters& p) {
  Window w;
  const double reach_to = s.motion_end ? std::max(s.lane_change_at, *s.motion_end) : s.lane_change_at;
  const double v = speed.max_planned(s.lane_change_at - 150.0, reach_to) + kSpeedSlack;
  w.possible_from = s.lane_change_at - std::max(v * p.search_time, p.minimum_search_distance) - kMargin;
  w.possible_to = s.end + kMargin;  // the lateral motion ends before the front leaves the edge
  if (s.motion_end) w.possible_to = std::max(w.possible_to, *s.motion_end + p.base_link_to_front + kMargin);
  w.from = w.to = w.possible_from;  // never guaranteed
  if (s.approval_front && s.motion_end && (s.side == Side::Left || s.side == Side::Right)) {
    w.from = *s.approval_front;
    w.from_why = "from its approval (the module signals before it approves, docs/behaviour.md §T8.2)";
    w.to = *s.motion_end + p.base_link_to_front;
    w.to_why = "until base_link ends the lateral motion (the module runs until then, docs/behaviour.md §T8.2)";
  }
  return w;
}

Window initial_window(const Section& s, const SpeedBounds& speed, const RuleParameters& p, double depart) {
  Window w;
  const double b2f = p.base_link_to_front;
  switch (s.kind) {
    case SectionKind::Turn:
    case SectionKind::RoundaboutEntry: {
      w.possible_from = s.start - search_upper(s, speed, p);
      const Activation a = guaranteed_activation(s, speed, p, depart);
      w.from = a.from;
      w.from_why = a.why;
      break;
    }
    case SectionKind::RoundaboutExit:
      w.possible_from = s.exit_desired_start;
      w.from = std::max(s.exit_desired_start, depart);
      w.from_why = s.exit_desired_start < s.start - 1e-6
                       ? "from the start of the enable_exit_turn_signal chain at s " +
                             rounded_fixed(s.exit_desired_start, 1) +
                             " (docs/behaviour.md §T5.3; the exit-signal marking from the previous exit)"
                       : "from the exit lanelet's start: exit signals have no search distance (docs/behaviour.md "
                         "§T5.3, §T12.1.8)";
      break;
    case SectionKind::LaneChange: return maneuver_window(s, speed, p);
  }
  w.possible_to = s.end + b2f;  // base_link leaves the section: its desired end (§T4.3, §T5.2, §T5.3)
  w.to = w.possible_to;
  if (s.persistent_end) w.possible_to = std::max(w.possible_to, *s.persistent_end + b2f);  // §T5.2 persistence
  w.to_why = "until base_link leaves it (its desired end, docs/behaviour.md §T4.3/§T5)";
  return w;
}

// A stretch shorter than this may hold no step at all: the ego moves up to upper speed x step per
// step (the generated scenarios' 0.1 s), so a stated stretch is at least that and a metre more.
double step_room(const SpeedBounds& speed, double from, double to, double step_length) {
  return speed.max_planned(from, to) * step_length + kSpeedSlack * step_length + 1.0;
}

bool overlaps(double a_from, double a_to, double b_from, double b_to) { return a_from <= b_to && b_from <= a_to; }

// Narrows X's guaranteed window by Y (see the header).
void narrow(const Section& x, Window& wx, const Section& y, const Window& wy, const RuleParameters& p) {
  if (y.side == Side::None || (y.side == x.side && y.kind != SectionKind::LaneChange)) return;
  if (!overlaps(wx.from, wx.to, wy.possible_from, wy.possible_to)) return;
  const double b2f = p.base_link_to_front;
  const bool y_first = y.kind == SectionKind::LaneChange ? y.end <= x.start + 1e-6 : y.start < x.start;
  if (y_first) {
    const double from = wy.possible_to + kMargin;
    if (from > wx.from) {
      wx.from = from;
      wx.from_why = "after base_link leaves the " + name_of(y) + " (its request may win until then, docs/behaviour.md §T6.2)";
    }
    return;
  }
  double to = wx.to;
  std::string why;
  if (y.kind == SectionKind::LaneChange) {
    to = x.start + b2f - kMargin;
    why = "until base_link reaches its start: the " + name_of(y) +
          " follows and PRIOR_WINS keeps this request only to its required end (docs/behaviour.md §T6.2, §T7)";
  } else if (module_of(y.kind) == module_of(x.kind)) {
    if (x.kind == SectionKind::RoundaboutExit && y.kind == SectionKind::RoundaboutEntry) {
      to = wy.possible_from - kMargin;
      why = "until the " + name_of(y) + " may be queued: entries queue before exits (docs/behaviour.md §T5.3, §T12.1.7)";
    } else {
      to = x.start + b2f - kMargin;
      why = "until base_link reaches its start: with the " + name_of(y) +
            " queued, FIRST_ACTIVE drops it at its required end (docs/behaviour.md §T4.3, §T7)";
    }
  } else {
    to = y.start - kMargin;
    why = "until the front reaches the " + name_of(y) + ": PRIOR_WINS keeps it only that far (docs/behaviour.md §T6.2)";
  }
  if (to < wx.to) {
    wx.to = to;
    wx.to_why = why;
  }
}

using Interval = std::pair<double, double>;

// [from, to] less the union of `blocked` (sorted or not).
std::vector<Interval> free_parts(double from, double to, std::vector<Interval> blocked) {
  std::sort(blocked.begin(), blocked.end());
  std::vector<Interval> out;
  double cursor = from;
  for (const Interval& b : blocked) {
    if (b.second < cursor) continue;
    if (b.first > to) break;
    if (b.first > cursor) out.push_back({cursor, std::min(b.first, to)});
    cursor = std::max(cursor, b.second);
  }
  if (cursor < to) out.push_back({cursor, to});
  return out;
}

// The blinker expectation of a left or right section from its narrowed window: through the whole
// section when the window covers it and it has a junction or lanelet to name, else blinker_on over
// the window's stretch when that is long enough, else a note saying why nothing is stated.
void add_blinker_expectation(const Section& s, const Window& w, const SpeedBounds& speed,
                             const RuleParameters& params, Derivation& d) {
  if (s.side != Side::Left && s.side != Side::Right) return;
  using Kind = GeneratedExpectation::Kind;
  const double b2f = params.base_link_to_front;
  GeneratedExpectation e;
  e.blinker = to_string(s.side);
  // Through expectations start at least kMargin before the section: an exit whose request starts
  // at its own start (no marking) gets blinker_on from just after it, since the front exactly at
  // the start has not reached it (docs/behaviour.md §T5.3 "DIST - b2f >= 0"), and SUMO does hold the ego at
  // a lane's very end for a step while the link ahead is not yet open.
  const bool whole = w.to >= s.end + b2f - 1e-9 && w.from <= s.start - kMargin;
  const bool named = !s.target.junction.empty() || !s.target.lanelet.empty();
  if (whole && named) {
    e.kind = s.target.junction.empty() ? Kind::ThroughLanelet : Kind::ThroughJunction;
    e.target = s.target.junction.empty() ? s.target.lanelet : s.target.junction;
    e.lead = std::max(0.0, floor_tenth(s.start - w.from - kMargin));
    e.why = name_of(s) + " (s " + rounded_fixed(s.start, 1) + "-" + rounded_fixed(s.end, 1) + "): " + e.blinker +
            " from " + rounded_fixed(e.lead, 1) + " m before it (" + rounded_fixed(kMargin, 1) +
            " m kept): " + w.from_why + "; " + w.to_why;
  } else if (w.to - w.from >= std::max(kMinBlinkerOn, step_room(speed, w.from, w.to, params.step_length)) + 2 * kMargin) {
    e.kind = Kind::BlinkerOn;
    e.from_s = ceil_tenth(w.from + kMargin);
    e.to_s = floor_tenth(w.to - kMargin);
    e.why = name_of(s) + " (s " + rounded_fixed(s.start, 1) + "-" + rounded_fixed(s.end, 1) + "): " + e.blinker +
            " with the front in [" + rounded_fixed(e.from_s, 1) + ", " + rounded_fixed(e.to_s, 1) + "] (" +
            rounded_fixed(kMargin, 1) + " m kept): " + w.from_why + "; " + w.to_why +
            (named ? "" : " (no single junction or lanelet to name)");
  } else {
    d.notes.push_back(name_of(s) + " (s " + rounded_fixed(s.start, 1) + "-" + rounded_fixed(s.end, 1) +
                      "): no blinker expectation, the rules leave no stretch where its blinker is certain (" +
                      w.from_why + "; " + w.to_why + ")");
    return;
  }
  d.expectations.push_back(std::move(e));
}

// no_blinker over every stretch of at least `straight` metres outside the `blocked` windows (the
// route's start and end kept clear); returns the stretches stated.
std::vector<Interval> add_no_blinker_stretches(const std::vector<Interval>& blocked, const RouteFacts& facts,
                                               const RuleParameters& params, Derivation& d) {
  const std::vector<Interval> quiet = free_parts(facts.depart_front + 1.0, facts.route_end - 1.0, blocked);
  std::vector<Interval> stated;
  for (const Interval& q : quiet) {
    if (q.second - q.first < params.straight) continue;
    GeneratedExpectation e;
    e.kind = GeneratedExpectation::Kind::NoBlinker;
    e.from_s = ceil_tenth(q.first);
    e.to_s = floor_tenth(q.second);
    e.why = "no request can be valid with the front in [" + rounded_fixed(e.from_s, 1) + ", " +
            rounded_fixed(e.to_s, 1) +
            "]: it is outside every turn's, roundabout's and lane change's possible stretch (search distance at "
            "the upper speed, docs/behaviour.md §T4.1, §T5, §T8.2)";
    stated.push_back(q);
    d.expectations.push_back(std::move(e));
  }
  return stated;
}

// No entry signal at roundabout entry `s` where the country gives none (docs/behaviour.md §T5.2:
// on_entry None, no exit tag): no_blinker over the free piece around its start, else the longest
// one, unless a stated stretch covers it already; a note when no piece is long enough.
void add_quiet_entry(const Section& s, const std::vector<Interval>& blocked, const std::vector<Interval>& stated,
                     const RouteFacts& facts, const SpeedBounds& speed, const RuleParameters& params,
                     Derivation& d) {
  const double from = std::max(facts.depart_front + 1.0, s.start - s.search_distance);
  const double to = s.end + params.base_link_to_front;
  std::optional<Interval> best;
  bool best_contains = false;
  for (const Interval& q : free_parts(from, to, blocked)) {
    if (q.second - q.first < std::max(kMinEntryQuiet, step_room(speed, q.first, q.second, params.step_length))) continue;
    const bool contains = q.first <= s.start && s.start <= q.second;
    if (!best || (contains && !best_contains) ||
        (contains == best_contains && q.second - q.first > best->second - best->first)) {
      best = q;
      best_contains = contains;
    }
  }
  const auto stated_already = [&](const Interval& piece) {
    return std::any_of(stated.begin(), stated.end(),
                       [&](const Interval& q) { return q.first <= piece.first && q.second >= piece.second; });
  };
  if (best && stated_already(*best)) return;  // a no_blinker stretch already covers it
  if (!best) {
    d.notes.push_back(name_of(s) + ": no entry signal (turn_signal_roundabout_on_entry None), but other requests "
                                   "may be valid all along it: not stated");
    return;
  }
  GeneratedExpectation e;
  e.kind = GeneratedExpectation::Kind::NoBlinker;
  e.from_s = ceil_tenth(best->first);
  e.to_s = floor_tenth(best->second);
  e.why = name_of(s) + ": no entry signal (turn_signal_roundabout_on_entry None and no exit tag, docs/behaviour.md §T5.2, §T5.5)";
  d.expectations.push_back(std::move(e));
}

// The expectations of the whole route: blinker_never for a side no section asks for and for the
// hazard lights, never_runs_red when the route has lights, and arrives.
void add_route_wide_expectations(const std::vector<Section>& sections, const RouteFacts& facts, Derivation& d) {
  using Kind = GeneratedExpectation::Kind;
  bool left = false, right = false;
  for (const Section& s : sections) {
    left |= s.side == Side::Left || s.side == Side::Either;
    right |= s.side == Side::Right || s.side == Side::Either;
  }
  for (const auto& [side, possible] : {std::pair<const char*, bool>{"left", left}, {"right", right}}) {
    if (possible) continue;
    GeneratedExpectation e;
    e.kind = Kind::BlinkerNever;
    e.blinker = side;
    e.why = std::string("no section of the route asks for ") + side;
    d.expectations.push_back(std::move(e));
  }
  GeneratedExpectation hazard;
  hazard.kind = Kind::BlinkerNever;
  hazard.blinker = "hazard";
  hazard.why = "hazard lights only when a module drives backward (docs/behaviour.md §T3.1): never here";
  d.expectations.push_back(std::move(hazard));
  if (!facts.lights.empty()) {
    GeneratedExpectation e;
    e.kind = Kind::NeverRunsRed;
    e.why = std::to_string(facts.lights.size()) + " light(s) on the route: the judge never lets the front cross a red "
            "stop line (docs/behaviour.md §L1-§L2)";
    d.expectations.push_back(std::move(e));
  }
  GeneratedExpectation arrives;
  arrives.kind = Kind::Arrives;
  arrives.why = "every generated route is drivable to its end within the duration";
  d.expectations.push_back(std::move(arrives));
}

}  // namespace

double floor_tenth(double v) { return std::floor(v * 10.0 + 1e-6) / 10.0; }
double ceil_tenth(double v) { return std::ceil(v * 10.0 - 1e-6) / 10.0; }

Derivation derive_expectations(const std::vector<Section>& sections, const RouteFacts& facts,
                               const SpeedBounds& speed, const RuleParameters& params) {
  Derivation d;
  std::vector<Window> windows;
  windows.reserve(sections.size());
  for (const Section& s : sections) windows.push_back(initial_window(s, speed, params, facts.depart_front));
  std::vector<Window> narrowed = windows;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    if (sections[i].side != Side::Left && sections[i].side != Side::Right) continue;
    for (std::size_t j = 0; j < sections.size(); ++j)
      if (j != i) narrow(sections[i], narrowed[i], sections[j], windows[j], params);
  }
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const Window& w = narrowed[i];
    d.windows.push_back({w.possible_from, w.possible_to, w.from, w.to, w.from_why, w.to_why});
    const std::size_t before = d.expectations.size();
    add_blinker_expectation(sections[i], w, speed, params, d);
    if (d.expectations.size() > before) d.expectations.back().section = static_cast<int>(i);
  }
  // Stretches where no request can be valid: outside every section's possible window (not narrowed).
  std::vector<Interval> blocked;
  for (std::size_t i = 0; i < sections.size(); ++i)
    if (sections[i].side != Side::None)
      blocked.push_back({windows[i].possible_from - kMargin, windows[i].possible_to + kMargin});
  const std::vector<Interval> stated = add_no_blinker_stretches(blocked, facts, params, d);
  for (const Section& s : sections)
    if (s.kind == SectionKind::RoundaboutEntry && s.side == Side::None)
      add_quiet_entry(s, blocked, stated, facts, speed, params, d);
  add_route_wide_expectations(sections, facts, d);
  return d;
}

}  // namespace signalsim::law
