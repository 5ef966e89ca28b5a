// The checker must fail on broken meshes, or every other test proves nothing.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace geocdt
