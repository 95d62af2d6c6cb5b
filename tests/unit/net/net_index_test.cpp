// NetIndex::load on nets built by netconvert 1.15 (tests/data/nets) and on small hand-written files.
#include "net/net_index.hpp"
#include "net/net_file.hpp"
#include "net/internal_lane.hpp"

#include <sys/stat.h>

#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>

#include "test_nets.hpp"

namespace signalsim::sumo {
namespace {

using ::testing::HasSubstr;
using testing::net_path;
using testing::read_all;
using testing::ScratchDir;

/// The message of the NetError thrown by loading `path` ("" when it loads).
std::string load_error(const std::string& path) {
  try {
    NetIndex::load(path);
  } catch (const NetError& e) {
    return e.what();
  }
  return "";
}

/// The message of reading the net file at `path` with at most `max_text` bytes of text ("" when none).
std::string read_error(const std::string& path, std::size_t max_text) {
  try {
    (void)read_net_file(path, max_text);
  } catch (const NetError& e) {
    return e.what();
  }
  return "";
}

/// A minimal net around one lane element, for attribute tests.
std::string net_with_lane(const std::string& lane_xml, const std::string& net_attrs = "") {
  return "<?xml version=\"1.0\"?>\n<net version=\"1.9\"" + net_attrs +
         ">\n  <edge id=\"a\" from=\"J0\" to=\"J1\">\n    " + lane_xml +
         "\n  </edge>\n  <junction id=\"J0\" type=\"dead_end\" x=\"0\" y=\"0\"/>\n"
         "  <junction id=\"J1\" type=\"dead_end\" x=\"10\" y=\"0\"/>\n</net>\n";
}

std::vector<std::string> edge_ids_in(const std::string& path) {
  const std::string text = read_all(path);
  const std::regex edge_re("<edge id=\"([^\"]+)\"");
  std::vector<std::string> ids;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), edge_re); it != std::sregex_iterator(); ++it) {
    ids.push_back((*it)[1]);
  }
  return ids;
}

void expect_same_net(const NetIndex& a, const NetIndex& b, const std::vector<std::string>& edge_ids) {
  ASSERT_EQ(a.edge_count(), b.edge_count());
  ASSERT_EQ(a.edge_count(), edge_ids.size());
  EXPECT_EQ(a.lefthand(), b.lefthand());
  for (const std::string& id : edge_ids) {
    const NetEdge* ea = a.edge(id);
    const NetEdge* eb = b.edge(id);
    ASSERT_NE(ea, nullptr) << id;
    ASSERT_NE(eb, nullptr) << id;
    EXPECT_EQ(ea->from_junction, eb->from_junction);
    EXPECT_EQ(ea->to_junction, eb->to_junction);
    EXPECT_EQ(ea->is_internal, eb->is_internal);
    EXPECT_EQ(ea->params, eb->params);
    EXPECT_EQ(ea->stop_offset, eb->stop_offset);
    ASSERT_EQ(ea->lanes.size(), eb->lanes.size());
    for (std::size_t i = 0; i < ea->lanes.size(); ++i) {
      const NetLane& la = ea->lanes[i];
      const NetLane& lb = eb->lanes[i];
      EXPECT_EQ(la.id, lb.id);
      EXPECT_EQ(la.index, lb.index);
      EXPECT_EQ(la.speed, lb.speed);
      EXPECT_EQ(la.length, lb.length);
      EXPECT_EQ(la.width, lb.width);
      EXPECT_EQ(la.shape.points(), lb.shape.points());
      EXPECT_EQ(la.params, lb.params);
      EXPECT_EQ(la.stop_offset, lb.stop_offset);
      const auto& ca = a.connections_from_lane(la.id);
      const auto& cb = b.connections_from_lane(lb.id);
      ASSERT_EQ(ca.size(), cb.size()) << la.id;
      for (std::size_t k = 0; k < ca.size(); ++k) {
        EXPECT_EQ(ca[k].to_edge, cb[k].to_edge);
        EXPECT_EQ(ca[k].to_lane, cb[k].to_lane);
        EXPECT_EQ(ca[k].via, cb[k].via);
        EXPECT_EQ(ca[k].dir, cb[k].dir);
        EXPECT_EQ(ca[k].tl, cb[k].tl);
        EXPECT_EQ(ca[k].link_index, cb[k].link_index);
      }
    }
    const NetJunction* ja = a.junction(ea->to_junction);
    const NetJunction* jb = b.junction(eb->to_junction);
    ASSERT_EQ(ja == nullptr, jb == nullptr);
    if (ja != nullptr) {
      EXPECT_EQ(ja->type, jb->type);
      EXPECT_EQ(ja->x, jb->x);
      EXPECT_EQ(ja->y, jb->y);
    }
  }
  ASSERT_EQ(a.roundabouts().size(), b.roundabouts().size());
  for (std::size_t i = 0; i < a.roundabouts().size(); ++i) {
    EXPECT_EQ(a.roundabouts()[i].edges, b.roundabouts()[i].edges);
    EXPECT_EQ(a.roundabouts()[i].nodes, b.roundabouts()[i].nodes);
  }
  ASSERT_EQ(a.tl_logics().size(), b.tl_logics().size());
  for (std::size_t i = 0; i < a.tl_logics().size(); ++i) {
    EXPECT_EQ(a.tl_logics()[i].id, b.tl_logics()[i].id);
    ASSERT_EQ(a.tl_logics()[i].phases.size(), b.tl_logics()[i].phases.size());
    for (std::size_t k = 0; k < a.tl_logics()[i].phases.size(); ++k) {
      EXPECT_EQ(a.tl_logics()[i].phases[k].state, b.tl_logics()[i].phases[k].state);
      EXPECT_EQ(a.tl_logics()[i].phases[k].duration, b.tl_logics()[i].phases[k].duration);
    }
  }
}

// ---- plain and gzip --------------------------------------------------------------------------------

TEST(NetIndexLoad, PlainAndGzipLoadIdentically) {
  const ScratchDir scratch;
  for (const char* name : {"crossing.net.xml", "roundabout.net.xml"}) {
    const std::string plain = net_path(name);
    // Compressed under a name without ".gz": gzip is detected by its magic bytes.
    const std::string gz = scratch.write_gzip(std::string("copy_of_") + name, read_all(plain));
    ASSERT_EQ(static_cast<unsigned char>(read_all(gz)[0]), 0x1f);
    const NetIndex a = NetIndex::load(plain);
    const NetIndex b = NetIndex::load(gz);
    EXPECT_EQ(b.path(), gz);
    expect_same_net(a, b, edge_ids_in(plain));
  }
}

TEST(NetIndexLoad, PlainFileNamedGzLoads) {
  const ScratchDir scratch;
  const std::string path = scratch.write("plain.net.xml.gz", read_all(net_path("line.net.xml")));
  EXPECT_EQ(NetIndex::load(path).edge_count(), NetIndex::load(net_path("line.net.xml")).edge_count());
}

// ---- the net attributes ---------------------------------------------------------------------------

TEST(NetIndexLoad, LefthandFlag) {
  EXPECT_TRUE(NetIndex::load(net_path("line_lefthand.net.xml")).lefthand());
  EXPECT_FALSE(NetIndex::load(net_path("line.net.xml")).lefthand());
}

TEST(NetIndexLoad, LefthandNetWritesUTurnsAsCapitalT) {
  // netconvert 1.15 --lefthand: U-turns get dir="T" (LinkDirection::TURN_LEFTHAND).
  const NetIndex net = NetIndex::load(net_path("line_lefthand.net.xml"));
  const NetConnection* u = net.connection_via(":C_0_0");
  ASSERT_NE(u, nullptr);
  EXPECT_EQ(u->from_edge, "bc");
  EXPECT_EQ(u->to_edge, "cb");
  EXPECT_EQ(u->dir, 'T');
}

TEST(NetIndexLoad, CrossingEdgesLanesAndParams) {
  const NetIndex net = NetIndex::load(net_path("crossing.net.xml"));
  const NetEdge* s_in = net.edge("s_in");
  ASSERT_NE(s_in, nullptr);
  EXPECT_FALSE(s_in->is_internal);
  EXPECT_EQ(s_in->from_junction, "S");
  EXPECT_EQ(s_in->to_junction, "C");
  ASSERT_EQ(s_in->lanes.size(), 2u);
  EXPECT_EQ(s_in->lanes[0].id, "s_in_0");
  EXPECT_EQ(s_in->lanes[1].id, "s_in_1");
  EXPECT_EQ(s_in->lanes[1].index, 1);
  EXPECT_DOUBLE_EQ(s_in->lanes[0].speed, 13.89);
  EXPECT_DOUBLE_EQ(s_in->lanes[0].length, 89.60);
  EXPECT_DOUBLE_EQ(s_in->lanes[0].width, 3.2);  // no width attribute: SUMO's default
  ASSERT_EQ(s_in->lanes[0].shape.size(), 2u);
  EXPECT_EQ(s_in->lanes[0].shape.points()[0], (Vec2{204.80, 0.0}));
  EXPECT_EQ(s_in->lanes[0].shape.points()[1], (Vec2{204.80, 89.60}));

  // Plain-XML <param>s on edges and lanes survive netconvert.
  EXPECT_EQ(s_in->params, (std::map<std::string, std::string>{{"origin", "edge"}}));
  EXPECT_TRUE(s_in->lanes[0].params.empty());
  EXPECT_EQ(s_in->lanes[1].params,
            (std::map<std::string, std::string>{{"origin", "lane"}, {"turn_signal_distance", "50"}}));

  EXPECT_EQ(net.edge_of_lane("s_in_1"), s_in);
  EXPECT_EQ(net.lane("s_in_1"), &s_in->lanes[1]);
  EXPECT_EQ(net.lane("nope_0"), nullptr);
  EXPECT_EQ(net.edge("nope"), nullptr);
  EXPECT_EQ(net.edge_of_lane("nope_0"), nullptr);
  // 10 normal edges, 2 + 1 + 1 per arm at C (right, straight x2 lanes, left x2 chained, U-turn x2 chained).
  EXPECT_GT(net.edge_count(), 10u);

  const NetEdge* internal = net.edge(":C_13");
  ASSERT_NE(internal, nullptr);
  EXPECT_TRUE(internal->is_internal);
  EXPECT_TRUE(internal->from_junction.empty());
}

TEST(NetIndexLoad, StopOffsetFromLaneElseEdge) {
  const NetIndex net = NetIndex::load(net_path("crossing.net.xml"));
  // s_in: edge-level <stopOffset value="2.5"/> applies to both lanes.
  EXPECT_DOUBLE_EQ(net.edge("s_in")->stop_offset, 2.5);
  EXPECT_DOUBLE_EQ(net.lane("s_in_0")->stop_offset, 2.5);
  EXPECT_DOUBLE_EQ(net.lane("s_in_1")->stop_offset, 2.5);
  // e_in: edge 3 m, lane 1 overrides with 1 m.
  EXPECT_DOUBLE_EQ(net.edge("e_in")->stop_offset, 3.0);
  EXPECT_DOUBLE_EQ(net.lane("e_in_0")->stop_offset, 3.0);
  EXPECT_DOUBLE_EQ(net.lane("e_in_1")->stop_offset, 1.0);
  EXPECT_DOUBLE_EQ(net.lane("w_in_0")->stop_offset, 0.0);
}

TEST(NetIndexLoad, CrossingConnectionsJunctionsAndLight) {
  const NetIndex net = NetIndex::load(net_path("crossing.net.xml"));
  const auto& from_s_in_1 = net.connections_from_lane("s_in_1");
  ASSERT_EQ(from_s_in_1.size(), 3u);  // straight, left, U-turn
  const NetConnection* left = net.connection_via(":C_13_0");
  ASSERT_NE(left, nullptr);
  EXPECT_EQ(left->from_edge, "s_in");
  EXPECT_EQ(left->to_edge, "w_out");
  EXPECT_EQ(left->from_lane, 1);
  EXPECT_EQ(left->to_lane, 1);
  EXPECT_EQ(left->dir, 'l');
  EXPECT_EQ(left->state, 'o');
  EXPECT_EQ(left->tl, "C");
  EXPECT_EQ(left->link_index, 13);

  // The left turn continues on a second internal lane: a connection from the internal lane.
  const auto& chained = net.connections_from_lane(":C_13_0");
  ASSERT_EQ(chained.size(), 1u);
  EXPECT_EQ(chained[0].from_edge, ":C_13");
  EXPECT_EQ(chained[0].via, ":C_24_0");
  EXPECT_EQ(chained[0].dir, 'l');
  EXPECT_TRUE(chained[0].tl.empty());
  EXPECT_EQ(chained[0].link_index, -1);
  ASSERT_NE(net.connection_via(":C_24_0"), nullptr);
  EXPECT_TRUE(net.connections_from_lane(":C_24_0").at(0).via.empty());
  EXPECT_TRUE(net.connections_from_lane("nope_0").empty());
  EXPECT_EQ(net.connection_via("s_in_0"), nullptr);

  const NetJunction* c = net.junction("C");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->type, "traffic_light");
  EXPECT_DOUBLE_EQ(c->x, 200.0);  // netconvert shifts the net by its netOffset
  EXPECT_DOUBLE_EQ(c->y, 100.0);
  ASSERT_NE(net.junction(":C_24_0"), nullptr);  // the internal junction on the left turn
  EXPECT_EQ(net.junction(":C_24_0")->type, "internal");
  EXPECT_EQ(net.junction("nope"), nullptr);

  ASSERT_EQ(net.tl_logics().size(), 1u);
  const NetTlLogic* tl = net.tl_logic("C");
  ASSERT_NE(tl, nullptr);
  EXPECT_EQ(tl->type, "static");
  EXPECT_EQ(tl->program_id, "0");
  EXPECT_DOUBLE_EQ(tl->offset, 0.0);
  ASSERT_EQ(tl->phases.size(), 4u);
  EXPECT_DOUBLE_EQ(tl->phases[1].duration, 3.0);
  EXPECT_EQ(tl->phases[0].state.size(), 20u);
  EXPECT_EQ(net.tl_logic("nope"), nullptr);
}

TEST(NetIndexLoad, Roundabout) {
  const NetIndex net = NetIndex::load(net_path("roundabout.net.xml"));
  ASSERT_EQ(net.roundabouts().size(), 1u);
  EXPECT_EQ(net.roundabouts()[0].edges, (std::vector<std::string>{"r01", "r12", "r23", "r30"}));
  EXPECT_EQ(net.roundabouts()[0].nodes, (std::vector<std::string>{"R0", "R1", "R2", "R3"}));
  EXPECT_EQ(net.roundabout_of_edge("r12"), std::optional<std::size_t>(0));
  EXPECT_EQ(net.roundabout_of_edge("in0"), std::nullopt);
  EXPECT_EQ(net.lane("r01_0")->params, (std::map<std::string, std::string>{{"ring", "yes"}}));
}

// ---- hand-written files: attributes ---------------------------------------------------------------

TEST(NetIndexLoad, ShapeWithZCoordinateWidthAndLaneStopOffset) {
  const ScratchDir scratch;
  const std::string path = scratch.write(
      "z.net.xml",
      net_with_lane("<lane id=\"a_0\" index=\"0\" speed=\"+8.5\" length=\"10.0\" width=\"2.75\" "
                    "shape=\"0.00,-1.60,5.00  10.00,-1.60,6.5\">\n"
                    "      <stopOffset value=\"1.25\" vClasses=\"passenger\" exceptions=\"bus\"/>\n"
                    "      <param key=\"k\" value=\"v\"/>\n    </lane>",
                    " lefthand=\"1\""));
  const NetIndex net = NetIndex::load(path);
  EXPECT_TRUE(net.lefthand());
  const NetLane* lane = net.lane("a_0");
  ASSERT_NE(lane, nullptr);
  EXPECT_DOUBLE_EQ(lane->speed, 8.5);
  EXPECT_DOUBLE_EQ(lane->width, 2.75);
  EXPECT_DOUBLE_EQ(lane->stop_offset, 1.25);
  EXPECT_EQ(lane->params.at("k"), "v");
  ASSERT_EQ(lane->shape.size(), 2u);
  EXPECT_EQ(lane->shape.points()[1], (Vec2{10.0, -1.6}));
  EXPECT_DOUBLE_EQ(lane->shape.length(), 10.0);
  EXPECT_DOUBLE_EQ(net.junction("J1")->x, 10.0);
}

TEST(NetIndexLoad, LanesSortedByIndex) {
  const ScratchDir scratch;
  const std::string path = scratch.write(
      "order.net.xml", net_with_lane("<lane id=\"a_1\" index=\"1\" length=\"10\" shape=\"0,1.6 10,1.6\"/>\n"
                                     "    <lane id=\"a_0\" index=\"0\" length=\"10\" shape=\"0,-1.6 10,-1.6\"/>"));
  const NetIndex net = NetIndex::load(path);
  EXPECT_EQ(net.edge("a")->lanes[0].id, "a_0");
  EXPECT_EQ(net.edge("a")->lanes[1].id, "a_1");
  EXPECT_EQ(net.lane("a_1"), &net.edge("a")->lanes[1]);
}

// ---- errors (whole files; a defect in one element is not an error, see net_defects_test.cpp) -----

TEST(NetIndexErrors, MissingFile) {
  const std::string path = net_path("no_such.net.xml");
  const std::string message = load_error(path);
  EXPECT_EQ(message, path + ": not found");
}

TEST(NetIndexErrors, FolderAndNamedPipeSayWhatTheyAre) {
  EXPECT_EQ(load_error(SIGNALSIM_TEST_NETS_DIR), std::string(SIGNALSIM_TEST_NETS_DIR) + ": is a folder, not a file");
  // A named pipe nobody writes to: never opened (an open would block until a writer comes).
  const ScratchDir scratch;
  const std::string fifo = scratch.write("pipe.net.xml", "");
  std::filesystem::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(load_error(fifo), fifo + ": is a named pipe (FIFO), not a file");
  EXPECT_EQ(load_error("/dev/null"), "/dev/null: is a device, not a file");
}

TEST(NetIndexErrors, TextBeyondTheLimitIsRefusedPlainOrInflated) {
  const ScratchDir scratch;
  const std::string text = read_all(net_path("crossing.net.xml"));
  const std::string plain = scratch.write("plain.net.xml", text);
  const std::string gzip = scratch.write_gzip("bomb.net.xml.gz", text + std::string(3u << 20, ' '));
  EXPECT_EQ(read_net_file(plain, text.size()), text);  // at the limit
  EXPECT_THAT(read_error(plain, text.size() - 1),
              HasSubstr(plain + ": holds more than " + std::to_string(text.size() - 1) + " bytes, the most a net"));
  EXPECT_THAT(read_error(gzip, 2u << 20),
              HasSubstr(gzip + ": inflates to more than 2 MiB, the most a net"));
  EXPECT_EQ(read_net_file(gzip, 4u << 20).size(), text.size() + (3u << 20));
  EXPECT_EQ(kMaxNetText, std::size_t{512} << 20);  // the limit docs/sumo.md gives
}

TEST(NetIndexErrors, MalformedXml) {
  const ScratchDir scratch;
  const std::string path = scratch.write("bad.net.xml", "<net>\n  <edge id=\"a\">\n</net>\n");
  const std::string message = load_error(path);
  EXPECT_THAT(message, HasSubstr(path + ":3: not XML: "));  // the line of pugixml's offset
  EXPECT_THAT(message, HasSubstr("Start-end tags mismatch"));  // pugixml's description
}

TEST(NetIndexErrors, EmptyFile) {
  const ScratchDir scratch;
  const std::string path = scratch.write("empty.net.xml", "");
  EXPECT_THAT(load_error(path), HasSubstr(path + ":1: not XML: "));
}

TEST(NetIndexErrors, NoNetRoot) {
  const ScratchDir scratch;
  const std::string path = scratch.write("routes.rou.xml", "<?xml version=\"1.0\"?>\n\n<routes><vehicle id=\"v\"/></routes>");
  const std::string message = load_error(path);
  EXPECT_THAT(message, HasSubstr(path + ":3: no <net> root element"));
  EXPECT_THAT(message, HasSubstr("<routes>"));
  // A byte order mark: the scan declines the text and it is read whole.
  EXPECT_THAT(load_error(scratch.write("bom.rou.xml", "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n<routes/>\n")),
              HasSubstr("bom.rou.xml:2: no <net> root element"));
}

TEST(NetIndexErrors, BadLefthand) {
  const ScratchDir scratch;
  const std::string path = scratch.write("badlh.net.xml", "<net lefthand=\"maybe\"/>");
  EXPECT_THAT(load_error(path), HasSubstr(path + ":1: <net>: attribute 'lefthand' is not a boolean: 'maybe'"));
}

TEST(NetIndexErrors, TruncatedGzip) {
  const ScratchDir scratch;
  const std::string whole = read_all(scratch.write_gzip("whole.net.xml.gz", read_all(net_path("crossing.net.xml"))));
  const std::string path = scratch.write("cut.net.xml.gz", whole.substr(0, whole.size() / 2));
  const std::string message = load_error(path);
  EXPECT_THAT(message, HasSubstr(path + ": corrupt gzip data"));
}

TEST(InternalLaneIds, NameTheirJunctionWhateverItsUnderscores) {
  EXPECT_EQ(junction_of_internal_lane(":C_0_0"), "C");
  EXPECT_EQ(junction_of_internal_lane(":cluster_12_3_4_1"), "cluster_12_3");  // a joined junction's id
  EXPECT_EQ(junction_of_internal_lane(":J_10_2"), "J");
  EXPECT_EQ(junction_of_internal_lane("in_S_1"), "") << "a normal lane: no two number groups";
  EXPECT_EQ(junction_of_internal_lane(":C_w0_0"), "") << "a walking area";
}

}  // namespace
}  // namespace signalsim::sumo
