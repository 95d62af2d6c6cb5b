// The .sumocfg reader on signalsim's own configurations (tests/data/user_sumo, bologna_acosta).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "net/net_index.hpp"
#include "net/sumocfg.hpp"
#include "temp_dir.hpp"

namespace signalsim::sumo {
namespace {

const std::string kSource = SIGNALSIM_SOURCE_DIR;


TEST(Sumocfg, ReadsFilesTimesSeedAndKeepsTheOtherOptionsWithTheirLines) {
  const SumoConfigFile cfg = read_sumocfg(kSource + "/tests/data/user_sumo/cross.sumocfg");
  ASSERT_TRUE(cfg.net);
  EXPECT_EQ(*cfg.net, kSource + "/sumo_nets/cross/cross.net.xml");  // relative to the .sumocfg
  ASSERT_EQ(cfg.route_files.size(), 1u);
  EXPECT_EQ(cfg.route_files[0], kSource + "/tests/data/user_sumo/demand.rou.xml");
  ASSERT_EQ(cfg.additional.size(), 1u);
  EXPECT_EQ(cfg.begin, 0.0);
  EXPECT_EQ(cfg.end, 120.0);
  EXPECT_EQ(cfg.step_length, 0.1);
  EXPECT_EQ(cfg.seed, 7);
  ASSERT_EQ(cfg.others.size(), 4u);
  EXPECT_EQ(cfg.others[0].option.name, "time-to-teleport");
  EXPECT_EQ(cfg.others[1].option.name, "tripinfo-output");
  EXPECT_EQ(cfg.others[1].option.value, "tripinfo.xml");
  EXPECT_EQ(cfg.others[2].option.name, "log");
  EXPECT_EQ(cfg.others[2].line, 26);
}

TEST(Sumocfg, ThePublishedShapeWithSeveralFilesPerOption) {
  const SumoConfigFile cfg = read_sumocfg(kSource + "/sumo_nets/bologna_acosta/acosta.sumocfg");
  EXPECT_EQ(cfg.route_files.size(), 2u);
  EXPECT_EQ(cfg.additional.size(), 3u);
  EXPECT_FALSE(cfg.step_length);  // not given: the scenario's (or signalsim's 0.1 s)
}

TEST(Sumocfg, AFlatFileAndEnvironmentVariablesAsSumoReadsThem) {
  const TempDir dir("sumocfg_flat");
  setenv("SIGNALSIM_TEST_NETS", (kSource + "/sumo_nets/cross").c_str(), 1);
  const std::string flat = dir.file("flat.sumocfg", "<configuration>\n  <net-file value=\"${SIGNALSIM_TEST_NETS}/cross.net.xml\"/>\n"
                                                    "  <end value=\"30\"/>\n  <tripinfo-output v=\"t.xml\"/>\n"
                                                    "</configuration>\n");
  const SumoConfigFile cfg = read_sumocfg(flat);
  ASSERT_TRUE(cfg.net);
  EXPECT_EQ(*cfg.net, kSource + "/sumo_nets/cross/cross.net.xml");
  EXPECT_EQ(cfg.end, 30.0);
  EXPECT_EQ(cfg.end_line, 3);
  ASSERT_EQ(cfg.others.size(), 1u);
  EXPECT_EQ(cfg.others[0].option.value, "t.xml");
  const std::string unset = dir.file("unset.sumocfg", "<configuration>\n<input>\n"
                                                      "<net-file value=\"${SIGNALSIM_NOT_SET_ANYWHERE}/x.net.xml\"/>\n"
                                                      "</input>\n</configuration>\n");
  try {
    read_sumocfg(unset);
    ADD_FAILURE() << "an unset variable was accepted";
  } catch (const NetError& e) {
    EXPECT_NE(std::string(e.what()).find("unset.sumocfg:3: option 'net-file': environment variable "
                                         "'SIGNALSIM_NOT_SET_ANYWHERE' is not set"),
              std::string::npos)
        << e.what();
  }
}

TEST(Sumocfg, BadFilesNameTheFileAndLine) {
  const auto message = [](const std::string& path) {
    try {
      read_sumocfg(path);
    } catch (const NetError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const TempDir dir("sumocfg");
  const std::string missing_input = dir.file("signalsim_missing_input.sumocfg",
                                               "<configuration>\n<input>\n<net-file value=\"nowhere.net.xml\"/>\n"
                                               "</input>\n</configuration>\n");
  EXPECT_NE(message(missing_input).find("signalsim_missing_input.sumocfg:3: option 'net-file': file"), std::string::npos)
      << message(missing_input);
  const std::string bad_number = dir.file("signalsim_bad_number.sumocfg",
                                            "<configuration>\n<time>\n<end value=\"soon\"/>\n</time>\n</configuration>\n");
  EXPECT_NE(message(bad_number).find(":3: option 'end' is not a number: 'soon'"), std::string::npos)
      << message(bad_number);
  const std::string not_cfg = dir.file("signalsim_not_cfg.sumocfg", "<net/>\n");
  EXPECT_NE(message(not_cfg).find("not a SUMO configuration"), std::string::npos) << message(not_cfg);
  EXPECT_NE(message(kSource + "/nowhere.sumocfg").find("nowhere.sumocfg"), std::string::npos);
}

}  // namespace
}  // namespace signalsim::sumo
