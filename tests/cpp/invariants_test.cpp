// The checker must fail on broken meshes, or every other test proves nothing.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "constraint_invariants.h"
#include "geocdt/triangulation.h"
#include "invariants.h"
#include "point_generators.h"

namespace geocdt {
namespace {

Mesh square() {
  // Two triangles over the unit square, split along 0-2: Delaunay (cocircular, either works).
  Mesh m;
  m.points = {0, 0, 1, 0, 1, 1, 0, 1};
  m.triangles = {0, 1, 2, 0, 2, 3};
  m.halfedges = {-1, -1, 3, 2, -1, -1};
  m.constrained = {0, 0, 0, 0, 0, 0};
  return m;
}

TEST(Invariants, AcceptsAValidMesh) { EXPECT_EQ(testing::checkTriangulation(square()), ""); }

TEST(Invariants, RejectsBrokenTwins) {
  Mesh m = square();
  m.halfedges[2] = -1;
  EXPECT_NE(testing::checkTriangulation(m), "");
}

TEST(Invariants, RejectsClockwiseTriangle) {
  Mesh m = square();
  std::swap(m.triangles[1], m.triangles[2]);
  EXPECT_NE(testing::checkTriangulation(m), "");
}

TEST(Invariants, RejectsNonConvexHull) {
  Mesh m = square();
  m.points[4] = 0.4;  // vertex 2 moves inside: the boundary turns right there
  m.points[5] = 0.4;
  EXPECT_NE(testing::checkTriangulation(m), "");
}

TEST(Invariants, RejectsNonDelaunayEdge) {
  Mesh m = square();
  m.points[4] = 3;  // vertex 2 far out: vertex 3 now lies inside the circle of 0, 1, 2
  m.points[5] = 3;
  m.points[6] = 0.2;
  m.points[7] = 1;
  EXPECT_NE(testing::checkTriangulation(m).find("Delaunay"), std::string::npos);
}

TEST(Invariants, RejectsMissingOrMisplacedInputPoint) {
  Mesh m = square();
  const std::vector<double> input = {0, 0, 1, 1};
  const std::vector<std::uint32_t> wrong = {0, 1};
  testing::CheckOptions c;
  c.inputXY = &input;
  c.inputToVertex = &wrong;
  EXPECT_NE(testing::checkTriangulation(m, c), "");
}

TEST(Invariants, RejectsMissingTriangle) {
  // Dropping a triangle of a real result breaks Euler's count or the hull.
  const std::vector<double> xy = testing::uniformPoints(200, 3);
  Mesh m;
  ASSERT_TRUE(triangulate(xy.data(), 100, nullptr, 0, {}, {}, m).ok());
  ASSERT_EQ(testing::checkTriangulation(m), "");
  const std::size_t last = m.triangles.size() - 3;
  for (std::size_t e = last; e < last + 3; ++e)
    if (m.halfedges[e] >= 0) m.halfedges[m.halfedges[e]] = -1;
  m.triangles.resize(last);
  m.halfedges.resize(last);
  m.constrained.resize(last);
  EXPECT_NE(testing::checkTriangulation(m), "");
}

TEST(Invariants, RejectsDuplicateVertices) {
  Mesh m = square();
  m.points.push_back(1);
  m.points.push_back(1);
  EXPECT_NE(testing::checkTriangulation(m), "");
}

// Constrained edges alone, each as a degenerate triangle (u, v, v) whose first half-edge is
// constrained: the constraint checker reads nothing else.
Mesh edgesOnly(const std::vector<double>& points,
               const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges) {
  Mesh m;
  m.points = points;
  for (const auto& [u, v] : edges) {
    m.triangles.insert(m.triangles.end(), {u, v, v});
    m.halfedges.insert(m.halfedges.end(), {-1, -1, -1});
    m.constrained.insert(m.constrained.end(), {1, 0, 0});
  }
  return m;
}

TEST(ConstraintInvariants, BoundIsTwoUlpsOfTheLargestCoordinate) {
  // Segment (0, 0)-(4, 0): ulp(4) = 2^-50, so the bound is 2^-49 = 1.78e-15.
  EXPECT_EQ(testing::chainBound(0, 0, 4, 0), 0x1p-49);
  EXPECT_EQ(testing::chainBound(-1e-320, 0, 0, 0), 2 * std::numeric_limits<double>::denorm_min());
  const testing::Polylines line = {{0, 0, 4, 0}};
  const Mesh near = edgesOnly({0, 0, 4, 0, 2, 1.7e-15}, {{0, 2}, {2, 1}});
  EXPECT_EQ(testing::checkConstraints(near, line, {0, 1}), "");
  const Mesh far = edgesOnly({0, 0, 4, 0, 2, 1.8e-15}, {{0, 2}, {2, 1}});
  EXPECT_NE(testing::checkConstraints(far, line, {0, 1}).find("bound"), std::string::npos);
}

TEST(ConstraintInvariants, RejectsAChainOutOfOrder) {
  // On the segment, but from 3 back to 2.
  const Mesh m = edgesOnly({0, 0, 4, 0, 3, 0, 2, 0}, {{0, 2}, {2, 3}, {3, 1}});
  EXPECT_NE(testing::checkConstraints(m, {{0, 0, 4, 0}}, {0, 1}).find("in order"),
            std::string::npos);
}

TEST(ConstraintInvariants, RejectsANewCrossing) {
  // t lies strictly above s; both chains pass through c, within the bound (1.78e-15) of
  // each, but s's chain passes above t's start and below t's end: a crossing the segments
  // lack.
  const testing::Polylines lines = {{0, 0, 4, 0}, {1, 0.2e-15, 4, 1.1e-15}};
  const std::vector<double> points = {0, 0, 4, 0, 1, 0.2e-15, 4, 1.1e-15, 2, 1.6e-15};
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> edges = {
      {0, 4}, {4, 1}, {2, 4}, {4, 3}};
  EXPECT_NE(testing::checkConstraints(edgesOnly(points, edges), lines, {0, 1, 2, 3})
                .find("cross 1 times"),
            std::string::npos);
  // Through a point below t's start instead, s's chain stays below t's: they touch.
  std::vector<double> below = points;
  below[9] = 0.3e-15;
  EXPECT_EQ(testing::checkConstraints(edgesOnly(below, edges), lines, {0, 1, 2, 3}), "");
}

TEST(ConstraintInvariants, RejectsAnOverlapNamingOnePolyline) {
  // (0, 0)-(4, 0) and (2, 0)-(6, 0) share (2, 0)-(4, 0): that edge must name both polylines.
  const testing::Polylines lines = {{0, 0, 4, 0}, {2, 0, 6, 0}};
  Mesh m = edgesOnly({0, 0, 4, 0, 2, 0, 6, 0}, {{0, 2}, {2, 1}, {1, 3}});
  m.constraintEdges = {0, 3, 6};
  m.sourceOffsets = {0, 1, 3, 4};
  m.sources = {0, 0, 1, 1};
  m.segmentOffsets = m.sourceOffsets;
  m.segmentSources = m.sources;  // segment i is polyline i's
  EXPECT_EQ(testing::checkConstraints(m, lines, {0, 1, 2, 3}, true), "");
  // Routed for the first segment only, naming the first polyline only.
  m.sourceOffsets = m.segmentOffsets = {0, 1, 2, 3};
  m.sources = m.segmentSources = {0, 0, 1};
  EXPECT_NE(
      testing::checkConstraints(m, lines, {0, 1, 2, 3}, true).find("does not name polyline 1"),
      std::string::npos);
}

TEST(ConstraintInvariants, RejectsALostCrossing) {
  const testing::Polylines lines = {{0, 0, 4, 0}, {2, -1, 2, 1}};
  const Mesh m = edgesOnly({0, 0, 4, 0, 2, -1, 2, 1}, {{0, 1}, {2, 3}});
  EXPECT_NE(testing::checkConstraints(m, lines, {0, 1, 2, 3}).find("share no vertex"),
            std::string::npos);
}

}  // namespace
}  // namespace geocdt
