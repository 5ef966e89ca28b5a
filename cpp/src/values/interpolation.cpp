// Values anywhere in the triangulation: barycentric in a triangle, or Sibson's natural
// neighbours.
#include "values/interpolation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "exact/euclidean_norm.h"
#include "geocdt/predicates.h"

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

}  // namespace geocdt
