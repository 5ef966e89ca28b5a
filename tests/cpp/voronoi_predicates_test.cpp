// The exact layer of the Voronoi cells: the bisector predicates against GMP rationals on random,
// lattice and nearly degenerate inputs at every scale, and circumcentres within their stated
// tolerance of the exact centre.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>

#include "exact/bisector_predicates.h"
#include "exact/circumcenter.h"
#include "point_generators.h"
#include "voronoi/crossing_point.h"

namespace geocdt {
namespace {

int signOf(const mpq_class& v) { return mpq_sgn(v.get_mpq_t()); }
int signOf(Sign s) { return static_cast<int>(s); }

mpq_class q(double v) { return mpq_class(v); }

mpq_class f(XY c, XY t, XY x) {  // |x - c|^2 - |x - t|^2
  const mpq_class ax = q(x.x) - q(c.x), ay = q(x.y) - q(c.y);
  const mpq_class bx = q(x.x) - q(t.x), by = q(x.y) - q(t.y);
  return ax * ax + ay * ay - bx * bx - by * by;
}

// Points that make ties likely: a lattice, its midpoints, ulp neighbours, at a scale.
XY pick(testing::Random& r, double scale, double offset) {
  const int mode = static_cast<int>(r.next() % 4);
  double x = static_cast<double>(r.next() % 7), y = static_cast<double>(r.next() % 7);
  if (mode == 1) {
    x += 0.5;
    y -= 0.5;
  } else if (mode == 2) {
    x = r.uniform() * 6;
    y = r.uniform() * 6;
  }
  x = offset + x * scale;
  y = offset + y * scale;
  if (mode == 3) x = std::nextafter(x, INFINITY);
  return {x, y};
}

TEST(BisectorPredicates, AgreeWithRationals) {
  testing::Random r(11);
  int zeros = 0;
  for (const double scale : {1.0, 0x1p-600, 0x1p+400, 0.1}) {
    for (const double offset : {0.0, 1e6, -3.25e-200}) {
      for (int i = 0; i < 3000; ++i) {
        const XY c = pick(r, scale, offset), t = pick(r, scale, offset), u = pick(r, scale, offset);
        const XY p = pick(r, scale, offset), p2 = pick(r, scale, offset);
        XY qq = pick(r, scale, offset), q2 = pick(r, scale, offset);
        if (c == t || c == u || t == u) continue;
        ASSERT_EQ(signOf(bisectorSide(c, t, p)), signOf(f(c, t, p)));
        zeros += bisectorSide(c, t, p) == Sign::Zero;
        const mpq_class at = f(c, t, p), bt = f(c, t, qq), au = f(c, u, p), bu = f(c, u, qq);
        ASSERT_EQ(signOf(firstBisectorCrossed(c, t, u, p, qq)), signOf(at * bu - au * bt));
        const mpq_class gx = q(t.x) - q(c.x), gy = q(t.y) - q(c.y);
        ASSERT_EQ(signOf(bisectorApproach(c, t, p, qq)),
                  signOf(gx * (q(qq.x) - q(p.x)) + gy * (q(qq.y) - q(p.y))));
        // Two segments crossing the bisector: compare where, along n = (-gy, gx).
        const mpq_class b2 = f(c, t, q2), a2 = f(c, t, p2);
        if (signOf(at) * signOf(bt) >= 0 || signOf(a2) * signOf(b2) >= 0) continue;
        const auto along = [&](XY a, XY b, const mpq_class& fa, const mpq_class& fb) -> mpq_class {
          const mpq_class lambda = fa / (fa - fb);
          const mpq_class x = q(a.x) + lambda * (q(b.x) - q(a.x));
          const mpq_class y = q(a.y) + lambda * (q(b.y) - q(a.y));
          return -gy * x + gx * y;
        };
        const mpq_class first = along(p, qq, at, bt), second = along(p2, q2, a2, b2);
        ASSERT_EQ(signOf(crossingsAlongBisector(c, t, p, qq, p2, q2)), signOf(second - first));
      }
    }
  }
  EXPECT_GT(zeros, 100);  // the lattice made ties
}

// The stated accuracy, on random triangles and on nearly collinear ones (the exact path).
// Each coordinate of a crossing within 2^-49 of its distance from the segment's nearer end plus
// an ulp, at mixed scales (sites ulps or subnormals apart, segments up to 1e67 long: the fuzz
// findings where lambda and the double-double error bound underflowed).
TEST(CrossingPoint, NearItsExactPointAtMixedScales) {
  testing::Random r(31);
  int checked = 0;
  for (const double near : {1.0, 1e-312, 0x1p-1070, 1e100}) {
    for (const double far : {1.0, 1e67, 1e-154, 1e300}) {
      for (int i = 0; i < 1500; ++i) {
        const XY c{near * r.uniform(), near * r.uniform()};
        const XY t{i % 3 == 0 ? std::nextafter(c.x, INFINITY) : near * r.uniform(),
                   near * r.uniform()};
        const XY p{i % 2 ? c.x : far * (r.uniform() - 0.5), i % 2 ? c.y : far * r.uniform()};
        const XY e{i % 4 < 2 ? t.x : far * (r.uniform() - 0.5), far * r.uniform()};
        const mpq_class a = f(c, t, p), b = f(c, t, e);
        if (!(signOf(a) < 0 && signOf(b) > 0)) continue;
        const mpq_class lambda = a / (a - b);
        const mpq_class x = q(p.x) + lambda * (q(e.x) - q(p.x));
        const mpq_class y = q(p.y) + lambda * (q(e.y) - q(p.y));
        const mpq_class part = lambda <= mpq_class(1, 2) ? lambda : 1 - lambda;
        const CrossingPoint at = crossingPoint(c, t, p, e);
        const double wx = std::fabs(e.x - p.x), wy = std::fabs(e.y - p.y);
        const double tx = 0x1p-49 * part.get_d() * wx + 0x1p-52 * std::fabs(at.at.x) + 0x1p-1073;
        const double ty = 0x1p-49 * part.get_d() * wy + 0x1p-52 * std::fabs(at.at.y) + 0x1p-1073;
        ASSERT_LE(std::fabs(mpq_class(q(at.at.x) - x).get_d()), tx)
            << near << " " << far << " " << i;
        ASSERT_LE(std::fabs(mpq_class(q(at.at.y) - y).get_d()), ty)
            << near << " " << far << " " << i;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 4000);
}

// Whether circumcenter(a, b, c) is within its stated tolerance of the exact centre (false
// when the centre or the radius is not finite, or the corners are collinear: not checked).
::testing::AssertionResult centreWithinTolerance(XY a, XY b, XY c, bool& checked) {
  checked = false;
  const mpq_class dx = q(b.x) - q(a.x), dy = q(b.y) - q(a.y);
  const mpq_class ex = q(c.x) - q(a.x), ey = q(c.y) - q(a.y);
  const mpq_class det = dx * ey - dy * ex;
  if (det == 0) return ::testing::AssertionSuccess();
  const mpq_class bl = dx * dx + dy * dy, cl = ex * ex + ey * ey;
  const mpq_class cx = q(a.x) + (ey * bl - dy * cl) / (2 * det);
  const mpq_class cy = q(a.y) + (dx * cl - ex * bl) / (2 * det);
  const XY v = circumcenter(a, b, c);
  const double m = std::fmax(std::fmax(std::fmax(std::fabs(a.x), std::fabs(a.y)),
                                       std::fmax(std::fabs(b.x), std::fabs(b.y))),
                             std::fmax(std::fabs(c.x), std::fabs(c.y)));
  const mpq_class rx = cx - q(a.x), ry = cy - q(a.y);
  const double radius = std::hypot(rx.get_d(), ry.get_d());
  if (!std::isfinite(radius) || !std::isfinite(v.x) || !std::isfinite(v.y))
    return ::testing::AssertionSuccess();
  checked = true;
  const double tolerance = kCircumcenterTolerance * (m + radius);
  const double errorX = std::fabs(mpq_class(q(v.x) - cx).get_d());
  const double errorY = std::fabs(mpq_class(q(v.y) - cy).get_d());
  if (errorX <= tolerance && errorY <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "centre (" << v.x << ", " << v.y << ") is off by ("
                                       << errorX << ", " << errorY << "), tolerance " << tolerance;
}

TEST(Circumcenter, WithinItsTolerance) {
  testing::Random r(12);
  int checked = 0;
  for (const double scale : {1.0, 0x1p-700, 0x1p+300, 1e-7}) {
    for (const double offset : {0.0, 123456.789, -1e100}) {
      for (int i = 0; i < 2000; ++i) {
        XY a{offset + r.uniform() * scale, offset + r.uniform() * scale};
        XY b{offset + r.uniform() * scale, offset + r.uniform() * scale};
        XY c{offset + r.uniform() * scale, offset + r.uniform() * scale};
        if (i % 3 == 0)
          c = {0.5 * a.x + 0.5 * b.x, std::nextafter(0.5 * a.y + 0.5 * b.y, INFINITY)};
        bool counted = false;
        ASSERT_TRUE(centreWithinTolerance(a, b, c, counted)) << i;
        checked += counted;
      }
    }
  }
  EXPECT_GT(checked, 15000);  // some collapse: offsets that swallow the scale
}

// Triangles far wider than tall, at scales where |d|^2, |e|^2 and d x e are normal doubles but
// the numerators' products (of degree three) underflow: the centre once came out as a corner
// (fuzz_voronoi: sites 1e-108 apart in x, 1e-115 in y, after Lloyd's steps).
TEST(Circumcenter, WithinItsToleranceWhereTheNumeratorsUnderflow) {
  bool counted = false;
  EXPECT_TRUE(centreWithinTolerance({3.9629639294964028e-109, 2.4723453763970394e-115},
                                    {-1.664802838514186e-276, 4.7851845994717875e-116},
                                    {3.9629639294963933e-109, 3.1901230663473527e-116}, counted));
  EXPECT_TRUE(counted);
  testing::Random r(13);
  int checked = 0;
  for (const double tall : {0x1p-380, 0x1p-400, 0x1p-420}) {
    for (int i = 0; i < 2000; ++i) {
      const XY a{r.uniform() * 0x1p-360, r.uniform() * tall};
      const XY b{r.uniform() * 0x1p-360, r.uniform() * tall};
      const XY c{r.uniform() * 0x1p-360, r.uniform() * tall};
      ASSERT_TRUE(centreWithinTolerance(a, b, c, counted)) << i;
      checked += counted;
    }
  }
  EXPECT_GT(checked, 5000);
}

}  // namespace
}  // namespace geocdt
