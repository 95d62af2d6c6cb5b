// Comparing a run's events with a golden events.csv: the alignment and the diff a person reads
// (see golden.hpp).
#include "batch/golden.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/number_text.hpp"

namespace signalsim {
namespace {

constexpr double kEpsilon = 1e-6;  // the files hold 3 decimals

bool same_key(const TimelineEvent& a, const TimelineEvent& b) {
  return a.kind == b.kind && a.from == b.from && a.to == b.to && a.source == b.source;
}

std::string describe(const TimelineEvent& e) {
  return format_text("%9.3f s %9.3f m  %s %s -> %s (%s)", e.time, e.s_front, e.kind.c_str(), e.from.c_str(),
                     e.to.c_str(), e.source.c_str());
}

}  // namespace

std::vector<EventDiff> compare_events(const std::vector<TimelineEvent>& golden, const std::vector<TimelineEvent>& run,
                                      double tol_s, double tol_t) {
  const std::size_t n = golden.size(), m = run.size();
  constexpr int kInf = std::numeric_limits<int>::max() / 2;
  // cost[i][j]: fewest differences aligning golden[0, i) with run[0, j).
  std::vector<std::vector<int>> cost(n + 1, std::vector<int>(m + 1, kInf));
  auto pair_cost = [&](std::size_t i, std::size_t j) {
    if (!same_key(golden[i], run[j])) return kInf;
    const bool within = std::abs(golden[i].s_front - run[j].s_front) <= tol_s + kEpsilon &&
                        std::abs(golden[i].time - run[j].time) <= tol_t + kEpsilon;
    return within ? 0 : 1;
  };
  cost[0][0] = 0;
  for (std::size_t i = 0; i <= n; ++i)
    for (std::size_t j = 0; j <= m; ++j) {
      int& c = cost[i][j];
      if (i > 0) c = std::min(c, cost[i - 1][j] + 1);
      if (j > 0) c = std::min(c, cost[i][j - 1] + 1);
      if (i > 0 && j > 0) {
        const int p = pair_cost(i - 1, j - 1);
        if (p < kInf) c = std::min(c, cost[i - 1][j - 1] + p);
      }
    }
  // Walk back, preferring pairs, then missing golden events, then extra run events.
  std::vector<EventDiff> out;
  std::size_t i = n, j = m;
  while (i > 0 || j > 0) {
    if (i > 0 && j > 0) {
      const int p = pair_cost(i - 1, j - 1);
      if (p < kInf && cost[i][j] == cost[i - 1][j - 1] + p) {
        out.push_back({p == 0 ? EventDiff::Op::Same : EventDiff::Op::Moved, golden[i - 1], run[j - 1]});
        --i, --j;
        continue;
      }
    }
    if (i > 0 && cost[i][j] == cost[i - 1][j] + 1) {
      out.push_back({EventDiff::Op::Missing, golden[i - 1], std::nullopt});
      --i;
      continue;
    }
    out.push_back({EventDiff::Op::Extra, std::nullopt, run[j - 1]});
    --j;
  }
  std::reverse(out.begin(), out.end());
  return out;
}

std::size_t count_differences(const std::vector<EventDiff>& diff) {
  return static_cast<std::size_t>(
      std::count_if(diff.begin(), diff.end(), [](const EventDiff& d) { return d.op != EventDiff::Op::Same; }));
}

std::string format_diff(const std::vector<EventDiff>& diff, const std::string& indent) {
  std::string out;
  for (const EventDiff& d : diff) {
    switch (d.op) {
      case EventDiff::Op::Same:
        out += indent + "=  " + describe(*d.run) + "\n";
        break;
      case EventDiff::Op::Moved:
        out += indent + "~  " + describe(*d.run) +
               format_text("   golden %.3f s %.3f m: ds %+.3f m, dt %+.3f s\n", d.golden->time, d.golden->s_front,
                           d.run->s_front - d.golden->s_front, d.run->time - d.golden->time);
        break;
      case EventDiff::Op::Missing:
        out += indent + "-  " + describe(*d.golden) + "   missing in this run\n";
        break;
      case EventDiff::Op::Extra:
        out += indent + "+  " + describe(*d.run) + "   not in the golden file\n";
        break;
    }
  }
  if (diff.empty()) out += indent + "(no events on either side)\n";
  return out;
}

}  // namespace signalsim
