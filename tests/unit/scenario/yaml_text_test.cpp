// What a YAML file may not hold although yaml-cpp reads it: a second document (even a malformed one),
// a quoted text without its closing quote, control characters in the file or written as escapes; and
// the same for a --set value. Each is refused at its line with the reason.
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "scenario/overrides.hpp"
#include "scenario/yaml_fields.hpp"
#include "temp_dir.hpp"
#include "test_files.hpp"

namespace signalsim {
namespace {

using test::error_of;

// The message of loading `text` as a scenario file named y.yaml ("" when it loads).
std::string yaml_error(const std::string& text) {
  const TempDir dir("yaml-text");
  const std::string path = dir.file("y.yaml", text);
  const std::string message = error_of([&] { (void)load_yaml_file(path, "scenario file"); });
  return message.empty() ? "" : message.substr(message.find("y.yaml"));
}

TEST(YamlText, ASecondDocumentIsRefusedAtItsMarkerEvenWhenMalformed) {
  EXPECT_EQ(yaml_error("name: a\n---\nname: b\n"),
            "y.yaml:2: a second YAML document starts here; a scenario file holds one document");
  EXPECT_EQ(yaml_error("name: a\n# two\n---\nfoo: [\n"),
            "y.yaml:3: a second YAML document starts here; a scenario file holds one document");
  EXPECT_EQ(yaml_error("name: a\n...\nname: b\n"),
            "y.yaml:3: a second YAML document starts here; a scenario file holds one document");
}

TEST(YamlText, OneDocumentWithItsMarkersLoads) {
  EXPECT_EQ(yaml_error("# a comment\n---\nname: a\n...\n"), "");
  EXPECT_EQ(yaml_error("%YAML 1.2\n--- # the document\nname: a\ntext: |\n  --- inside a block\n"), "");
}

TEST(YamlText, AQuoteWithoutItsClosingQuoteIsRefusedAtItsLine) {
  EXPECT_EQ(yaml_error("name: a\ndescription: \"unterminated\n"),
            "y.yaml:2: malformed YAML: the quoted text opened here has no closing \"");
  EXPECT_EQ(yaml_error("name: 'oops\nnet: x.net.xml\nego: {route: [a]}\n"),
            "y.yaml:1: malformed YAML: the quoted text opened here has no closing '");
  EXPECT_EQ(yaml_error("\xEF\xBB\xBFname: a\nb: \"x\"\nc: \"y\n"),
            "y.yaml:3: malformed YAML: the quoted text opened here has no closing \"");
}

TEST(YamlText, ClosedQuotesWithEscapesLoad) {
  EXPECT_EQ(yaml_error("a: \"x\\\"y\"\nb: 'it''s'\nc: \"multi\n  line\"\n\"d\": \"\\u00e9\"\n"), "");
}

TEST(YamlText, ControlCharactersAreRefusedAtTheirLine) {
  EXPECT_EQ(yaml_error("name: a\ndescription: red\x1b[31m\n"),
            "y.yaml:2: a control character (U+001B at column 17); texts may hold tabs and line breaks only");
  EXPECT_EQ(yaml_error("name: a\ndescription: \"red\\e[31m\"\n"),
            "y.yaml:2: a text holds a control character (U+001B); texts may hold tabs and line breaks only");
  EXPECT_EQ(yaml_error("name: \"bell\\x07\"\n"),
            "y.yaml:1: a text holds a control character (U+0007); texts may hold tabs and line breaks only");
  EXPECT_EQ(yaml_error("name: a\nb: c\xc2\x9b" "31m\n"),
            "y.yaml:2: a control character (U+009B at column 5); texts may hold tabs and line breaks only");
}

TEST(YamlText, TabsAndLineEndsLoad) {
  EXPECT_EQ(yaml_error("name: a\r\ndescription: \"a\\tb\"\r\nc: |\n  two\n  lines\n"), "");
}

TEST(YamlText, AControlCharacterInASetValueIsRefused) {
  YAML::Node parameters;
  EXPECT_EQ(error_of([&] { apply_overrides(YAML::Load("name: s\n"), ScenarioOverrides{{"name=\"q\\e[31m\""}}, parameters); }),
            "--set: 'name=\"q\\e[31m\"': a text holds a control character (U+001B); texts may hold tabs and line "
            "breaks only");
  EXPECT_EQ(error_of([&] { apply_overrides(YAML::Load("name: s\n"), ScenarioOverrides{{"name=q\x1b"}}, parameters); }),
            "--set: an override holds a control character (U+001B at column 7)");
}

}  // namespace
}  // namespace signalsim
