// The option table of src/net/sumo_options.cpp against the installed SUMO: every FILE option that
// `sumo --save-template` lists is classified (owned, output or input), so a SUMO upgrade that adds a
// file option shows up here instead of as an output written beside a user's files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "net/sumo_options.hpp"

namespace signalsim::sumo {
namespace {

TEST(SumoOptionTable, EveryFileOptionOfTheInstalledSumoIsClassified) {
  const auto path = std::filesystem::temp_directory_path() / "signalsim_sumo_template.xml";
  ASSERT_EQ(std::system(("sumo --save-template " + path.string() + " > /dev/null 2>&1").c_str()), 0);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  const std::regex file_option(R"(<([A-Za-z0-9._-]+) value="[^"]*"[^>]*type="FILE")");
  const std::vector<std::string> known = classified_file_options();
  int seen = 0;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), file_option); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1];
    ++seen;
    EXPECT_TRUE(std::find(known.begin(), known.end(), name) != known.end())
        << "SUMO's FILE option '" << name << "' is not classified in src/net/sumo_options.cpp";
  }
  EXPECT_GE(seen, 40);
  // Every synonym SUMO knows maps onto its option's long name (a user may write either).
  const std::regex with_synonyms(R"re(<([A-Za-z0-9._-]+) value="[^"]*"[^>]*synonymes="([^"]*)")re");
  int synonyms = 0;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), with_synonyms); it != std::sregex_iterator(); ++it) {
    std::istringstream names((*it)[2].str());
    for (std::string synonym; names >> synonym; ++synonyms)
      EXPECT_EQ(canonical_option(synonym), (*it)[1].str()) << "synonym '" << synonym << "'";
  }
  EXPECT_GE(synonyms, 80);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace signalsim::sumo
