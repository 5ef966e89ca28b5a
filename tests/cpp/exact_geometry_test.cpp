// The exact decisions of snap rounding against GMP rationals, on coordinates from subnormal
// to 1e150 and on the cases that sit exactly on a boundary.
#include "exact/exact_geometry.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "exact/euclidean_norm.h"
#include "point_generators.h"

namespace geocdt {
namespace {

mpq_class q(double v) { return mpq_class(v); }

// The crossing of the lines of s and t, exactly.
void exactCrossing(const InputSegment& s, const InputSegment& t, mpq_class& x, mpq_class& y) {
  const mpq_class dx = q(s.bx) - q(s.ax), dy = q(s.by) - q(s.ay);
  const mpq_class fx = q(t.bx) - q(t.ax), fy = q(t.by) - q(t.ay);
  const mpq_class along =
      ((q(t.ax) - q(s.ax)) * fy - (q(t.ay) - q(s.ay)) * fx) / (dx * fy - dy * fx);
  x = q(s.ax) + along * dx;
  y = q(s.ay) + along * dy;
}

// Whether v lies in c's rounding interval [(c + below) / 2, (c + above) / 2).
bool inInterval(const mpq_class& v, double c) {
  const mpq_class lo = (q(c) + q(std::nextafter(c, -INFINITY))) / 2;
  const mpq_class hi = (q(c) + q(std::nextafter(c, INFINITY))) / 2;
  return lo <= v && v < hi;
}

// Coordinates of every kind: small integers, fractions, huge, tiny and subnormal values,
// and values a few ulps from each other.
class Coordinates {
 public:
  explicit Coordinates(std::uint64_t seed) : r_(seed) {}
  double next() {
    static const double kOffsets[] = {0, 1, -12345.678, 16777216, 1e100, 1e-300, 3e-320, -7e149};
    const double offset = kOffsets[r_.next() % 8];
    switch (r_.next() % 4) {
      case 0: return offset + double(int(r_.next() % 9) - 4);
      case 1: {
        double v = offset;
        for (int k = int(r_.next() % 7); k > 0; --k)
          v = std::nextafter(v, r_.next() % 2 ? 1e300 : -1e300);
        return v;
      }
      case 2: return offset * (1 + (r_.uniform() - 0.5) * 1e-9);
      default: return std::ldexp(r_.uniform() - 0.5, int(r_.next() % 900) - 600);
    }
  }
  InputSegment segment() { return {next(), next(), next(), next()}; }

 private:
  testing::Random r_;
};

TEST(ExactGeometry, RoundedCrossingHoldsTheExactCrossing) {
  Coordinates c(1);
  int checked = 0;
  for (int i = 0; i < 20000 && checked < 3000; ++i) {
    const InputSegment s = c.segment(), t = c.segment();
    const mpq_class den =
        (q(s.bx) - q(s.ax)) * (q(t.by) - q(t.ay)) - (q(s.by) - q(s.ay)) * (q(t.bx) - q(t.ax));
    if (den == 0) continue;
    mpq_class x, y;
    exactCrossing(s, t, x, y);
    // The crossing must lie within s's box for the rounding to search there.
    if (x < q(std::min(s.ax, s.bx)) || x > q(std::max(s.ax, s.bx)) || y < q(std::min(s.ay, s.by)) ||
        y > q(std::max(s.ay, s.by)))
      continue;
    double rx, ry;
    roundedCrossing(s, t, rx, ry);
    EXPECT_TRUE(inInterval(x, rx)) << s.ax << " " << s.ay << " " << s.bx << " " << s.by;
    EXPECT_TRUE(inInterval(y, ry));
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(ExactGeometry, RoundedLineCrossingIsTheNearestDoubleOrRefused) {
  // The crossing that segment insertion computes: the nearest double on each axis where the
  // lines cross within s's box, false where they are parallel or cross outside it.
  Coordinates c(2);
  int inside = 0, outside = 0, parallel = 0;
  for (int i = 0; i < 3000; ++i) {
    InputSegment s = c.segment(), t = c.segment();
    if (i % 20 == 0) t = {2 * s.ax, 2 * s.ay, 2 * s.bx, 2 * s.by};  // parallel
    const mpq_class den =
        (q(s.bx) - q(s.ax)) * (q(t.by) - q(t.ay)) - (q(s.by) - q(s.ay)) * (q(t.bx) - q(t.ax));
    double rx = 0, ry = 0;
    const bool found = roundedLineCrossing(s, t, rx, ry);
    if (den == 0) {
      EXPECT_FALSE(found);
      ++parallel;
      continue;
    }
    mpq_class x, y;
    exactCrossing(s, t, x, y);
    const bool inBox = x >= q(std::min(s.ax, s.bx)) && x <= q(std::max(s.ax, s.bx)) &&
                       y >= q(std::min(s.ay, s.by)) && y <= q(std::max(s.ay, s.by));
    if (inBox) {
      ASSERT_TRUE(found) << s.ax << " " << s.ay << " " << s.bx << " " << s.by;
      EXPECT_TRUE(inInterval(x, rx));
      EXPECT_TRUE(inInterval(y, ry));
      ++inside;
    } else if (found) {
      // Only just outside: within the rounding intervals of the box's ends.
      EXPECT_TRUE(inInterval(x, rx));
      EXPECT_TRUE(inInterval(y, ry));
    } else {
      ++outside;
    }
  }
  EXPECT_GT(inside, 500);
  EXPECT_GT(outside, 500);
  EXPECT_GT(parallel, 100);
}

TEST(ExactGeometry, EuclideanNormWithinTwoUlps) {
  Coordinates c(3);
  for (int i = 0; i < 20000; ++i) {
    const double x = c.next(), y = c.next();
    const double norm = euclideanNorm(x, y), reference = std::hypot(x, y);
    EXPECT_LE(std::fabs(norm - reference), 2 * spacingAt(reference)) << x << " " << y;
  }
  EXPECT_EQ(euclideanNorm(0, 0), 0);
  EXPECT_EQ(euclideanNorm(-3, 4), 5);
  EXPECT_EQ(euclideanNorm(INFINITY, 1), INFINITY);
  EXPECT_EQ(euclideanNorm(1e300, 1e300), std::hypot(1e300, 1e300));
}

TEST(ExactGeometry, HalfwayCrossingsRoundUp) {
  // Above 2^53 the doubles are the even integers: a crossing at 2^53 + 1 lies halfway
  // between two of them and rounds up, to 2^53 + 2; at -2^53 - 1 it rounds up to -2^53.
  const double big = 0x1p53;
  double x, y;
  roundedCrossing({big - 2, -1, big + 4, 1}, {big - 8, 0, big + 8, 0}, x, y);
  EXPECT_EQ(x, big + 2);
  EXPECT_EQ(y, 0);
  roundedCrossing({-big - 4, -1, -big + 2, 1}, {-big - 8, 0, -big + 8, 0}, x, y);
  EXPECT_EQ(x, -big);
}

// The exact cell test: the segment meets [(x + below) / 2, (x + above) / 2) on each axis.
bool meetsCellExactly(const InputSegment& s, double x, double y) {
  const mpq_class lo[2] = {(q(x) + q(std::nextafter(x, -INFINITY))) / 2,
                           (q(y) + q(std::nextafter(y, -INFINITY))) / 2};
  const mpq_class hi[2] = {(q(x) + q(std::nextafter(x, INFINITY))) / 2,
                           (q(y) + q(std::nextafter(y, INFINITY))) / 2};
  const mpq_class a[2] = {q(s.ax), q(s.ay)}, d[2] = {q(s.bx) - q(s.ax), q(s.by) - q(s.ay)};
  // t ranges over [from, to] with open flags.
  mpq_class from = 0, to = 1;
  bool fromOpen = false, toOpen = false;
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0) {
      if (!(lo[k] <= a[k] && a[k] < hi[k])) return false;
      continue;
    }
    mpq_class t0 = (lo[k] - a[k]) / d[k], t1 = (hi[k] - a[k]) / d[k];
    bool open0 = false, open1 = true;
    if (d[k] < 0) {
      std::swap(t0, t1);
      std::swap(open0, open1);
    }
    if (t0 > from || (t0 == from && open0)) from = t0, fromOpen = open0;
    if (t1 < to || (t1 == to && open1)) to = t1, toOpen = open1;
  }
  return from < to || (from == to && !fromOpen && !toOpen);
}

TEST(ExactGeometry, SegmentMeetsCellAgreesWithRationals) {
  Coordinates c(2);
  testing::Random r(3);
  int met = 0, missed = 0;
  for (int i = 0; i < 20000; ++i) {
    const InputSegment s = c.segment();
    // A point near the segment: on it, rounded, or a few ulps away.
    const double t = r.uniform();
    double x = s.ax + t * (s.bx - s.ax), y = s.ay + t * (s.by - s.ay);
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    for (int k = int(r.next() % 4); k > 0; --k)
      x = std::nextafter(x, r.next() % 2 ? 1e300 : -1e300);
    const bool expected = meetsCellExactly(s, x, y);
    ASSERT_EQ(segmentMeetsCell(s, x, y), expected)
        << s.ax << " " << s.ay << " " << s.bx << " " << s.by << " at " << x << " " << y;
    (expected ? met : missed) += 1;
  }
  EXPECT_GT(met, 1000);
  EXPECT_GT(missed, 1000);
}

TEST(ExactGeometry, CellsAreHalfOpen) {
  // Above 2^53 the doubles are the even integers: the cell of (2^53 + 2, 2^53 + 2) is
  // [2^53 + 1, 2^53 + 3) on each axis. Segments that touch it at one corner only: the lower
  // one belongs to it, the others do not.
  const double big = 0x1p53, c = big + 2;
  EXPECT_TRUE(segmentMeetsCell({big - 2, big + 4, big + 2, big}, c, c));       // (b+1, b+1)
  EXPECT_FALSE(segmentMeetsCell({big + 2, big + 4, big + 4, big + 2}, c, c));  // (b+3, b+3)
  EXPECT_FALSE(segmentMeetsCell({big, big + 2, big + 2, big + 4}, c, c));      // (b+1, b+3)
  EXPECT_FALSE(segmentMeetsCell({big + 2, big, big + 4, big + 2}, c, c));      // (b+3, b+1)
  // At a binade's start the cell reaches half as far down: (2^53, 2^53) owns
  // [2^53 - 1/2, 2^53 + 1) on each axis, so its lower corner is (2^53 - 1/2, 2^53 - 1/2).
  EXPECT_TRUE(segmentMeetsCell({big - 1, big, big, big - 1}, big, big));
  EXPECT_FALSE(segmentMeetsCell({big - 2, big, big, big - 2}, big, big));
  // Subnormal cells: half the smallest double is not a double, but a cell size.
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_TRUE(segmentMeetsCell({-tiny, -tiny, tiny, tiny}, 0, 0));
  EXPECT_FALSE(segmentMeetsCell({tiny, -tiny, tiny, tiny}, 0, 0));
}

TEST(ExactGeometry, DistanceAndOrderAgreeWithRationals) {
  Coordinates c(4);
  testing::Random r(5);
  for (int i = 0; i < 20000; ++i) {
    const InputSegment s = c.segment();
    const double px = c.next(), py = c.next();
    double qx = px, qy = py;
    for (int k = int(r.next() % 3); k > 0; --k)
      qx = std::nextafter(qx, r.next() % 2 ? 1e300 : -1e300);
    if (r.next() % 2) qy = c.next();
    const mpq_class dot =
        (q(qx) - q(px)) * (q(s.bx) - q(s.ax)) + (q(qy) - q(py)) * (q(s.by) - q(s.ay));
    ASSERT_EQ(signAlong(s, px, py, qx, qy), sgn(dot));

    // Distance to a point near the segment, against 2^e around its true distance.
    const double t = r.uniform();
    double x = s.ax + t * (s.bx - s.ax), y = s.ay + t * (s.by - s.ay);
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    for (int k = int(r.next() % 5); k > 0; --k)
      y = std::nextafter(y, r.next() % 2 ? 1e300 : -1e300);
    const mpq_class dx = q(s.bx) - q(s.ax), dy = q(s.by) - q(s.ay), wx = q(x) - q(s.ax),
                    wy = q(y) - q(s.ay);
    const mpq_class along = wx * dx + wy * dy, length2 = dx * dx + dy * dy;
    mpq_class d2;
    if (along <= 0) {
      d2 = wx * wx + wy * wy;
    } else if (along >= length2) {
      d2 = (q(x) - q(s.bx)) * (q(x) - q(s.bx)) + (q(y) - q(s.by)) * (q(y) - q(s.by));
    } else {
      const mpq_class cross = dx * wy - dy * wx;
      d2 = cross * cross / length2;
    }
    int e = spacingExponent(
                std::max({std::fabs(s.ax), std::fabs(s.ay), std::fabs(s.bx), std::fabs(s.by)})) +
            int(r.next() % 5) - 2;
    const mpq_class bound =
        e >= 0 ? mpq_class(mpz_class(1) << e) : mpq_class(1, mpz_class(1) << -e);
    ASSERT_EQ(withinDistance(s, x, y, e), d2 <= bound * bound) << x << " " << y << " e " << e;
  }
}

// The squared distance from (x, y) to the closed segment s, exactly.
mpq_class distance2(const InputSegment& s, double x, double y) {
  const mpq_class dx = q(s.bx) - q(s.ax), dy = q(s.by) - q(s.ay), wx = q(x) - q(s.ax),
                  wy = q(y) - q(s.ay);
  const mpq_class along = wx * dx + wy * dy, length2 = dx * dx + dy * dy;
  if (along <= 0) return wx * wx + wy * wy;
  if (along >= length2) {
    const mpq_class vx = q(x) - q(s.bx), vy = q(y) - q(s.by);
    return vx * vx + vy * vy;
  }
  const mpq_class cross = dx * wy - dy * wx;
  return cross * cross / length2;
}

TEST(ExactGeometry, DistanceToTheChainsBoundOfPointsComputedOnSegments) {
  // What refinement asks: whether a point computed on a segment (one rounding per
  // coordinate, then nudged a few doubles) lies within the chains' bound, two spacings at
  // the segment's largest coordinate. The distances are a few spacings, like the bound:
  // short segments far from the origin (borders in degrees), long ones (a box around the
  // data), along an axis and not, and ends a spacing or two apart.
  testing::Random r(6);
  int within = 0, beyond = 0;
  for (int i = 0; i < 40000; ++i) {
    const double scale = std::ldexp(1.0, int(r.next() % 40) - 10);
    const double cx = (r.uniform() - 0.5) * 360 * scale, cy = (r.uniform() - 0.5) * 180 * scale;
    const double length = scale * std::ldexp(r.uniform(), -int(r.next() % 30));
    const double angle = r.uniform() * 6.283185307179586;
    InputSegment s{cx, cy, cx + length * std::cos(angle), cy + length * std::sin(angle)};
    switch (r.next() % 4) {
      case 0: s.by = s.ay; break;  // along an axis
      case 1: s.bx = s.ax; break;
      case 2:  // ends a few doubles apart
        s.bx = std::nextafter(s.ax, r.next() % 2 ? 1e300 : -1e300);
        if (r.next() % 2) s.by = std::nextafter(s.ay, r.next() % 2 ? 1e300 : -1e300);
        break;
      default: break;
    }
    const double t = r.next() % 8 == 0 ? 0.5 : r.uniform();
    double x = (1 - t) * s.ax + t * s.bx, y = (1 - t) * s.ay + t * s.by;
    for (int k = int(r.next() % 6); k > 0; --k) {
      double& v = r.next() % 2 ? x : y;
      v = std::nextafter(v, r.next() % 2 ? 1e300 : -1e300);
    }
    const int e = chainBoundExponent(s) + int(r.next() % 3) - 1;
    const mpq_class bound =
        e >= 0 ? mpq_class(mpz_class(1) << e) : mpq_class(1, mpz_class(1) << -e);
    const bool exact = distance2(s, x, y) <= bound * bound;
    ASSERT_EQ(withinDistance(s, x, y, e), exact)
        << s.ax << " " << s.ay << " " << s.bx << " " << s.by << " " << x << " " << y << " e " << e;
    ++(exact ? within : beyond);
  }
  EXPECT_GT(within, 10000);
  EXPECT_GT(beyond, 2000);
}

}  // namespace
}  // namespace geocdt
