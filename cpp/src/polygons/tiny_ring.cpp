#include "polygons/tiny_ring.h"

#include "geocdt/predicates.h"

namespace geocdt {

namespace {

bool same(const double* xy, std::uint32_t i, std::uint32_t j) {
  return xy[2 * i] == xy[2 * j] && xy[2 * i + 1] == xy[2 * j + 1];
}

Sign turn(const double* xy, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  return orient2d(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], xy[2 * c], xy[2 * c + 1]);
}

void emit(std::vector<std::uint32_t>& out, std::uint32_t base, std::uint32_t a, std::uint32_t b,
          std::uint32_t c) {
  out.push_back(base + a);
  out.push_back(base + b);
  out.push_back(base + c);
}

}  // namespace

bool triangulateTinyRing(const double* xy, std::uint32_t n, std::uint32_t base,
                         std::vector<std::uint32_t>& out) {
  if (n > 5) return false;
  // The distinct corners in ring order; a repeat is allowed only next to itself.
  std::uint32_t v[5];
  std::uint32_t m = 0;
  for (std::uint32_t k = 0; k < n; ++k) {
    if (m > 0 && same(xy, k, v[m - 1])) continue;
    v[m++] = k;
  }
  if (m > 1 && same(xy, v[m - 1], v[0])) --m;  // closed
  if (m > 4) return false;
  for (std::uint32_t i = 0; i < m; ++i)
    for (std::uint32_t j = i + 1; j < m; ++j)
      if (same(xy, v[i], v[j])) return false;
  if (m < 3) return true;  // a point or a segment: nothing inside
  if (m == 3) {
    const Sign o = turn(xy, v[0], v[1], v[2]);
    if (o == Sign::Positive) emit(out, base, v[0], v[1], v[2]);
    if (o == Sign::Negative) emit(out, base, v[0], v[2], v[1]);
    return true;  // collinear: no area
  }
  // Four corners: the sign of the turn at each. All alike: convex; three alike: concave at
  // the fourth; two and two: the ring crosses itself (a bow tie); a zero: collinear corners.
  Sign s[4];
  int positive = 0;
  for (int i = 0; i < 4; ++i) {
    s[i] = turn(xy, v[(i + 3) % 4], v[i], v[(i + 1) % 4]);  // at corner i
    if (s[i] == Sign::Zero) return false;
    positive += s[i] == Sign::Positive;
  }
  if (positive == 2) return false;
  if (positive < 2) {  // clockwise: the same corners counter-clockwise
    const std::uint32_t w[4] = {v[0], v[3], v[2], v[1]};
    const Sign t[4] = {s[0], s[3], s[2], s[1]};
    for (int i = 0; i < 4; ++i) {
      v[i] = w[i];
      s[i] = t[i] == Sign::Positive ? Sign::Negative : Sign::Positive;
    }
  }
  int r = 0;  // the reflex corner, or the diagonal's end for a convex quad
  for (int i = 0; i < 4; ++i)
    if (s[i] == Sign::Negative) r = i;
  if (positive == 4 || positive == 0) {
    // Convex: the diagonal 0-2 unless corner 3 lies inside the circle through 0, 1, 2.
    const double* p = xy;
    const Sign in = incircle(p[2 * v[0]], p[2 * v[0] + 1], p[2 * v[1]], p[2 * v[1] + 1],
                             p[2 * v[2]], p[2 * v[2] + 1], p[2 * v[3]], p[2 * v[3] + 1]);
    r = in == Sign::Positive ? 1 : 0;
  }
  const std::uint32_t a = v[r], b = v[(r + 1) % 4], c = v[(r + 2) % 4], d = v[(r + 3) % 4];
  emit(out, base, a, b, c);
  emit(out, base, c, d, a);
  return true;
}

}  // namespace geocdt
