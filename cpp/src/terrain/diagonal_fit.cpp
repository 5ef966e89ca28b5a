#include "terrain/diagonal_fit.h"

#include <algorithm>
#include <cmath>

namespace geocdt::terrain {

namespace {

// Twice the signed area of (u, v, (x, y)): positive when (x, y) is left of u -> v.
double leftOf(const Corner& u, const Corner& v, double x, double y) {
  return (v.x - u.x) * (y - u.y) - (v.y - u.y) * (x - u.x);
}

// A triangle's plane, made when a pixel first needs it.
class LazyPlane {
 public:
  LazyPlane(const Corner& u, const Corner& v, const Corner& w) : u_(u), v_(v), w_(w) {}
  // False when the triangle is flat.
  bool at(double x, double y, double& z) {
    if (state_ == 0) state_ = planeOf(u_, v_, w_, plane_) ? 1 : -1;
    z = plane_.at(x, y);
    return state_ > 0;
  }

 private:
  const Corner &u_, &v_, &w_;
  Plane plane_{};
  int state_ = 0;  // 0 not made yet, 1 made, -1 flat
};

// Sides of a convex polygon that bound its rows' pixels from one side: side k crosses row y
// at x[k] + (y - y[k]) run[k].
struct Chain {
  double x[4], y[4], run[4];
  int sides = 0;
  void add(const Corner& u, const Corner& v) {
    x[sides] = u.x;
    y[sides] = u.y;
    run[sides] = (v.x - u.x) / (v.y - u.y);
    ++sides;
  }
};

// The largest errors of the two meshes of the quad over its inner pixels, row by row. Rows
// through the quad's top or bottom meet it on its border only. The quad lies left of each
// side: a side towards larger y keeps a row's pixels at smaller x than where it crosses the
// row, a side towards smaller y at larger x. False when a triangle is flat (no pixel then
// tells the two meshes apart).
bool innerErrors(const Corner& a, const Corner& b, const Corner& d, const Corner& p,
                 const RasterSampler& raster, const std::uint8_t* skip, double& viaAb,
                 double& viaPd) {
  const double top = std::min(std::min(a.y, b.y), std::min(d.y, p.y));
  const double bottom = std::max(std::max(a.y, b.y), std::max(d.y, p.y));
  // The rows strictly between, by conversions (the library's floor and ceil are calls).
  const std::int64_t first = std::max<std::int64_t>(
      0, static_cast<std::int64_t>(std::max(top, -1.0) + 1));  // floor(top) + 1
  std::int64_t last = static_cast<std::int64_t>(std::min(bottom, raster.height() - 0.5));
  if (static_cast<double>(last) == bottom) --last;  // ceil(bottom) - 1
  if (first > last || bottom < 0) return true;
  Chain upper, lower;  // the sides whose crossings bound x from above, from below
  const Corner* ends[5] = {&a, &d, &b, &p, &a};  // counter-clockwise, the quad on the left
  for (int k = 0; k < 4; ++k) {
    const Corner &u = *ends[k], &v = *ends[k + 1];
    if (v.y > u.y) upper.add(u, v);
    if (v.y < u.y) lower.add(u, v);
  }
  LazyPlane abp(a, b, p), bad(b, a, d), adp(a, d, p), dbp(d, b, p);
  const double width = raster.width();
  const bool allValid = raster.allValid();
  for (std::int64_t row = first; row <= last; ++row) {
    const double y = static_cast<double>(row);
    double lo = -1, hi = width;  // the row's inner pixels lie strictly between
    for (int k = 0; k < upper.sides; ++k)
      hi = std::min(hi, upper.x[k] + (y - upper.y[k]) * upper.run[k]);
    for (int k = 0; k < lower.sides; ++k)
      lo = std::max(lo, lower.x[k] + (y - lower.y[k]) * lower.run[k]);
    const std::size_t rowStart = raster.pixel(0, static_cast<std::uint32_t>(row));
    // From floor(lo) + 1, lo being -1 or more.
    for (double x = static_cast<double>(static_cast<std::int64_t>(lo + 1)); x < hi; ++x) {
      const std::size_t i = rowStart + static_cast<std::size_t>(x);
      if (skip[i] || (!allValid && !raster.valid(i))) continue;
      double zAb, zPd;
      if (!(leftOf(a, b, x, y) >= 0 ? abp : bad).at(x, y, zAb) ||
          !(leftOf(p, d, x, y) >= 0 ? dbp : adp).at(x, y, zPd))
        return false;
      const double h = raster.at(i);
      viaAb = std::max(viaAb, std::fabs(h - zAb));
      viaPd = std::max(viaPd, std::fabs(h - zPd));
    }
  }
  return true;
}

}  // namespace

bool otherDiagonalFitsBetter(const Corner& a, const Corner& b, const Corner& d, const Corner& p,
                             const RasterSampler& raster, const std::uint8_t* skip) {
  double viaAb = 0, viaPd = 0;
  return innerErrors(a, b, d, p, raster, skip, viaAb, viaPd) && viaPd < viaAb;
}

}  // namespace geocdt::terrain
