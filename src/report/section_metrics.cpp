// Measuring the blinker against each signal section: lead, time on, missed, flickers (see section_metrics.hpp).
#include "report/section_metrics.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "core/number_text.hpp"

namespace signalsim {
namespace {

// A run of consecutive rows with the same blinker: rows [first, last].
struct Stretch {
  Blinker blinker = Blinker::None;
  std::size_t first = 0;
  std::size_t last = 0;
};

std::vector<Stretch> stretches_of(const std::vector<TimelineRow>& rows) {
  std::vector<Stretch> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (out.empty() || rows[i].blinker != out.back().blinker) out.push_back({rows[i].blinker, i, i});
    else out.back().last = i;
  }
  return out;
}

// How long a stretch lasted: until the next row's time, or one step past its last row.
double duration_of(const std::vector<TimelineRow>& rows, std::size_t first, std::size_t last, double step) {
  const double end = last + 1 < rows.size() ? rows[last + 1].time : rows[last].time + step;
  return end - rows[first].time;
}

// Flickers: stretches with a change on both sides shorter than kFlickerSeconds.
bool is_flicker(const std::vector<TimelineRow>& rows, const std::vector<Stretch>& stretches, std::size_t i,
                double step) {
  if (i == 0 || i + 1 >= stretches.size()) return false;
  return duration_of(rows, stretches[i].first, stretches[i].last, step) < kFlickerSeconds - 1e-9;
}

SectionMetrics measure_section(const SignalSection& section, const RunRecord& record,
                               const std::vector<Stretch>& stretches, double step, double window_from,
                               double window_to) {
  const auto& rows = record.rows;
  SectionMetrics m;
  m.section = section;
  for (std::size_t i = 0; i < stretches.size(); ++i) {
    const double s = rows[stretches[i].first].s_front;
    if (s > window_from && s <= window_to && is_flicker(rows, stretches, i, step)) ++m.flickers;
  }
  // The front has reached the section once it is beyond its start: a front exactly at the start is
  // still on the lane before (SUMO holds a vehicle at a lane's end while a link is not yet open), and
  // the reference's "front has reached it" test is strict too (docs/behaviour.md §T5.3: DIST - b2f >= 0 is "not yet").
  const auto enter = std::find_if(rows.begin(), rows.end(),
                                  [&](const TimelineRow& r) { return r.s_front > section.s_start; });
  if (enter == rows.end()) return m;
  m.reached = true;
  m.blinker_at_start = enter->blinker;
  if (section.blinker == Blinker::None) return m;
  const std::size_t k = static_cast<std::size_t>(enter - rows.begin());
  // The stretch of the expected blinker around row i, if row i shows it.
  const auto stretch_at = [&](std::size_t i) -> std::optional<std::pair<std::size_t, std::size_t>> {
    if (rows[i].blinker != section.blinker) return std::nullopt;
    std::size_t first = i, last = i;
    while (first > 0 && rows[first - 1].blinker == section.blinker) --first;
    while (last + 1 < rows.size() && rows[last + 1].blinker == section.blinker) ++last;
    return std::make_pair(first, last);
  };
  // Serving stretch: on just before the front reached the start, or at that step; else the first
  // one that began later while base_link was still in the section (a late blinker).
  auto serving = k > 0 ? stretch_at(k - 1) : std::nullopt;
  if (!serving) serving = stretch_at(k);
  m.missed = !serving;
  const double end_front = section.s_end + record.base_link_to_front;
  for (std::size_t i = k + 1; !serving && i < rows.size() && rows[i].s_front <= end_front; ++i) serving = stretch_at(i);
  if (!serving) {
    m.time_on = 0.0;
    return m;
  }
  const auto [first, last] = *serving;
  double t_enter = rows[k].time;  // the front reached s_start: interpolate between the two rows
  if (k > 0 && rows[k].s_front > rows[k - 1].s_front)
    t_enter = rows[k - 1].time + (section.s_start - rows[k - 1].s_front) /
                                     (rows[k].s_front - rows[k - 1].s_front) * (rows[k].time - rows[k - 1].time);
  m.lead_distance = rounded(section.s_start - rows[first].s_front, 3);
  m.lead_time = rounded(t_enter - rows[first].time, 3);
  m.time_on = rounded(duration_of(rows, first, last, step), 3);
  m.on_s = rounded(rows[first].s_front, 3);
  m.off_s = rounded(rows[last + 1 < rows.size() ? last + 1 : last].s_front, 3);
  return m;
}

}  // namespace

int count_flickers(const std::vector<TimelineRow>& rows, double step) {
  const std::vector<Stretch> stretches = stretches_of(rows);
  int flickers = 0;
  for (std::size_t i = 0; i < stretches.size(); ++i) flickers += is_flicker(rows, stretches, i, step);
  return flickers;
}

std::vector<SectionMetrics> measure_sections(const std::vector<SignalSection>& sections, const RunRecord& record,
                                             double step) {
  const std::vector<Stretch> stretches = stretches_of(record.rows);
  std::vector<SectionMetrics> out;
  double window_from = -std::numeric_limits<double>::infinity();
  for (const SignalSection& section : sections) {
    const double window_to = section.s_end + record.base_link_to_front;
    out.push_back(measure_section(section, record, stretches, step, window_from, window_to));
    window_from = window_to;
  }
  return out;
}

}  // namespace signalsim
