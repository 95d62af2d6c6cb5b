// A country preset's driving side against the net's: the side read from the net's <net lefthand>
// alone, the warning when they differ (the exit blinker then points the wrong way for SUMO's traffic),
// none when they agree, when the preset does not say or when the net cannot be read.
#include <string>

#include <gtest/gtest.h>

#include "net/net_file.hpp"
#include "scenario/countries.hpp"
#include "scenario/scenario.hpp"
#include "temp_dir.hpp"

namespace signalsim {
namespace {

const std::string kSource = SIGNALSIM_SOURCE_DIR;
const std::string kRightHandNet = kSource + "/sumo_nets/roundabout/roundabout.net.xml";
const std::string kLeftHandNet = kSource + "/sumo_nets/roundabout_lefthand/roundabout_lefthand.net.xml";

TEST(DrivingSide, TheNetsSideIsItsRootsLefthand) {
  EXPECT_EQ(sumo::read_net_lefthand(kLeftHandNet), std::optional<bool>(true));  // a comment names lefthand too
  EXPECT_EQ(sumo::read_net_lefthand(kRightHandNet), std::optional<bool>(false));
  TempDir dir("side");
  EXPECT_EQ(sumo::read_net_lefthand(dir.file("yes.net.xml", "<net lefthand=\"yes\"><edge id=\"a\"/></net>\n")),
            std::optional<bool>(true));
  EXPECT_EQ(sumo::read_net_lefthand(dir.file("bad.net.xml", "<net lefthand=\"maybe\"/>\n")), std::nullopt);
  EXPECT_EQ(sumo::read_net_lefthand(dir.file("other.xml", "<routes/>\n")), std::nullopt);
  EXPECT_EQ(sumo::read_net_lefthand(dir.path() + "/missing.net.xml"), std::nullopt);
}

TEST(DrivingSide, APresetForTheOtherSideIsAWarning) {
  Country jp;
  jp.code = "jp";
  jp.driving_side = "left";
  EXPECT_EQ(driving_side_warning(jp, "r.net.xml", false),
            std::optional<std::string>("country jp drives on the left, but the net r.net.xml is right-hand traffic "
                                       "(no lefthand=\"true\"): the exit blinker is then on the wrong side for that "
                                       "traffic"));
  EXPECT_EQ(driving_side_warning(jp, "l.net.xml", true), std::nullopt);
  Country de;
  de.code = "de";
  de.driving_side = "right";
  EXPECT_EQ(driving_side_warning(de, "l.net.xml", true),
            std::optional<std::string>("country de drives on the right, but the net l.net.xml is left-hand traffic "
                                       "(lefthand=\"true\"): the exit blinker is then on the wrong side for that "
                                       "traffic"));
  de.driving_side.clear();  // a preset that does not say
  EXPECT_EQ(driving_side_warning(de, "l.net.xml", true), std::nullopt);
}

TEST(DrivingSide, TheBundledPresetsSayTheirSide) {
  EXPECT_EQ(load_country("jp").driving_side, "left");
  EXPECT_EQ(load_country("de").driving_side, "right");
  EXPECT_EQ(load_country("kr").driving_side, "right");
}

TEST(DrivingSide, TheScenarioKeepsTheWarning) {
  const Scenario jp_on_right = load_scenario(kSource + "/scenarios/roundabout_jp_exit2.yaml");
  ASSERT_EQ(jp_on_right.warnings.size(), 1u);
  EXPECT_EQ(jp_on_right.warnings[0], "country jp drives on the left, but the net " + kRightHandNet +
                                         " is right-hand traffic (no lefthand=\"true\"): the exit blinker is then "
                                         "on the wrong side for that traffic");
  EXPECT_TRUE(load_scenario(kSource + "/scenarios/roundabout_lefthand_jp_exit2.yaml").warnings.empty());
  const Scenario de_on_left =
      load_scenario(kSource + "/scenarios/roundabout_lefthand_jp_exit2.yaml", ScenarioOverrides{{"country=de"}});
  ASSERT_EQ(de_on_left.warnings.size(), 1u);
  EXPECT_NE(de_on_left.warnings[0].find("country de drives on the right"), std::string::npos);
}

}  // namespace
}  // namespace signalsim
