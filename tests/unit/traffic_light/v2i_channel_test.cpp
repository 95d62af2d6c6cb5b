// The V2I channel's faults (docs/behaviour.md §L1.7 predictions through a perception-like model): latency,
// dropout, blackouts, the age limit, and its own seeded stream.
#include <gtest/gtest.h>

#include <cmath>

#include "traffic_light/v2i_channel.hpp"

namespace signalsim {
namespace {

std::vector<SignalPrediction> red_predictions_at(double stamp) {
  return {{stamp, {SignalElement{SignalColor::Red, SignalShape::Circle, SignalStatus::SolidOn, 1.0}}}};
}

// Steps a channel at 0.1 s from 0 to `until` with predictions stamped 100 + t; returns, per step,
// the stamp of the prediction in force (NaN when none).
std::vector<double> run(V2iChannel& channel, double until) {
  std::vector<double> out;
  for (int i = 0; i * 0.1 <= until + 1e-9; ++i) {
    const double now = i * 0.1;
    const auto p = channel.step(red_predictions_at(100.0 + now), now);
    out.push_back(p.empty() ? std::nan("") : p.front().stamp);
  }
  return out;
}

TEST(V2iChannel, WithoutFaultsTheTruthPassesAtOnce) {
  V2iChannel channel;
  const auto got = run(channel, 1.0);
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], 100.0 + 0.1 * i, 1e-9);
}

TEST(V2iChannel, LatencyDelaysTheMessages) {
  V2iChannelParameters p;
  p.latency = 0.5;
  V2iChannel channel(p);
  const auto got = run(channel, 1.0);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(std::isnan(got[i])) << "step " << i;
  for (std::size_t i = 5; i < got.size(); ++i) EXPECT_NEAR(got[i], 100.0 + 0.1 * (i - 5), 1e-9) << "sent 0.5 s earlier";
}

TEST(V2iChannel, ALatencyBeyondTheAgeLimitNeverCounts) {
  V2iChannelParameters p;
  p.latency = 1.5;
  V2iChannel channel(p);
  for (double g : run(channel, 3.0)) EXPECT_TRUE(std::isnan(g));
}

TEST(V2iChannel, FullDropoutDeliversNothing) {
  V2iChannelParameters p;
  p.dropout_probability = 1.0;
  V2iChannel channel(p);
  for (double g : run(channel, 2.0)) EXPECT_TRUE(std::isnan(g));
}

TEST(V2iChannel, ABlackoutRemovesThePredictionOnceTheLastMessageIsTooOld) {
  V2iChannelParameters p;
  p.blackouts = {{1.0, 3.0}};
  V2iChannel channel(p);
  const auto got = run(channel, 3.5);
  EXPECT_NEAR(got[15], 100.9, 1e-9) << "1.5 s: the message sent at 0.9 s is 0.6 s old";
  EXPECT_NEAR(got[19], 100.9, 1e-9) << "1.9 s: 1.0 s old, still counts";
  EXPECT_TRUE(std::isnan(got[20])) << "2.0 s: 1.1 s old";
  EXPECT_TRUE(std::isnan(got[30])) << "3.0 s: still blacked out";
  EXPECT_NEAR(got[31], 103.1, 1e-9);
}

TEST(V2iChannel, DropoutIsSeededAndReproducible) {
  V2iChannelParameters p;
  p.dropout_probability = 0.5;
  p.max_age = 0.0;  // only this step's message counts
  p.seed = 7;
  V2iChannel a(p), b(p);
  const auto ga = run(a, 10.0), gb = run(b, 10.0);
  int lost = 0;
  for (std::size_t i = 0; i < ga.size(); ++i) {
    EXPECT_EQ(std::isnan(ga[i]), std::isnan(gb[i]));
    lost += std::isnan(ga[i]);
  }
  EXPECT_GT(lost, 20);
  EXPECT_LT(lost, 81);
  p.seed = 8;
  V2iChannel c(p);
  const auto gc = run(c, 10.0);
  bool differs = false;
  for (std::size_t i = 0; i < gc.size(); ++i) differs = differs || std::isnan(gc[i]) != std::isnan(gb[i]);
  EXPECT_TRUE(differs) << "another seed, another pattern";
}

TEST(V2iChannel, RejectsBadParametersAndTimeGoingBack) {
  V2iChannelParameters p;
  p.dropout_probability = 1.5;
  EXPECT_THROW(V2iChannel{p}, std::invalid_argument);
  p = {};
  p.blackouts = {{2.0, 1.0}};
  EXPECT_THROW(V2iChannel{p}, std::invalid_argument);
  V2iChannel channel;
  channel.step({}, 1.0);
  EXPECT_THROW(channel.step({}, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace signalsim
