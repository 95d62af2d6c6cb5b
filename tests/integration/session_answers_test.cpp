// What the session answers within one step is SUMO's state at that moment, on the real libsumo: the
// session keeps each step's answers (session/session_step_answers.hpp), and these tests fail if it kept
// one too long: the ego's place after move_back moved it, a light's state and timing after its
// program was shifted, the time and the ego after the next step. Net: sumo_nets/cross (in_S runs
// north into the light C; its program: 30 s green for in_S, 3 s yellow, 2 s red, then the cross
// direction).
#include <gtest/gtest.h>

#include <string>

#include "session/sumo_session.hpp"

namespace signalsim {
namespace {

sumo::SessionConfig config(double depart_pos, double depart_speed) {
  sumo::SessionConfig c;
  c.net = std::string(SIGNALSIM_SOURCE_DIR) + "/sumo_nets/cross/cross.net.xml";
  c.route = {"in_S", "out_N"};
  c.step_length = 0.1;
  c.depart_lane = 0;
  c.depart_pos = depart_pos;
  c.depart_speed = depart_speed;
  return c;
}

TEST(SessionAnswers, TheEgoMovedBackIsReportedWhereItIsNowInTheSameStep) {
  const auto session = sumo::open_session(config(50.0, 0.0));
  session->command(0, 0.0);
  ASSERT_TRUE(session->step());
  const sumo::EgoState before = session->ego();
  ASSERT_EQ(before.lane, "in_S_0");
  session->move_back(5.0);
  const sumo::EgoState after = session->ego();  // no step in between
  EXPECT_EQ(after.lane, before.lane);
  EXPECT_NEAR(after.lane_pos, before.lane_pos - 5.0, 1e-6);
  EXPECT_DOUBLE_EQ(after.time, before.time);
  session->command(0, 0.0);
  ASSERT_TRUE(session->step());
  const sumo::EgoState next = session->ego();  // at rest where it was moved
  EXPECT_NEAR(next.lane_pos, before.lane_pos - 5.0, 1e-6);
  EXPECT_NEAR(next.y, before.y - 5.0, 1e-6);  // in_S runs north (SUMO updates x, y in the step)
}

TEST(SessionAnswers, AShiftedLightShowsItsNewPhaseInTheSameStep) {
  const auto session = sumo::open_session(config(0.0, 0.0));
  EXPECT_EQ(session->light_state("C"), "GGGgrrrrGGGgrrrr");
  EXPECT_EQ(session->light_timing("C").phase, 0);
  // 31 s into the 70 s cycle: the yellow phase (30-33 s).
  session->shift_light_program("C", 31.0);
  EXPECT_EQ(session->light_state("C"), "yyyyrrrryyyyrrrr");
  EXPECT_EQ(session->light_timing("C").phase, 1);
}

// A light's state is kept in one place for the run (the step stages hold a reference to it while they
// judge): the next steps answer into the same string, with the state SUMO shows then.
TEST(SessionAnswers, ALightsStateIsKeptAtOnePlaceAndAnsweredAfreshEachStep) {
  const auto session = sumo::open_session(config(0.0, 0.0));
  const std::string& first = session->light_state("C");
  EXPECT_EQ(first, "GGGgrrrrGGGgrrrr");
  const std::string* kept_at = &first;
  bool saw_yellow = false;
  for (int k = 0; k < 320 && !saw_yellow; ++k) {  // yellow from 30 s on: shown after the step to 30.1 s
    session->command(0, 0.0);
    ASSERT_TRUE(session->step());
    const std::string& now = session->light_state("C");
    EXPECT_EQ(&now, kept_at);
    EXPECT_EQ(now, session->time() < 30.05 ? "GGGgrrrrGGGgrrrr" : "yyyyrrrryyyyrrrr") << session->time();
    saw_yellow = now == "yyyyrrrryyyyrrrr";
  }
  EXPECT_TRUE(saw_yellow);
}

TEST(SessionAnswers, EachStepIsAnsweredAfresh) {
  const auto session = sumo::open_session(config(0.0, 10.0));
  session->command(0, 10.0);
  ASSERT_TRUE(session->step());
  const double t0 = session->time();
  const sumo::EgoState e0 = session->ego();
  const int signals0 = session->ego_signals();
  EXPECT_EQ(signals0 & sumo::kBlinkerMask, 0);
  session->command(sumo::kBlinkerLeft, 10.0);
  ASSERT_TRUE(session->step());
  EXPECT_NEAR(session->time(), t0 + 0.1, 1e-9);
  const sumo::EgoState e1 = session->ego();
  EXPECT_NEAR(e1.time, t0 + 0.1, 1e-9);
  EXPECT_NEAR(e1.lane_pos, e0.lane_pos + 1.0, 1e-6);  // 10 m/s for 0.1 s
  EXPECT_EQ(session->ego_signals() & sumo::kBlinkerMask, sumo::kBlinkerLeft);
}

}  // namespace
}  // namespace signalsim
