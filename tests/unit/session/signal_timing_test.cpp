// V2I predictions from SUMO's programs (docs/behaviour.md §L1.7), SUMO-free: phases + current phase + next
// switch -> the phases to come -> the predicted red stamp of the ego's link (static programs: the
// whole cycle; actuated ones: the next switch only), with arrows (docs/behaviour.md §S3).
#include <gtest/gtest.h>

#include <optional>

#include "route/approach_lights.hpp"
#include "session/signal_timing.hpp"

namespace signalsim::sumo {
namespace {

// The cross net's south approach: links 8 right, 9 straight, 10 straight, 11 left.
ApproachLight south_approach(TurnDirection ego, int ego_link) {
  ApproachLight light;
  light.tls_id = "C";
  light.link_index = ego_link;
  light.lane_index = ego_link <= 9 ? 0 : 1;
  light.direction = ego;
  light.links = {{TurnDirection::Right, 8, 0}, {TurnDirection::Straight, 9, 0}, {TurnDirection::Straight, 10, 1},
                 {TurnDirection::Left, 11, 1}};
  return light;
}

// The first predicted phase that is a red stop for the ego's lane, as the judge's V2I rule reads it.
std::optional<double> red_stamp(const LightProgram& program, int phase, double next_switch, const ApproachLight& light) {
  for (const PhasePrediction& p : predict_phases(program, phase, next_switch)) {
    const auto elements = signal_elements(p.state, light);
    if (elements && is_traffic_signal_red_stop(judge_turn_direction(light.direction), *elements)) return p.stamp;
  }
  return std::nullopt;
}

// v2i_green_ends.add.xml: green 20 s, yellow 3 s, red 40 s.
LightProgram green_yellow_red(ProgramKind kind) {
  return {"p", kind,
          {{20, "GGGgrrrrGGGgrrrr", {}}, {3, "yyyyrrrryyyyrrrr", {}}, {40, "rrrrrrrrrrrrrrrr", {}}}};
}

TEST(SignalTiming, StaticProgramPredictsTheWholeCycle) {
  const auto p = predict_phases(green_yellow_red(ProgramKind::Static), 0, 20.0);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0], (PhasePrediction{20.0, 1, "yyyyrrrryyyyrrrr"}));
  EXPECT_EQ(p[1], (PhasePrediction{23.0, 2, "rrrrrrrrrrrrrrrr"}));
  EXPECT_EQ(p[2], (PhasePrediction{63.0, 0, "GGGgrrrrGGGgrrrr"})) << "the cycle ends with the current phase's return";
}

TEST(SignalTiming, StaticRedStampFollowsTheNextSwitch) {
  const ApproachLight straight = south_approach(TurnDirection::Straight, 9);
  const LightProgram program = green_yellow_red(ProgramKind::Static);
  EXPECT_EQ(red_stamp(program, 0, 20.0, straight), 23.0) << "green now: red after the yellow";
  EXPECT_EQ(red_stamp(program, 0, 12.5, straight), 15.5) << "a shortened phase (setPhaseDuration) moves it";
  EXPECT_EQ(red_stamp(program, 1, 21.0, straight), 21.0) << "yellow now: red at the next switch";
  // Red now: the next red is the one after the coming green and yellow.
  EXPECT_EQ(red_stamp(program, 2, 60.0, straight), 83.0);
}

TEST(SignalTiming, StaticProgramFollowsNext) {
  // Phase 0 jumps to phase 2 (the red) and skips the yellow 1; phase 2 goes back to 0.
  LightProgram program = green_yellow_red(ProgramKind::Static);
  program.phases[0].next = {2};
  program.phases[2].next = {0};
  const auto p = predict_phases(program, 0, 20.0);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].phase, 2);
  EXPECT_EQ(p[0].stamp, 20.0);
  EXPECT_EQ(p[1].phase, 0);
  EXPECT_EQ(p[1].stamp, 60.0);
  EXPECT_EQ(static_successor(program, 1), 2);
  EXPECT_EQ(static_successor(program, 5), -1);
}

TEST(SignalTiming, ActuatedProgramPredictsOnlyTheNextSwitch) {
  const ApproachLight straight = south_approach(TurnDirection::Straight, 9);
  const LightProgram program = green_yellow_red(ProgramKind::Actuated);
  const auto p = predict_phases(program, 0, 25.0);
  ASSERT_EQ(p.size(), 1u) << "what comes after the next switch depends on detectors";
  EXPECT_EQ(p[0], (PhasePrediction{25.0, 1, "yyyyrrrryyyyrrrr"}));
  EXPECT_EQ(red_stamp(program, 0, 25.0, straight), std::nullopt) << "green now: the red is beyond what is known";
  EXPECT_EQ(red_stamp(program, 1, 27.0, straight), 27.0) << "yellow now: the red comes at the next switch";
  EXPECT_EQ(red_stamp(green_yellow_red(ProgramKind::DelayBased), 1, 27.0, straight), 27.0);
}

TEST(SignalTiming, ActuatedPhaseWithSeveralTargetsPredictsNothing) {
  LightProgram program = green_yellow_red(ProgramKind::Actuated);
  program.phases[1].next = {2, 0};  // chosen by demand
  EXPECT_TRUE(predict_phases(program, 1, 27.0).empty());
  program.phases[1].next = {2};
  EXPECT_EQ(predict_phases(program, 1, 27.0).size(), 1u);
}

TEST(SignalTiming, ArrowsDecideWhoseRedItIs) {
  // 0: straight and left green; 1: red circle with a green left arrow; 2: all red.
  const LightProgram program{"arrows", ProgramKind::Static,
                             {{20, "rrrrrrrrGGGGrrrr", {}}, {10, "rrrrrrrrrrrGrrrr", {}}, {30, "rrrrrrrrrrrrrrrr", {}}}};
  const ApproachLight left = south_approach(TurnDirection::Left, 11);
  const ApproachLight straight = south_approach(TurnDirection::Straight, 10);
  EXPECT_EQ(red_stamp(program, 0, 20.0, straight), 20.0) << "the straight lane's red comes with the arrow phase";
  EXPECT_EQ(red_stamp(program, 0, 20.0, left), 30.0) << "the left turner's green arrow is no red stop";
}

TEST(SignalTiming, NothingForAnUnknownPhaseOrProgram) {
  const LightProgram program = green_yellow_red(ProgramKind::Static);
  EXPECT_TRUE(predict_phases(program, 3, 10.0).empty());
  EXPECT_TRUE(predict_phases(program, -1, 10.0).empty());
  EXPECT_TRUE(predict_phases(LightProgram{}, 0, 10.0).empty());
  const std::vector<LightProgram> programs = {program};
  EXPECT_EQ(find_program(programs, "p"), &programs[0]);
  EXPECT_EQ(find_program(programs, "online"), nullptr) << "a state set by TraCI has no program to predict from";
  EXPECT_EQ(program_kind_of(0), ProgramKind::Static);
  EXPECT_EQ(program_kind_of(3), ProgramKind::Actuated);
  EXPECT_EQ(program_kind_of(4), ProgramKind::DelayBased);
  EXPECT_EQ(program_kind_of(5), ProgramKind::Other);
}

}  // namespace
}  // namespace signalsim::sumo
