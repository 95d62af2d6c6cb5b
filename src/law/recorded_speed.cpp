// A run's recorded speeds by front position (see recorded_speed.hpp).
#include "law/recorded_speed.hpp"

#include <algorithm>

#include "core/number_text.hpp"

namespace signalsim::law {

RecordedSpeed::RecordedSpeed(std::vector<std::pair<double, double>> samples) {
  std::stable_sort(samples.begin(), samples.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [s, v] : samples) {
    s_.push_back(s);
    v_.push_back(v);
  }
}

// The samples from the last one at or before `from` to the first one at or after `to` (every sample
// at those two positions included); clamped to the recorded positions.
std::pair<std::size_t, std::size_t> RecordedSpeed::bracket(double from, double to) const {
  if (s_.empty()) return {0, 0};
  const auto below = std::upper_bound(s_.begin(), s_.end(), from);
  const double a = below == s_.begin() ? s_.front() : *(below - 1);
  const auto above = std::lower_bound(s_.begin(), s_.end(), to);
  const double b = above == s_.end() ? s_.back() : *above;
  const auto first = std::lower_bound(s_.begin(), s_.end(), std::min(a, b));
  const auto last = std::upper_bound(s_.begin(), s_.end(), std::max(a, b));
  return {static_cast<std::size_t>(first - s_.begin()), static_cast<std::size_t>(last - s_.begin())};
}

double RecordedSpeed::lower(double s) const {
  const auto [first, last] = bracket(s, s);
  if (first >= last) return 0.0;
  return std::max(0.0, *std::min_element(v_.begin() + static_cast<std::ptrdiff_t>(first),
                                         v_.begin() + static_cast<std::ptrdiff_t>(last)));
}

std::string RecordedSpeed::lower_reason(double s) const {
  return "the least speed of the run's steps around it, " + rounded_fixed(lower(s), 1) + " m/s";
}

double RecordedSpeed::max_planned(double from, double to) const {
  const auto [first, last] = bracket(from, to);
  if (first >= last) return 0.0;
  return *std::max_element(v_.begin() + static_cast<std::ptrdiff_t>(first),
                           v_.begin() + static_cast<std::ptrdiff_t>(last));
}

}  // namespace signalsim::law
