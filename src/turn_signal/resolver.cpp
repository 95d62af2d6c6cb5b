// The resolver of the three request slots and the overwrite rule (see the header).
#include "turn_signal/resolver.hpp"

#include <array>
#include <cstddef>
#include <utility>

namespace signalsim {
namespace {

// Front-referenced distance to a start point (docs/behaviour.md §T2: DIST(target) - base_link2front).
double from_front(double s_target, const EgoOnRoute& ego) { return s_target - ego.s_front; }
// Base_link-referenced distance to an end point (docs/behaviour.md §T2: plain DIST(target)).
double from_base(double s_target, const EgoOnRoute& ego) { return s_target - ego.s_base; }

struct Candidate {
  const TurnSignalInfo* info = nullptr;
  SectionDistances distances;
};

// docs/behaviour.md §T6.1: the blinker may be on from the front reaching the desired start (inclusive) until
// base_link passes the desired end (still on exactly at it).
bool is_valid(const TurnSignalInfo& info, const SectionDistances& d) {
  return is_enable(info.turn) && d.desired_start <= 0.0 && d.desired_end >= 0.0;
}

}  // namespace

SectionDistances section_distances(const TurnSignalInfo& info, const EgoOnRoute& ego) {
  return SectionDistances{
      .desired_start = from_front(info.desired_start, ego),
      .desired_end = from_base(info.desired_end, ego),
      .required_start = from_front(info.required_start, ego),
      .required_end = from_base(info.required_end, ego),
  };
}

bool prior_wins(double ps, double pe, double ss, double se) {
  const bool before_prior = ps > 0.0;
  const bool before_subsequent = ss > 0.0;
  // Strict on the start: with ps == 0 exactly ego is neither before nor inside (docs/behaviour.md §T6.2 edge).
  const bool inside_prior = ps < 0.0 && pe >= 0.0;

  if (ps < ss) {                                       // prior's required section starts first
    if (se < pe) return true;                          // P3: subsequent required inside prior required
    if (before_prior || inside_prior) return true;     // P1/P2: until the prior required section ends
    if (before_subsequent) return true;                // gap between disjoint required sections
    return false;                                      // prior passed, subsequent started
  }
  if (pe < se) return before_prior || inside_prior;    // P5: prior required inside subsequent required
  return !before_prior;                                // P4: subsequent until front reaches prior start
}

ResolvedTurnSignal resolve_turn_signal(const EgoOnRoute& ego, const TurnSignalInfo& intersection,
                                       const TurnSignalInfo& roundabout, const TurnSignalInfo& behavior) {
  // Slot order is the tie rule (docs/behaviour.md §T6.1, §T12.1.9): intersection < roundabout < behaviour.
  const std::array<const TurnSignalInfo*, 3> slots{&intersection, &roundabout, &behavior};

  std::array<Candidate, 3> valid;  // no allocation: this runs every step
  std::size_t count = 0;
  for (const TurnSignalInfo* info : slots) {
    const SectionDistances d = section_distances(*info, ego);
    if (is_valid(*info, d)) valid[count++] = {info, d};
  }
  if (count == 0) return {};  // DISABLE, not NO_COMMAND (docs/behaviour.md §T12.1.2)

  // Earliest passed desired start first; a stable sort (insertion, of at most three) keeps slot
  // order on exactly equal ds.
  for (std::size_t i = 1; i < count; ++i)
    for (std::size_t j = i; j > 0 && valid[j].distances.desired_start < valid[j - 1].distances.desired_start; --j)
      std::swap(valid[j], valid[j - 1]);

  Candidate winner = valid.front();
  for (std::size_t k = 1; k < count; ++k) {
    const SectionDistances& p = winner.distances;
    const SectionDistances& s = valid[k].distances;
    if (!prior_wins(p.required_start, p.required_end, s.required_start, s.required_end)) winner = valid[k];
  }
  return {winner.info->turn, winner.info->source};
}

TurnSignalInfo overwrite_turn_signal(const EgoOnRoute& ego, const TurnSignalInfo& original,
                                     const TurnSignalInfo& next) {
  if (!is_enable(original.turn)) return next;  // NO_COMMAND or DISABLE
  // Both front-referenced in the reference (docs/behaviour.md §T6.4), so the offset cancels.
  const double to_next_desired_start = from_front(next.desired_start, ego);
  const double to_original_desired_end = from_front(original.desired_end, ego);
  if (to_next_desired_start > to_original_desired_end) return original;  // next starts after original ends
  return next;
}

TurnSignalInfo use_prior_turn_signal(const EgoOnRoute& ego, const TurnSignalInfo& original,
                                     const TurnSignalInfo& next) {
  // docs/behaviour.md §T6.4: the commands are never looked at.
  const SectionDistances o = section_distances(original, ego);
  const SectionDistances n = section_distances(next, ego);

  const bool original_not_started = o.desired_start > 0.0;
  const bool next_not_started = n.desired_start > 0.0;
  if (original_not_started && next_not_started) return {};
  if (original_not_started) return next;
  if (next_not_started) return original;

  const bool original_ended = o.desired_end < 0.0;
  const bool next_ended = n.desired_end < 0.0;
  if (original_ended && next_ended) return {};
  if (original_ended) return next;
  if (next_ended) return original;

  if (o.desired_start <= n.desired_start) {
    return prior_wins(o.required_start, o.required_end, n.required_start, n.required_end) ? original : next;
  }
  return prior_wins(n.required_start, n.required_end, o.required_start, o.required_end) ? next : original;
}

}  // namespace signalsim
