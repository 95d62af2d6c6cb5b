// Cost of one decider step and one speed-planning step on routes of growing length.
// The window ahead of the ego is fixed (100 m back, 300 m ahead), so the time per step must stay
// flat as the route grows from 100 to 100 000 lanelets.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "planning/speed_limit_planner.hpp"
#include "turn_signal/turn_signal_decider.hpp"

namespace {

using namespace signalsim;

// A route of straight 50 m lanes with a 15 m left-turn quarter arc (R ~ 9.5 m) every fifth lanelet.
RouteMap synthetic_route(std::size_t lanelets) {
  std::vector<Lanelet> out;
  out.reserve(lanelets);
  double s = 0.0;
  for (std::size_t i = 0; i < lanelets; ++i) {
    Lanelet l;
    l.lane_id = "l" + std::to_string(i);
    l.edge_id = "e" + std::to_string(i);
    l.s_start = s;
    const bool turn = i % 5 == 4;
    l.is_internal = turn;
    l.turn_direction = turn ? TurnDirection::Left : TurnDirection::None;
    l.length = turn ? 15.0 : 50.0;
    l.speed_limit = turn ? 6.0 : 13.89;
    std::vector<Vec2> pts;
    if (turn) {
      const double r = 15.0 / (M_PI / 2);
      for (int k = 0; k <= 8; ++k) {
        const double a = (M_PI / 2) * k / 8.0;
        pts.push_back({s + r * std::sin(a), r * (1 - std::cos(a))});
      }
    } else {
      pts = {{s, 0.0}, {s + 50.0, 0.0}};
    }
    l.shape = Polyline(pts);
    s += l.length;
    out.push_back(std::move(l));
  }
  return RouteMap(std::move(out));
}

void BM_DeciderStep(benchmark::State& state) {
  const RouteMap route = synthetic_route(static_cast<std::size_t>(state.range(0)));
  TurnSignalDecider decider(TurnSignalParameters{});
  double s = route.length() / 2;
  for (auto _ : state) {
    s += 1.389;  // 13.89 m/s at a 0.1 s step
    if (s > route.length() - 400) s = route.length() / 2;
    const EgoOnRoute ego{s, s - 3.7, 13.89};
    benchmark::DoNotOptimize(decider.decide(route, ego));
  }
}
BENCHMARK(BM_DeciderStep)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000);

void BM_SpeedPlanStep(benchmark::State& state) {
  const RouteMap route = synthetic_route(static_cast<std::size_t>(state.range(0)));
  double s = route.length() / 2;
  for (auto _ : state) {
    s += 1.389;
    if (s > route.length() - 400) s = route.length() / 2;
    benchmark::DoNotOptimize(plan_speed_under_limits(route, s, 13.0, 0.0, 0.1, SpeedLimits{}));
  }
}
BENCHMARK(BM_SpeedPlanStep)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000);

}  // namespace
