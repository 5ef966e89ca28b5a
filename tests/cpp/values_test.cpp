// Values on vertices: carried from the input, derived at crossings, interpolated (linear and
// natural neighbour) and rasterized.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "geocdt/triangulation.h"
#include "point_generators.h"
#include "values/vertex_values.h"

namespace geocdt {
namespace {

using testing::Random;

// A linear function with an offset and slopes of different sizes.
double linear(double x, double y) { return 3.25 - 1.5 * x + 0.75 * y; }

std::vector<double> valuesOf(const std::vector<double>& xy) {
  std::vector<double> f(xy.size() / 2);
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = linear(xy[2 * i], xy[2 * i + 1]);
  return f;
}

// Random queries over the points' bounding box, and the largest |f| over the points.
std::vector<double> queriesFor(const std::vector<double>& xy, std::size_t n, double* scale) {
  double lo[2] = {xy[0], xy[1]}, hi[2] = {xy[0], xy[1]};
  for (std::size_t i = 0; i < xy.size(); ++i) {
    lo[i % 2] = std::min(lo[i % 2], xy[i]);
    hi[i % 2] = std::max(hi[i % 2], xy[i]);
  }
  *scale = 0;
  for (std::size_t i = 0; i < xy.size(); i += 2)
    *scale = std::max(*scale, std::fabs(linear(xy[i], xy[i + 1])));
  Random random(7);
  std::vector<double> q(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    q[2 * i] = lo[0] + random.uniform() * (hi[0] - lo[0]);
    q[2 * i + 1] = lo[1] + random.uniform() * (hi[1] - lo[1]);
  }
  return q;
}

void expectLinearPrecision(const std::vector<double>& xy, Interpolation method) {
  Triangulation t;
  const std::vector<double> f = valuesOf(xy);
  ASSERT_TRUE(t.insertPoints(xy.data(), xy.size() / 2, nullptr, f.data()).ok());
  double scale = 0;
  const std::vector<double> q = queriesFor(xy, 5000, &scale);
  std::vector<double> out(q.size() / 2);
  t.interpolate(q.data(), out.size(), method, out.data());
  std::size_t inside = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Location::Kind kind = t.locate(q[2 * i], q[2 * i + 1]).kind;
    if (kind == Location::Kind::Outside) {
      EXPECT_TRUE(std::isnan(out[i])) << "query " << i;
      continue;
    }
    ++inside;
    EXPECT_NEAR(out[i], linear(q[2 * i], q[2 * i + 1]), 1e-12 * scale) << "query " << i;
  }
  EXPECT_GT(inside, out.size() / 2);
  // At the vertices themselves: the values exactly.
  std::vector<double> at(xy.size() / 2);
  t.interpolate(xy.data(), at.size(), method, at.data());
  for (std::size_t i = 0; i < at.size(); ++i) ASSERT_EQ(at[i], f[i]) << "vertex " << i;
}

TEST(Values, LinearPrecisionUniform) {
  const std::vector<double> xy = testing::uniformPoints(3000, 1);
  expectLinearPrecision(xy, Interpolation::Linear);
  expectLinearPrecision(xy, Interpolation::Natural);
}

TEST(Values, LinearPrecisionClustered) {
  const std::vector<double> xy = testing::gaussianClusters(3000, 2);
  expectLinearPrecision(xy, Interpolation::Linear);
  expectLinearPrecision(xy, Interpolation::Natural);
}

TEST(Values, LinearPrecisionLattice) {
  // Cocircular everywhere: every cavity has several triangles with one circumcentre.
  const std::vector<double> xy = testing::latticePoints(40);
  expectLinearPrecision(xy, Interpolation::Linear);
  expectLinearPrecision(xy, Interpolation::Natural);
  const std::vector<double> far = testing::transformed(xy, 0.25, 1e6, -3e5);
  expectLinearPrecision(far, Interpolation::Linear);
  expectLinearPrecision(far, Interpolation::Natural);
}

TEST(Values, NaturalIsNotLinear) {
  // On a non-linear surface the two methods differ inside triangles: the natural method
  // really blends more than the three corners.
  const std::vector<double> xy = testing::uniformPoints(500, 3);
  std::vector<double> f(xy.size() / 2);
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = xy[2 * i] * xy[2 * i] + xy[2 * i + 1];
  Triangulation t;
  ASSERT_TRUE(t.insertPoints(xy.data(), f.size(), nullptr, f.data()).ok());
  const double q[2] = {0.5123, 0.4871};
  double a = 0, b = 0;
  t.interpolate(q, 1, Interpolation::Linear, &a);
  t.interpolate(q, 1, Interpolation::Natural, &b);
  EXPECT_NE(a, b);
  EXPECT_NEAR(a, b, 0.05);
}

TEST(Values, NanOutsideAndWithoutValues) {
  Triangulation t;
  const double xy[] = {0, 0, 1, 0, 0, 1};
  const double q[] = {0.25, 0.25, 2, 2, std::numeric_limits<double>::quiet_NaN(), 0};
  double out[3];
  ASSERT_TRUE(t.insertPoints(xy, 3).ok());
  EXPECT_FALSE(t.hasValues());
  t.interpolate(q, 3, Interpolation::Linear, out);
  for (double v : out) EXPECT_TRUE(std::isnan(v));
  const double f[] = {1, 2, 3};
  const double more[] = {1, 1};
  const double g[] = {4};
  ASSERT_TRUE(t.insertPoints(more, 1, nullptr, g).ok());
  EXPECT_TRUE(t.hasValues());
  t.interpolate(q, 3, Interpolation::Linear, out);
  // The first three points came without values: NaN there, hence NaN inside their triangle.
  EXPECT_TRUE(std::isnan(out[0]));
  EXPECT_TRUE(std::isnan(out[1]));
  EXPECT_TRUE(std::isnan(out[2]));
  Triangulation u;
  ASSERT_TRUE(u.insertPoints(xy, 3, nullptr, f).ok());
  u.interpolate(q, 3, Interpolation::Natural, out);
  EXPECT_DOUBLE_EQ(out[0], 1 + 0.25 + 0.5);
  EXPECT_TRUE(std::isnan(out[1]));
  EXPECT_TRUE(std::isnan(out[2]));
}

TEST(Values, SeveralValuesPerPoint) {
  Options options;
  options.valuesPerPoint = 2;
  Triangulation t(options);
  const std::vector<double> xy = testing::uniformPoints(200, 4);
  std::vector<double> f;
  for (std::size_t i = 0; i < xy.size(); i += 2) {
    f.push_back(linear(xy[i], xy[i + 1]));
    f.push_back(-2 * xy[i]);
  }
  ASSERT_TRUE(t.insertPoints(xy.data(), xy.size() / 2, nullptr, f.data()).ok());
  const double q[] = {0.5, 0.5, 0.25, 0.75};
  double out[4];
  for (Interpolation m : {Interpolation::Linear, Interpolation::Natural}) {
    t.interpolate(q, 2, m, out);
    EXPECT_NEAR(out[0], linear(0.5, 0.5), 1e-12);
    EXPECT_NEAR(out[1], -1, 1e-12);
    EXPECT_NEAR(out[2], linear(0.25, 0.75), 1e-12);
    EXPECT_NEAR(out[3], -0.5, 1e-12);
  }
  const Mesh m = t.mesh();
  ASSERT_EQ(m.values.size(), 2 * (m.points.size() / 2));
}

TEST(Values, DuplicatesKeepTheFirst) {
  Triangulation t;
  const double xy[] = {0, 0, 1, 0, 0, 1, 1, 0, 1, 0};
  const double f[] = {1, 2, 3, 5, 2};
  std::uint32_t ids[5];
  ASSERT_TRUE(t.insertPoints(xy, 5, ids, f).ok());
  const Mesh m = t.mesh();
  EXPECT_EQ(m.values[ids[1]], 2);
  EXPECT_EQ(ids[3], ids[1]);
  // One duplicate with other values (5); the one with equal values (2) is not counted.
  EXPECT_EQ(t.stats().valueDuplicates, 1u);
  EXPECT_EQ(t.stats().duplicates, 2u);
}

// Two polylines crossing: the crossing takes values interpolated along both.
TEST(Values, CrossingsAreInterpolated) {
  const std::vector<double> points = {-1, -1, 3, -1, 3, 3, -1, 3};
  const std::vector<double> a = {0, 0, 2, 1.5}, b = {0, 1.25, 2, 0};
  std::vector<double> f = valuesOf(points);
  for (const auto* line : {&a, &b})
    for (std::size_t i = 0; i < line->size(); i += 2)
      f.push_back(linear((*line)[i], (*line)[i + 1]));
  const PolylineView views[] = {{a.data(), 2}, {b.data(), 2}};
  Mesh m;
  ASSERT_TRUE(triangulate(points.data(), 4, views, 2, {}, {}, m, nullptr, f.data()).ok());
  ASSERT_EQ(m.points.size() / 2, 9u);
  const std::uint32_t crossing = 8;
  EXPECT_NEAR(m.values[crossing], linear(m.points[16], m.points[17]), 1e-14);
  ASSERT_EQ(m.derivedVertices, std::vector<std::uint32_t>{crossing});
  ASSERT_EQ(m.derivedOffsets, (std::vector<std::uint32_t>{0, 4}));
  double sum = 0, weights = 0;
  for (std::uint32_t j = 0; j < 4; ++j) {
    sum += m.derivedWeights[j] * m.values[m.derivedParents[j]];
    weights += m.derivedWeights[j];
  }
  EXPECT_DOUBLE_EQ(sum, m.values[crossing]);
  EXPECT_DOUBLE_EQ(weights, 1);

  // Values that disagree at the crossing: the mean, counted.
  Triangulation t;
  ASSERT_TRUE(t.insertPoints(points.data(), 4, nullptr, f.data()).ok());
  const double fa[] = {0, 0}, fb[] = {10, 10};
  ASSERT_TRUE(t.insertPolyline(a.data(), 2, nullptr, fa).ok());
  EXPECT_EQ(t.stats().valueDisagreements, 0u);
  ASSERT_TRUE(t.insertPolyline(b.data(), 2, nullptr, fb).ok());
  EXPECT_EQ(t.stats().valueDisagreements, 1u);
  EXPECT_DOUBLE_EQ(t.mesh().values[crossing], 5);
}

// Linear interpolation along constrained edges, both sides of them continuous.
TEST(Values, ContinuousAcrossConstrainedEdges) {
  std::vector<double> xy = testing::uniformPoints(400, 5);
  Triangulation t;
  std::vector<double> f(xy.size() / 2);
  Random random(11);
  for (double& v : f) v = random.uniform();  // not linear: the sides differ in general
  ASSERT_TRUE(t.insertPoints(xy.data(), f.size(), nullptr, f.data()).ok());
  const std::vector<double> line = {0.1, 0.13, 0.9, 0.77, 0.2, 0.85};
  const double fl[] = {0.5, 0.25, 0.75};
  ASSERT_TRUE(t.insertPolyline(line.data(), 3, nullptr, fl).ok());
  for (Interpolation m : {Interpolation::Linear, Interpolation::Natural}) {
    for (int s = 0; s < 2; ++s) {
      const double* a = &line[2 * s];
      const double* b = &line[2 * s + 2];
      const double nx = -(b[1] - a[1]), ny = b[0] - a[0];
      for (double u : {0.1, 0.37, 0.5, 0.81}) {
        const double x = a[0] + u * (b[0] - a[0]), y = a[1] + u * (b[1] - a[1]);
        const double eps = 1e-9;
        const double q[] = {x + eps * nx, y + eps * ny, x - eps * nx, y - eps * ny};
        double out[2];
        t.interpolate(q, 2, m, out);
        EXPECT_NEAR(out[0], out[1], 1e-6) << "segment " << s << " at " << u;
      }
    }
  }
}

TEST(Values, RasterMatchesLinearQueries) {
  const std::vector<double> xy = testing::gaussianClusters(2000, 6);
  std::vector<double> f(xy.size() / 2);
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = std::sin(3 * xy[2 * i]) + xy[2 * i + 1];
  Triangulation t;
  ASSERT_TRUE(t.insertPoints(xy.data(), f.size(), nullptr, f.data()).ok());
  double lo[2] = {xy[0], xy[1]}, hi[2] = {xy[0], xy[1]};
  for (std::size_t i = 0; i < xy.size(); ++i) {
    lo[i % 2] = std::min(lo[i % 2], xy[i]);
    hi[i % 2] = std::max(hi[i % 2], xy[i]);
  }
  // A little wider than the points, with pixels that are not square.
  const double w = hi[0] - lo[0], h = hi[1] - lo[1];
  RasterGrid grid{lo[0] - 0.05 * w, lo[1] - 0.1 * h, hi[0] + 0.05 * w, hi[1] + 0.02 * h, 97, 61};
  std::vector<float> raster(97 * 61);
  ASSERT_TRUE(t.rasterize(grid, Interpolation::Linear, raster.data()).ok());
  std::vector<double> q;
  for (std::uint32_t j = 0; j < grid.height; ++j)
    for (std::uint32_t i = 0; i < grid.width; ++i) {
      q.push_back(grid.minX + (i + 0.5) * (grid.maxX - grid.minX) / grid.width);
      q.push_back(grid.maxY - (j + 0.5) * (grid.maxY - grid.minY) / grid.height);
    }
  std::vector<double> expected(raster.size());
  t.interpolate(q.data(), expected.size(), Interpolation::Linear, expected.data());
  std::size_t inside = 0;
  for (std::size_t i = 0; i < raster.size(); ++i) {
    if (std::isnan(expected[i])) {
      EXPECT_TRUE(std::isnan(raster[i])) << "pixel " << i;
      continue;
    }
    ++inside;
    EXPECT_NEAR(raster[i], expected[i], 1e-5) << "pixel " << i;
  }
  EXPECT_GT(inside, 1000u);
  std::vector<float> natural(raster.size());
  ASSERT_TRUE(t.rasterize(grid, Interpolation::Natural, natural.data()).ok());
  t.interpolate(q.data(), expected.size(), Interpolation::Natural, expected.data());
  for (std::size_t i = 0; i < raster.size(); ++i) {
    if (std::isnan(expected[i]))
      EXPECT_TRUE(std::isnan(natural[i]));
    else
      EXPECT_FLOAT_EQ(natural[i], static_cast<float>(expected[i]));
  }
  EXPECT_FALSE(t.rasterize({1, 0, 0, 1, 4, 4}, Interpolation::Linear, raster.data()).ok());
}

// Natural neighbours seen past constrained edges only: still linear precision.
TEST(Values, LinearPrecisionWithConstraints) {
  const std::vector<double> xy = testing::uniformPoints(2000, 8);
  Triangulation t;
  const std::vector<double> f = valuesOf(xy);
  ASSERT_TRUE(t.insertPoints(xy.data(), f.size(), nullptr, f.data()).ok());
  Random random(9);
  for (int i = 0; i < 30; ++i) {
    std::vector<double> line;
    for (int k = 0; k < 4; ++k) line.push_back(random.uniform());
    const std::vector<double> fl = valuesOf(line);
    ASSERT_TRUE(t.insertPolyline(line.data(), 2, nullptr, fl.data()).ok());
  }
  EXPECT_GT(t.stats().crossings, 50u);
  EXPECT_EQ(t.stats().valueDisagreements, 0u);
  double scale = 0;
  const std::vector<double> q = queriesFor(xy, 5000, &scale);
  for (Interpolation m : {Interpolation::Linear, Interpolation::Natural}) {
    std::vector<double> out(q.size() / 2);
    t.interpolate(q.data(), out.size(), m, out.data());
    for (std::size_t i = 0; i < out.size(); ++i)
      if (!std::isnan(out[i]))
        EXPECT_NEAR(out[i], linear(q[2 * i], q[2 * i + 1]), 1e-12 * scale) << "query " << i;
  }
}

// Queries a hair's breadth from a constrained edge, at huge and tiny scales: finite values
// between the neighbours' (natural falls back to linear where its areas overflow).
TEST(Values, NaturalNextToConstrainedEdges) {
  for (double scale : {1e-150, 1.0, 1e140}) {
    const std::vector<double> xy =
        testing::transformed(testing::uniformPoints(300, 10), scale, 0, 0);
    Triangulation t;
    std::vector<double> f(xy.size() / 2);
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = static_cast<double>(i % 7);
    ASSERT_TRUE(t.insertPoints(xy.data(), f.size(), nullptr, f.data()).ok());
    const double line[] = {0.2 * scale, 0.3 * scale, 0.8 * scale, 0.6 * scale};
    const double fl[] = {1, 5};
    ASSERT_TRUE(t.insertPolyline(line, 2, nullptr, fl).ok());
    for (double u : {0.25, 0.5, 0.75}) {
      const double x = line[0] + u * (line[2] - line[0]), y = line[1] + u * (line[3] - line[1]);
      const double q[] = {x, std::nextafter(y, 2 * y), x, std::nextafter(y, 0.0), x, y};
      double out[3];
      t.interpolate(q, 3, Interpolation::Natural, out);
      for (double v : out) {
        EXPECT_TRUE(std::isfinite(v)) << scale << " at " << u;
        EXPECT_GE(v, 0);
        EXPECT_LE(v, 6);
      }
    }
  }
}

// The hook for Steiner points: a vertex no input point became, off every constraint, gets its
// values from the parents derive() names (NaN without).
TEST(Values, DerivedVerticesHook) {
  Delaunay d{Options{}};
  const double corners[] = {0, 0, 4, 0, 4, 4, 0, 4};
  std::uint32_t ids[4];
  ASSERT_TRUE(d.insertBatch(corners, 4, ids).ok());
  VertexValues values(1);
  const double f[] = {1, 2, 3, 4};
  values.record(ids, 4, f, d.vertexCount());
  const double steiner[] = {1, 1, 3, 2};
  std::uint32_t added[2];
  ASSERT_TRUE(d.insertBatch(steiner, 2, added).ok());
  const std::uint32_t parents[] = {ids[0], ids[1], ids[3]};
  const double weights[] = {0.5, 0.25, 0.25};
  values.derive(added[0], parents, weights, 3);
  Mesh m;
  const std::vector<double>& all = values.update(d, &m);
  EXPECT_DOUBLE_EQ(all[added[0]], 0.5 * 1 + 0.25 * 2 + 0.25 * 4);
  EXPECT_TRUE(std::isnan(all[added[1]]));
  EXPECT_EQ(m.derivedVertices, std::vector<std::uint32_t>{added[0]});
  EXPECT_EQ(m.derivedOffsets, (std::vector<std::uint32_t>{0, 3}));
  EXPECT_EQ(m.derivedParents, (std::vector<std::uint32_t>{ids[0], ids[1], ids[3]}));
  // A derivation of a vertex an input point became is ignored: the input's values win.
  values.derive(ids[2], parents, weights, 3);
  EXPECT_EQ(values.update(d, nullptr)[ids[2]], 3);
}

}  // namespace
}  // namespace geocdt
