// The constraint store against a plain model: each edge holds a map from (polyline, segment)
// to that pair's share of the winding, from the lower vertex id to the higher. Random marks,
// takes (moved elsewhere, either way round, as bent pieces are) and splits must leave every
// edge with the model's total winding, its polylines, its segments and each polyline's share.
#include "mesh/constraint_store.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>

#include "point_generators.h"

namespace geocdt {
namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;  // (polyline, segment)
using Shares = std::map<Pair, std::int32_t>;           // from the lower vertex id up

class Model {
 public:
  // Adds shares s, given from u to v, to edge u-v.
  void mark(std::uint32_t u, std::uint32_t v, const Shares& s) {
    Shares& e = edges_[ConstraintStore::key(u, v)];
    for (const auto& [pair, w] : s) e[pair] += u < v ? w : -w;
  }
  // Removes u-v; returns its shares from u to v.
  Shares take(std::uint32_t u, std::uint32_t v) {
    Shares s = edges_.at(ConstraintStore::key(u, v));
    edges_.erase(ConstraintStore::key(u, v));
    if (u > v)
      for (auto& [pair, w] : s) w = -w;
    return s;
  }
  const std::map<std::uint64_t, Shares>& edges() const { return edges_; }

 private:
  std::map<std::uint64_t, Shares> edges_;
};

// "" when the store's edge u-v (u < v) carries what the model says.
std::string compare(const ConstraintStore& store, std::uint64_t key, const Shares& expected) {
  const auto u = static_cast<std::uint32_t>(key >> 32), v = static_cast<std::uint32_t>(key);
  const EdgeSource* e = store.find(u, v);
  if (e == nullptr) return "edge missing";
  std::int32_t total = 0;
  std::map<std::uint32_t, std::int32_t> byPolyline;
  std::set<std::uint32_t> segments;
  for (const auto& [pair, w] : expected) {
    total += w;
    byPolyline[pair.first] += w;
    segments.insert(pair.second);
  }
  if (e->winding != total) return "total winding";
  std::map<std::uint32_t, std::int32_t> gotShares;
  store.forEachPolylineWinding(*e, [&](std::uint32_t p, std::int32_t w) { gotShares[p] += w; });
  if (gotShares != byPolyline) return "per-polyline shares";
  std::multiset<std::uint32_t> polylines;
  store.forEachPolyline(*e, [&](std::uint32_t p) { polylines.insert(p); });
  std::set<std::uint32_t> expectedPolylines;
  for (const auto& [p, w] : byPolyline) expectedPolylines.insert(p);
  if (polylines.size() != expectedPolylines.size() ||
      std::set<std::uint32_t>(polylines.begin(), polylines.end()) != expectedPolylines)
    return "polylines (each once)";
  std::multiset<std::uint32_t> gotSegments;
  store.forEachSegment(*e, [&](std::uint32_t s) { gotSegments.insert(s); });
  if (std::set<std::uint32_t>(gotSegments.begin(), gotSegments.end()) != segments)
    return "segments";
  return "";
}

// Random marks, takes and splits on a dozen vertices, then every edge compared with the
// model; returns the store's count of extra members.
std::size_t runAgainstModel(std::uint64_t seed, int steps) {
  testing::Random r(seed);
  ConstraintStore store;
  Model model;
  const auto pick = [&](std::uint32_t n) { return static_cast<std::uint32_t>(r.next() % n); };
  std::uint32_t nextVertex = 12;  // split points are new vertices
  for (int step = 0; step < steps; ++step) {
    std::uint32_t u = pick(12), v = pick(12);
    if (u == v) continue;
    const std::uint32_t op = pick(4);
    const auto& edges = model.edges();
    if (op == 0 || edges.empty()) {  // a fresh segment's piece
      EdgeSource src;
      src.segment = pick(8);
      src.polyline = src.segment / 3;
      src.winding = static_cast<std::int32_t>(pick(4)) - 1;
      store.mark(u, v, src);
      model.mark(u, v, {{{src.polyline, src.segment}, src.winding}});
      continue;
    }
    // An existing edge, either way round.
    auto at = edges.begin();
    std::advance(at, pick(static_cast<std::uint32_t>(edges.size())));
    std::uint32_t a = static_cast<std::uint32_t>(at->first >> 32),
                  b = static_cast<std::uint32_t>(at->first);
    if (pick(2)) std::swap(a, b);
    if (op == 3) {
      const std::uint32_t w = nextVertex++;
      store.split(a, b, w);
      const Shares s = model.take(a, b);
      model.mark(a, w, s);
      model.mark(w, b, s);
      continue;
    }
    // Taken and marked on another edge (op 1), or on two pieces through a vertex (op 2).
    const EdgeSource moved = store.take(a, b);
    const Shares s = model.take(a, b);
    if (op == 1) {
      store.mark(u, v, moved);
      model.mark(u, v, s);
    } else {
      const std::uint32_t w = pick(nextVertex);
      if (w == u || w == v) continue;
      store.mark(u, w, moved);
      store.mark(w, v, moved);
      model.mark(u, w, s);
      model.mark(w, v, s);
    }
  }
  EXPECT_EQ(store.edgeCount(), model.edges().size()) << "seed " << seed;
  for (const auto& [key, shares] : model.edges())
    EXPECT_EQ(compare(store, key, shares), "")
        << "seed " << seed << " edge " << (key >> 32) << "-" << (key & 0xFFFFFFFFu);
  return store.extraMembers();
}

TEST(ConstraintStore, SharesSurviveMarksTakesAndSplitsAgainstAModel) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) runAgainstModel(seed, 300);
}

// The extra members live in blocks of 4096: long runs fill several, and lists link members
// of different blocks.
TEST(ConstraintStore, SharesSurviveAcrossTheExtraMembersBlocks) {
  for (std::uint64_t seed = 41; seed <= 42; ++seed)
    EXPECT_GT(runAgainstModel(seed, 8000), 2u * 4096) << "seed " << seed;
}

// The shared border of two rings wound opposite ways nets zero, yet each ring keeps its
// share, also after the border is split and moved.
TEST(ConstraintStore, OppositeRingsOnASharedBorderKeepTheirShares) {
  ConstraintStore store;
  EdgeSource a, b;
  a.polyline = 0, a.segment = 1, a.winding = 1;
  b.polyline = 1, b.segment = 5, b.winding = 1;
  store.mark(2, 7, a);
  store.mark(7, 2, b);
  store.split(2, 7, 9);
  const EdgeSource moved = store.take(9, 2);  // bent through 4: 9 -> 4 -> 2
  store.mark(9, 4, moved);
  store.mark(4, 2, moved);
  for (const auto& [u, v] : {Pair{2, 4}, Pair{4, 9}, Pair{9, 7}}) {
    const EdgeSource* e = store.find(u, v);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->winding, 0);
    std::map<std::uint32_t, std::int32_t> shares;
    store.forEachPolylineWinding(*e, [&](std::uint32_t p, std::int32_t w) { shares[p] += w; });
    const std::int32_t up = u < v ? 1 : -1;  // ring 0 runs from 2 to 7
    EXPECT_EQ(shares, (std::map<std::uint32_t, std::int32_t>{{0, up}, {1, -up}})) << u << "-" << v;
  }
}

// The hash map alone, against std::map: tables of every size from the smallest up, so that
// probe runs wrap around the end and erasures shift entries across it; keys crowded into a
// few vertex blocks, as a polyline's edges are.
TEST(EdgeMap, InsertsFindsAndErasesAgainstAModel) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    testing::Random r(seed);
    const auto pick = [&](std::uint32_t n) { return static_cast<std::uint32_t>(r.next() % n); };
    EdgeMap<std::uint32_t, EdgeSlot> map;
    std::map<std::uint64_t, std::uint32_t> model;
    const std::uint32_t ids = 8 + pick(4000);
    if (seed % 3) map.orderIds(seed % 3 == 1 ? ids : ids / 8);  // ids past the bound wrap
    if (seed % 2) map.reserve(pick(3000));
    for (int step = 0; step < 6000; ++step) {
      const std::uint32_t u = pick(ids);
      const std::uint32_t v = u + 1 + pick(3);
      const std::uint64_t key = ConstraintStore::key(u, v);
      if (pick(3) == 0) {
        map.erase(key);
        model.erase(key);
      } else {
        const std::uint32_t value = static_cast<std::uint32_t>(step);
        const auto [at, fresh] = map.insert(key, value);
        const auto [it, modelFresh] = model.insert({key, value});
        ASSERT_EQ(fresh, modelFresh) << "seed " << seed << " step " << step;
        ASSERT_EQ(*at, it->second) << "seed " << seed << " step " << step;
      }
      ASSERT_EQ(map.size(), model.size()) << "seed " << seed << " step " << step;
    }
    for (std::uint32_t u = 0; u < ids + 3; ++u)
      for (std::uint32_t v = u + 1; v <= u + 3; ++v) {
        const std::uint64_t key = ConstraintStore::key(u, v);
        const std::uint32_t* got = map.find(key);
        const auto it = model.find(key);
        ASSERT_EQ(got != nullptr, it != model.end())
            << "seed " << seed << " edge " << u << "-" << v;
        if (got) ASSERT_EQ(*got, it->second);
      }
  }
}

TEST(EdgeMap, SlotsInIdOrderTurnHashedWhereIdsCrowd) {
  // Edges along polylines (consecutive ids) keep slots in id order; a hub of 20,000 edges
  // from one vertex would probe a run as long as its edges for each: the table turns to
  // hashed slots, and every edge is still found.
  EdgeMap<std::uint32_t, EdgeSlot> along;
  along.orderIds(100000);
  along.reserve(100000);
  for (std::uint32_t u = 0; u + 1 < 100000; ++u) along.insert(ConstraintStore::key(u, u + 1), u);
  EXPECT_FALSE(along.scattered());
  EdgeMap<std::uint32_t, EdgeSlot> hub;
  hub.orderIds(20001);
  hub.reserve(20000);
  for (std::uint32_t v = 1; v <= 20000; ++v) hub.insert(ConstraintStore::key(0, v), v);
  EXPECT_TRUE(hub.scattered());
  EXPECT_EQ(hub.size(), 20000u);
  for (std::uint32_t v = 1; v <= 20000; ++v) {
    const std::uint32_t* got = hub.find(ConstraintStore::key(v, 0));
    ASSERT_NE(got, nullptr) << v;
    EXPECT_EQ(*got, v);
  }
  EXPECT_EQ(hub.find(ConstraintStore::key(1, 2)), nullptr);
}

}  // namespace
}  // namespace geocdt
