// SUMO's command line for a session, and SUMO's first error line.
#include <gtest/gtest.h>

#include <algorithm>

#include "session/sumo_command_line.hpp"

namespace signalsim::sumo {
namespace {

bool has_pair(const std::vector<std::string>& args, const std::string& option, const std::string& value) {
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == option && args[i + 1] == value) return true;
  return false;
}

TEST(SumoCommandLine, RouteFilesAreRouteFilesAndTheLogGoesToTheRun) {
  SessionConfig c;
  c.net = "n.net.xml";
  c.route_files = {"a.rou.xml", "b.rou.xml"};
  c.additional = {"types.add.xml"};
  c.log_file = "/out/sumo.log";
  c.begin = 300;
  const auto args = sumo_command_line(c, "sumo");
  EXPECT_EQ(args.front(), "sumo");
  EXPECT_TRUE(has_pair(args, "-r", "a.rou.xml,b.rou.xml"));  // loaded incrementally, not as additional
  EXPECT_TRUE(has_pair(args, "-a", "types.add.xml"));
  EXPECT_TRUE(has_pair(args, "--log", "/out/sumo.log"));
  EXPECT_TRUE(has_pair(args, "--begin", "300"));
  EXPECT_EQ(std::count(args.begin(), args.end(), "--no-warnings"), 0) << "warnings go to the log";
}

TEST(SumoCommandLine, AUsersValueReplacesADefaultInsteadOfRepeatingIt) {
  SessionConfig c;
  c.net = "n.net.xml";
  c.extra_args = {"--time-to-teleport", "300"};
  const auto args = sumo_command_line(c, "sumo");
  EXPECT_EQ(std::count(args.begin(), args.end(), "--time-to-teleport"), 1);  // SUMO refuses a repeat
  EXPECT_TRUE(has_pair(args, "--time-to-teleport", "300"));
  SessionConfig d;
  d.net = "n.net.xml";
  EXPECT_TRUE(has_pair(sumo_command_line(d, "sumo"), "--time-to-teleport", "-1"));
  EXPECT_TRUE(has_pair(sumo_command_line(d, "sumo"), "--no-warnings", "true")) << "no log: as before";
}

TEST(SumoCommandLine, FirstErrorLine) {
  EXPECT_EQ(first_error_line("Warning: x\nLoading\nError: The edge 'q' is not known.\n The route can not be build.\n"
                             "Quitting (on error).\n"),
            "The edge 'q' is not known. The route can not be build.");
  EXPECT_EQ(first_error_line("Warning: x\nFXApp::openDisplay: unable to open display :9\n"),
            "FXApp::openDisplay: unable to open display :9");
}

}  // namespace
}  // namespace signalsim::sumo
