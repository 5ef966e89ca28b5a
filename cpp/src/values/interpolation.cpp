// Values anywhere in the triangulation: barycentric in a triangle, Sibson's natural
// neighbours, and rasters scan-converted triangle by triangle.
#include <algorithm>
#include <cmath>
#include <limits>

#include "exact/euclidean_norm.h"
#include "geocdt/predicates.h"
#include "triangulation_state.h"

namespace geocdt {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Vec {
  double x, y;
};

double cross(Vec a, Vec b) { return a.x * b.y - a.y * b.x; }

// The centre of the circle through the origin, u and v (relative coordinates keep the
// digits that an absolute formula would cancel away).
Vec circumcentre(Vec u, Vec v) {
  const double d = 2 * cross(u, v);
  const double u2 = u.x * u.x + u.y * u.y, v2 = v.x * v.x + v.y * v.y;
  return {(u2 * v.y - v2 * u.y) / d, (v2 * u.x - u2 * v.x) / d};
}

// Sets out[0..k) to the weighted sum of the values of vertices with weights.
class Blender {
 public:
  Blender(const std::vector<double>& values, std::uint32_t k) : values_(values), k_(k) {}
  void clear(double* out) const { std::fill(out, out + k_, 0.0); }
  void add(double* out, std::uint32_t v, double w) const {
    const double* f = values_.data() + static_cast<std::size_t>(v) * k_;
    for (std::uint32_t j = 0; j < k_; ++j) out[j] += w * f[j];
  }
  void copy(double* out, std::uint32_t v) const {
    const double* f = values_.data() + static_cast<std::size_t>(v) * k_;
    std::copy(f, f + k_, out);
  }
  void nan(double* out) const { std::fill(out, out + k_, kNaN); }

 private:
  const std::vector<double>& values_;
  std::uint32_t k_;
};

// Linear along the edge a-b at q (its projection, clamped).
void alongEdge(const double* p, std::uint32_t a, std::uint32_t b, double x, double y,
               const Blender& blend, double* out) {
  const double dx = p[2 * b] - p[2 * a], dy = p[2 * b + 1] - p[2 * a + 1];
  double t = ((x - p[2 * a]) * dx + (y - p[2 * a + 1]) * dy) / (dx * dx + dy * dy);
  t = std::min(1.0, std::max(0.0, t));
  blend.clear(out);
  blend.add(out, a, 1 - t);
  blend.add(out, b, t);
}

// Barycentric in triangle (a, b, c), relative to a.
void barycentric(const double* p, const std::uint32_t* v, double x, double y, const Blender& blend,
                 double* out) {
  const Vec a{p[2 * v[0]], p[2 * v[0] + 1]};
  const Vec ab{p[2 * v[1]] - a.x, p[2 * v[1] + 1] - a.y};
  const Vec ac{p[2 * v[2]] - a.x, p[2 * v[2] + 1] - a.y};
  const Vec aq{x - a.x, y - a.y};
  const double area = cross(ab, ac);
  // q lies in the triangle (located exactly): weights below 0 or above 1 are rounding, which
  // in a sliver can be large. Clamped and normalised, the value stays between the corners'.
  const double wb = std::max(0.0, cross(aq, ac) / area), wc = std::max(0.0, cross(ab, aq) / area);
  const double wa = std::max(0.0, 1 - wb - wc), sum = wa + wb + wc;
  if (!(area > 0) || !std::isfinite(sum)) {
    // A sliver whose area rounds to nothing: q lies along its longest edge.
    const Vec bc{ac.x - ab.x, ac.y - ab.y};
    const double lab = ab.x * ab.x + ab.y * ab.y, lac = ac.x * ac.x + ac.y * ac.y,
                 lbc = bc.x * bc.x + bc.y * bc.y;
    if (lab >= lac && lab >= lbc) return alongEdge(p, v[0], v[1], x, y, blend, out);
    if (lac >= lbc) return alongEdge(p, v[0], v[2], x, y, blend, out);
    return alongEdge(p, v[1], v[2], x, y, blend, out);
  }
  blend.clear(out);
  blend.add(out, v[0], wa / sum);
  blend.add(out, v[1], wb / sum);
  blend.add(out, v[2], wc / sum);
}

// Sibson's coordinates of q, which lies strictly inside the triangle of half-edge e or on an
// unconstrained edge between two real triangles: the triangles whose circumcircle holds q
// strictly and that q sees without crossing a constrained edge (the cavity of inserting q),
// then for each vertex on the cavity's border the area q's cell takes from that vertex's
// cell: the polygon of the new Voronoi vertices at its two border edges and the old ones of
// the cavity triangles around it.
class NaturalNeighbours {
 public:
  explicit NaturalNeighbours(const Delaunay& d) : d_(d) {}

  // false when q sees a border edge of its cavity at an angle within 1e-6 of a straight one
  // (q next to a constrained or hull edge): the new Voronoi vertex of that edge lies out
  // where its digits cancel (a relative error of about 1e-16 over the sine of that angle),
  // and the caller falls back to linear, which has the same limit on the edge.
  bool operator()(std::int32_t e, double x, double y, const Blender& blend, double* out) {
    const Topology& topo = d_.topo;
    const double* p = d_.xy.data();
    // A stamp per query marks the cavity's slots: degenerate inputs (cocircular points)
    // make cavities of thousands of triangles.
    if (mark_.size() != static_cast<std::size_t>(topo.slotCount())) {
      mark_.assign(topo.slotCount(), 0);
      stamp_ = 0;
    }
    if (++stamp_ == 0) {
      std::fill(mark_.begin(), mark_.end(), 0);
      stamp_ = 1;
    }
    cavity_.assign(1, e / 3);
    mark_[e / 3] = stamp_;
    for (std::size_t head = 0; head < cavity_.size(); ++head) {
      const std::int32_t t = cavity_[head];
      for (int k = 0; k < 3; ++k) {
        const std::int32_t f = 3 * t + k;
        if (topo.fixed[f]) continue;
        const std::int32_t n = topo.adj[f] / 3;
        if (topo.isGhost(n) || inCavity(n)) continue;
        const std::uint32_t* v = &topo.tri[3 * n];
        if (incircle(p[2 * v[0]], p[2 * v[0] + 1], p[2 * v[1]], p[2 * v[1] + 1], p[2 * v[2]],
                     p[2 * v[2] + 1], x, y) == Sign::Positive) {
          cavity_.push_back(n);
          mark_[n] = stamp_;
        }
      }
    }
    // Each border half-edge u->w (cavity inside, on its left) starts the polygon of u: the
    // new Voronoi vertex of (q, u, w), then the old ones of the cavity triangles around u
    // counter-clockwise, to the border edge that ends at u.
    blend.clear(out);
    double total = 0;
    const auto rel = [&](std::uint32_t v) { return Vec{p[2 * v] - x, p[2 * v + 1] - y}; };
    for (const std::int32_t t : cavity_)
      for (int k = 0; k < 3; ++k) {
        std::int32_t f = 3 * t + k;
        if (!isBorder(f)) continue;
        const std::uint32_t u = topo.tri[f];
        const Vec ru = rel(u), rw = rel(topo.tri[nextEdge(f)]);
        if (cross(ru, rw) < kFlat * euclideanNorm(ru.x, ru.y) * euclideanNorm(rw.x, rw.y))
          return false;
        Vec first = circumcentre(ru, rw);
        Vec last = first;
        double area = 0;
        for (int guard = 0; guard < 1 << 20; ++guard) {
          const std::int32_t g = f - f % 3;
          const Vec a = rel(topo.tri[g]), b = rel(topo.tri[g + 1]), c = rel(topo.tri[g + 2]);
          const Vec cb = circumcentre({b.x - a.x, b.y - a.y}, {c.x - a.x, c.y - a.y});
          const Vec centre{a.x + cb.x, a.y + cb.y};
          area += cross(last, centre);
          last = centre;
          const std::int32_t in = prevEdge(f);  // ends at u
          if (isBorder(in)) {
            const Vec closing = circumcentre(rel(topo.tri[in]), rel(u));
            area += cross(last, closing) + cross(closing, first);
            break;
          }
          f = topo.adj[in];
        }
        area = std::max(area, 0.0);  // below 0 only by rounding (cocircular neighbours)
        total += area;
        blend.add(out, u, area);
      }
    if (!(total > 0) || !std::isfinite(total)) return false;
    for (double* o = out; o != out + kValues_; ++o) *o /= total;
    return true;
  }

  void setValuesPerPoint(std::uint32_t k) { kValues_ = k; }

 private:
  bool inCavity(std::int32_t t) const { return mark_[t] == stamp_; }
  static constexpr double kFlat = 1e-6;
  bool isBorder(std::int32_t f) const {
    return d_.topo.fixed[f] || d_.topo.isGhost(d_.topo.adj[f] / 3) || !inCavity(d_.topo.adj[f] / 3);
  }

  const Delaunay& d_;
  std::vector<std::int32_t> cavity_;
  std::vector<std::uint32_t> mark_;  // stamp_ for the slots in the current cavity
  std::uint32_t stamp_ = 0;
  std::uint32_t kValues_ = 1;
};

}  // namespace

void interpolateValues(Delaunay& d, const std::vector<double>& values, std::uint32_t perPoint,
                       const double* xy, std::size_t count, Interpolation method, double* out) {
  const Blender blend(values, perPoint);
  NaturalNeighbours natural(d);
  natural.setValuesPerPoint(perPoint);
  const Topology& topo = d.topo;
  for (std::size_t i = 0; i < count; ++i) {
    double* o = out + i * perPoint;
    const double x = xy[2 * i], y = xy[2 * i + 1];
    if (values.empty() || !std::isfinite(x) || !std::isfinite(y)) {
      blend.nan(o);
      continue;
    }
    const Hit h = d.locate(x, y, true);
    const double* p = d.xy.data();
    switch (h.kind) {
      case Hit::Kind::Vertex: blend.copy(o, topo.tri[h.edge]); break;
      case Hit::Kind::Edge: {
        const std::int32_t e = h.edge;
        const bool border = topo.fixed[e] || topo.isGhost(e / 3) || topo.isGhost(topo.adj[e] / 3);
        if (border || method == Interpolation::Linear || !natural(e, x, y, blend, o))
          alongEdge(p, topo.tri[e], topo.tri[nextEdge(e)], x, y, blend, o);
        break;
      }
      case Hit::Kind::Face:
        if (method == Interpolation::Linear || !natural(h.edge, x, y, blend, o))
          barycentric(p, &topo.tri[h.edge - h.edge % 3], x, y, blend, o);
        break;
      default: blend.nan(o); break;
    }
  }
}

Status Triangulation::rasterize(const RasterGrid& grid, Interpolation method, float* out) const {
  if (!(grid.minX < grid.maxX) || !(grid.minY < grid.maxY) || !std::isfinite(grid.minX) ||
      !std::isfinite(grid.maxX) || !std::isfinite(grid.minY) || !std::isfinite(grid.maxY))
    return {StatusCode::InvalidArgument, "raster bounds must be finite with min < max"};
  const std::uint32_t k = state_->values.perPoint();
  const std::size_t width = grid.width, height = grid.height;
  std::fill(out, out + width * height * k, std::numeric_limits<float>::quiet_NaN());
  if (width == 0 || height == 0 || !hasValues()) return Status::success();
  const double dx = (grid.maxX - grid.minX) / static_cast<double>(width);
  const double dy = (grid.maxY - grid.minY) / static_cast<double>(height);
  if (method == Interpolation::Natural) {
    // One query per pixel, in row order: each walks a step or two from the previous one.
    std::vector<double> row(2 * width), values(width * k);
    for (std::size_t j = 0; j < height; ++j) {
      for (std::size_t i = 0; i < width; ++i) {
        row[2 * i] = grid.minX + (static_cast<double>(i) + 0.5) * dx;
        row[2 * i + 1] = grid.maxY - (static_cast<double>(j) + 0.5) * dy;
      }
      interpolate(row.data(), width, method, values.data());
      std::copy(values.begin(), values.end(), out + j * width * k);
    }
    return Status::success();
  }
  const std::vector<double>& values = state_->values.update(state_->delaunay, nullptr);
  const Topology& topo = state_->delaunay.topo;
  const double* p = state_->delaunay.xy.data();
  // Pixel centres within this fraction of a pixel outside a triangle still take its plane, so
  // that rounding leaves no gap along shared edges (a pixel on one is written twice, with
  // values equal up to rounding).
  constexpr double kSlack = 1e-9;
  std::vector<double> gradient(3 * k);
  for (std::int32_t t = 0; t < topo.slotCount(); ++t) {
    if (topo.isGhost(t)) continue;
    const std::uint32_t* v = &topo.tri[3 * t];
    // Pixel coordinates (column and row as continuous numbers; centres at + 0.5).
    double px[3], py[3];
    for (int c = 0; c < 3; ++c) {
      px[c] = (p[2 * v[c]] - grid.minX) / dx;
      py[c] = (grid.maxY - p[2 * v[c] + 1]) / dy;
    }
    const double rowLo = std::min({py[0], py[1], py[2]});
    const double rowHi = std::max({py[0], py[1], py[2]});
    const double first = std::max(0.0, std::ceil(rowLo - 0.5 - kSlack));
    const double last = std::min(static_cast<double>(height) - 1, std::floor(rowHi - 0.5 + kSlack));
    if (first > last) continue;
    // The plane of each value in pixel coordinates: f = f0 + gx (X - px0) + gy (Y - py0).
    const double ux = px[1] - px[0], uy = py[1] - py[0], wx = px[2] - px[0], wy = py[2] - py[0];
    const double det = ux * wy - uy * wx;
    if (det == 0) continue;
    for (std::uint32_t j = 0; j < k; ++j) {
      const double f0 = values[v[0] * k + j];
      const double fu = values[v[1] * k + j] - f0, fw = values[v[2] * k + j] - f0;
      gradient[3 * j] = f0;
      gradient[3 * j + 1] = (fu * wy - fw * uy) / det;
      gradient[3 * j + 2] = (fw * ux - fu * wx) / det;
    }
    for (double r = first; r <= last; ++r) {
      const double yc = r + 0.5;
      // The span of the row inside the triangle: intersect the three edges' lines.
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (int c = 0; c < 3; ++c) {
        const int n = (c + 1) % 3;
        const double y0 = py[c], y1 = py[n];
        if ((yc < std::min(y0, y1) - kSlack) || (yc > std::max(y0, y1) + kSlack)) continue;
        if (y0 == y1) {
          lo = std::min({lo, px[c], px[n]});
          hi = std::max({hi, px[c], px[n]});
          continue;
        }
        const double s = std::min(1.0, std::max(0.0, (yc - y0) / (y1 - y0)));
        const double xe = px[c] + s * (px[n] - px[c]);
        lo = std::min(lo, xe);
        hi = std::max(hi, xe);
      }
      const double colFirst = std::max(0.0, std::ceil(lo - 0.5 - kSlack));
      const double colLast =
          std::min(static_cast<double>(width) - 1, std::floor(hi - 0.5 + kSlack));
      const std::size_t row = static_cast<std::size_t>(r) * width;
      for (double c = colFirst; c <= colLast; ++c) {
        float* o = out + (row + static_cast<std::size_t>(c)) * k;
        const double ex = c + 0.5 - px[0], ey = yc - py[0];
        for (std::uint32_t j = 0; j < k; ++j)
          o[j] = static_cast<float>(gradient[3 * j] + gradient[3 * j + 1] * ex +
                                    gradient[3 * j + 2] * ey);
      }
    }
  }
  return Status::success();
}

}  // namespace geocdt
