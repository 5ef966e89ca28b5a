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

}  // namespace
}  // namespace geocdt
