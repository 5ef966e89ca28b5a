// Editing in place: removals and moves of points and polylines, checked after each batch by
// the exact invariants and against a fresh triangulation of what remains.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "edit_model.h"
#include "geocdt/triangulation.h"
#include "invariants.h"
#include "point_generators.h"

namespace geocdt {
namespace {

using testing::EditModel;
using testing::Random;

// Removes every point of a random set in random order, checking every `every` removals.
void removeAllPoints(const std::vector<double>& xy, std::uint64_t seed, std::size_t every) {
  Triangulation t;
  EditModel model;
  ASSERT_TRUE(model.insertPoints(t, xy).ok());
  std::vector<std::uint32_t> ids = model.pointIds();
  Random random(seed);
  for (std::size_t i = ids.size(); i > 1; --i) std::swap(ids[i - 1], ids[random.next() % i]);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    bool removed = false;
    const Status s = model.removePoint(t, ids[k], &removed);
    ASSERT_TRUE(s.ok()) << s.message << " (removal " << k << ")";
    ASSERT_TRUE(removed);
    if (k % every == 0 || k + 1 == ids.size()) {
      ASSERT_EQ(model.check(t), "") << "after removal " << k;
      ASSERT_EQ(model.compare(t), "") << "after removal " << k;
    }
  }
  EXPECT_EQ(t.vertexCount(), 0u);
  EXPECT_EQ(t.triangleCount(), 0u);
}

TEST(Editing, RemovingEveryRandomPoint) { removeAllPoints(testing::uniformPoints(300, 1), 2, 7); }

TEST(Editing, RemovingEveryLatticePoint) {
  // Cocircular everywhere: only the invariants are exact, the triangles may differ.
  Triangulation t;
  EditModel model;
  ASSERT_TRUE(model.insertPoints(t, testing::latticePoints(12)).ok());
  std::vector<std::uint32_t> ids = model.pointIds();
  Random random(3);
  for (std::size_t i = ids.size(); i > 1; --i) std::swap(ids[i - 1], ids[random.next() % i]);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    ASSERT_TRUE(model.removePoint(t, ids[k]).ok());
    if (k % 5 == 0) ASSERT_EQ(model.check(t), "") << "after removal " << k;
  }
  EXPECT_EQ(t.vertexCount(), 0u);
}

TEST(Editing, RemovingClusteredPointsAndHullVertices) {
  removeAllPoints(testing::gaussianClusters(400, 4), 5, 11);
}

TEST(Editing, RemovingHullVerticesFirst) {
  // The points on a circle are all hull vertices; the centre goes last.
  std::vector<double> xy = testing::circlePoints(40);
  xy.push_back(0.1);
  xy.push_back(0.05);
  Triangulation t;
  EditModel model;
  ASSERT_TRUE(model.insertPoints(t, xy).ok());
  const std::vector<std::uint32_t> ids = model.pointIds();
  for (std::size_t k = 0; k < ids.size(); ++k) {
    ASSERT_TRUE(model.removePoint(t, ids[k]).ok()) << k;
    ASSERT_EQ(model.check(t), "") << "after removal " << k;
  }
}

// removePoints: batches of random points, some of them polylines' vertices too, removed in
// its own order; the mesh must be what removing them one by one gives (triangulate() of
// what remains), and the count must say how many vertices went.
TEST(Editing, RemovingPointsInBatches) {
  Triangulation t;
  EditModel model;
  ASSERT_TRUE(model.insertPoints(t, testing::uniformPoints(2000, 21)).ok());
  Random random(22);
  // Polylines through some of the points: those points' vertices stay.
  std::vector<std::uint32_t> ids = model.pointIds();
  std::vector<std::uint32_t> onLines;
  for (int line = 0; line < 12; ++line) {
    std::vector<double> xy;
    for (int k = 0; k < 4; ++k) {
      const std::uint32_t id = ids[random.next() % ids.size()];
      if (std::find(onLines.begin(), onLines.end(), id) != onLines.end()) continue;
      onLines.push_back(id);
      const std::vector<double> at = model.place(id);
      xy.insert(xy.end(), at.begin(), at.end());
    }
    ASSERT_TRUE(model.insertPolyline(t, xy).ok());
  }
  for (std::size_t i = ids.size(); i > 1; --i) std::swap(ids[i - 1], ids[random.next() % i]);
  std::size_t at = 0;
  for (const std::size_t batch : {1u, 7u, 250u, 900u}) {
    const std::vector<std::uint32_t> chosen(ids.begin() + at, ids.begin() + at + batch);
    at += batch;
    std::size_t stay = 0;
    for (const std::uint32_t id : chosen)
      stay += std::find(onLines.begin(), onLines.end(), id) != onLines.end();
    const std::size_t vertices = t.vertexCount();
    std::size_t removed = 0;
    const Status s = model.removePoints(t, chosen, &removed);
    ASSERT_TRUE(s.ok()) << s.message;
    EXPECT_EQ(removed, batch - stay) << "batch of " << batch;
    EXPECT_EQ(t.vertexCount(), vertices - removed);
    for (const std::uint32_t id : chosen) {
      const bool kept = std::find(onLines.begin(), onLines.end(), id) != onLines.end();
      EXPECT_EQ(t.hasVertex(id), kept) << id;
    }
    ASSERT_EQ(model.check(t), "") << "after the batch of " << batch;
    ASSERT_EQ(model.compare(t), "") << "after the batch of " << batch;
  }
  // The rest, in one call: the polylines' vertices stay, nothing else.
  const std::vector<std::uint32_t> rest(ids.begin() + at, ids.end());
  const std::size_t vertices = t.vertexCount();
  std::size_t removed = 0;
  ASSERT_TRUE(model.removePoints(t, rest, &removed).ok());
  ASSERT_EQ(model.check(t), "");
  ASSERT_EQ(model.compare(t), "");
  EXPECT_EQ(t.vertexCount(), vertices - removed);
  for (const std::uint32_t id : onLines) EXPECT_TRUE(t.hasVertex(id)) << id;
  for (const std::uint32_t id : ids)
    if (std::find(onLines.begin(), onLines.end(), id) == onLines.end())
      EXPECT_FALSE(t.hasVertex(id)) << id;
  ASSERT_TRUE(t.removePoints(nullptr, 0).ok());
}

TEST(Editing, RemovingPointsWithABadIdChangesNothing) {
  Triangulation t;
  std::uint32_t ids[4];
  const double xy[] = {0, 0, 1, 0, 0, 1, 1, 1};
  ASSERT_TRUE(t.insertPoints(xy, 4, ids).ok());
  const double line[] = {0, 0, 2, 2};
  std::uint32_t lineIds[2];
  ASSERT_TRUE(t.insertPolyline(line, 2, lineIds).ok());
  ASSERT_TRUE(t.removePoint(ids[3]).ok());
  const auto refused = [&](std::vector<std::uint32_t> batch, std::size_t index,
                           const std::string& words) {
    std::size_t removed = 7;
    const Status s = t.removePoints(batch.data(), batch.size(), &removed);
    EXPECT_EQ(s.code, StatusCode::InvalidArgument);
    EXPECT_EQ(s.index, index) << s.message;
    EXPECT_NE(s.message.find(words), std::string::npos) << s.message;
    EXPECT_EQ(removed, 0u);
    EXPECT_EQ(t.vertexCount(), 4u);  // three points and the polyline's far end
  };
  refused({ids[0], 99}, 1, "ids[1]: no vertex has id 99");
  refused({ids[1], ids[0], ids[3]}, 2, "ids[2]: vertex 3 was removed");
  refused({ids[0], lineIds[1]}, 1, "is not a point inserted with insertPoints");
  refused({ids[1], ids[0], ids[1]}, 2, "ids[2]: vertex 1 is also ids[0]");
  // The first problem in ids' order is named.
  refused({ids[0], ids[0], 99}, 1, "ids[1]: vertex 0 is also ids[0]");
  refused({ids[2], ids[0], ids[2], ids[0]}, 2, "ids[2]: vertex 2 is also ids[0]");
  refused({ids[0], 99, ids[0]}, 1, "ids[1]: no vertex has id 99");
  std::size_t removed = 0;
  ASSERT_TRUE(t.removePoints(ids, 3, &removed).ok());
  EXPECT_EQ(removed, 2u);  // (0, 0) stays as the polyline's
  EXPECT_TRUE(t.hasVertex(ids[0]));
  EXPECT_EQ(t.vertexCount(), 2u);
}

TEST(Editing, RemovingPointsThatAreUlpsApart) {
  // Their spread is subnormal: the Hilbert order's scale would overflow.
  Triangulation t;
  EditModel model;
  ASSERT_TRUE(
      model.insertPoints(t, {0, 0, 5e-324, 0, 0, 5e-324, 5e-324, 5e-324, 1e-323, 1e-323, 1e-323, 0})
          .ok());
  std::size_t removed = 0;
  ASSERT_TRUE(model.removePoints(t, {0, 2, 4}, &removed).ok());
  EXPECT_EQ(removed, 3u);
  EXPECT_EQ(model.check(t), "");
  EXPECT_EQ(t.vertexCount(), 3u);
}

TEST(Editing, CollinearStateAndBack) {
  Triangulation t;
  EditModel model;
  ASSERT_TRUE(model.insertPoints(t, {0, 0, 1, 0, 2, 0, 3, 0, 1, 1}).ok());
  EXPECT_EQ(t.triangleCount(), 3u);
  ASSERT_TRUE(model.removePoint(t, 4).ok());  // the only point off the line
  EXPECT_EQ(t.triangleCount(), 0u);
  EXPECT_EQ(t.vertexCount(), 4u);
  EXPECT_EQ(t.locate(0.5, 0.5).kind, Location::Kind::Empty);
  ASSERT_TRUE(model.removePoint(t, 1).ok());
  EXPECT_EQ(t.vertexCount(), 3u);
  ASSERT_TRUE(model.insertPoints(t, {2, 5}).ok());
  EXPECT_EQ(t.triangleCount(), 2u);
  EXPECT_EQ(model.check(t), "");
  EXPECT_EQ(model.compare(t), "");
  // A move takes it back off the line and onto it again.
  ASSERT_TRUE(model.movePoint(t, 5, 2.5, 0).ok());
  EXPECT_EQ(t.triangleCount(), 0u);
  ASSERT_TRUE(model.movePoint(t, 5, 1, -1).ok());
  EXPECT_EQ(t.triangleCount(), 2u);
  EXPECT_EQ(model.check(t), "");
  EXPECT_EQ(model.compare(t), "");
}

TEST(Editing, BadIdsChangeNothing) {
  Triangulation t;
  std::uint32_t ids[3];
  const double xy[] = {0, 0, 1, 0, 0, 1};
  ASSERT_TRUE(t.insertPoints(xy, 3, ids).ok());
  const double line[] = {0, 0, 1, 1};
  std::uint32_t lineIds[2];
  ASSERT_TRUE(t.insertPolyline(line, 2, lineIds).ok());
  const Mesh before = t.mesh();
  EXPECT_EQ(t.removePoint(99).code, StatusCode::InvalidArgument);
  EXPECT_EQ(t.removePoint(lineIds[1]).code, StatusCode::InvalidArgument);  // a polyline's
  EXPECT_EQ(t.removePolyline(1).code, StatusCode::InvalidArgument);
  EXPECT_EQ(t.movePoint(99, 0.5, 0.5).code, StatusCode::InvalidArgument);
  EXPECT_EQ(t.movePoint(ids[1], NAN, 0.5).code, StatusCode::InvalidCoordinate);
  EXPECT_EQ(t.movePoint(ids[1], 1e300, 0.5).code, StatusCode::InvalidCoordinate);
  EXPECT_EQ(t.movePoint(ids[1], 0, 1).code, StatusCode::InvalidArgument);  // onto a point
  ASSERT_TRUE(t.removePoint(ids[1]).ok());
  EXPECT_EQ(t.removePoint(ids[1]).code, StatusCode::InvalidArgument);  // removed already
  EXPECT_EQ(t.movePoint(ids[1], 3, 3).code, StatusCode::InvalidArgument);
  ASSERT_TRUE(t.removePolyline(0).ok());
  EXPECT_EQ(t.removePolyline(0).code, StatusCode::InvalidArgument);
  EXPECT_EQ(before.points.size(), 8u);
}

// A random polyline of n points in [0, 1000)^2, closed into a ring when asked.
std::vector<double> randomPolyline(Random& random, std::size_t n, bool ring) {
  std::vector<double> line;
  for (std::size_t k = 0; k < n; ++k) {
    line.push_back(std::floor(random.uniform() * 1000 * 64) / 64);
    line.push_back(std::floor(random.uniform() * 1000 * 64) / 64);
  }
  if (ring) {
    line.push_back(line[0]);
    line.push_back(line[1]);
  }
  return line;
}

// n uniform points in [0, 1000)^2, into t and the model.
Status insertUniformPoints(EditModel& model, Triangulation& t, std::size_t n, std::uint64_t seed) {
  return model.insertPoints(t, testing::transformed(testing::uniformPoints(n, seed), 1000, 0, 0));
}

TEST(Editing, RemovingCrossingPolylinesOneByOne) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    Random random(seed);
    Triangulation t;
    EditModel model;
    ASSERT_TRUE(insertUniformPoints(model, t, 200, seed).ok());
    for (int k = 0; k < 8; ++k)
      ASSERT_TRUE(model.insertPolyline(t, randomPolyline(random, 3 + k % 4, k % 3 == 0)).ok());
    ASSERT_EQ(model.compare(t), "") << "seed " << seed << " before any removal";
    std::vector<std::size_t> order = model.polylineNumbers();
    for (std::size_t i = order.size(); i > 1; --i)
      std::swap(order[i - 1], order[random.next() % i]);
    for (const std::size_t k : order) {
      const Status s = model.removePolyline(t, k);
      ASSERT_TRUE(s.ok()) << s.message;
      ASSERT_EQ(model.check(t), "") << "seed " << seed << " after removing polyline " << k;
      ASSERT_EQ(model.compare(t), "") << "seed " << seed << " after removing polyline " << k;
    }
    EXPECT_EQ(t.vertexCount(), 200u);
  }
}

TEST(Editing, PointsOnPolylinesStayOrJoinTheChainAgain) {
  Triangulation t;
  EditModel model;
  // A point that is a polyline's vertex, one that lies on a segment, one beside it.
  ASSERT_TRUE(model.insertPoints(t, {0, 0, 10, 0, 10, 10, 0, 10, 2, 2, 5, 5, 6, 4}).ok());
  ASSERT_TRUE(model.insertPolyline(t, {2, 2, 8, 8}).ok());
  ASSERT_EQ(model.compare(t), "");
  bool removed = true;
  ASSERT_TRUE(model.removePoint(t, 4, &removed).ok());  // (2, 2): the polyline's end
  EXPECT_FALSE(removed);
  EXPECT_TRUE(t.hasVertex(4));
  ASSERT_TRUE(model.removePoint(t, 5, &removed).ok());  // (5, 5): on the segment
  EXPECT_TRUE(removed);
  EXPECT_FALSE(t.hasVertex(5));
  EXPECT_EQ(model.check(t), "");
  EXPECT_EQ(model.compare(t), "");
  // The polyline gone, its end goes too (no point holds it any more).
  ASSERT_TRUE(model.removePolyline(t, 0).ok());
  EXPECT_FALSE(t.hasVertex(4));
  EXPECT_EQ(model.compare(t), "");
  EXPECT_EQ(t.stats().removed, 3u);  // (2, 2), (5, 5) and (8, 8)
}

TEST(Editing, RemovingACrossingsPolylineJoinsTheOthers) {
  Triangulation t;
  EditModel model;
  ASSERT_TRUE(model.insertPoints(t, {0, 0, 10.5, 0.25, 10.125, 10.75, -0.25, 10}).ok());
  ASSERT_TRUE(model.insertPolyline(t, {1, 5.25, 9, 4.875}).ok());
  ASSERT_TRUE(model.insertPolyline(t, {3.125, 1.25, 2.875, 8.75}).ok());
  // A ring across the first line four times, the second twice.
  ASSERT_TRUE(model.insertPolyline(t, {0.5, 1, 9.25, 9, 8, 1.5, 1.5, 9.5, 0.5, 1}).ok());
  EXPECT_EQ(t.stats().crossings, 7u);
  ASSERT_TRUE(model.removePolyline(t, 2).ok());
  EXPECT_EQ(model.check(t), "");
  EXPECT_EQ(model.compare(t), "");
  // The two lines still cross at (3, 5); the ring's crossings are gone.
  EXPECT_EQ(t.vertexCount(), 4u + 4u + 1u);
  ASSERT_TRUE(model.removePolyline(t, 0).ok());
  EXPECT_EQ(t.vertexCount(), 4u + 2u);
  EXPECT_EQ(model.compare(t), "");
}

TEST(Editing, MovingPointsAndPolylineVertices) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    Random random(seed);
    Triangulation t;
    EditModel model;
    ASSERT_TRUE(insertUniformPoints(model, t, 100, seed).ok());
    for (int k = 0; k < 5; ++k)
      ASSERT_TRUE(model.insertPolyline(t, randomPolyline(random, 4, k % 2 == 0)).ok());
    for (int step = 0; step < 60; ++step) {
      std::vector<std::uint32_t> ids = model.pointIds();
      if (step % 2 == 1) {
        const std::vector<std::size_t> lines = model.polylineNumbers();
        ids = model.polylineVertexIds(lines[random.next() % lines.size()]);
      }
      const std::uint32_t id = ids[random.next() % ids.size()];
      const double x = std::floor(random.uniform() * 1000 * 64) / 64;
      const double y = std::floor(random.uniform() * 1000 * 64) / 64;
      const Status s = model.movePoint(t, id, x, y);
      ASSERT_TRUE(s.ok()) << s.message;
      ASSERT_EQ(model.check(t), "") << "seed " << seed << " step " << step;
      ASSERT_EQ(model.compare(t), "") << "seed " << seed << " step " << step;
    }
  }
}

// Small moves (a drag, an animation frame): most stay within the point's star and take flips
// only, with no point location: free points, and polyline vertices whose segments are single
// edges. After each move the mesh is the fresh triangulation, polylines' edges unflipped.
TEST(Editing, SmallMovesFlipInPlace) {
  int lineVerticesInPlace = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    Random random(seed);
    Triangulation t;
    EditModel model;
    ASSERT_TRUE(insertUniformPoints(model, t, 300, seed).ok());
    if (seed % 2 == 0) {
      for (int k = 0; k < 3; ++k)  // long: crossing each other, their segments split
        ASSERT_TRUE(model.insertPolyline(t, randomPolyline(random, 5, k == 0)).ok());
      for (int k = 0; k < 4; ++k) {  // short steps, mostly crossing nothing: whole segments
        std::vector<double> road{100 + 800 * random.uniform(), 100 + 800 * random.uniform()};
        for (int j = 0; j < 6; ++j) {
          road.push_back(road[road.size() - 2] + 40 * random.uniform() - 20);
          road.push_back(road[road.size() - 2] + 40 * random.uniform() - 20);
        }
        ASSERT_TRUE(model.insertPolyline(t, road).ok());
      }
    }
    const std::vector<std::uint32_t> points = model.pointIds();
    const std::vector<std::size_t> lines = model.polylineNumbers();
    int inPlace = 0;
    const int steps = 200;
    for (int step = 0; step < steps; ++step) {
      const bool onLine = !lines.empty() && step % 2 == 1;
      const std::vector<std::uint32_t> ids =
          onLine ? model.polylineVertexIds(lines[random.next() % lines.size()]) : points;
      const std::uint32_t id = ids[random.next() % ids.size()];
      const std::vector<double> at = model.place(id);
      // Up to half the mean spacing (about 58), in any direction.
      const double angle = 6.283185307179586 * random.uniform(), r = 29 * random.uniform();
      const std::uint64_t locates = t.stats().locates;
      const Status s =
          model.movePoint(t, id, at[0] + r * std::cos(angle), at[1] + r * std::sin(angle));
      ASSERT_TRUE(s.ok()) << s.message;
      const bool located = t.stats().locates != locates;
      inPlace += !located;
      lineVerticesInPlace += onLine && !located;
      ASSERT_EQ(model.check(t), "") << "seed " << seed << " step " << step;
      ASSERT_EQ(model.compare(t), "") << "seed " << seed << " step " << step;
    }
    EXPECT_GT(inPlace, steps / 3) << "seed " << seed;
    EXPECT_LT(inPlace, steps) << "seed " << seed;  // some leave their star
  }
  EXPECT_GT(lineVerticesInPlace, 20);
}

// Random sequences of every edit, checked after each batch of a few. Returns whether the
// constraints were snap-rounded at some point.
bool randomEdits(std::uint64_t seed, int steps, double grid, bool compare) {
  Random random(seed);
  Triangulation t;
  EditModel model;
  // grid < 0: an 8 x 8 lattice of neighbouring doubles next to (1, 1), where crossings tangle
  // and the constraints get snap-rounded.
  const auto coordinate = [&] {
    if (grid < 0) return 1 + std::floor(random.uniform() * 8) * 0x1p-52;
    return std::floor(random.uniform() * 1000 / grid) * grid;
  };
  for (int step = 0; step < steps; ++step) {
    const std::uint64_t r = random.next() % 100;
    const std::vector<std::uint32_t> points = model.pointIds();
    const std::vector<std::size_t> lines = model.polylineNumbers();
    Status s;
    std::string what;
    if (r < 25 || points.empty()) {
      std::vector<double> xy;
      for (int k = 0; k < 1 + static_cast<int>(random.next() % 20); ++k) {
        xy.push_back(coordinate());
        xy.push_back(coordinate());
      }
      what = "insertPoints";
      s = model.insertPoints(t, xy);
    } else if (r < 35) {
      const std::size_t n = 2 + random.next() % 5;
      std::vector<double> line;
      for (std::size_t k = 0; k < n; ++k) {
        line.push_back(coordinate());
        line.push_back(coordinate());
      }
      if (random.next() % 3 == 0) line.insert(line.end(), {line[0], line[1]});
      what = "insertPolyline";
      s = model.insertPolyline(t, line);
    } else if (r < 60) {
      const std::uint32_t id = points[random.next() % points.size()];
      what = "removePoint " + std::to_string(id);
      s = model.removePoint(t, id);
    } else if (r < 70 && !lines.empty()) {
      const std::size_t k = lines[random.next() % lines.size()];
      what = "removePolyline " + std::to_string(k);
      s = model.removePolyline(t, k);
    } else {
      std::vector<std::uint32_t> ids = points;
      if (!lines.empty() && random.next() % 2 == 0)
        ids = model.polylineVertexIds(lines[random.next() % lines.size()]);
      const std::uint32_t id = ids[random.next() % ids.size()];
      what = "movePoint " + std::to_string(id);
      s = model.movePoint(t, id, coordinate(), coordinate());
      // Onto another point's place: refused, nothing changed.
      if (s.code == StatusCode::InvalidArgument) s = Status::success();
    }
    EXPECT_TRUE(s.ok()) << "seed " << seed << " step " << step << " " << what << ": " << s.message;
    if (!s.ok()) return false;
    if (step % 5 == 4) {
      const std::string checked = model.check(t);
      EXPECT_EQ(checked, "") << "seed " << seed << " step " << step << " " << what;
      const std::string compared = compare ? model.compare(t) : "";
      EXPECT_EQ(compared, "") << "seed " << seed << " step " << step << " " << what;
      if (!checked.empty() || !compared.empty()) return false;
    }
  }
  return t.stats().snapRoundings > 0;
}

// A Steiner point that a later insertPoints gives as a point (a point at its place) is
// needed as a point: it stays when what it was placed from goes, by removePolyline or by
// removePoint (fuzz_edits found it removed with its parent's other Steiner points).
std::uint32_t steinerGivenAsAPoint(Triangulation& t) {
  RefineOptions options;
  options.maxArea = 2.0;
  EXPECT_TRUE(t.refine(options).ok());
  const Mesh m = t.mesh();
  EXPECT_FALSE(m.steiner.empty());
  const std::uint32_t s = m.steiner.back();
  std::uint32_t id = 0;
  EXPECT_TRUE(t.insertPoints(&m.points[2 * std::size_t{s}], 1, &id).ok());
  EXPECT_EQ(id, s);
  return id;
}

TEST(Editing, SteinerPointGivenAgainAsAPointStays) {
  {
    Triangulation t;
    const std::vector<double> ring{0, 0, 10, 0, 10, 4, 0, 4, 0, 0};
    ASSERT_TRUE(t.insertPolyline(ring.data(), ring.size() / 2).ok());
    const std::uint32_t id = steinerGivenAsAPoint(t);
    ASSERT_TRUE(t.removePolyline(0).ok());
    EXPECT_TRUE(t.hasVertex(id));
    EXPECT_GT(t.stats().removed, 0u);  // the other Steiner points went
  }
  {
    Triangulation t;
    const std::vector<double> corners{0, 0, 10, 0, 10, 4, 0, 4};
    std::uint32_t ids[4];
    ASSERT_TRUE(t.insertPoints(corners.data(), 4, ids).ok());
    const std::uint32_t id = steinerGivenAsAPoint(t);
    for (const std::uint32_t corner : ids) ASSERT_TRUE(t.removePoint(corner).ok());
    EXPECT_TRUE(t.hasVertex(id));
  }
}

// fuzz_edits: refinement put Steiner points along a column of hull vertices; a polyline then
// took one of them as its vertex. Moving the point they were placed from removes them, and
// the chain through the first ones went into the editor's queue before the check reached the
// polyline's vertex, which then looked unneeded: "segment 2 ends there".
TEST(Editing, SteinerPointGivenAgainAsAPolylineVertexStaysWhenItsParentMoves) {
  // Two columns of points 3e135 apart, their heights ulps apart.
  const double x0 = -9.9999999999999998e+149, x1 = -9.9999999999999707e+149;
  const double low = 179.99999999999963, middle = 179.99999999999974, high = 179.99999999999986;
  for (const bool move : {true, false}) {
    Options options;
    options.gridDensity = 2;
    Triangulation t(options);
    EditModel model;
    ASSERT_TRUE(model.insertPolyline(t, {x0, middle, x0, low, x0, middle}).ok());
    ASSERT_TRUE(model.insertPoints(t, {x0, 180.00000000000009, x1, 180.00000000000043}).ok());
    RefineOptions refine;
    refine.minAngle = 20;
    ASSERT_TRUE(t.refine(refine).ok());
    ASSERT_FALSE(t.mesh().steiner.empty());
    // (high is where refinement put a Steiner point.)
    ASSERT_TRUE(model.insertPolyline(t, {x0, low, x0, high, x0, low}).ok());
    const std::uint32_t point = model.pointIds()[0];
    const Status s =
        move ? model.movePoint(t, point, x0, 179.99999999999997) : model.removePoint(t, point);
    ASSERT_TRUE(s.ok()) << s.message;
    for (const std::size_t k : model.polylineNumbers())
      for (const std::uint32_t id : model.polylineVertexIds(k)) EXPECT_TRUE(t.hasVertex(id));
    EXPECT_EQ(model.check(t), "");  // (refined: the Steiner points not placed from it stay)
  }
}

// fuzz_edits: two rings in a tangle a few ulps wide, where one segment's chain runs through
// two crossings and an edge beside it names that segment too, so that its edges at a crossing
// are three. The editor cannot splice such a chain when a move takes the crossing away: the
// constraints are inserted again from the input.
TEST(Editing, ChainsThatDoNotPairUpAtACrossingAreInsertedAgain) {
  const double x = 16000000.25, below = 16000000.249999998, unit = 0x1p-1074;
  const std::vector<double> first{x,         -3 * unit, 16000000.249999994, -3 * unit, below,
                                  -2 * unit, x,         3 * unit,           x,         -3 * unit};
  const std::vector<double> second{
      16000000.250000004, -2 * unit,          below,     unit, x,
      -3 * unit,          16000000.249999996, -3 * unit, x,    3 * unit,
      16000000.250000004, -2 * unit};
  Options options;
  options.order = InsertionOrder::Input;
  options.gridDensity = 2;
  Triangulation t(options);
  EditModel model;
  ASSERT_TRUE(model.insertPolyline(t, first).ok());
  ASSERT_TRUE(model.insertPolyline(t, second).ok());
  ASSERT_EQ(t.stats().snapRoundings, 0u);
  const std::uint32_t moved = model.polylineVertexIds(1)[1];  // (below, unit)
  const Status s = model.movePoint(t, moved, 16000000.249999996, unit);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(model.check(t), "");
  EXPECT_EQ(model.compare(t, false), "");
}

// A large batch leaves the location grid stale; the first edit fills it from its table of a
// half-edge per vertex (read in vertex order). Locations from that grid must walk as few
// triangles as from one filled from the triangles, as a triangulation that was not edited
// fills it on its first locate().
TEST(Editing, FirstEditFillsTheStaleGridForShortWalks) {
  const std::vector<double> xy = testing::uniformPoints(200000, 31);
  const std::size_t n = xy.size() / 2;
  Triangulation edited, plain;
  std::vector<std::uint32_t> ids(n);
  ASSERT_TRUE(edited.insertPoints(xy.data(), n, ids.data()).ok());
  ASSERT_TRUE(plain.insertPoints(xy.data(), n, nullptr).ok());
  ASSERT_TRUE(edited.removePoint(ids[n / 2]).ok());
  const std::vector<double> queries = testing::uniformPoints(4000, 32);
  const auto stepsPerLocation = [&](const Triangulation& t) {
    const Stats before = t.stats();
    for (std::size_t q = 0; q < queries.size(); q += 2) {
      const Location at = t.locate(queries[q], queries[q + 1]);
      EXPECT_NE(at.kind, Location::Kind::Invalid);
    }
    const Stats after = t.stats();
    return static_cast<double>(after.walkSteps - before.walkSteps) /
           static_cast<double>(after.locates - before.locates);
  };
  const double fromVertices = stepsPerLocation(edited), fromTriangles = stepsPerLocation(plain);
  EXPECT_LT(fromVertices, 10.0);
  EXPECT_LT(fromVertices, 1.5 * fromTriangles + 1) << "from triangles: " << fromTriangles;
}

TEST(Editing, RandomSequencesOfEveryEdit) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) randomEdits(seed, 200, 1.0 / 64, true);
}

TEST(Editing, RandomSequencesOnACoarseGrid) {
  // Coordinates on a coarse grid: points on segments, overlaps, T-junctions, repeated points
  // (cocircular points too: only the invariants decide there).
  for (std::uint64_t seed = 1; seed <= 6; ++seed) randomEdits(seed, 150, 125, false);
}

TEST(Editing, RandomSequencesInUlpTangles) {
  int snapped = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) snapped += randomEdits(seed, 150, -1, false);
  EXPECT_GE(snapped, 2);  // the snap-rounded state was edited too
}

TEST(Editing, RemovingTheTangledPolylineGivesComputedCrossingsBack) {
  // Four segments within 4 ulps of (-3.5e-7, -12345.678): inserted together they are
  // snap-rounded (constraints_test.cpp). Without any one of them, the fresh triangulation may
  // need no rounding: then the edited one must have its computed crossings.
  const std::vector<std::vector<double>> lines = {
      {-3.500000000000001e-07, -12345.677999999998, -3.4999999999999993e-07, -12345.678000000004},
      {-3.500000000000001e-07, -12345.678000000004, -3.5e-07, -12345.678},
      {-3.4999999999999993e-07, -12345.678, -3.500000000000001e-07, -12345.678000000002},
      {-3.5000000000000004e-07, -12345.677999999998, -3.499999999999999e-07, -12345.678000000002}};
  int computed = 0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    Triangulation t;
    EditModel model;
    ASSERT_TRUE(
        model.insertPoints(t, {-3.6e-7, -12345.679, -3.4e-7, -12345.679, -3.5e-7, -12345.677})
            .ok());
    for (const auto& line : lines) ASSERT_TRUE(model.insertPolyline(t, line).ok());
    ASSERT_GE(t.stats().snapRoundings, 1u);
    ASSERT_TRUE(model.removePolyline(t, k).ok());
    EXPECT_EQ(model.check(t), "") << "without line " << k;
    // The fresh triangulation of the three left, one polyline a call as above.
    Triangulation fresh;
    EditModel freshModel;
    ASSERT_TRUE(
        freshModel
            .insertPoints(fresh, {-3.6e-7, -12345.679, -3.4e-7, -12345.679, -3.5e-7, -12345.677})
            .ok());
    for (std::size_t j = 0; j < lines.size(); ++j)
      if (j != k) ASSERT_TRUE(freshModel.insertPolyline(fresh, lines[j]).ok());
    if (fresh.stats().snapRoundings > 0) continue;
    ++computed;
    EXPECT_EQ(t.stats().snapRoundings, 1u);  // the one before the removal
    // The crossings are the computed ones. (On a lattice of neighbouring doubles cocircular
    // points abound, and chains may route through other triangles: vertices are compared.)
    EXPECT_EQ(model.compare(t, false), "") << "without line " << k;
  }
  EXPECT_GE(computed, 1);
}

}  // namespace
}  // namespace geocdt
