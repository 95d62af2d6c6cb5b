// Reading on demand (net/net_index.hpp): whatever order the lookups come in, every answer (edges,
// lanes, connections, junctions, defects with their lines) is the one an index that read the whole
// net in file order gives. Checked on every committed test net, the bundled real net bologna_acosta,
// and variants of line.net.xml whose answers depend on the order of reading (repeated edge, lane
// and via ids, elements without ids).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>
#include <regex>
#include <set>
#include <sstream>

#include "net/net_index.hpp"
#include "test_nets.hpp"

namespace signalsim::sumo {
namespace {

using testing::net_path;
using testing::read_all;
using testing::ScratchDir;

enum class Ask { Edge, Lane, EdgeOfLane, Junction, Connections, Via, DefectEdge, DefectLane, DefectJunction, DefectTl };
struct Query {
  Ask ask;
  std::string id;
};

void put_lane(std::ostream& out, const NetLane& l) {
  out << " lane " << l.id << " " << l.index << " " << l.speed << " " << l.length << " " << l.width << " "
      << l.stop_offset << " " << l.allows_passenger << " [" << l.allow << "|" << l.disallow << "]";
  for (const Vec2& p : l.shape.points()) out << " " << p.x << "," << p.y;
  for (const auto& [k, v] : l.params) out << " " << k << "=" << v;
}

void put_edge(std::ostream& out, const NetEdge* e) {
  if (e == nullptr) {
    out << " none";
    return;
  }
  out << " edge " << e->id << " " << e->from_junction << ">" << e->to_junction << " " << e->is_internal << " "
      << e->stop_offset << " " << e->bidi;
  for (const auto& [k, v] : e->params) out << " " << k << "=" << v;
  for (const NetLane& l : e->lanes) put_lane(out, l);
}

void put_connection(std::ostream& out, const NetConnection& c) {
  out << " conn " << c.from_edge << "_" << c.from_lane << ">" << c.to_edge << "_" << c.to_lane << " " << c.via << " "
      << c.dir << c.state << " " << c.tl << ":" << c.link_index;
}

void put_defect(std::ostream& out, const NetDefect* d) {
  if (d == nullptr) out << " no defect";
  else out << " defect " << d->line << " " << d->element << ": " << d->reason << " " << d->affects_routes;
}

std::string answer(const NetIndex& net, const Query& q) {
  std::ostringstream out;
  out << static_cast<int>(q.ask) << " '" << q.id << "':";
  switch (q.ask) {
    case Ask::Edge: put_edge(out, net.edge(q.id)); break;
    case Ask::Lane:
      if (const NetLane* l = net.lane(q.id)) put_lane(out, *l);
      break;
    case Ask::EdgeOfLane: put_edge(out, net.edge_of_lane(q.id)); break;
    case Ask::Junction:
      if (const NetJunction* j = net.junction(q.id)) out << " " << j->type << " " << j->x << "," << j->y;
      break;
    case Ask::Connections:
      for (const NetConnection& c : net.connections_from_lane(q.id)) put_connection(out, c);
      break;
    case Ask::Via:
      if (const NetConnection* c = net.connection_via(q.id)) put_connection(out, *c);
      break;
    case Ask::DefectEdge: put_defect(out, net.defect(NetElement::Edge, q.id)); break;
    case Ask::DefectLane: put_defect(out, net.defect(NetElement::Lane, q.id)); break;
    case Ask::DefectJunction: put_defect(out, net.defect(NetElement::Junction, q.id)); break;
    case Ask::DefectTl: put_defect(out, net.defect(NetElement::TlLogic, q.id)); break;
  }
  return out.str();
}

std::string whole_net(const NetIndex& net) {
  std::ostringstream out;
  out << net.edge_count() << " edges:";
  for (const NetEdge& e : net.edges()) out << " " << e.id;
  out << "\n";
  for (const NetDefect& d : net.defects()) put_defect(out, &d);
  return out.str();
}

/// Every id the file names (and a few it does not), asked every way.
std::vector<Query> queries_for(const std::string& text) {
  std::set<std::string> ids = {"", "nope", "ab_01", "ab_+0", "ab_-0", "bc_1_", "_0"};
  const std::regex named("(?:id|from|to|via|tl)=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), named); it != std::sregex_iterator(); ++it)
    ids.insert((*it)[1]);
  std::vector<Query> out;
  for (const std::string& id : ids)
    for (int ask = 0; ask <= static_cast<int>(Ask::DefectTl); ++ask) out.push_back({static_cast<Ask>(ask), id});
  return out;
}

/// Answers from an index that read the whole net at load, in file order, and from indexes reading
/// on demand asked in file-id order, in reverse and shuffled: all the same, and so is the whole net
/// read afterwards.
void expect_order_independent(const std::string& path) {
  const std::vector<Query> queries = queries_for(read_all(path));
  const NetIndex whole = NetIndex::load(path, NetReading::Whole);
  const std::string whole_text = whole_net(whole);
  std::vector<std::string> expected;
  for (const Query& q : queries) expected.push_back(answer(whole, q));

  std::vector<std::size_t> order(queries.size());
  std::iota(order.begin(), order.end(), 0);
  for (int pass = 0; pass < 3; ++pass) {
    if (pass == 1) std::reverse(order.begin(), order.end());
    if (pass == 2) std::shuffle(order.begin(), order.end(), std::mt19937(7));
    const NetIndex lazy = NetIndex::load(path);
    for (std::size_t i : order) ASSERT_EQ(answer(lazy, queries[i]), expected[i]) << path << " pass " << pass;
    EXPECT_EQ(whole_net(lazy), whole_text) << path << " pass " << pass;
  }
}

TEST(NetOnDemand, EveryTestNetAnswersAsTheWholeNet) {
  int nets = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(SIGNALSIM_TEST_NETS_DIR)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".net.xml") == std::string::npos) continue;
    expect_order_independent(entry.path().string());
    ++nets;
  }
  EXPECT_GE(nets, 8);
}

TEST(NetOnDemand, BolognaAcostaAnswersAsTheWholeNet) {
  expect_order_independent(std::string(SIGNALSIM_SOURCE_DIR) + "/sumo_nets/bologna_acosta/acosta_buslanes.net.xml");
}

/// line.net.xml with `from` replaced by `to` (which must be there).
std::string line_with(const std::string& from, const std::string& to) {
  std::string text = read_all(net_path("line.net.xml"));
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(NetOnDemand, NetsWhoseAnswersDependOnTheOrderOfReading) {
  const std::vector<std::pair<std::string, std::string>> changes = {
      {"<lane id=\"cb_0\"", "<lane id=\"ab_0\""},                      // a later edge repeats a lane id
      {"<lane id=\"ab_0\"", "<lane id=\"cb_0\""},                      // an earlier edge defines a later edge's lane id
      {"<lane id=\"ab_0\"", "<lane id=\":C_0_0\""},                    // ... of another kind
      {"<edge id=\"cb\" from=\"C\"", "<edge id=\"bc\" from=\"C\""},    // a repeated edge id
      {"via=\":B_0_0\" dir=\"t\"", "via=\":B_1_0\" dir=\"t\""},        // two connections through one lane
      {"<connection from=\"ab\" to=\"bc\" fromLane=\"0\"", "<connection from=\"ab\" to=\"bc\" fromLane=\"x\""},
      {"<connection from=\"cb\"", "<connection"},                      // no from-edge
      {"<edge id=\"cb\" ", "<edge "},                                   // no id
      {"<junction id=\"A\"", "<junction"},
      {"<junction id=\"A\"", "<junction id=\"C\""},                    // a repeated junction id
      {"<lane id=\"bc_1\" ", "<lane "},
      {"id=\"bc_1\" index=\"1\"", "id=\"bc_1\" index=\"2\""},
      {"<connection from=\":B_0\" to=\"bc\" fromLane=\"0\"", "<connection from=\":B_0\" to=\"bc\" fromLane=\"00\""},
  };
  ScratchDir scratch;
  for (std::size_t i = 0; i < changes.size(); ++i) {
    SCOPED_TRACE(changes[i].second);
    expect_order_independent(
        scratch.write("changed" + std::to_string(i) + ".net.xml", line_with(changes[i].first, changes[i].second)));
  }
}

/// `text` with every `from` replaced by `to`.
std::string replaced_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

TEST(NetOnDemand, TextsWhoseElementsAreParsedAgainFromTheirStretch) {
  const std::string line = read_all(net_path("line.net.xml"));
  ASSERT_NE(line.find("\n</net>"), std::string::npos);
  std::u16string utf16 = u"\xfeff";
  for (char c : line) utf16 += static_cast<char16_t>(static_cast<unsigned char>(c));
  const std::vector<std::string> texts = {
      "\xef\xbb\xbf" + line,                                               // a UTF-8 byte order mark
      replaced_all(line, "\n", "\r\n"),                                      // CRLF line ends
      replaced_all(line, "\"cb", "\"c&amp;b"),                               // an id with an entity
      replaced_all(line, "\"cb", "\"c&#98;"),
      replaced_all(line, "    <edge id=\"cb\"", "    <!-- <edge id=\"x\"/> -->\n    <edge id=\"cb\""),
      replaced_all(line, "</net>", "</net>\n<!-- </net> <edge id=\"x\"/> -->"),  // after the last element
      replaced_all(line, "encoding=\"UTF-8\"", "encoding=\"ISO-8859-1\""),  // read whole (offsets of a conversion)
      std::string(reinterpret_cast<const char*>(utf16.data()), utf16.size() * 2),  // UTF-16: read whole
  };
  ScratchDir scratch;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    SCOPED_TRACE(i);
    const std::string path = scratch.write("text" + std::to_string(i) + ".net.xml", texts[i]);
    ASSERT_EQ(NetIndex::load(path).edge_count(), 6u);
    expect_order_independent(path);
  }
}

TEST(NetOnDemand, ALaneIdOfAnEarlierEdgeStaysItsWhenTheLaterEdgeIsReadFirst) {
  ScratchDir scratch;
  const std::string text = line_with("<lane id=\"ab_0\"", "<lane id=\"cb_0\"");
  const NetIndex net = NetIndex::load(scratch.write("net.net.xml", text));
  ASSERT_NE(net.edge("cb"), nullptr);  // read first: its lane cb_0 repeats ab's
  EXPECT_EQ(net.lane("cb_0"), &net.edge("ab")->lanes[0]);
  const NetDefect* d = net.defect(NetElement::Lane, "cb_0");
  ASSERT_NE(d, nullptr);
  const int first_line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(
                                                                                         text.find("<lane id=\"cb_0\"")),
                                                          '\n'));
  EXPECT_EQ(d->reason, "another lane has this id (first defined at line " + std::to_string(first_line) + ")");
  EXPECT_EQ(d->line, first_line + 7);  // the lane of edge cb, seven lines on
}

TEST(NetOnDemand, ThroughALaneTheFirstConnectionInTheFile) {
  ScratchDir scratch;
  const NetIndex net =
      NetIndex::load(scratch.write("net.net.xml", line_with("via=\":B_0_0\" dir=\"t\"", "via=\":B_1_0\" dir=\"t\"")));
  ASSERT_EQ(net.connections_from_lane("cb_0").size(), 1u);  // the later one read first
  const NetConnection* via = net.connection_via(":B_1_0");
  ASSERT_NE(via, nullptr);
  EXPECT_EQ(via->from_edge, "ab");
}

}  // namespace
}  // namespace signalsim::sumo
