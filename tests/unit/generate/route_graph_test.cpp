// The random walk that chooses generate's routes (route_graph.hpp), on small hand-made graphs.
#include "generate/route_graph.hpp"

#include <algorithm>
#include <map>
#include <set>

#include <gtest/gtest.h>

namespace signalsim::generate {
namespace {

// A four-arm crossing: in_X (X -> C, 200 m) connects to every out_Y (C -> Y, 200 m) with Y != X
// through a 10 m internal lane; no U-turns.
RouteGraph crossing(bool reversed_order = false) {
  const std::vector<std::string> arms = {"N", "E", "S", "W"};
  std::vector<GraphEdge> edges;
  for (const auto& a : arms) edges.push_back({"in_" + a, a, "C", 200.0});
  for (const auto& a : arms) edges.push_back({"out_" + a, "C", a, 200.0});
  std::vector<std::vector<GraphLink>> links(edges.size());
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j)
      if (i != j) links[i].push_back({4 + j, 10.0});
  if (reversed_order) {
    // The same graph listed in another order: the walk must not depend on the net file's order.
    std::vector<std::size_t> perm(edges.size());
    for (std::size_t k = 0; k < perm.size(); ++k) perm[k] = perm.size() - 1 - k;  // old -> new
    std::vector<GraphEdge> e2(edges.size());
    std::vector<std::vector<GraphLink>> l2(edges.size());
    for (std::size_t k = 0; k < edges.size(); ++k) {
      e2[perm[k]] = edges[k];
      for (GraphLink link : links[k]) l2[perm[k]].push_back({perm[link.to], link.via_length});
    }
    return RouteGraph(std::move(e2), std::move(l2));
  }
  return RouteGraph(std::move(edges), std::move(links));
}

std::vector<std::string> ids(const RouteGraph& g, const Walk& w) {
  std::vector<std::string> out;
  for (std::size_t e : w.edges) out.push_back(g.edges()[e].id);
  return out;
}

TEST(RandomWalk, CrossingRoutesAreAnArmInAndAnotherArmOut) {
  const RouteGraph g = crossing();
  EXPECT_EQ(g.starts().size(), 4u);  // only the in_ edges have successors
  Rng rng(3);
  std::set<std::vector<std::string>> seen;
  for (int i = 0; i < 400; ++i) {
    const auto w = random_walk(g, rng, {300.0, 500.0});
    ASSERT_TRUE(w);
    const auto route = ids(g, *w);
    ASSERT_EQ(route.size(), 2u);
    EXPECT_EQ(route[0].substr(0, 3), "in_");
    EXPECT_EQ(route[1].substr(0, 4), "out_");
    EXPECT_NE(route[0].substr(3), route[1].substr(4)) << "a U-turn";
    EXPECT_DOUBLE_EQ(w->length, 410.0);
    seen.insert(route);
  }
  EXPECT_EQ(seen.size(), 12u);  // every route is drawn
}

TEST(RandomWalk, TooShortOrTooLongIsRejected) {
  const RouteGraph g = crossing();
  Rng rng(1);
  EXPECT_FALSE(random_walk(g, rng, {450.0, 1000.0}));  // the dead end at 410 m is too short
  EXPECT_FALSE(random_walk(g, rng, {100.0, 150.0}));   // the first edge already overshoots
}

TEST(RandomWalk, SameSeedSameWalksWhateverTheNetsOrder) {
  const RouteGraph a = crossing(false), b = crossing(true);
  Rng ra(11), rb(11);
  for (int i = 0; i < 50; ++i) {
    const auto wa = random_walk(a, ra, {300.0, 500.0});
    const auto wb = random_walk(b, rb, {300.0, 500.0});
    ASSERT_TRUE(wa && wb);
    EXPECT_EQ(ids(a, *wa), ids(b, *wb));
  }
}

TEST(RandomWalk, NeverVisitsAJunctionTwice) {
  // A ring J1 -> J2 -> J3 -> J1 of 100 m edges with a way out x (J3 -> K) and a loop back (J2 -> J1).
  std::vector<GraphEdge> edges = {{"e1", "J1", "J2", 100.0}, {"e2", "J2", "J3", 100.0}, {"e3", "J3", "J1", 100.0},
                                  {"x", "J3", "K", 100.0},   {"back", "J2", "J1", 100.0}};
  std::vector<std::vector<GraphLink>> links = {{{1, 0.0}, {4, 0.0}}, {{2, 0.0}, {3, 0.0}}, {{0, 0.0}}, {}, {{0, 0.0}}};
  const RouteGraph g(edges, links);
  Rng rng(5);
  int accepted = 0;
  for (int i = 0; i < 500; ++i) {
    const auto w = random_walk(g, rng, {150.0, 10000.0});
    if (!w) continue;
    ++accepted;
    std::set<std::string> junctions = {g.edges()[w->edges.front()].from_junction};
    for (std::size_t e : w->edges) EXPECT_TRUE(junctions.insert(g.edges()[e].to_junction).second) << "revisited";
  }
  EXPECT_GT(accepted, 0);
}

TEST(RandomWalk, OneLinkPerSuccessorTheShortest) {
  std::vector<GraphEdge> edges = {{"a", "A", "B", 50.0}, {"b", "B", "C", 50.0}};
  std::vector<std::vector<GraphLink>> links = {{{1, 9.0}, {1, 4.0}, {1, 6.0}}, {}};
  const RouteGraph g(edges, links);
  ASSERT_EQ(g.successors(0).size(), 1u);
  EXPECT_DOUBLE_EQ(g.successors(0).front().via_length, 4.0);
}

}  // namespace
}  // namespace signalsim::generate
