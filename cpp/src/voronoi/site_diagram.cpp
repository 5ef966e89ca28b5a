#include "voronoi/site_diagram.h"

#include <algorithm>
#include <cmath>

#include "base/chunks.h"
#include "delaunay/insertion_order.h"
#include "exact/circumcenter.h"
#include "voronoi/perturbation.h"

namespace geocdt {

// The sites go in in the core's own spatial order (Brio), applied here so that the vertex ids
// follow it: every later pass over vertices or triangles then reads memory close to the last
// (the core would otherwise number the vertices in input order, scattered over the arrays).
// Room for the guards' vertices and triangles is reserved with the sites', so that adding
// them moves no array.
Status SiteDiagram::build(const double* sites, std::uint32_t count, double minX, double minY,
                          double maxX, double maxY, std::uint32_t threads) {
  Options options;
  options.threads = threads;
  options.order = InsertionOrder::Input;
  delaunay_ = std::make_unique<Delaunay>(options);
  const std::vector<std::uint32_t> order = insertionOrder(sites, count, InsertionOrder::Brio);
  std::vector<double> sorted;
  sorted.reserve(2 * static_cast<std::size_t>(count) + 6);
  sorted.resize(2 * static_cast<std::size_t>(count));
  double* to = sorted.data();
  forChunks(0, count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      to[2 * k] = sites[2 * static_cast<std::size_t>(order[k])];
      to[2 * k + 1] = sites[2 * static_cast<std::size_t>(order[k]) + 1];
    }
  });
  delaunay_->topo.reserve(2 * static_cast<std::size_t>(count) + 64);
  std::vector<std::uint32_t> ids(count);
  const Status s = delaunay_->insertBatch(std::move(sorted), ids.data());
  if (!s.ok()) return s;
  siteVertex_.resize(count);
  for (std::uint32_t k = 0; k < count; ++k) siteVertex_[order[k]] = ids[k];
  realVertices_ = delaunay_->vertexCount();
  threads_ = delaunay_->stats.threads;
  recordHull();
  const Status guarded = addGuards(minX, minY, maxX, maxY);
  if (!guarded.ok()) return guarded;
  computeCenters();
  return Status::success();
}

// The hull edges are the real half-edges whose twins lie in ghost triangles, counter-clockwise
// with the real triangle on their left.
void SiteDiagram::recordHull() {
  hull_.clear();
  if (!delaunay_->built()) return;
  const Topology& topo = delaunay_->topo;
  std::vector<std::uint32_t> after(realVertices_, kGhost);
  std::uint32_t start = kGhost;
  for (std::int32_t g = 0; g < topo.slotCount(); ++g) {
    if (!topo.isGhost(g)) continue;
    for (int k = 0; k < 3; ++k) {  // the ghost's real edge, whose twin runs along the hull
      const std::int32_t e = 3 * g + k;
      if (topo.tri[e] == kGhost || topo.tri[nextEdge(e)] == kGhost) continue;
      after[topo.tri[nextEdge(e)]] = topo.tri[e];
      start = topo.tri[e];
    }
  }
  std::uint32_t v = start;
  do {
    hull_.push_back(point(v));
    v = after[v];
  } while (v != start && v != kGhost && hull_.size() <= realVertices_);
}

// Three sites 8 L from the centre of the region (L its larger side): a point of the region is
// within sqrt(2) L of every real site and at least 7.5 L from every guard, so no guard's cell
// reaches it, and the guards' triangle holds the region, so every real cell is bounded.
Status SiteDiagram::addGuards(double minX, double minY, double maxX, double maxY) {
  const double cx = 0.5 * minX + 0.5 * maxX, cy = 0.5 * minY + 0.5 * maxY;
  double side = std::max(maxX - minX, maxY - minY);
  if (!(side > 0)) side = 1 + std::fabs(cx) + std::fabs(cy);
  const double far = 8 * side;
  const double guards[6] = {cx - far, cy - far, cx + far, cy - far, cx, cy + far};
  std::uint32_t ids[3];
  return delaunay_->insertBatch(guards, 3, ids);
}

// One pass in slot order, one write per slot: each slot's circumcentre (NaN for ghost
// triangles; the same doubles for a triangle on any number of threads), each real site's
// out-edge (the least centre by x, then y, the first in slot order among equal ones: the same
// whatever the slots' layout), and each real site's corner count (an edge's pair of half-edges
// is compared when its later triangle comes, both centres then known).
void SiteDiagram::computeCenters() {
  const Topology& topo = delaunay_->topo;
  const auto slots = static_cast<std::size_t>(topo.slotCount());
  centers_.clear();
  centers_.reserve(slots);
  outEdge_.assign(realVertices_, -1);
  corners_.assign(realVertices_, 0);
  const std::uint32_t* tri = topo.tri.data();
  const std::int32_t* adj = topo.adj.data();
  const double* xy = delaunay_->xy.data();
  const XY* centers = centers_.data();
  std::int32_t* out = outEdge_.data();
  std::uint32_t* corners = corners_.data();
  const std::uint32_t real = realVertices_;
  const auto at = [xy](std::uint32_t v) { return XY{xy[2 * v], xy[2 * v + 1]}; };
  forChunks(0, slots, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) {
      std::uint32_t a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
      XY centre{NAN, NAN};
      if (a != kGhost && b != kGhost && c != kGhost) {
        // From the least vertex id: the rounding depends on the rotation, which threads change.
        if (b < a && b < c) {
          std::swap(a, b);  // b a c
          std::swap(b, c);  // b c a
        } else if (c < a && c < b) {
          std::swap(a, c);  // c b a
          std::swap(b, c);  // c a b
        }
        centre = circumcenter(at(a), at(b), at(c));
      }
      centers_.push_back(centre);
      for (std::size_t e = 3 * t; e < 3 * t + 3; ++e) {
        const std::uint32_t v = tri[e];
        if (v < real) {
          const std::int32_t best = out[v];
          if (best < 0 || centre.x < centers[best / 3].x ||
              (centre.x == centers[best / 3].x && centre.y < centers[best / 3].y))
            out[v] = static_cast<std::int32_t>(e);
        }
        const std::int32_t f = adj[e];
        if (static_cast<std::size_t>(f / 3) >= t) continue;  // compared when f's comes
        const std::uint32_t distinct = centre != centers[f / 3];
        if (v < real) corners[v] += distinct;
        if (tri[f] < real) corners[tri[f]] += distinct;
      }
    }
  });
}

std::int32_t SiteDiagram::nearest(XY p) {
  const Hit h = delaunay_->locate(p.x, p.y, true);
  std::int32_t e = h.edge >= 0 ? h.edge : outEdge_[0];
  if (origin(e) == kGhost) e = nextEdge(e);
  bool moved = true;
  while (moved) {
    moved = false;
    const XY c = point(origin(e));
    std::int32_t f = e;
    do {
      const std::uint32_t t = target(f);
      if (t != kGhost && nearerTo(c, point(t), p)) {
        e = twin(f);
        moved = true;
        break;
      }
      f = turn(f);
    } while (f != e);
  }
  return e;
}

}  // namespace geocdt
