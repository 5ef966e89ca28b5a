// The predicates against an exact rational oracle, on the doubles actually passed: random,
// near-degenerate, exactly degenerate, tiny to huge, offset, mixed and subnormal inputs.
// Each case is checked through the public filter, the exact path alone, and the big-integer
// path alone, so that a filter deciding most calls cannot hide a bug behind it.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <string>

#include "exact/predicates_bigint.h"
#include "exact/predicates_range.h"
#include "exact/scaled_filters.h"
#include "geocdt/predicates.h"

namespace geocdt {
namespace {

using Rng = std::mt19937_64;
constexpr int kOrientFloor = detail::kOrient2dLsbFloor;
constexpr int kOrientCeiling = detail::kOrient2dExponentCeiling;
constexpr int kIncircleFloor = detail::kIncircleLsbFloor;
constexpr int kIncircleCeiling = detail::kIncircleExponentCeiling;

mpq_class exact(double v) {
  if (v == 0.0) return 0;
  int exponent;
  const double fraction = std::frexp(v, &exponent);  // |fraction| in [0.5, 1)
  mpq_class q(mpz_class(std::ldexp(fraction, 53)));  // an integer below 2^53: exact
  exponent -= 53;
  if (exponent >= 0)
    mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), exponent);
  else
    mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), -exponent);
  return q;
}

Sign sign_of(const mpq_class& q) {
  const int s = sgn(q);
  return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
}

Sign oracle_orient2d(const double* v) {
  const mpq_class ax = exact(v[0]), ay = exact(v[1]), bx = exact(v[2]), by = exact(v[3]);
  const mpq_class cx = exact(v[4]), cy = exact(v[5]);
  return sign_of((ax - cx) * (by - cy) - (ay - cy) * (bx - cx));
}

Sign oracle_incircle(const double* v) {
  const mpq_class dx = exact(v[6]), dy = exact(v[7]);
  const mpq_class adx = exact(v[0]) - dx, ady = exact(v[1]) - dy;
  const mpq_class bdx = exact(v[2]) - dx, bdy = exact(v[3]) - dy;
  const mpq_class cdx = exact(v[4]) - dx, cdy = exact(v[5]) - dy;
  const mpq_class det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                        (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                        (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return sign_of(det);
}

// What a category of cases turned out to contain.
struct Tally {
  int cases = 0, failures = 0, positive = 0, negative = 0, zero = 0;
  int shiftable = 0, too_wide = 0;  // how the exact path had to treat the exponents
  int naive_wrong = 0;              // plain double evaluation gets the sign wrong
};

Sign sign_of(double d) { return d > 0 ? Sign::Positive : (d < 0 ? Sign::Negative : Sign::Zero); }

std::string show(const double* v, int n) {
  std::string s;
  char buffer[40];
  for (int i = 0; i < n; ++i) {
    std::snprintf(buffer, sizeof buffer, "%s%.17g", i ? ", " : "", v[i]);
    s += buffer;
  }
  return s;
}

// One predicate, seen through each of its evaluations.
struct Predicate {
  int n;  // coordinates per call
  Sign (*filtered)(const double*);
  Sign (*exact)(const double*);
  Sign (*bigint)(const double*);
  Sign (*oracle)(const double*);
  double (*naive)(const double*);
  detail::RangeCheck (*range)(const double*);
};

const Predicate kOrient2d = {
    6,
    [](const double* v) { return orient2d(v[0], v[1], v[2], v[3], v[4], v[5]); },
    [](const double* v) { return detail::orient2d_exact(v[0], v[1], v[2], v[3], v[4], v[5]); },
    detail::orient2d_bigint,
    oracle_orient2d,
    [](const double* v) { return (v[0] - v[4]) * (v[3] - v[5]) - (v[1] - v[5]) * (v[2] - v[4]); },
    [](const double* v) { return detail::check_range<kOrientFloor, kOrientCeiling>(v, 6); }};

const Predicate kIncircle = {
    8,
    [](const double* v) { return incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]); },
    [](const double* v) {
      return detail::incircle_exact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
    },
    detail::incircle_bigint,
    oracle_incircle,
    [](const double* v) {
      const double adx = v[0] - v[6], ady = v[1] - v[7], bdx = v[2] - v[6];
      const double bdy = v[3] - v[7], cdx = v[4] - v[6], cdy = v[5] - v[7];
      return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
             (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
             (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
    },
    [](const double* v) { return detail::check_range<kIncircleFloor, kIncircleCeiling>(v, 8); }};

using Maker = std::function<void(Rng&, double*)>;

// Runs count cases from make: every evaluation must agree with the oracle.
Tally check(const Predicate& p, int count, std::uint64_t seed, const Maker& make) {
  Rng rng(seed);
  Tally t;
  double v[8];
  for (int i = 0; i < count; ++i) {
    make(rng, v);
    const Sign expected = p.oracle(v);
    const Sign filtered = p.filtered(v), exact = p.exact(v), bigint = p.bigint(v);
    if ((filtered != expected || exact != expected || bigint != expected) && ++t.failures <= 5) {
      ADD_FAILURE() << "oracle " << static_cast<int>(expected) << ", filtered "
                    << static_cast<int>(filtered) << ", exact " << static_cast<int>(exact)
                    << ", bigint " << static_cast<int>(bigint) << " for " << show(v, p.n);
    }
    ++t.cases;
    t.positive += expected == Sign::Positive;
    t.negative += expected == Sign::Negative;
    t.zero += expected == Sign::Zero;
    t.shiftable += p.range(v).range == detail::Range::Shiftable;
    t.too_wide += p.range(v).range == detail::Range::TooWide;
    t.naive_wrong += sign_of(p.naive(v)) != expected;
  }
  return t;
}

Tally check_orient2d(int count, std::uint64_t seed, const Maker& make) {
  return check(kOrient2d, count, seed, make);
}

Tally check_incircle(int count, std::uint64_t seed, const Maker& make) {
  return check(kIncircle, count, seed, make);
}

// ---- Generators -------------------------------------------------------------------------

double unit(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }  // [0, 1)
double symmetric(Rng& rng) { return 2.0 * unit(rng) - 1.0; }                  // [-1, 1)
int pick(Rng& rng, int n) { return static_cast<int>(rng() % static_cast<std::uint64_t>(n)); }

double nudge(double x, int ulps) {
  for (; ulps > 0; --ulps) x = std::nextafter(x, HUGE_VAL);
  for (; ulps < 0; ++ulps) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

// Any finite double, every exponent equally likely.
double any_finite(Rng& rng) {
  for (;;) {
    const std::uint64_t bits = rng();
    if (((bits >> 52) & 0x7ff) == 0x7ff) continue;
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
}

double subnormal(Rng& rng) {
  const std::uint64_t bits = (rng() & ((std::uint64_t{1} << 52) - 1)) >> pick(rng, 52);
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return rng() & 1 ? -v : v;
}

// Powers of ten from 1e-300 to 1e150: the scaled doubles are rounded, and the oracle judges
// those rounded values.
double power_of_ten_scale(Rng& rng) {
  // Around 1e-160 the products of differences fall into the subnormal range.
  static const int exponents[] = {-300, -250, -200, -163, -161, -158, -155, -150, -100,
                                  -50,  -8,   0,    3,    8,    50,   100,  120,  150};
  return std::pow(10.0, exponents[pick(rng, 18)]);
}

// Three points on a line (c rounded from a point between a and b), c then nudged by a few
// ulps. scale and offset place the configuration.
void near_line(Rng& rng, double* v, double scale, double ox, double oy) {
  const double ax = ox + scale * symmetric(rng), ay = oy + scale * symmetric(rng);
  const double bx = ox + scale * symmetric(rng), by = oy + scale * symmetric(rng);
  const double t = unit(rng) * 2.0 - 0.5;
  double cx = ax + t * (bx - ax), cy = ay + t * (by - ay);
  cx = nudge(cx, pick(rng, 5) - 2);
  cy = nudge(cy, pick(rng, 5) - 2);
  const double p[6] = {ax, ay, bx, by, cx, cy};
  const int rotate = pick(rng, 3);  // the rounded point may be any of the three
  for (int i = 0; i < 6; ++i) v[i] = p[(i + 2 * rotate) % 6];
}

// Four points on a circle, rounded, the last nudged by a few ulps.
void near_circle(Rng& rng, double* v, double scale, double ox, double oy) {
  const double cx = ox + scale * symmetric(rng), cy = oy + scale * symmetric(rng);
  const double r = scale * (0.05 + unit(rng));
  for (int i = 0; i < 4; ++i) {
    const double angle = 6.283185307179586 * unit(rng);
    v[2 * i] = cx + r * std::cos(angle);
    v[2 * i + 1] = cy + r * std::sin(angle);
  }
  v[6] = nudge(v[6], pick(rng, 5) - 2);
  v[7] = nudge(v[7], pick(rng, 5) - 2);
}

// Exactly collinear: p + k * step for small integers k, with p and step of at most 20
// significant bits so that every coordinate is exact, then scaled by 2^shift.
void exact_line(Rng& rng, double* v, int shift) {
  const double px = std::ldexp(static_cast<double>(pick(rng, 1 << 20)) - (1 << 19), -10);
  const double py = std::ldexp(static_cast<double>(pick(rng, 1 << 20)) - (1 << 19), -10);
  const double sx = pick(rng, 2001) - 1000, sy = pick(rng, 2001) - 1000;
  for (int i = 0; i < 3; ++i) {
    const int k = pick(rng, 41) - 20;
    v[2 * i] = std::ldexp(px + k * sx, shift);
    v[2 * i + 1] = std::ldexp(py + k * sy, shift);
  }
}

// Exactly cocircular: four distinct integer points at distance 5, 13, 25 or 65 from an
// integer centre (Pythagorean triples, every sign and swap), then scaled by 2^shift.
void exact_circle(Rng& rng, double* v, int shift, bool centred = false) {
  static const int triples[][3] = {{3, 4, 5},    {5, 12, 13},  {7, 24, 25},  {15, 20, 25},
                                   {16, 63, 65}, {33, 56, 65}, {25, 60, 65}, {39, 52, 65}};
  const auto& t = triples[pick(rng, 8)];
  double points[12][2];
  for (int i = 0; i < 8; ++i) {
    const double x = i & 1 ? -t[0] : t[0], y = i & 2 ? -t[1] : t[1];
    points[i][0] = i & 4 ? y : x;
    points[i][1] = i & 4 ? x : y;
  }
  for (int i = 8; i < 12; ++i) {
    const double r = i & 2 ? -t[2] : t[2];
    points[i][0] = i & 1 ? 0 : r;
    points[i][1] = i & 1 ? r : 0;
  }
  const double ox = centred ? 0 : pick(rng, 1 << 20) - (1 << 19);
  const double oy = centred ? 0 : pick(rng, 1 << 20) - (1 << 19);
  for (int i = 0; i < 4; ++i) {  // a partial shuffle picks four distinct points
    const int j = i + pick(rng, 12 - i);
    std::swap(points[i][0], points[j][0]);
    std::swap(points[i][1], points[j][1]);
    v[2 * i] = std::ldexp(ox + points[i][0], shift);
    v[2 * i + 1] = std::ldexp(oy + points[i][1], shift);
  }
}

// Moves a configuration to (ox, oy); exact when the offsets have room for its low bits.
void translate(double* v, int n, double ox, double oy) {
  for (int i = 0; i < n; i += 2) {
    v[i] += ox;
    v[i + 1] += oy;
  }
}

void nudge_one(Rng& rng, double* v, int n) {
  const int i = pick(rng, n);
  v[i] = nudge(v[i], pick(rng, 2) ? 1 : -1);
}

// A double with a random 30-bit mantissa and a random exponent in [-span, span].
double spread_out(Rng& rng, int span) {
  const double mantissa = static_cast<double>((rng() >> 34) | 1);
  return std::ldexp(rng() & 1 ? -mantissa : mantissa, pick(rng, 2 * span + 1) - span - 30);
}

// Exactly collinear points (q t, p t) on a line through the origin whose parameters t differ
// wildly in magnitude: the coordinate differences round.
void collinear_through_origin(Rng& rng, double* v) {
  const double p = pick(rng, 31) - 15, q = pick(rng, 31) - 15;
  for (int i = 0; i < 3; ++i) {
    const double t = spread_out(rng, 60);
    v[2 * i] = q * t;
    v[2 * i + 1] = p * t;
  }
}

// The corners (x, y), (y, -x), (-x, -y), (-y, x) of a square centred on the origin, in a
// random order: cocircular, and x + y rounds when x and y differ wildly in magnitude.
void rotated_square(Rng& rng, double* v) {
  const double x = spread_out(rng, 60), y = spread_out(rng, 60);
  const double corners[8] = {x, y, y, -x, -x, -y, -y, x};
  int order[4] = {0, 1, 2, 3};
  std::shuffle(order, order + 4, rng);
  for (int i = 0; i < 4; ++i) {
    v[2 * i] = corners[2 * order[i]];
    v[2 * i + 1] = corners[2 * order[i] + 1];
  }
}

void fill(Rng& rng, double* v, int n, const std::function<double(Rng&)>& coordinate) {
  for (int i = 0; i < n; ++i) v[i] = coordinate(rng);
}

// ---- Tests ------------------------------------------------------------------------------

TEST(Predicates, SignConventions) {
  EXPECT_EQ(orient2d(0, 0, 1, 0, 0, 1), Sign::Positive);  // counter-clockwise, y up
  EXPECT_EQ(orient2d(0, 0, 0, 1, 1, 0), Sign::Negative);
  EXPECT_EQ(orient2d(0, 0, 1, 1, 2, 2), Sign::Zero);
  EXPECT_EQ(orient2d(0, 0, 1, 1, 1, 1), Sign::Zero);
  EXPECT_EQ(incircle(1, 0, 0, 1, -1, 0, 0, 0), Sign::Positive);  // centre: inside
  EXPECT_EQ(incircle(1, 0, 0, 1, -1, 0, 0, -1), Sign::Zero);     // on the circle
  EXPECT_EQ(incircle(1, 0, 0, 1, -1, 0, 2, 0), Sign::Negative);  // outside
  EXPECT_EQ(incircle(0, 1, 1, 0, -1, 0, 0, 0), Sign::Negative);  // clockwise a, b, c flips

  // Swapping two points flips the sign; rotating them keeps it.
  Rng rng(7);
  for (int i = 0; i < 2000; ++i) {
    double v[8];
    fill(rng, v, 8, symmetric);
    const Sign o = orient2d(v[0], v[1], v[2], v[3], v[4], v[5]);
    const Sign swapped = orient2d(v[2], v[3], v[0], v[1], v[4], v[5]);
    ASSERT_EQ(static_cast<int>(swapped), -static_cast<int>(o));
    ASSERT_EQ(orient2d(v[2], v[3], v[4], v[5], v[0], v[1]), o);
    const Sign c = incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
    ASSERT_EQ(static_cast<int>(incircle(v[2], v[3], v[0], v[1], v[4], v[5], v[6], v[7])),
              -static_cast<int>(c));
    ASSERT_EQ(incircle(v[2], v[3], v[4], v[5], v[0], v[1], v[6], v[7]), c);
    // The centroid is inside the circumcircle: Positive for a counter-clockwise triangle.
    const double area = (v[0] - v[4]) * (v[3] - v[5]) - (v[1] - v[5]) * (v[2] - v[4]);
    if (std::fabs(area) > 1e-3) {
      const double gx = (v[0] + v[2] + v[4]) / 3, gy = (v[1] + v[3] + v[5]) / 3;
      ASSERT_EQ(incircle(v[0], v[1], v[2], v[3], v[4], v[5], gx, gy), o);
    }
  }
  const double cx = 0.25, cy = -0.5;  // triangle centroid is inside its circumcircle
  EXPECT_EQ(incircle(cx, cy, cx + 3, cy, cx, cy + 2, cx + 1, cy + 0.6), Sign::Positive);
  EXPECT_EQ(incircle(cx, cy, cx, cy + 2, cx + 3, cy, cx + 1, cy + 0.6), Sign::Negative);
}

TEST(Predicates, Random) {
  auto t = check_orient2d(20000, 1, [](Rng& r, double* v) { fill(r, v, 6, symmetric); });
  EXPECT_GT(t.positive, 9000);
  EXPECT_GT(t.negative, 9000);
  t = check_incircle(20000, 2, [](Rng& r, double* v) { fill(r, v, 8, symmetric); });
  EXPECT_GT(t.positive, 5000);
  EXPECT_GT(t.negative, 5000);
}

TEST(Predicates, NearDegenerateAcrossPowersOfTen) {
  auto line = [](Rng& r, double* v) { near_line(r, v, power_of_ten_scale(r), 0, 0); };
  auto t = check_orient2d(30000, 3, line);
  EXPECT_GT(t.naive_wrong, 3000);
  EXPECT_GT(t.positive, 5000);
  EXPECT_GT(t.negative, 5000);
  EXPECT_GT(t.shiftable, 1000);  // 1e-300 and 1e150 need scaling
  auto circle = [](Rng& r, double* v) { near_circle(r, v, power_of_ten_scale(r), 0, 0); };
  t = check_incircle(20000, 4, circle);
  EXPECT_GT(t.positive, 3000);
  EXPECT_GT(t.negative, 3000);
  EXPECT_GT(t.shiftable, 3000);
}

TEST(Predicates, NearDegenerateAtLargeOffsets) {
  // Web-mercator metres (x ~ 1.6e7, sub-metre spacing) and lon/lat degrees (1e-7 spacing).
  struct Place {
    double x, y;
    int shift;  // the spacing of the exact configurations: 2^shift
  };
  const Place places[] = {
      {1.6e7, -4.2e6, -4}, {13.404954, 52.520008, -30}, {-122.4194, 37.7749, -30}};
  std::uint64_t seed = 100;
  for (const Place& p : places) {
    const double scale = std::ldexp(1.0, p.shift + 3);
    auto t =
        check_orient2d(5000, ++seed, [&](Rng& r, double* v) { near_line(r, v, scale, p.x, p.y); });
    EXPECT_GT(t.positive, 1000);
    EXPECT_GT(t.negative, 1000);
    t = check_orient2d(5000, ++seed, [&](Rng& r, double* v) {
      exact_line(r, v, p.shift);
      translate(v, 6, p.x, p.y);
    });
    EXPECT_EQ(t.zero, t.cases);
    t = check_orient2d(5000, ++seed, [&](Rng& r, double* v) {
      exact_line(r, v, p.shift);
      translate(v, 6, p.x, p.y);
      nudge_one(r, v, 6);
    });
    EXPECT_GT(t.positive, 1000);
    EXPECT_GT(t.negative, 1000);
    t = check_incircle(5000, ++seed,
                       [&](Rng& r, double* v) { near_circle(r, v, scale, p.x, p.y); });
    EXPECT_GT(t.positive, 1000);
    EXPECT_GT(t.negative, 1000);
    t = check_incircle(5000, ++seed, [&](Rng& r, double* v) {
      exact_circle(r, v, p.shift);
      translate(v, 8, p.x, p.y);
    });
    EXPECT_EQ(t.zero, t.cases);
    t = check_incircle(5000, ++seed, [&](Rng& r, double* v) {
      exact_circle(r, v, p.shift);
      translate(v, 8, p.x, p.y);
      nudge_one(r, v, 8);
    });
    EXPECT_GT(t.positive, 1000);
    EXPECT_GT(t.negative, 1000);
  }
}

TEST(Predicates, ExactlyDegenerateAtPowersOfTwo) {
  // Shifts from the subnormal range up to near the top of the doubles.
  auto shift = [](Rng& r) { return pick(r, 1850) - 1030; };
  auto t = check_orient2d(20000, 9, [&](Rng& r, double* v) { exact_line(r, v, shift(r)); });
  EXPECT_EQ(t.zero, t.cases);
  EXPECT_GT(t.shiftable, 5000);
  t = check_incircle(20000, 10, [&](Rng& r, double* v) { exact_circle(r, v, shift(r)); });
  EXPECT_EQ(t.zero, t.cases);
  EXPECT_GT(t.shiftable, 5000);
  // Then one point moved by an ulp: never zero any more.
  t = check_orient2d(10000, 11, [&](Rng& r, double* v) {
    exact_line(r, v, shift(r));
    nudge_one(r, v, 6);
  });
  EXPECT_GT(t.positive, 3000);
  EXPECT_GT(t.negative, 3000);
  t = check_incircle(10000, 12, [&](Rng& r, double* v) {
    exact_circle(r, v, shift(r));
    nudge_one(r, v, 8);
  });
  EXPECT_EQ(t.zero, 0);
}

// Lattice points (pixels, tile coordinates): integers below 2^25 take a shortcut past the
// expansions when their determinant was exact in doubles. Small grids make many cocircular and
// collinear cases; wide ones reach the bound where the permanent passes 2^53 and the shortcut
// must give way.
TEST(Predicates, SmallIntegerLattices) {
  for (const int range : {4, 64, 1 << 12, 1 << 20, (1 << 25) - 1}) {
    SCOPED_TRACE(range);
    const auto lattice = [range](Rng& r) {
      return static_cast<double>(pick(r, 2 * range + 1)) - range;
    };
    auto t =
        check_orient2d(20000, 40 + range % 7, [&](Rng& r, double* v) { fill(r, v, 6, lattice); });
    if (range == 4) EXPECT_GT(t.zero, 1000);
    t = check_incircle(20000, 50 + range % 7, [&](Rng& r, double* v) { fill(r, v, 8, lattice); });
    if (range == 4) EXPECT_GT(t.zero, 1000);
    // Exactly cocircular, and then one point moved by one.
    t = check_incircle(5000, 60, [&](Rng& r, double* v) { exact_circle(r, v, 0); });
    EXPECT_EQ(t.zero, t.cases);
    t = check_incircle(5000, 61, [&](Rng& r, double* v) {
      exact_circle(r, v, 0);
      v[pick(r, 8)] += pick(r, 2) ? 1 : -1;
    });
    EXPECT_EQ(t.zero, 0);
  }
}

TEST(Predicates, ExactlyDegenerateWithRoundedDifferences) {
  auto t = check_orient2d(20000, 25, collinear_through_origin);
  EXPECT_EQ(t.zero, t.cases);
  EXPECT_GT(t.naive_wrong, 2000);
  t = check_incircle(20000, 26, rotated_square);
  EXPECT_EQ(t.zero, t.cases);
  EXPECT_GT(t.naive_wrong, 5000);
  t = check_orient2d(10000, 27, [](Rng& r, double* v) {
    collinear_through_origin(r, v);
    nudge_one(r, v, 6);
  });
  EXPECT_GT(t.positive, 3000);
  EXPECT_GT(t.negative, 3000);
  t = check_incircle(10000, 28, [](Rng& r, double* v) {
    rotated_square(r, v);
    nudge_one(r, v, 8);
  });
  EXPECT_GT(t.positive, 3000);
  EXPECT_GT(t.negative, 3000);
}

TEST(Predicates, MixedMagnitudesInOneCall) {
  auto mixed = [](Rng& r) {
    static const double magnitudes[] = {1e150, 1e-300, 1.0, 3e-310, 1e100, 1e-150, 0.0};
    return magnitudes[pick(r, 7)] * symmetric(r);
  };
  auto t = check_orient2d(20000, 13, [&](Rng& r, double* v) { fill(r, v, 6, mixed); });
  EXPECT_GT(t.too_wide, 5000);
  t = check_incircle(20000, 14, [&](Rng& r, double* v) { fill(r, v, 8, mixed); });
  EXPECT_GT(t.too_wide, 5000);
  // Nearly collinear and cocircular triples with one far outlier or a tiny coordinate.
  t = check_orient2d(10000, 15, [](Rng& r, double* v) {
    near_line(r, v, 1.0, 0, 0);
    v[pick(r, 6)] = pick(r, 2) ? 1e-300 * symmetric(r) : subnormal(r);
  });
  EXPECT_GT(t.too_wide, 5000);
  t = check_incircle(10000, 16, [](Rng& r, double* v) {
    exact_circle(r, v, 0, true);
    v[pick(r, 8)] += pick(r, 2) ? 1e-200 : -1e-300;  // rounds away except at zero
  });
  EXPECT_GT(t.too_wide, 1000);
  EXPECT_GT(t.zero, 5000);
}

// Points in columns far apart, as fuzz_strips once made 33,000 of them (seed 7108): every call
// spans too many binades for the expansions. Most only overflowed the filter, which decides
// them on the differences scaled by a power of two; the nearly cocircular ones and the
// rectangles (exactly cocircular) go to the big integers.
TEST(Predicates, ColumnsFarApart) {
  // Columns 1e131 apart, points along them about 1e2 apart, a few with y near 1e-240; a
  // quarter of the cases are rectangles across two columns.
  const auto columns = [](Rng& r, double* v) {
    const auto y = [&r] { return pick(r, 10) ? 1000 * symmetric(r) : 1e-240 * symmetric(r); };
    for (int i = 0; i < 4; ++i) {
      v[2 * i] = 7.5464049804045463e+131 * pick(r, 4);
      v[2 * i + 1] = y();
    }
    if (pick(r, 4) == 0) {
      const double left = v[0], right = v[2] == v[0] ? 2 * v[0] + 1e131 : v[2];
      const double low = v[1], high = v[3];
      const double corners[8] = {left, low, right, low, right, high, left, high};
      const int turn = pick(r, 4);  // which corner comes first
      for (int i = 0; i < 8; ++i) v[i] = corners[(i + 2 * turn) % 8];
    }
  };
  auto t = check_incircle(20000, 41, columns);
  EXPECT_GT(t.too_wide, 15000);
  EXPECT_GT(t.zero, 2000);
  // Columns 1e150 apart with y near 1e-150: orient2d spans too wide.
  const auto far = [](Rng& r, double* v) {
    for (int i = 0; i < 3; ++i) {
      v[2 * i] = 1e150 * pick(r, 3);
      v[2 * i + 1] = 1e-150 * symmetric(r);
    }
  };
  auto o = check_orient2d(20000, 42, far);
  EXPECT_GT(o.too_wide, 15000);
  // The scaled filters alone: each sign they give is the oracle's, and they give most.
  Rng rng(43);
  double v[8];
  int decided = 0, wrong = 0, cocircular = 0, cocircular_decided = 0;
  for (int i = 0; i < 20000; ++i) {
    columns(rng, v);
    const Sign scaled = detail::incircle_scaled_filter(v), expected = oracle_incircle(v);
    decided += scaled != Sign::Zero;
    wrong += scaled != Sign::Zero && scaled != expected;
    if (expected == Sign::Zero) {
      ++cocircular;
      cocircular_decided += scaled != Sign::Zero;
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(decided, 8000);
  EXPECT_GT(cocircular, 2000);
  EXPECT_EQ(cocircular_decided, 0);
  decided = 0;
  for (int i = 0; i < 20000; ++i) {
    far(rng, v);
    const Sign scaled = detail::orient2d_scaled_filter(v);
    decided += scaled != Sign::Zero;
    wrong += scaled != Sign::Zero && scaled != oracle_orient2d(v);
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(decided, 15000);
}

TEST(Predicates, SubnormalsAndZeros) {
  auto t = check_orient2d(20000, 17, [](Rng& r, double* v) { fill(r, v, 6, subnormal); });
  EXPECT_GT(t.positive, 5000);
  t = check_incircle(20000, 18, [](Rng& r, double* v) { fill(r, v, 8, subnormal); });
  EXPECT_GT(t.positive, 5000);
  // Zeros of both signs with small integers and subnormals: many exact degeneracies.
  auto sparse = [](Rng& r) {
    switch (pick(r, 4)) {
      case 0: return 0.0;
      case 1: return -0.0;
      case 2: return static_cast<double>(pick(r, 5) - 2);
      default: return std::numeric_limits<double>::denorm_min() * (pick(r, 5) - 2);
    }
  };
  t = check_orient2d(20000, 19, [&](Rng& r, double* v) { fill(r, v, 6, sparse); });
  EXPECT_GT(t.zero, 2000);
  t = check_incircle(20000, 20, [&](Rng& r, double* v) { fill(r, v, 8, sparse); });
  EXPECT_GT(t.zero, 2000);
  EXPECT_EQ(orient2d(-0.0, 0.0, 0.0, -0.0, -0.0, -0.0), Sign::Zero);
  EXPECT_EQ(incircle(0.0, -0.0, -0.0, 0.0, 0.0, 0.0, -0.0, -0.0), Sign::Zero);
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(orient2d(0, 0, tiny, 0, 0, tiny), Sign::Positive);
  EXPECT_EQ(incircle(tiny, 0, 0, tiny, -tiny, 0, 0, 0), Sign::Positive);
  EXPECT_EQ(incircle(tiny, 0, 0, tiny, -tiny, 0, 0, -tiny), Sign::Zero);
}

TEST(Predicates, SharedCoordinates) {
  // Points on a common parallel or meridian, and points sharing one coordinate with another:
  // both products are then exactly zero, or only one is, with differences that round.
  auto share = [](Rng& r, double* v, const std::function<double(Rng&)>& coordinate) {
    fill(r, v, 6, coordinate);
    const int left = pick(r, 3), right = pick(r, 3);  // which factor of each product is 0
    if (left == 0) v[0] = v[4];                       // ax == cx
    if (left == 1) v[3] = v[5];                       // by == cy
    if (right == 0) v[1] = v[5];                      // ay == cy
    if (right == 1) v[2] = v[4];                      // bx == cx
  };
  auto t = check_orient2d(20000, 29, [&](Rng& r, double* v) { share(r, v, any_finite); });
  EXPECT_GT(t.zero, 5000);
  EXPECT_GT(t.positive + t.negative, 5000);
  t = check_orient2d(20000, 30, [&](Rng& r, double* v) { share(r, v, subnormal); });
  EXPECT_GT(t.zero, 5000);
  EXPECT_GT(t.positive + t.negative, 5000);
  // Near-collinear triples with one coordinate shared: the other product decides alone.
  t = check_orient2d(20000, 31, [&](Rng& r, double* v) {
    near_line(r, v, 1e6, 12.5, -7.25);
    v[pick(r, 2) ? 3 : 0] = pick(r, 2) ? v[5] : v[4];
  });
  EXPECT_GT(t.positive, 3000);
  EXPECT_GT(t.negative, 3000);
}

TEST(Predicates, AnyFiniteDouble) {
  // Beyond kMaxCoordinate too: every exponent from subnormal to 1.8e308.
  auto t = check_orient2d(20000, 21, [](Rng& r, double* v) { fill(r, v, 6, any_finite); });
  EXPECT_GT(t.too_wide, 10000);
  t = check_incircle(10000, 22, [](Rng& r, double* v) { fill(r, v, 8, any_finite); });
  EXPECT_GT(t.too_wide, 5000);
  // Near-degenerate configurations at the very top of the range overflow any naive
  // evaluation, even of the differences.
  t = check_orient2d(5000, 23, [](Rng& r, double* v) { near_line(r, v, 4e307, 0, 0); });
  EXPECT_GT(t.shiftable, 4000);
  t = check_incircle(5000, 24, [](Rng& r, double* v) { near_circle(r, v, 4e307, 0, 0); });
  EXPECT_GT(t.shiftable, 4000);
}

TEST(Predicates, NonFiniteInputsGiveZero) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(orient2d(0, 0, inf, 0, 0, 1), Sign::Zero);
  EXPECT_EQ(orient2d(0, 0, nan, 0, 0, 1), Sign::Zero);
  EXPECT_EQ(incircle(1, 0, 0, 1, -1, 0, nan, 0), Sign::Zero);
  EXPECT_EQ(incircle(1, 0, 0, 1, -inf, 0, 0, 0), Sign::Zero);
}

}  // namespace
}  // namespace geocdt
