// SUMO options as a user passes them: tokens to options, the owned ones refused with the reason,
// relative output paths into --out, relative inputs from their file's folder, gui-only ones dropped.
#include <gtest/gtest.h>

#include "net/sumo_options.hpp"

namespace signalsim::sumo {
namespace {

using Tokens = std::vector<std::string>;

TEST(SumoOptions, TokensBecomeOptionsWithValuesOrBareSwitches) {
  const auto o = parse_sumo_tokens({"--fcd-output", "fcd.xml", "--fcd-output.signals", "--time-to-teleport", "-1",
                                    "--end=10", "-v"});
  ASSERT_EQ(o.size(), 5u);
  EXPECT_EQ(o[0].name, "fcd-output");
  EXPECT_EQ(o[0].value, "fcd.xml");
  EXPECT_EQ(o[1].name, "fcd-output.signals");
  EXPECT_FALSE(o[1].has_value);  // followed by an option: a bare boolean switch
  EXPECT_EQ(o[2].value, "-1");   // a negative number is a value, not an option
  EXPECT_EQ(o[3].name, "end");
  EXPECT_EQ(o[3].value, "10");
  EXPECT_EQ(o[4].name, "verbose");  // synonyms become SUMO's long names
  EXPECT_THROW(parse_sumo_tokens({"fcd.xml"}), SumoOptionError);
}

TEST(SumoOptions, OwnedOptionsAreRefusedWithTheReason) {
  for (const Tokens& t : {Tokens{"--step-length", "0.5"}, Tokens{"-n", "x.net.xml"}, Tokens{"--remote-port", "9"},
                          Tokens{"-c", "x.sumocfg"}, Tokens{"--log", "x.log"}, Tokens{"--seed", "3"},
                          Tokens{"--random"}, Tokens{"--srand", "4"}, Tokens{"--mesosim"},
                          Tokens{"--no-internal-links", "true"}}) {
    try {
      sumo_tokens(parse_sumo_tokens(t), "sumo_args", "/out", "/in", false);
      ADD_FAILURE() << t[0] << " was accepted";
    } catch (const SumoOptionError& e) {
      EXPECT_NE(std::string(e.what()).find("is set by signalsim: "), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("sumo_args: SUMO option '", 0), 0u) << e.what();
    }
  }
}

TEST(SumoOptions, RelativeOutputsLandInOutAndInputsAreResolvedFromTheirFile) {
  const Tokens out = sumo_tokens(parse_sumo_tokens({"--tripinfo", "trips.xml", "--emission-output", "/abs/e.xml",
                                                    "--weight-files", "w1.xml,sub/w2.xml", "--fcd-output.geo", "true"}),
                                 "sumo_args", "/runs/0001", "/scenarios", false);
  EXPECT_EQ(out, (Tokens{"--tripinfo-output", "/runs/0001/trips.xml", "--emission-output", "/abs/e.xml",
                         "--weight-files", "/scenarios/w1.xml,/scenarios/sub/w2.xml", "--fcd-output.geo", "true"}));
  EXPECT_THROW(sumo_tokens(parse_sumo_tokens({"--fcd-output"}), "sumo_args", "/o", "/i", false), SumoOptionError)
      << "an output option without a file";
}

TEST(SumoOptions, AnOptionGivenTwiceAndEveryEntryOfAnOutputList) {
  EXPECT_THROW(sumo_tokens(parse_sumo_tokens({"--fcd-output", "a.xml", "--fcd-output", "b.xml"}), "sumo_args", "/o",
                           "/i", false),
               SumoOptionError);
  EXPECT_EQ(sumo_tokens(parse_sumo_tokens({"--save-state.files", "sa.xml,sb.xml", "--device.ssm.file", "ssm.xml"}),
                        "sumo_args", "/runs/1", "/in", false),
            (Tokens{"--save-state.files", "/runs/1/sa.xml,/runs/1/sb.xml", "--device.ssm.file", "/runs/1/ssm.xml"}));
  EXPECT_EQ(sumo_tokens(parse_sumo_tokens({"--lateral-resolution", "0.4"}), "sumo_args", "/o", "/i", false),
            (Tokens{"--lateral-resolution", "0.4"}))
      << "a user's own sublane model is theirs";
}

TEST(SumoOptions, GuiOnlyOptionsReachOnlySumoGui) {
  const auto options = parse_sumo_tokens({"--gui-settings-file", "view.xml", "--window-size", "800,600"});
  EXPECT_TRUE(sumo_tokens(options, "sumocfg", "/o", "/cfg", false).empty());
  EXPECT_EQ(sumo_tokens(options, "sumocfg", "/o", "/cfg", true),
            (Tokens{"--gui-settings-file", "/cfg/view.xml", "--window-size", "800,600"}));
}

}  // namespace
}  // namespace signalsim::sumo
