// signalsim check's event comparison: tolerance, moved/missing/extra events (JUnit XML: junit_xml_test.cpp);
// a golden file's times and positions are finite numbers.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

#include "batch/golden.hpp"
#include "batch/run_outputs.hpp"

namespace signalsim {
namespace {

TimelineEvent ev(double t, double s, const std::string& from, const std::string& to,
                 const std::string& source = "intersection") {
  return {t, s, "blinker", from, to, source};
}

std::vector<EventDiff::Op> ops(const std::vector<EventDiff>& diff) {
  std::vector<EventDiff::Op> out;
  for (const auto& d : diff) out.push_back(d.op);
  return out;
}

using Op = EventDiff::Op;

const std::vector<TimelineEvent> golden = {ev(10.0, 122.331, "none", "left"), ev(17.9, 205.716, "left", "right"),
                                           ev(24.9, 260.867, "right", "none", "none")};

TEST(GoldenCompare, WithinToleranceIsTheSame) {
  auto run = golden;
  run[0].s_front += 0.5;  // exactly the tolerance
  run[1].time += 0.1;     // one step
  const auto diff = compare_events(golden, run, 0.5, 0.1);
  EXPECT_EQ(ops(diff), (std::vector<Op>{Op::Same, Op::Same, Op::Same}));
  EXPECT_EQ(count_differences(diff), 0u);
}

TEST(GoldenCompare, ShiftedMissingAndExtraEvents) {
  auto run = golden;
  run[1].s_front += 2.0;
  EXPECT_EQ(ops(compare_events(golden, run, 0.5, 0.1)), (std::vector<Op>{Op::Same, Op::Moved, Op::Same}));
  run = golden;
  run[0].time += 0.2;
  EXPECT_EQ(ops(compare_events(golden, run, 0.5, 0.1)), (std::vector<Op>{Op::Moved, Op::Same, Op::Same}));

  run = {golden[0], golden[2]};
  EXPECT_EQ(ops(compare_events(golden, run, 0.5, 0.1)), (std::vector<Op>{Op::Same, Op::Missing, Op::Same}));
  run = {golden[0], ev(15.0, 180.0, "left", "hazard"), golden[1], golden[2]};
  const auto diff = compare_events(golden, run, 0.5, 0.1);
  EXPECT_EQ(ops(diff), (std::vector<Op>{Op::Same, Op::Extra, Op::Same, Op::Same}));
  const std::string text = format_diff(diff, "");
  EXPECT_NE(text.find("+     15.000 s   180.000 m  blinker left -> hazard (intersection)   not in the golden file"),
            std::string::npos);
  // Another source is another event.
  run = golden;
  run[0].source = "lane_change";
  EXPECT_EQ(count_differences(compare_events(golden, run, 0.5, 0.1)), 2u);
}

// The message of reading `text` as an events.csv ("" when it reads).
std::string events_error(const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / ("golden_" + std::to_string(::getpid()) + ".events.csv")).string();
  std::ofstream(path) << text;
  std::string message;
  try {
    (void)read_events_csv(path);
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message.empty() ? "" : message.substr(message.find(".events.csv") + 11);
}

TEST(GoldenCompare, AGoldenTimeOrPositionThatIsNotFiniteIsRefused) {
  const std::string header = "time,s_front,kind,from,to,source\n";
  EXPECT_EQ(events_error(header + "0.100,0.000,light,none,pass,C\n"), "");
  EXPECT_EQ(events_error(header + "0.100,0.000,light,none,pass,C\nnan,118.164,blinker,none,left,intersection\n"),
            ":3: 'nan' is not a finite number");
  EXPECT_EQ(events_error(header + "9.7,inf,blinker,none,left,intersection\n"), ":2: 'inf' is not a finite number");
  EXPECT_EQ(events_error(header + "9.7,-infinity,blinker,none,left,intersection\n"),
            ":2: '-infinity' is not a finite number");
}

}  // namespace
}  // namespace signalsim
