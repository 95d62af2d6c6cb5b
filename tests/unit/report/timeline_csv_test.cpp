// timeline.csv and events.csv of hand-made records (report/outputs.hpp): each column where the header
// says, empty fields where a value is absent, numbers to 1 mm / 1 ms with no "-0.000", the
// v2i_time_to_red column only when asked for.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "report/outputs.hpp"

namespace signalsim {
namespace {

namespace fs = std::filesystem;

const std::string kHeader =
    "time,s_front,x,y,speed,accel,edge,lane,lateral_offset,blinker,blinker_source,sumo_signals,tl_id,tl_state,"
    "tl_observed,tl_decision,stop_distance,judge_distance,yellow_lamp_line,zone,stop_s,stop_level,planned_offset,"
    "planned_speed,speed_limited_by,sumo_speed,sumo_limited_by,leader,leader_gap";

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class TimelineCsv : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("signalsim_timeline_csv_" + std::to_string(getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// A row at a light: every column has a value.
TimelineRow judged_row() {
  TimelineRow r;
  r.time = 12.3;
  r.s_front = 118.40049;
  r.x = 1.6;
  r.y = -81.5996;
  r.speed = 13.89;
  r.accel = -0.0002;  // rounds to zero: written "0.000"
  r.edge = "in_S";
  r.lane = "in_S_1";
  r.lateral_offset = -0.125;  // an exact binary tie: to even, as printf
  r.planned_offset = 0.0625;
  r.blinker = Blinker::Left;
  r.blinker_source = RequestSource::Intersection;
  r.sumo_signals = 2;
  r.tl_id = "C";
  r.tl_state = 'g';
  r.tl_observed = "green";
  r.tl_decision = JudgeDecision::Stop;
  r.zone = JudgeZone::Stoppable;
  r.stop_distance = 71.2;
  r.judge_distance = 30.0006;
  r.yellow_lamp_line = 41.67;
  r.stop_s = 188.6;
  r.stop_level = StopLevel::Limit;
  r.v2i_time_to_red = 3.25;
  r.planned_speed = 13.8;
  r.speed_limited_by = "light_stop";
  r.sumo_speed = 12.5;
  r.sumo_limited_by = "leader";
  r.leader = "car7";
  r.leader_gap = 4.25;
  return r;
}

TEST_F(TimelineCsv, EveryColumnOfAJudgedRowAndTheEmptyFieldsOfAPlainOne) {
  TimelineRow plain;  // no light, no plan, SUMO's signals unknown (the ego is gone)
  plain.time = 0.1;
  plain.edge = "e";
  plain.lane = "e_0";
  plain.lateral_offset = -0.0;
  plain.tl_id = "";
  plain.tl_decision = JudgeDecision::Pass;  // not written without a light
  const fs::path path = dir_ / "timeline.csv";
  write_timeline_csv(path.string(), {judged_row(), plain});
  EXPECT_EQ(read_file(path), kHeader + "\n" +
                                 "12.300,118.400,1.600,-81.600,13.890,0.000,in_S,in_S_1,-0.125,left,intersection,2,C,g,"
                                 "green,stop,71.200,30.001,41.670,stoppable,188.600,limit,0.062,13.800,light_stop,"
                                 "12.500,leader,car7,4.250\n"
                                 "0.100,0.000,0.000,0.000,0.000,0.000,e,e_0,0.000,none,none,,,,,,,,,,,,,,,,,,\n");
}

TEST_F(TimelineCsv, TheV2iColumnOnlyWhenAskedFor) {
  TimelineRow without = judged_row();
  without.v2i_time_to_red.reset();
  without.sumo_signals = 0;
  const fs::path path = dir_ / "timeline.csv";
  write_timeline_csv(path.string(), {judged_row(), without}, {.v2i = true});
  const std::string row =
      "12.300,118.400,1.600,-81.600,13.890,0.000,in_S,in_S_1,-0.125,left,intersection,2,C,g,green,stop,71.200,"
      "30.001,41.670,stoppable,188.600,limit,0.062,13.800,light_stop,12.500,leader,car7,4.250";
  const std::string row_without =
      "12.300,118.400,1.600,-81.600,13.890,0.000,in_S,in_S_1,-0.125,left,intersection,0,C,g,green,stop,71.200,"
      "30.001,41.670,stoppable,188.600,limit,0.062,13.800,light_stop,12.500,leader,car7,4.250";
  EXPECT_EQ(read_file(path), kHeader + ",v2i_time_to_red\n" + row + ",3.250\n" + row_without + ",\n");
}

TEST_F(TimelineCsv, AnEmptyRunIsTheHeaderAlone) {
  const fs::path path = dir_ / "timeline.csv";
  write_timeline_csv(path.string(), {});
  EXPECT_EQ(read_file(path), kHeader + "\n");
}

TEST_F(TimelineCsv, EventsWithTheirTimeAndPlace) {
  const fs::path path = dir_ / "events.csv";
  write_events_csv(path.string(), {{10.05, -0.0001, "blinker", "none", "left", "intersection"},
                                   {21.5, 190.2, "light", "pass", "stop", "C"}});
  EXPECT_EQ(read_file(path), "time,s_front,kind,from,to,source\n"
                             "10.050,0.000,blinker,none,left,intersection\n"
                             "21.500,190.200,light,pass,stop,C\n");
}

}  // namespace
}  // namespace signalsim
