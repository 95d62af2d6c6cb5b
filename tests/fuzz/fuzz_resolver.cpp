// libFuzzer target: the conflict resolver (src/turn_signal/resolver, docs/behaviour.md §T6) on random
// requests and ego positions. Never throws (resolver.hpp), so any exception is a finding.
// Invariants asserted:
//   - resolve_turn_signal's result is DISABLE/None when no candidate is valid, else the command and
//     source of one valid candidate; with exactly one valid candidate, that one. Valid (resolver.hpp,
//     spec TSD §6.1), computed here from the route positions and not with the resolver's own
//     section_distances: ENABLE_LEFT/RIGHT, the desired start reached by the front bumper
//     (desired_start - s_front <= 0) and the desired end not passed by base_link
//     (desired_end - s_base >= 0).
//   - use_prior_turn_signal returns one of its two requests or EMPTY; overwrite_turn_signal returns
//     one of its two requests.
#include <fuzzer/FuzzedDataProvider.h>

#include <array>
#include <cstring>
#include <cstdint>
#include <vector>

#include "fuzz_common.hpp"
#include "turn_signal/resolver.hpp"

using namespace signalsim;

namespace {

double position(FuzzedDataProvider& in) {
  // Mostly route-sized values on a coarse grid (ties and boundaries), sometimes any finite double
  // (ConsumeFloatingPoint: huge values) or one of NaN, +-infinity, -0.0, denorm_min
  // (special_double, fuzz_common.hpp).
  switch (in.ConsumeIntegralInRange<int>(0, 4)) {
    case 0: return in.ConsumeIntegralInRange<int>(-40, 40) * 0.5;
    case 1: return in.ConsumeFloatingPointInRange<double>(-500.0, 500.0);
    case 2: return in.ConsumeFloatingPoint<double>();
    case 3: return signalsim::fuzz::special_double(in);
    default: return 0.0;
  }
}

TurnSignalInfo request(FuzzedDataProvider& in, RequestSource source) {
  TurnSignalInfo t;
  t.turn = static_cast<TurnIndicator>(in.ConsumeIntegralInRange<int>(0, 3));
  t.hazard = static_cast<HazardLights>(in.ConsumeIntegralInRange<int>(0, 2));
  t.source = source;
  t.desired_start = position(in);
  t.desired_end = position(in);
  t.required_start = position(in);
  t.required_end = position(in);
  return t;
}

bool same(const TurnSignalInfo& a, const TurnSignalInfo& b) {
  // Bitwise on the doubles (NaN == NaN here): "is this the very request".
  return a.turn == b.turn && a.hazard == b.hazard && a.source == b.source &&
         std::memcmp(&a.desired_start, &b.desired_start, sizeof(double)) == 0 &&
         std::memcmp(&a.desired_end, &b.desired_end, sizeof(double)) == 0 &&
         std::memcmp(&a.required_start, &b.required_start, sizeof(double)) == 0 &&
         std::memcmp(&a.required_end, &b.required_end, sizeof(double)) == 0;
}

bool is_valid(const TurnSignalInfo& info, const EgoOnRoute& ego) {
  const double to_desired_start = info.desired_start - ego.s_front;  // front-referenced
  const double to_desired_end = info.desired_end - ego.s_base;       // base_link-referenced
  return (info.turn == TurnIndicator::EnableLeft || info.turn == TurnIndicator::EnableRight) &&
         to_desired_start <= 0.0 && to_desired_end >= 0.0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  EgoOnRoute ego;
  ego.s_front = position(in);
  ego.s_base = ego.s_front - (in.ConsumeBool() ? 3.7 : position(in));
  ego.speed = position(in);
  const std::array<TurnSignalInfo, 3> c{request(in, RequestSource::Intersection),
                                        request(in, in.ConsumeBool() ? RequestSource::RoundaboutEntry
                                                                     : RequestSource::RoundaboutExit),
                                        request(in, static_cast<RequestSource>(in.ConsumeIntegralInRange<int>(4, 7)))};

  const ResolvedTurnSignal r = resolve_turn_signal(ego, c[0], c[1], c[2]);
  int valid = 0;
  int last_valid = -1;
  bool matches_a_valid_candidate = false;
  for (int k = 0; k < 3; ++k) {
    if (!is_valid(c[k], ego)) continue;
    ++valid;
    last_valid = k;
    if (r.command == c[k].turn && r.source == c[k].source) matches_a_valid_candidate = true;
  }
  if (valid == 0) {
    FUZZ_ASSERT(r.command == TurnIndicator::Disable && r.source == RequestSource::None);
  } else {
    FUZZ_ASSERT(matches_a_valid_candidate);
    if (valid == 1) FUZZ_ASSERT(r.command == c[last_valid].turn && r.source == c[last_valid].source);
  }

  const TurnSignalInfo prior = use_prior_turn_signal(ego, c[0], c[2]);
  FUZZ_ASSERT(same(prior, c[0]) || same(prior, c[2]) || same(prior, TurnSignalInfo{}));
  const TurnSignalInfo over = overwrite_turn_signal(ego, c[1], c[2]);
  FUZZ_ASSERT(same(over, c[1]) || same(over, c[2]));

  // prior_wins is total: a bool for any four doubles (no UB under UBSan).
  (void)prior_wins(position(in), position(in), position(in), position(in));
  return 0;
}
