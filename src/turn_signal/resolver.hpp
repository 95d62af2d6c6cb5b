// Conflict resolution between the intersection, roundabout and behaviour requests (docs/behaviour.md §T6).
#pragma once

#include "turn_signal/turn_signal_info.hpp"

namespace signalsim {

/// The blinker the resolver chose and the request it came from.
struct ResolvedTurnSignal {
  TurnIndicator command = TurnIndicator::Disable;  ///< DISABLE when nothing is eligible (docs/behaviour.md §T12.1.2)
  RequestSource source = RequestSource::None;
};

/// Distances of one request relative to the ego (docs/behaviour.md §T6.1): starts front-referenced,
/// ends base_link-referenced. Positive = ahead.
struct SectionDistances {
  double desired_start = 0.0;
  double desired_end = 0.0;
  double required_start = 0.0;
  double required_end = 0.0;
};

SectionDistances section_distances(const TurnSignalInfo& info, const EgoOnRoute& ego);

/// docs/behaviour.md §T6.2: true when the prior request (earlier desired start) keeps the blinker.
/// ps/ss: required-start distances (front-referenced); pe/se: required-end distances (base_link).
bool prior_wins(double ps, double pe, double ss, double se);

/// docs/behaviour.md §T6.1 RESOLVE over the three candidates. A candidate is valid when its command is
/// ENABLE_LEFT/RIGHT, its desired start is reached (ds <= 0) and its desired end not passed (de >= 0).
/// Sorted by ds ascending, ties intersection < roundabout < behaviour, then folded with prior_wins.
/// Never throws.
ResolvedTurnSignal resolve_turn_signal(const EgoOnRoute& ego, const TurnSignalInfo& intersection,
                                       const TurnSignalInfo& roundabout, const TurnSignalInfo& behavior);

/// docs/behaviour.md §T6.4 OVERWRITE(original, new): merge used by the behaviour modules.
TurnSignalInfo overwrite_turn_signal(const EgoOnRoute& ego, const TurnSignalInfo& original,
                                     const TurnSignalInfo& next);

/// docs/behaviour.md §T6.4 USE_PRIOR_INFO(original, new): the older two-signal resolver (start planner).
/// Returns EMPTY (default TurnSignalInfo) when neither request is eligible.
TurnSignalInfo use_prior_turn_signal(const EgoOnRoute& ego, const TurnSignalInfo& original,
                                     const TurnSignalInfo& next);

}  // namespace signalsim
