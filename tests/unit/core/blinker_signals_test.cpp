// The blinker as SUMO's TraCI signal bits (core/blinker_signals.hpp): the bits SUMO documents, the
// encoding the session commands and the decoding of what SUMO shows, each the other's inverse.
#include <gtest/gtest.h>

#include "core/blinker_signals.hpp"

namespace signalsim {
namespace {

TEST(BlinkerSignals, EncodesTheBitsTraciDocuments) {
  EXPECT_EQ(signal_mask(Blinker::None), 0);
  EXPECT_EQ(signal_mask(Blinker::Right), 1);   // VEH_SIGNAL_BLINKER_RIGHT
  EXPECT_EQ(signal_mask(Blinker::Left), 2);    // VEH_SIGNAL_BLINKER_LEFT
  EXPECT_EQ(signal_mask(Blinker::Hazard), 4);  // VEH_SIGNAL_BLINKER_EMERGENCY
  EXPECT_EQ(sumo::kBlinkerMask, 7);
}

TEST(BlinkerSignals, DecodesWhatSumoShows) {
  EXPECT_EQ(blinker_of_signals(0), Blinker::None);
  EXPECT_EQ(blinker_of_signals(8), Blinker::None);  // brake light only
  EXPECT_EQ(blinker_of_signals(1), Blinker::Right);
  EXPECT_EQ(blinker_of_signals(9), Blinker::Right);
  EXPECT_EQ(blinker_of_signals(2), Blinker::Left);
  EXPECT_EQ(blinker_of_signals(3), Blinker::Hazard);  // both directions
  EXPECT_EQ(blinker_of_signals(4), Blinker::Hazard);
}

TEST(BlinkerSignals, DecodingInvertsEncoding) {
  for (Blinker b : {Blinker::None, Blinker::Left, Blinker::Right, Blinker::Hazard}) {
    EXPECT_EQ(blinker_of_signals(signal_mask(b)), b);
    EXPECT_EQ(blinker_of_signals(signal_mask(b) | 8), b);  // with the brake light
  }
}

}  // namespace
}  // namespace signalsim
