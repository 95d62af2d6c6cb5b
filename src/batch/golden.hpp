// Golden event files for `signalsim check`: a run's events (blinker changes, light decisions) against
// the events.csv a reviewer accepted, within a tolerance, with a diff a person can read.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/timeline.hpp"

namespace signalsim {

/// One line of the comparison, in event order.
struct EventDiff {
  enum class Op {
    Same,     ///< same kind/from/to/source, |Δs| <= tol_s and |Δt| <= tol_t
    Moved,    ///< same kind/from/to/source, outside the tolerance
    Missing,  ///< in the golden file only
    Extra,    ///< in this run only
  };
  Op op = Op::Same;
  std::optional<TimelineEvent> golden;
  std::optional<TimelineEvent> run;
};

/// Aligns the two event lists in order (an edit-distance alignment: pairs need the same kind,
/// from, to and source; a pair outside the tolerance counts as one change, an unpaired event as one).
std::vector<EventDiff> compare_events(const std::vector<TimelineEvent>& golden, const std::vector<TimelineEvent>& run,
                                      double tol_s, double tol_t);

/// Number of lines that are not Same.
std::size_t count_differences(const std::vector<EventDiff>& diff);

/// The comparison as text, one line per event, each prefixed by `indent`:
///   "=" same, "~" moved (with the golden values and the deltas), "-" missing, "+" extra.
std::string format_diff(const std::vector<EventDiff>& diff, const std::string& indent = "    ");

}  // namespace signalsim
