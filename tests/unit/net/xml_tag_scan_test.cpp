// The start-tag scan (net/xml_tag_scan.hpp) against pugixml, whose parse it stands in for on
// demand: the tags it reports, the texts it declines, attribute values decoded as pugixml decodes
// them, and, over thousands of damaged copies of a real net, that a text it accepts is one pugixml
// parses, with the same elements at the same offsets.
#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <random>
#include <string>
#include <vector>

#include "net/xml_tag_scan.hpp"
#include "test_nets.hpp"

namespace signalsim::sumo {
namespace {

struct Seen {
  std::string name;
  std::size_t begin;
  int depth;
  bool operator==(const Seen&) const = default;
};

class Recorder : public StartTagVisitor {
 public:
  void start(const StartTag& tag) override {
    tags.push_back({std::string(tag.name), tag.begin, tag.depth});
    last = tag;
  }
  std::vector<Seen> tags;
  StartTag last;
};

/// The scan's tags, or nullopt when it declines the text.
std::optional<std::vector<Seen>> scanned(const std::string& text) {
  Recorder recorder;
  if (!scan_start_tags(text, recorder)) return std::nullopt;
  return recorder.tags;
}

/// pugixml's elements of depth 0 to 2 under the first root, with the offsets of their '<'.
std::optional<std::vector<Seen>> parsed(const std::string& text) {
  pugi::xml_document doc;
  if (!doc.load_buffer(text.data(), text.size())) return std::nullopt;
  std::vector<Seen> out;
  const auto visit = [&](auto& self, pugi::xml_node node, int depth) -> void {
    if (node.type() != pugi::node_element || depth > 2) return;
    out.push_back({node.name(), static_cast<std::size_t>(node.offset_debug() - 1), depth});
    for (pugi::xml_node child : node.children()) self(self, child, depth + 1);
  };
  visit(visit, doc.document_element(), 0);
  return out;
}

TEST(XmlTagScan, ReportsTheRootItsChildrenAndTheirsWithTheirOffsets) {
  const std::string text =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- <edge id=\"in a comment\"/> -->\n"
      "<net a='1'>\n  <edge id=\"e\" note=\"a > b\">\n    <lane id=\"e_0\"><param key=\"k\"/></lane>\n"
      "  </edge>\n  <?pi <edge id=\"x\"/> ?>\n  <junction id=\"j\"><![CDATA[ <edge id=\"y\"/> ]]></junction>\n"
      "</net>\n<!-- after -->\n";
  const auto tags = scanned(text);
  ASSERT_TRUE(tags);
  const std::vector<Seen> expected = {{"net", text.find("<net"), 0},
                                      {"edge", text.find("<edge id=\"e\""), 1},
                                      {"lane", text.find("<lane"), 2},
                                      {"junction", text.find("<junction"), 1}};
  EXPECT_EQ(*tags, expected);  // <param> is at depth 3
  EXPECT_EQ(*tags, *parsed(text));
}

TEST(XmlTagScan, DeclinesWhatItDoesNotReadAsPugixmlDoes) {
  const std::string net = "<net><edge id=\"a\"/></net>";
  const std::vector<std::string> declined = {
      "",                                                      // no root
      "<!-- only a comment -->",
      "\xef\xbb\xbf" + net,                                    // a byte order mark
      std::string("<\0n\0e\0t\0>\0", 10),                      // UTF-16 without one
      "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>" + net,   // another encoding
      "<!DOCTYPE net>" + net,
      "<net><edge id=\"a\"></net>",                            // tags mismatch
      "<net><edge id=\"a\"/></net></edge>",
      "<net><edge id=\"a\"/>",                                 // not closed
      "<net><!-- open </net>",
      "<net><edge id=\"a/></net>",                             // a value without its quote
      "<net><edge id=a/></net>",
      "<net><edge id=\"a\"x=\"b\"/></net>",                     // no space between attributes
      "<net><edge id=\"a\" <lane/></net>",
      "<net><edge/ ></net>",
      "<net>< edge/></net>",
      "<net><edge id/></net>",
      "<net><1edge/></net>",
      std::string("<net><edge id=\"a\0\"/></net>", 26),        // a NUL
      "<net/><?xml version=\"1.0\"?>",                          // a declaration not first
  };
  for (const std::string& text : declined) EXPECT_FALSE(scanned(text)) << text;
  EXPECT_TRUE(scanned(net));
  EXPECT_TRUE(scanned("<?xml version=\"1.0\" encoding=\"utf-8\"?><net/>"));
}

TEST(XmlTagScan, AttributeValuesAsPugixmlDecodesThem) {
  const std::vector<std::string> values = {"plain",  "a&amp;b", "&#98;&#x63;", "&lt;&gt;&quot;&apos;", "tab\there",
                                           "cr\r\nlf", "",      "&unknown;",   "a'b"};
  for (const std::string& value : values) {
    const std::string text = "<net><edge x=\"1\" id=\"" + value + "\"/></net>";
    Recorder recorder;
    ASSERT_TRUE(scan_start_tags(text, recorder)) << value;
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_buffer(text.data(), text.size()));
    std::string scratch;
    EXPECT_EQ(attribute_value(recorder.last, "id", scratch), doc.child("net").child("edge").attribute("id").value())
        << value;
    EXPECT_EQ(raw_attribute(recorder.last, "id"), value);
  }
  Recorder recorder;
  ASSERT_TRUE(scan_start_tags("<net><edge from='a' via=\"b\"/></net>", recorder));
  std::string scratch;
  EXPECT_EQ(attribute_value(recorder.last, "via", scratch), "b");
  EXPECT_EQ(attribute_value(recorder.last, "from", scratch), "a");
  EXPECT_FALSE(raw_attribute(recorder.last, "id"));
  EXPECT_EQ(attribute_value(recorder.last, "id", scratch), "");
}

TEST(XmlTagScan, WhatItAcceptsPugixmlParsesWithTheSameElements) {
  // A real net (netconvert's line.net.xml) damaged at random: bytes deleted, repeated or replaced
  // by one of XML's special characters.
  const std::string net = testing::read_all(testing::net_path("line.net.xml"));
  ASSERT_TRUE(scanned(net));
  ASSERT_EQ(*scanned(net), *parsed(net));
  const std::string specials = "<>/=\"'!?-[]& \n";
  std::mt19937 random(16);
  int accepted = 0, declined = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::string text = net;
    const int damages = 1 + static_cast<int>(random() % 3);
    for (int d = 0; d < damages; ++d) {
      const std::size_t at = random() % text.size();
      switch (random() % 3) {
        case 0: text.erase(at, 1 + random() % 8); break;
        case 1: text.insert(at, text.substr(at, 1 + random() % 8)); break;
        default: text[at] = specials[random() % specials.size()]; break;
      }
    }
    const auto tags = scanned(text);
    if (!tags) {
      ++declined;
      continue;
    }
    ++accepted;
    const auto elements = parsed(text);
    ASSERT_TRUE(elements) << "scanned, but pugixml does not parse it:\n" << text;
    ASSERT_EQ(*tags, *elements) << text;
  }
  EXPECT_GT(accepted, 500);  // both outcomes are exercised
  EXPECT_GT(declined, 500);
}

}  // namespace
}  // namespace signalsim::sumo
