// JUnit XML of signalsim check: counts, outcomes and text, read back as XML (not compared as
// text: the indentation and escaping are pugixml's); special characters give well-formed XML.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include <pugixml.hpp>

#include "batch/junit_xml.hpp"
#include "scenario/utf8_text.hpp"

namespace signalsim {
namespace {

// The document parsed back; fails the test when it does not parse.
pugi::xml_document parsed(const std::string& xml) {
  pugi::xml_document doc;
  const pugi::xml_parse_result result = doc.load_string(xml.c_str(), pugi::parse_default | pugi::parse_declaration);
  EXPECT_TRUE(result) << result.description() << " at " << result.offset << " in\n" << xml;
  return doc;
}

std::string attribute(const pugi::xml_node& node, const char* name) { return node.attribute(name).value(); }

// XML 1.0 cannot hold a control character but tab, line feed and carriage return, not even as a
// character reference (&#1;): a strict parser (expat, python's xml.etree) refuses the document.
void expect_only_xml_characters(const std::string& xml) {
  for (const char c : xml)
    EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r')
        << "raw control character " << static_cast<int>(c) << " in\n" << xml;
  for (std::size_t at = xml.find("&#"); at != std::string::npos; at = xml.find("&#", at + 2)) {
    const bool hex = at + 2 < xml.size() && xml[at + 2] == 'x';
    const long code = std::strtol(xml.c_str() + at + (hex ? 3 : 2), nullptr, hex ? 16 : 10);
    EXPECT_TRUE(code >= 0x20 || code == '\n' || code == '\t' || code == '\r')
        << "reference to character " << code << " in\n" << xml;
  }
}

TEST(JUnitXml, CountsOutcomesAndTextReadBack) {
  std::vector<JUnitCase> cases(4);
  cases[0].name = "a";
  cases[0].file = "s/a.yaml";
  cases[0].time = 0.25;
  cases[1].name = "b<&>";
  cases[1].result = JUnitCase::Result::Failed;
  cases[1].message = "1 event \"differs\"";
  cases[1].details = "left -> right";
  cases[1].system_out = "expectation failed: never_runs_red: crossed on r\n";
  cases[2].name = "c";
  cases[2].result = JUnitCase::Result::Error;
  cases[2].message = "run error: boom";
  cases[3].name = "d";
  cases[3].result = JUnitCase::Result::Skipped;
  cases[3].message = "3 events match (note: the scenario has no expectations)";
  const std::string xml = junit_xml("signalsim check", cases, 1.5);
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n", 0), 0u) << xml;
  const pugi::xml_document doc = parsed(xml);

  const pugi::xml_node suites = doc.child("testsuites");
  const pugi::xml_node suite = suites.child("testsuite");
  for (const pugi::xml_node& node : {suites, suite}) {
    EXPECT_EQ(attribute(node, "name"), "signalsim check");
    EXPECT_EQ(attribute(node, "tests"), "4");
    EXPECT_EQ(attribute(node, "failures"), "1");
    EXPECT_EQ(attribute(node, "errors"), "1");
    EXPECT_EQ(attribute(node, "skipped"), "1");
    EXPECT_EQ(attribute(node, "time"), "1.500");
  }
  std::vector<pugi::xml_node> testcases;
  for (const pugi::xml_node& c : suite.children("testcase")) testcases.push_back(c);
  ASSERT_EQ(testcases.size(), 4u);

  EXPECT_EQ(attribute(testcases[0], "classname"), "signalsim check");
  EXPECT_EQ(attribute(testcases[0], "name"), "a");
  EXPECT_EQ(attribute(testcases[0], "file"), "s/a.yaml");
  EXPECT_EQ(attribute(testcases[0], "time"), "0.250");
  EXPECT_FALSE(testcases[0].first_child()) << "a passed case has no children";

  EXPECT_EQ(attribute(testcases[1], "name"), "b<&>");
  const pugi::xml_node failure = testcases[1].child("failure");
  ASSERT_TRUE(failure);
  EXPECT_EQ(attribute(failure, "message"), "1 event \"differs\"");
  EXPECT_STREQ(failure.text().get(), "left -> right");
  EXPECT_STREQ(testcases[1].child("system-out").text().get(), "expectation failed: never_runs_red: crossed on r\n");
  EXPECT_EQ(std::string(testcases[1].first_child().name()), "failure") << "<failure> before <system-out>";

  const pugi::xml_node error = testcases[2].child("error");
  ASSERT_TRUE(error);
  EXPECT_EQ(attribute(error, "message"), "run error: boom");
  EXPECT_FALSE(error.first_child()) << "no details: no text";
  EXPECT_FALSE(testcases[2].child("system-out"));

  const pugi::xml_node skipped = testcases[3].child("skipped");
  ASSERT_TRUE(skipped);
  EXPECT_EQ(attribute(skipped, "message"), "3 events match (note: the scenario has no expectations)");
}

TEST(JUnitXml, ClassnamePropertiesAndAttachmentLines) {
  std::vector<JUnitCase> cases(2);
  cases[0].name = "left";
  cases[0].classname = "scenarios.cross";
  cases[0].result = JUnitCase::Result::Failed;
  cases[0].message = "expectations failed";
  cases[0].system_out = "expectation failed: blinker_never: left at t=3.00 s";  // no final line feed
  cases[0].properties = {{"seed", "7"}, {"parameter_file", "a.yaml"}, {"parameter_file", "b <&>.yaml"}};
  cases[0].attachments = {"out/runs/0000-left/plots/blinker.png", "out/runs/0000-left/gui.png"};
  cases[1].name = "right";
  const pugi::xml_document doc = parsed(junit_xml("signalsim batch", cases, 1.0));
  const pugi::xml_node suite = doc.child("testsuites").child("testsuite");
  const pugi::xml_node failed = suite.find_child_by_attribute("testcase", "name", "left");
  const pugi::xml_node passed = suite.find_child_by_attribute("testcase", "name", "right");
  EXPECT_EQ(attribute(failed, "classname"), "scenarios.cross");
  EXPECT_EQ(attribute(passed, "classname"), "signalsim batch") << "no classname of its own: the suite's name";
  EXPECT_EQ(std::string(failed.first_child().name()), "properties") << "<properties> first in a test case";
  std::vector<std::pair<std::string, std::string>> properties;
  for (const pugi::xml_node& p : failed.child("properties").children("property"))
    properties.emplace_back(attribute(p, "name"), attribute(p, "value"));
  EXPECT_EQ(properties, cases[0].properties);
  // Each attachment a whole line of its own, after the text (which gets the line feed it lacked).
  EXPECT_STREQ(failed.child("system-out").text().get(),
               "expectation failed: blinker_never: left at t=3.00 s\n"
               "[[ATTACHMENT|out/runs/0000-left/plots/blinker.png]]\n"
               "[[ATTACHMENT|out/runs/0000-left/gui.png]]\n");
  EXPECT_FALSE(passed.child("properties"));
  EXPECT_FALSE(passed.child("system-out"));
}

TEST(JUnitXml, SpecialCharactersGiveWellFormedXml) {
  std::vector<JUnitCase> cases(1);
  cases[0].name = "x<y & \"z\" 'q'\x01\x1f>";
  cases[0].file = "dir/x<y & \"z\"\x01.yaml";
  cases[0].result = JUnitCase::Result::Failed;
  cases[0].message = "no golden file g/x<y & \"z\"\x01.events.csv\x02";
  cases[0].details = "line 1 ]]> <![CDATA[ &amp;\n\tline 2\x07\x1b[0m\r\n";
  cases[0].system_out = "expectation failed: <&>\x0b\n";
  const std::string xml = junit_xml("suite <&\">\x03", cases, 0.0);
  expect_only_xml_characters(xml);
  const pugi::xml_document doc = parsed(xml);
  const pugi::xml_node suite = doc.child("testsuites").child("testsuite");
  EXPECT_EQ(attribute(suite, "name"), "suite <&\"> ");
  const pugi::xml_node c = suite.child("testcase");
  // Each control character but tab, line feed and carriage return is a space; the rest is kept.
  EXPECT_EQ(attribute(c, "name"), "x<y & \"z\" 'q'  >");
  EXPECT_EQ(attribute(c, "classname"), "suite <&\"> ");
  EXPECT_EQ(attribute(c, "file"), "dir/x<y & \"z\" .yaml");
  EXPECT_EQ(attribute(c.child("failure"), "message"), "no golden file g/x<y & \"z\" .events.csv ");
  EXPECT_STREQ(c.child("failure").text().get(), "line 1 ]]> <![CDATA[ &amp;\n\tline 2  [0m\n");
  EXPECT_STREQ(c.child("system-out").text().get(), "expectation failed: <&> \n");
}

// A scenario file named in Latin-1 ("caf\xE9.yaml") gives names, files and messages that are not
// UTF-8: the document declares UTF-8, so each such byte is written as U+FFFD (expat, which GitLab's
// and python's parsers use, refuses the raw byte).
TEST(JUnitXml, BytesThatAreNotUtf8BecomeReplacementCharacters) {
  std::vector<JUnitCase> cases(1);
  cases[0].name = "caf\xE9";
  cases[0].file = "lat/caf\xE9.yaml";
  cases[0].result = JUnitCase::Result::Error;
  cases[0].message = "run error: lat/caf\xE9.yaml:3: bad \xC3";
  cases[0].system_out = "\xFF\xFEtext\n";
  const std::string xml = junit_xml("signalsim batch", cases, 1.0);
  EXPECT_FALSE(find_invalid_utf8(xml)) << xml;
  const pugi::xml_document doc = parsed(xml);
  const pugi::xml_node c = doc.child("testsuites").child("testsuite").child("testcase");
  EXPECT_EQ(attribute(c, "name"), "caf\uFFFD");
  EXPECT_EQ(attribute(c, "file"), "lat/caf\uFFFD.yaml");
  EXPECT_EQ(attribute(c.child("error"), "message"), "run error: lat/caf\uFFFD.yaml:3: bad \uFFFD");
  EXPECT_EQ(std::string(c.child("system-out").text().get()), "\uFFFD\uFFFDtext\n");
}

}  // namespace
}  // namespace signalsim
