// The seeded perception model (docs/behaviour.md §L0 "Perception model"): pass-through, determinism
// and each fault; plus how it produces "timed out" for the judge (docs/behaviour.md §L1.3 row 2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <string>

#include "traffic_light/perception_model.hpp"
#include "traffic_light/traffic_light_judge.hpp"

namespace signalsim {
namespace {

using C = SignalColor;
using S = SignalShape;

const std::vector<SignalElement> kTruth = {SignalElement{C::Red, S::Circle, SignalStatus::SolidOn, 1.0},
                                           SignalElement{C::Green, S::LeftArrow, SignalStatus::SolidOn, 1.0}};

// Runs `steps` steps at 0.1 s (accumulated clock) at distance `distance`.
std::vector<std::optional<SignalObservation>> run(PerceptionModel& model, int steps, double distance = 50.0) {
  std::vector<std::optional<SignalObservation>> out;
  double t = 0.0;
  for (int k = 0; k < steps; ++k) {
    out.push_back(model.observe(kTruth, distance, t).observation);
    t += 0.1;
  }
  return out;
}

PerceptionModelParameters all_faults(std::uint64_t seed) {
  PerceptionModelParameters p;
  p.seed = seed;
  p.detection_range = 150.0;
  p.dropout_probability = 0.2;
  p.latency = 0.2;
  p.detections_per_light = 3;
  p.confidence_noise = 0.3;
  p.misclassification_probability = 0.1;
  p.blackouts = {{5.0, 6.0}};
  return p;
}

TEST(PerceptionModel, StandardEngineOutputIsFixedByTheStandard) {
  // [rand.predef]: the 10000th output of a default-constructed mt19937_64 is 9981545732273789042.
  std::mt19937_64 engine;
  engine.discard(9999);
  EXPECT_EQ(engine(), 9981545732273789042ULL);
}

TEST(PerceptionModel, AllFaultsOffPassesTheTruthThrough) {
  PerceptionModel model;
  double t = 0.0;
  for (int k = 0; k < 100; ++k) {
    const auto o = model.observe(kTruth, 1e6 * (k % 3) - 50.0, t).observation;
    ASSERT_TRUE(o.has_value());
    EXPECT_EQ(o->elements, kTruth);
    EXPECT_EQ(o->stamp, t);
    t += 0.1;
  }
  EXPECT_EQ(model.pending(), 0u);
}

TEST(PerceptionModel, SameSeedSameSequence) {
  PerceptionModel a(all_faults(42));
  PerceptionModel b(all_faults(42));
  const auto sa = run(a, 500);
  EXPECT_EQ(sa, run(b, 500));
  // reset() replays it too.
  a.reset();
  EXPECT_EQ(sa, run(a, 500));
}

TEST(PerceptionModel, DifferentSeedDifferentSequence) {
  PerceptionModel a(all_faults(42));
  PerceptionModel b(all_faults(43));
  EXPECT_NE(run(a, 500), run(b, 500));
}

TEST(PerceptionModel, SeedRegressionPattern) {
  // Guards the documented draw order and transforms: seed 42, dropout 0.5, first 24 steps.
  PerceptionModelParameters p;
  p.seed = 42;
  p.dropout_probability = 0.5;
  PerceptionModel model(p);
  std::string pattern;
  for (const auto& o : run(model, 24)) pattern += o ? '1' : '0';
  EXPECT_EQ(pattern, "011101101010100011110001");
}

TEST(PerceptionModel, DetectionRange) {
  PerceptionModelParameters p;
  p.detection_range = 100.0;
  PerceptionModel model(p);
  EXPECT_TRUE(model.observe(kTruth, 100.0, 0.0).observation.has_value());   // inclusive
  EXPECT_FALSE(model.observe(kTruth, std::nextafter(100.0, 200.0), 0.1).observation.has_value());
  EXPECT_TRUE(model.observe(kTruth, -5.0, 0.2).observation.has_value());    // |distance|
  EXPECT_FALSE(model.observe(kTruth, -150.0, 0.3).observation.has_value());
  EXPECT_FALSE(model.observe(kTruth, std::numeric_limits<double>::infinity(), 0.4).observation.has_value());
}

TEST(PerceptionModel, DropoutProbability) {
  {
    PerceptionModelParameters p;
    p.dropout_probability = 1.0;
    PerceptionModel model(p);
    for (const auto& o : run(model, 100)) EXPECT_FALSE(o.has_value());
  }
  PerceptionModelParameters p;
  p.seed = 7;
  p.dropout_probability = 0.3;
  PerceptionModel model(p);
  int delivered = 0;
  const int n = 20000;
  for (const auto& o : run(model, n)) delivered += o ? 1 : 0;
  EXPECT_NEAR(1.0 - static_cast<double>(delivered) / n, 0.3, 0.015);
}

TEST(PerceptionModel, LatencyDeliversLateWithTheCaptureStamp) {
  PerceptionModelParameters p;
  p.latency = 0.3;
  PerceptionModel model(p);
  double t = 0.0;
  std::vector<double> captures;
  for (int k = 0; k < 20; ++k) {
    const auto o = model.observe(kTruth, 10.0, t).observation;
    captures.push_back(t);
    if (k < 3) {
      EXPECT_FALSE(o.has_value()) << k;
    } else {
      ASSERT_TRUE(o.has_value()) << k;  // exactly three steps late despite the accumulated clock
      EXPECT_EQ(o->stamp, captures[k - 3]);
      EXPECT_EQ(o->elements, kTruth);
    }
    t += 0.1;
  }
  EXPECT_EQ(model.pending(), 3u);
}

TEST(PerceptionModel, LatencyNewestDueCaptureWins) {
  // A gap in calls makes several captures due at once: only the newest is delivered.
  PerceptionModelParameters p;
  p.latency = 0.5;
  PerceptionModel model(p);
  EXPECT_FALSE(model.observe(kTruth, 10.0, 0.0).observation);
  EXPECT_FALSE(model.observe(kTruth, 10.0, 0.1).observation);
  EXPECT_FALSE(model.observe(kTruth, 10.0, 0.2).observation);
  const auto o = model.observe(kTruth, 10.0, 0.7).observation;  // captures at 0.0, 0.1, 0.2 are due
  ASSERT_TRUE(o.has_value());
  EXPECT_EQ(o->stamp, 0.2);
  EXPECT_EQ(model.pending(), 1u);  // the capture at 0.7
}

TEST(PerceptionModel, DetectionsPerLightWithConfidenceNoise) {
  PerceptionModelParameters p;
  p.seed = 3;
  p.detections_per_light = 4;
  p.confidence_noise = 0.2;
  PerceptionModel model(p);
  std::set<double> confidences;
  for (const auto& o : run(model, 50)) {
    ASSERT_TRUE(o.has_value());
    ASSERT_EQ(o->elements.size(), 8u);
    for (std::size_t i = 0; i < o->elements.size(); ++i) {
      const SignalElement& e = o->elements[i];
      EXPECT_EQ(e.color, kTruth[i % 2].color);  // camera-major order, truth order inside
      EXPECT_EQ(e.shape, kTruth[i % 2].shape);
      EXPECT_GE(e.confidence, 0.8);
      EXPECT_LE(e.confidence, 1.0);
      confidences.insert(e.confidence);
    }
    // The judge reduces them to one per shape.
    EXPECT_EQ(highest_confidence_per_shape(o->elements).size(), 2u);
  }
  EXPECT_GT(confidences.size(), 100u);
}

TEST(PerceptionModel, MisclassificationChangesTheColorOnly) {
  {
    PerceptionModelParameters p;
    p.seed = 11;
    p.misclassification_probability = 1.0;
    PerceptionModel model(p);
    std::set<C> seen;
    for (const auto& o : run(model, 200)) {
      ASSERT_TRUE(o.has_value());
      for (std::size_t i = 0; i < o->elements.size(); ++i) {
        EXPECT_NE(o->elements[i].color, kTruth[i].color);
        EXPECT_EQ(o->elements[i].shape, kTruth[i].shape);
        if (i == 0) seen.insert(o->elements[i].color);
      }
    }
    EXPECT_EQ(seen, (std::set<C>{C::Unknown, C::Amber, C::Green}));  // all alternatives to red
  }
  PerceptionModelParameters p;
  p.seed = 12;
  p.misclassification_probability = 0.2;
  PerceptionModel model(p);
  int wrong = 0;
  int total = 0;
  for (const auto& o : run(model, 10000)) {
    for (std::size_t i = 0; i < o->elements.size(); ++i) {
      wrong += o->elements[i].color != kTruth[i].color ? 1 : 0;
      ++total;
    }
  }
  EXPECT_NEAR(static_cast<double>(wrong) / total, 0.2, 0.015);
}

TEST(PerceptionModel, ScheduledBlackoutsAreInclusiveAndApplyToTheCapture) {
  PerceptionModelParameters p;
  p.blackouts = {{1.0, 2.0}, {3.0, 3.0}};
  PerceptionModel model(p);
  double t = 0.0;
  for (int k = 0; k <= 40; ++k) {
    const auto o = model.observe(kTruth, 10.0, t).observation;
    const bool dark = (k >= 10 && k <= 20) || k == 30;
    EXPECT_EQ(o.has_value(), !dark) << "t = " << t;
    t += 0.1;
  }
  // With latency, a capture just before the blackout is delivered inside it.
  p.latency = 0.3;
  PerceptionModel late(p);
  std::optional<SignalObservation> at_1_2;
  t = 0.0;
  for (int k = 0; k <= 12; ++k) {
    const auto o = late.observe(kTruth, 10.0, t).observation;
    if (k == 12) at_1_2 = o;
    t += 0.1;
  }
  ASSERT_TRUE(at_1_2.has_value());
  EXPECT_NEAR(at_1_2->stamp, 0.9, 1e-12);
}

TEST(PerceptionModel, FaultStreamsAreIndependent) {
  // Changing the misclassification probability leaves the dropout pattern unchanged.
  PerceptionModelParameters p = all_faults(5);
  p.blackouts.clear();
  p.latency = 0.0;
  PerceptionModelParameters q = p;
  q.misclassification_probability = 0.9;
  PerceptionModel a(p);
  PerceptionModel b(q);
  const auto sa = run(a, 300);
  const auto sb = run(b, 300);
  for (std::size_t k = 0; k < sa.size(); ++k) EXPECT_EQ(sa[k].has_value(), sb[k].has_value()) << k;
}

// A fault that is off skips its draws (perception_model.cpp). Against the same fault at the smallest
// positive setting (it draws, and never fires), every other fault's outcome is the same step for step.
// (Whether draws happen is not visible from outside; what must not change is pinned below.)
TEST(PerceptionModel, AFaultThatIsOffChangesNoOtherFaultsOutcome) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  for (int fault = 0; fault < 3; ++fault) {
    PerceptionModelParameters off = all_faults(11);
    if (fault == 0) off.dropout_probability = 0.0;
    if (fault == 1) off.misclassification_probability = 0.0;
    if (fault == 2) off.confidence_noise = 0.0;
    PerceptionModelParameters drawing = off;
    if (fault == 0) drawing.dropout_probability = tiny;
    if (fault == 1) drawing.misclassification_probability = tiny;
    if (fault == 2) drawing.confidence_noise = tiny;  // 1.0 +- tiny rounds to 1.0
    PerceptionModel a(off);
    PerceptionModel b(drawing);
    const auto sa = run(a, 400);
    EXPECT_EQ(sa, run(b, 400)) << "fault " << fault;
    // And the other faults did act in these runs.
    int delivered = 0;
    for (const auto& o : sa) delivered += o.has_value();
    EXPECT_GT(delivered, 0);
    EXPECT_LT(delivered, 400);
  }
}

// Every delivered observation of `steps` steps as text (stamp, then each detection's colour and
// confidence to the last bit), hashed with 64-bit FNV-1a.
std::uint64_t fingerprint(PerceptionModel& model, int steps) {
  std::uint64_t h = 14695981039346656037ULL;
  const auto mix = [&h](const std::string& text) {
    for (const char c : text) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  };
  for (const auto& o : run(model, steps)) {
    if (!o) {
      mix("-\n");
      continue;
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", o->stamp);
    mix(buf);
    for (const SignalElement& e : o->elements) {
      std::snprintf(buf, sizeof buf, " %d:%a", static_cast<int>(e.color), e.confidence);
      mix(buf);
    }
    mix("\n");
  }
  return h;
}

// The sequences the faults produce, pinned: any change to what is drawn when (an extra draw, a skipped
// one, another order) changes them. Recorded from the model as it drew before faults that are off
// stopped drawing (633f3ca), which gives the same sequences: skipping changed no outcome.
TEST(PerceptionModel, FaultSequencesArePinned) {
  struct Case {
    const char* what;
    PerceptionModelParameters params;
    std::uint64_t expected;
  };
  // all_faults(7) with some of its faults turned off.
  const auto but = [](auto turn_off) {
    PerceptionModelParameters p = all_faults(7);
    turn_off(p);
    return p;
  };
  const std::vector<Case> cases = {
      {"all faults", all_faults(7), 13290565394101973748ULL},
      {"dropout and latency", but([](auto& p) { p.misclassification_probability = p.confidence_noise = 0.0; }),
       15922233167065863515ULL},
      {"misclassification", but([](auto& p) { p.dropout_probability = p.latency = p.confidence_noise = 0.0; }),
       5911706812423107079ULL},
      {"confidence noise",
       but([](auto& p) { p.dropout_probability = p.misclassification_probability = p.latency = 0.0; }),
       9271802176736162990ULL},
      {"all but latency", but([](auto& p) { p.latency = 0.0; }), 1866753687920592712ULL},
  };
  for (const Case& c : cases) {
    PerceptionModel model(c.params);
    EXPECT_EQ(fingerprint(model, 400), c.expected) << c.what;
  }
}

TEST(PerceptionModel, InvalidParametersAndInputsThrow) {
  const auto bad = [](auto mutate) {
    PerceptionModelParameters p;
    mutate(p);
    EXPECT_THROW(PerceptionModel{p}, std::invalid_argument);
  };
  bad([](auto& p) { p.detection_range = std::numeric_limits<double>::quiet_NaN(); });
  bad([](auto& p) { p.detection_range = -1.0; });
  bad([](auto& p) { p.dropout_probability = 1.5; });
  bad([](auto& p) { p.misclassification_probability = -0.1; });
  bad([](auto& p) { p.latency = -0.1; });
  bad([](auto& p) { p.detections_per_light = 0; });
  bad([](auto& p) { p.confidence_noise = -0.1; });
  bad([](auto& p) { p.blackouts = {{2.0, 1.0}}; });

  PerceptionModel model;
  model.observe(kTruth, 10.0, 1.0);
  EXPECT_THROW(model.observe(kTruth, 10.0, 0.9), std::invalid_argument);
  EXPECT_THROW(model.observe(kTruth, std::numeric_limits<double>::quiet_NaN(), 1.1), std::invalid_argument);
  EXPECT_THROW(model.observe(kTruth, 10.0, std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_TRUE(model.observe(kTruth, 10.0, 1.0).observation.has_value());  // same time again is fine
}

TEST(PerceptionModelWithJudge, ABlackoutLongerThanTheTimeoutStopsTheEgo) {
  // Green light seen until t = 2.0, then a 3 s blackout: the last observation ages past
  // tl_state_timeout and the judge stops (docs/behaviour.md §L1.3 row 2), then passes again once seen.
  PerceptionModelParameters pp;
  pp.blackouts = {{2.05, 5.0}};
  PerceptionModel perception(pp);
  TrafficLightJudge judge;
  const std::vector<SignalElement> green = {SignalElement{C::Green, S::Circle, SignalStatus::SolidOn, 1.0}};
  double t = 0.0;
  double first_timeout = -1.0;
  double first_stop = -1.0;
  bool passed_after = false;
  for (int k = 0; k <= 60; ++k) {
    TrafficLightJudgeInput in;
    in.now = t;
    in.distance_to_stop_point = 200.0;  // far: a stop is always stoppable
    in.velocity = 10.0;
    in.observation = perception.observe(green, 200.0, t).observation;
    const auto r = judge.step(in);
    if (r.verdict == SignalVerdict::TimedOut && first_timeout < 0) first_timeout = t;
    if (r.decision == JudgeDecision::Stop && first_stop < 0) first_stop = t;
    if (t > 5.05 && r.decision == JudgeDecision::Pass && r.verdict == SignalVerdict::Go) passed_after = true;
    t += 0.1;
  }
  EXPECT_NEAR(first_timeout, 3.1, 1e-9);  // last stamp 2.0; 3.0 is not > 1.0 old, 3.1 is
  EXPECT_NEAR(first_stop, 3.3, 1e-9);     // plus the 0.1 s hysteresis (third stop cycle)
  EXPECT_TRUE(passed_after);
}

}  // namespace
}  // namespace signalsim
