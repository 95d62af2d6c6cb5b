// How well the blinker served each signal section of a run (signal_sections.hpp, plus the
// maneuvers' lateral motions), from the run's timeline rows alone:
//
//   serving stretch  of the expected blinker: the one on at the last step before the front reached
//                    s_start, else at the step it reached it, else the first one that began later
//                    while base_link was still in the section (a late blinker)
//     lead_distance  = s_start - s_front where the stretch began (< 0: late)
//     lead_time      = time the front reached s_start - time it began (< 0: late)
//     time_on        = how long the stretch lasted (0 when there is none)
//   missed           = the blinker was not on when the front reached s_start (within that step)
//   flickers         = blinker states shorter than 1 s (changes on both sides) that began between the
//                      previous section's end and this one's end (front bumper, plus base_link_to_front)
//
// A lane change's lead_time is its blinker's lead over the lateral motion (the prepare time, docs/behaviour.md
// §T8.2). Values are rounded to 1 mm / 1 ms; what does not apply is empty (std::nullopt).
#pragma once

#include <optional>
#include <vector>

#include "report/signal_sections.hpp"
#include "report/timeline.hpp"

namespace signalsim {

struct SectionMetrics {
  SignalSection section;
  bool reached = false;                  ///< the front got to the section start
  /// the blinker decided on the first row whose front is beyond the section start (whatever the
  /// section asks: a blinker to the wrong side shows here); empty when not reached
  std::optional<Blinker> blinker_at_start;
  std::optional<double> lead_distance;   ///< [m] blinker on before the start (front bumper); < 0 late
  std::optional<double> lead_time;       ///< [s]; < 0 late
  std::optional<double> time_on;         ///< [s] length of the blinker stretch serving the section
  int flickers = 0;                      ///< blinker states shorter than 1 s near the section
  std::optional<bool> missed;            ///< the blinker was not on when the front reached the start
  /// [m] front bumper route s where the serving stretch began, and where it ended (the first row
  /// after it, or its last row when the run ended with it on); empty when no stretch served.
  std::optional<double> on_s, off_s;
};

/// Shorter than this a blinker state counts as a flicker [s].
inline constexpr double kFlickerSeconds = 1.0;

/// Flickers over the whole run: blinker states with a change on both sides shorter than
/// kFlickerSeconds (the last row's state lasts one `step` [s]).
int count_flickers(const std::vector<TimelineRow>& rows, double step);

/// Each section measured against the run's rows, in the order given (sorted by s_start: each
/// section's flickers are those after the previous section's end).
std::vector<SectionMetrics> measure_sections(const std::vector<SignalSection>& sections, const RunRecord& record,
                                             double step);

}  // namespace signalsim
