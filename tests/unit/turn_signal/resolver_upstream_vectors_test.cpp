// docs/behaviour.md §T9: the upstream test_turn_signal.cpp vectors (Condition1/2/3) for resolve_turn_signal.
// Path along x, so s == x. Ego x is a C++ float (48.1f == 48.0999985) converted to double;
// base_link2front = 1.0, so s_base = x and s_front = x + 1.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "test_helpers.hpp"
#include "turn_signal/resolver.hpp"

namespace signalsim {
namespace {

using test::kLeft;
using test::kRight;
using test::kDisable;

struct UpstreamVector {
  std::string condition;
  TurnSignalInfo intersection;
  TurnSignalInfo behaviour;
  float ego_x;
  TurnIndicator expected;
};

std::ostream& operator<<(std::ostream& os, const UpstreamVector& v) {
  return os << v.condition << " x=" << v.ego_x << " -> " << to_string(v.expected);
}

// (cmd, desired_start, desired_end, required_start, required_end), roundabout = {} in all of them.
const TurnSignalInfo kCondition1Intersection = test::request(kLeft, 0, 65, 35, 48, RequestSource::Intersection);
const TurnSignalInfo kCondition1Behaviour = test::request(kRight, 5, 70, 45, 50, RequestSource::LaneChange);
const TurnSignalInfo kCondition2Intersection = test::request(kLeft, 0, 65, 35, 50, RequestSource::Intersection);
const TurnSignalInfo kCondition2Behaviour = test::request(kRight, 5, 70, 40, 45, RequestSource::LaneChange);
const TurnSignalInfo kCondition3Intersection = test::request(kLeft, 0, 65, 35, 50, RequestSource::Intersection);
const TurnSignalInfo kCondition3Behaviour = test::request(kRight, 5, 70, 30, 45, RequestSource::LaneChange);

std::vector<UpstreamVector> condition(const std::string& name, const TurnSignalInfo& intersection,
                                      const TurnSignalInfo& behaviour,
                                      const std::vector<std::pair<float, TurnIndicator>>& expectations) {
  std::vector<UpstreamVector> out;
  for (const auto& [x, expected] : expectations) out.push_back({name, intersection, behaviour, x, expected});
  return out;
}

std::vector<UpstreamVector> all_vectors() {
  std::vector<UpstreamVector> all;
  const auto append = [&all](const std::vector<UpstreamVector>& more) { all.insert(all.end(), more.begin(), more.end()); };
  append(condition("Condition1", kCondition1Intersection, kCondition1Behaviour,
                   {{4.9f, kLeft}, {5.0f, kLeft}, {34.99f, kLeft}, {40.0f, kLeft}, {45.0f, kLeft}, {48.0f, kLeft},
                    {48.1f, kRight}, {50.0f, kRight}, {50.1f, kRight}, {65.0f, kRight}, {65.1f, kRight},
                    {70.1f, kDisable}}));
  append(condition("Condition2", kCondition2Intersection, kCondition2Behaviour,
                   {{4.9f, kLeft}, {5.0f, kLeft}, {34.99f, kLeft}, {40.0f, kLeft}, {45.0f, kLeft}, {50.0f, kLeft},
                    {50.1f, kLeft}, {65.0f, kLeft}, {65.1f, kRight}, {70.1f, kDisable}}));
  append(condition("Condition3", kCondition3Intersection, kCondition3Behaviour,
                   {{4.9f, kRight}, {5.0f, kRight}, {29.9f, kRight}, {30.0f, kRight}, {33.9f, kRight}, {35.0f, kLeft},
                    {44.9f, kLeft}, {45.0f, kLeft}, {49.9f, kLeft}, {50.0f, kLeft}, {65.0f, kLeft}, {65.1f, kRight},
                    {70.1f, kDisable}}));
  return all;
}

class UpstreamResolverVectors : public ::testing::TestWithParam<UpstreamVector> {};

TEST_P(UpstreamResolverVectors, ResolvesLikeTheReference) {
  const UpstreamVector& v = GetParam();
  const double x = static_cast<double>(v.ego_x);
  const EgoOnRoute ego{.s_front = x + test::kBaseLinkToFront, .s_base = x, .speed = 0.0};
  const ResolvedTurnSignal r = resolve_turn_signal(ego, v.intersection, TurnSignalInfo{}, v.behaviour);
  EXPECT_EQ(r.command, v.expected) << "got " << to_string(r.command);
  const RequestSource expected_source = v.expected == kLeft    ? RequestSource::Intersection
                                        : v.expected == kRight ? RequestSource::LaneChange
                                                               : RequestSource::None;
  EXPECT_EQ(r.source, expected_source);
}

TEST(UpstreamResolverVectorTable, HasEveryVectorOfTheSpec) { EXPECT_EQ(all_vectors().size(), 12u + 10u + 13u); }

INSTANTIATE_TEST_SUITE_P(Spec9, UpstreamResolverVectors, ::testing::ValuesIn(all_vectors()),
                         [](const ::testing::TestParamInfo<UpstreamVector>& info) {
                           return info.param.condition + "_" + std::to_string(info.index);
                         });

}  // namespace
}  // namespace signalsim
