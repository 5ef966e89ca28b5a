#include "terrain/greedy_mesher.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geocdt/predicates.h"
#include "labels/slot_windings.h"
#include "terrain/diagonal_fit.h"
#include "terrain/triangle_scan.h"

namespace geocdt::terrain {

bool GreedyMesher::inside(std::int32_t t) const {
  if (topo_.isGhost(t)) return false;
  return !rings_ || insideByRule(winding_[t], FillRule::EvenOdd);
}

// Per-slot and per-vertex arrays follow the core's, grown by half again when short.
void GreedyMesher::grow() {
  const auto slots = static_cast<std::size_t>(topo_.slotCount());
  if (error_.size() < slots) {
    const std::size_t n = slots + slots / 2 + 16;
    error_.resize(n, 0);
    candidate_.resize(n, -1);
    corners_.resize(3 * n, kGhost);
    if (rings_) winding_.resize(n, 0);
  }
  const std::size_t vertices = d_.vertexCount();
  if (vertexEdge_.size() < vertices) vertexEdge_.resize(vertices + vertices / 2 + 16, -1);
}

void GreedyMesher::measure(std::vector<std::int32_t> windings) {
  // Vertices added on constrained edges take ids far past the store's id-ordered slots.
  d_.constraints.scatter();
  const std::int32_t slots = topo_.slotCount();
  // What was measured before (and what it found) stays where the slot holds the same triangle.
  const std::int32_t known = std::min(slots, static_cast<std::int32_t>(corners_.size() / 3));
  vertexEdge_.clear();
  grow();
  if (corners_.size() < 3 * static_cast<std::size_t>(slots)) corners_.resize(3 * error_.size());
  if (rings_) {
    if (windings.size() != static_cast<std::size_t>(slots)) windings = slotWindings(d_);
    std::copy(windings.begin(), windings.end(), winding_.begin());
  }
  const std::uint32_t* tri = topo_.tri.data();
  for (std::int32_t e = 0; e < 3 * slots; ++e)
    if (tri[e] != kGhost) vertexEdge_[tri[e]] = e;
  noteNewVertices();
  markBoundary();
  for (std::int32_t t = 0; t < slots; ++t) {
    const std::uint32_t* c = &corners_[3 * t];
    if (t < known && c[0] == tri[3 * t] && c[1] == tri[3 * t + 1] && c[2] == tri[3 * t + 2])
      continue;
    measureTriangle(t);
  }
}

// Passes over every slot after each refinement round took a tenth of a minAngle mesh's
// instructions and over a quarter of its last-level read misses (bench/EXPERIMENTS.md, TN36).
void GreedyMesher::measure(const std::vector<std::int32_t>& changed, const std::int32_t* windings) {
  d_.constraints.scatter();
  grow();
  const std::uint32_t* tri = topo_.tri.data();
  const auto rewritten = [&](std::int32_t t) {
    const std::uint32_t* c = &corners_[3 * t];
    return c[0] != tri[3 * t] || c[1] != tri[3 * t + 1] || c[2] != tri[3 * t + 2];
  };
  // The windings first, which the border needs; a vertex whose half-edge pointed into a
  // rewritten slot is a corner of a rewritten slot.
  for (const std::int32_t t : changed) {
    if (!rewritten(t)) continue;
    if (rings_) winding_[t] = windings[t];
    for (std::int32_t e = 3 * t; e < 3 * t + 3; ++e)
      if (tri[e] != kGhost) vertexEdge_[tri[e]] = e;
  }
  noteNewVertices();
  markBoundary();
  for (const std::int32_t t : changed)
    if (rewritten(t)) measureTriangle(t);
}

// Vertices the refiner adds have no height yet while it inserts them: quads with one keep
// the edge insertion finds.
bool GreedyMesher::chooseDiagonal(void* mesher, std::uint32_t a, std::uint32_t b, std::uint32_t d,
                                  std::uint32_t p) {
  const GreedyMesher& m = *static_cast<const GreedyMesher*>(mesher);
  const std::size_t heights = m.z_.size();
  if (m.skip_.empty() || std::max({a, b, d, p}) >= heights) return false;
  const double* xy = m.d_.xy.data();
  const auto corner = [&](std::uint32_t v) { return Corner{xy[2 * v], xy[2 * v + 1], m.z_[v]}; };
  return otherDiagonalFitsBetter(corner(a), corner(b), corner(d), corner(p), m.raster_,
                                 m.skip_.data());
}

// Vertices on pixels are never proposed again.
void GreedyMesher::noteNewVertices() {
  const std::uint32_t w = raster_.width(), h = raster_.height();
  if (skip_.empty()) skip_.assign(static_cast<std::size_t>(w) * h, 0);
  if (projected_.empty()) projected_.assign(skip_.size(), 0);
  for (std::uint32_t v = skipped_; v < d_.vertexCount(); ++v) {
    const double x = d_.xy[2 * v], y = d_.xy[2 * v + 1];
    if (x == std::floor(x) && y == std::floor(y) && x >= 0 && y >= 0 && x < w && y < h)
      skip_[raster_.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y))] = 1;
  }
  skipped_ = d_.vertexCount();
}

// The border segments: the edges between a triangle of the mesh and one outside it (a ghost,
// or outside the rings). Their pixels are the border's, which triangles do not propose.
// Without rings they are the hull's edges, found by a turn round the ghost vertex; with rings
// every slot is looked at. The mesh's triangles are counted on the way.
void GreedyMesher::markBoundary() {
  segments_.clear();
  segmentQueue_.clear();
  const std::int32_t slots = topo_.slotCount();
  if (!rings_) {
    // Every slot holds a triangle of the mesh but the ghosts, one a hull edge.
    triangles_ = static_cast<std::uint64_t>(slots);
    std::int32_t start = 0;
    const std::int32_t halfEdges = 3 * slots;
    while (start < halfEdges && topo_.tri[start] != kGhost) ++start;
    if (start == halfEdges) return;
    // Each ghost triangle (g, a, b) has the hull edge a -> b; its twin b -> a is the mesh's.
    std::int32_t e = start;
    do {
      const std::int32_t hull = nextEdge(e);
      addBoundary(topo_.tri[topo_.adj[hull]], topo_.tri[nextEdge(topo_.adj[hull])]);
      --triangles_;
      e = topo_.adj[prevEdge(e)];
    } while (e != start);
    return;
  }
  triangles_ = 0;
  for (std::int32_t t = 0; t < slots; ++t) {
    if (!inside(t)) continue;
    ++triangles_;
    for (std::int32_t e = 3 * t; e < 3 * t + 3; ++e)
      if (!inside(topo_.adj[e] / 3)) addBoundary(topo_.tri[e], topo_.tri[nextEdge(e)]);
  }
}

// A border segment from a to b, measured, its pixels marked.
void GreedyMesher::addBoundary(std::uint32_t a, std::uint32_t b) {
  measureSegment(segments_.add(a, b));
  // Its pixels, strictly between its ends (it runs along a row or a column).
  const double* xy = d_.xy.data();
  const double ax = xy[2 * a], ay = xy[2 * a + 1], bx = xy[2 * b], by = xy[2 * b + 1];
  const bool horizontal = ay == by;
  const double lo = horizontal ? std::min(ax, bx) : std::min(ay, by);
  const double hi = horizontal ? std::max(ax, bx) : std::max(ay, by);
  const double fixed = horizontal ? ay : ax;
  if (fixed != std::floor(fixed) || (ax != bx && ay != by)) return;
  for (double p = std::floor(lo) + 1; p < hi; ++p) {
    const double x = horizontal ? p : fixed, y = horizontal ? fixed : p;
    if (x < 0 || y < 0 || x >= raster_.width() || y >= raster_.height()) continue;
    skip_[raster_.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y))] = 1;
  }
}

// A triangle goes with the first tile it touches, the one holding its box's lower corner: a
// triangle across a border then goes before the tile it starts in is left, and the meshes
// come nearer to strict greedy insertion's (bench/EXPERIMENTS.md, TN35).
std::uint32_t GreedyMesher::rankOf(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
  if (!tiled_) return 0;
  const double* xy = d_.xy.data();
  return tiles_.rankAt(std::min({xy[2 * a], xy[2 * b], xy[2 * c]}),
                       std::min({xy[2 * a + 1], xy[2 * b + 1], xy[2 * c + 1]}));
}

std::uint32_t GreedyMesher::triangleRank(std::int32_t t) const {
  const std::uint32_t* c = &corners_[3 * t];
  return rankOf(c[0], c[1], c[2]);
}

std::uint32_t GreedyMesher::segmentRank(std::uint32_t s) const {
  return rankOf(segments_[s].a, segments_[s].b, segments_[s].b);
}

// Once the mesh outgrows the cache (and no limit asks for the largest errors first), the
// queues take the tiles' order.
void GreedyMesher::orderByTiles() {
  if (tiled_ || triangles_ < TileOrder::kFromTriangles) return;
  if (limits_.maxTriangles > 0 || limits_.maxVertices > 0) return;
  tiled_ = true;
  triangleQueue_.rerank(
      [&](std::uint32_t t) { return triangleRank(static_cast<std::int32_t>(t)); });
  segmentQueue_.rerank([&](std::uint32_t s) { return segmentRank(s); });
}

void GreedyMesher::measureTriangle(std::int32_t t) {
  std::copy(&topo_.tri[3 * t], &topo_.tri[3 * t] + 3, &corners_[3 * t]);
  if (!inside(t)) {
    error_[t] = 0;
    candidate_[t] = -1;
    triangleQueue_.remove(static_cast<std::uint32_t>(t));
    return;
  }
  const std::uint32_t* c = &topo_.tri[3 * t];
  const double* xy = d_.xy.data();
  const auto corner = [&](std::uint32_t v) { return Corner{xy[2 * v], xy[2 * v + 1], z_[v]}; };
  const ScanResult r = scanTriangle(corner(c[0]), corner(c[1]), corner(c[2]), raster_, skip_.data(),
                                    &blocks_, &scratch_);
  stats_.scannedPixels += r.scanned;
  error_[t] = r.error;
  candidate_[t] = r.pixel;
  if (r.pixel >= 0 && r.error > limits_.maxError) {
    triangleQueue_.set(static_cast<std::uint32_t>(t), r.error, triangleRank(t));
  } else {
    triangleQueue_.remove(static_cast<std::uint32_t>(t));
  }
}

void GreedyMesher::measureSegment(std::uint32_t s) {
  stats_.scannedPixels += segments_.scan(s, d_.xy.data(), z_.data(), raster_);
  const BorderSegment& seg = segments_[s];
  if (seg.pixel >= 0 && seg.error > limits_.maxError) {
    segmentQueue_.set(s, seg.error, segmentRank(s));
  } else {
    segmentQueue_.remove(s);
  }
}

bool GreedyMesher::run(std::uint64_t& inserted) {
  inserted = 0;
  firstInserted_ = std::min(firstInserted_, d_.vertexCount());
  for (;;) {
    const bool triangle = !triangleQueue_.empty(), segment = !segmentQueue_.empty();
    if (!triangle && !segment) break;
    orderByTiles();
    const bool takeSegment =
        segment && (!triangle || segmentQueue_.topRank() < triangleQueue_.topRank() ||
                    (segmentQueue_.topRank() == triangleQueue_.topRank() &&
                     segmentQueue_.topError() >= triangleQueue_.topError()));
    // A point on the border adds one triangle, one inside adds two.
    const std::uint64_t added = takeSegment ? 1 : 2;
    if (limits_.maxTriangles > 0 && triangles_ + added > limits_.maxTriangles) break;
    if (limits_.maxVertices > 0 && d_.vertexCount() + std::uint64_t{1} > limits_.maxVertices) break;
    const bool ok = takeSegment
                        ? insertSegmentCandidate(segmentQueue_.top())
                        : insertTriangleCandidate(static_cast<std::int32_t>(triangleQueue_.top()));
    if (!ok) return false;
    ++inserted;
  }
  return true;
}

// Where (x, y), a pixel the scan of triangle t found in it, lies: decided exactly against
// t's edges; a pixel that rounding put in t from just outside is located by a walk from t.
Hit GreedyMesher::locateIn(std::int32_t t, double x, double y) {
  const std::uint32_t* c = &topo_.tri[3 * t];
  const double* xy = d_.xy.data();
  int zeros = 0, zeroEdge = -1;
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t a = c[k], b = c[k == 2 ? 0 : k + 1];
    const Sign s = orient2d(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], x, y);
    if (s == Sign::Negative) {
      d_.setLastTriangle(t);
      return d_.locate(x, y, false);
    }
    if (s == Sign::Zero) {
      ++zeros;
      zeroEdge = k;
    }
  }
  if (zeros == 0) return {Hit::Kind::Face, 3 * t};
  if (zeros == 1) return {Hit::Kind::Edge, 3 * t + zeroEdge};
  return {Hit::Kind::Vertex, -1};
}

// A pixel in a face within kEdgeReach of one of its constrained edges (a breakline whose
// chain runs through a rounded crossing passes beside the pixels on it) goes onto that edge:
// the chain bends through it, by no more than that, instead of passing a pixel-less sliver
// away with the heights of its far ends. Only where all four triangles of the split keep
// their orientation, not on the hull, which must stay convex, and where the split's joins are
// Delaunay: it joins the point to the face's third corner c and to the corner d beyond the
// edge, and only the edges facing the point are tested for flips then, so the point must lie
// strictly inside both triangles' circumcircles. On the edge it always does; ulps off it,
// beside a corner ulps from the line (a rounded point of a breakline), it may not.
Hit GreedyMesher::ontoConstraint(const Hit& face, double x, double y) const {
  const double* xy = d_.xy.data();
  const auto orient = [&](std::uint32_t a, std::uint32_t b) {
    return orient2d(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], x, y);
  };
  const auto inCircle = [&](std::uint32_t u, std::uint32_t v, std::uint32_t w) {
    return incircle(xy[2 * u], xy[2 * u + 1], xy[2 * v], xy[2 * v + 1], xy[2 * w], xy[2 * w + 1], x,
                    y) == Sign::Positive;
  };
  const std::int32_t t = face.edge / 3;
  for (std::int32_t e = 3 * t; e < 3 * t + 3; ++e) {
    if (!topo_.fixed[e]) continue;
    const std::uint32_t a = topo_.tri[e], b = topo_.tri[nextEdge(e)];
    const double ax = xy[2 * a], ay = xy[2 * a + 1], bx = xy[2 * b], by = xy[2 * b + 1];
    const double cross = (bx - ax) * (y - ay) - (by - ay) * (x - ax);
    if (!(std::fabs(cross) <= kEdgeReach * std::hypot(bx - ax, by - ay))) continue;
    const std::uint32_t beyond = topo_.tri[prevEdge(topo_.adj[e])];
    if (beyond == kGhost) continue;
    if (orient(beyond, b) == Sign::Positive && orient(a, beyond) == Sign::Positive &&
        inCircle(a, b, topo_.tri[prevEdge(e)]) && inCircle(b, a, beyond))
      return {Hit::Kind::Edge, e};
  }
  return face;
}

// A pixel closer to a breakline than this (in pixels) has its projection onto the line go in
// first: the pixel itself beside the line would leave a sliver, which refinement (minAngle)
// can only mend with a cascade of ever shorter subsegments along the line, and which the
// surface through the point on the line often makes needless (bench/EXPERIMENTS.md, TN27).
// The other constrained edges, the boundary of the area with data, run along pixel rows and
// columns: no pixel lies that near them but on them.
constexpr double kBreaklineReach = 0.5;

// The point of a constrained edge of face h nearest the pixel at (x, y), if the pixel lies
// within kBreaklineReach of it and the point lies farther from the edge's ends than from the
// pixel (else an end is as near, and the split would only make a short edge); placed on the
// edge as ontoConstraint places points, with the line's height there.
bool GreedyMesher::breaklinePointNear(const Hit& h, double x, double y,
                                      BreaklinePoint& onto) const {
  const double* xy = d_.xy.data();
  const std::int32_t t = h.edge / 3;
  for (std::int32_t e = 3 * t; e < 3 * t + 3; ++e) {
    if (!topo_.fixed[e]) continue;
    const std::uint32_t a = topo_.tri[e], b = topo_.tri[nextEdge(e)];
    const double ax = xy[2 * a], ay = xy[2 * a + 1], dx = xy[2 * b] - ax, dy = xy[2 * b + 1] - ay;
    const double length = std::hypot(dx, dy);
    const double along = ((x - ax) * dx + (y - ay) * dy) / (length * length);
    const double qx = ax + along * dx, qy = ay + along * dy;
    const double away = std::hypot(x - qx, y - qy);
    if (!(away <= kBreaklineReach && along * length > away && (1 - along) * length > away))
      continue;
    // (Where rounding puts q ulps off the edge, ontoConstraint checks that the split keeps
    // the mesh Delaunay.)
    const Hit split = ontoConstraint(h, qx, qy);
    if (split.kind != Hit::Kind::Edge || split.edge != e) continue;
    onto.x = qx;
    onto.y = qy;
    onto.z = heightOnBreakline(a, b, qx, qy, onto.given);
    onto.edge = split;
    return true;
  }
  return false;
}

// The height at (x, y) on the constrained edge a-b: interpolated along each input segment
// through it whose ends have given heights (averaged, as at crossings), else the raster's.
double GreedyMesher::heightOnBreakline(std::uint32_t a, std::uint32_t b, double x, double y,
                                       bool& given) const {
  const ConstraintStore& store = d_.constraints;
  double sum = 0;
  int segments = 0;
  if (const EdgeSource* source = store.find(a, b)) {
    store.forEachSegment(*source, [&](std::uint32_t i) {
      const SegmentEnds& ends = store.segments[i];
      if (!given_[ends.a] || !given_[ends.b]) return;
      const InputSegment g = store.geometry(i, d_.xy);
      const double dx = g.bx - g.ax, dy = g.by - g.ay;
      const double t = ((x - g.ax) * dx + (y - g.ay) * dy) / (dx * dx + dy * dy);
      sum += (1 - t) * z_[ends.a] + t * z_[ends.b];
      ++segments;
    });
  }
  given = segments > 0;
  return given ? sum / segments : raster_.sample(x, y);
}

bool GreedyMesher::insertBreaklinePoint(std::size_t pixel, const BreaklinePoint& onto) {
  projected_[pixel] = 1;
  return insertVertex(onto.x, onto.y, onto.z, onto.given, onto.edge);
}

bool GreedyMesher::insertTriangleCandidate(std::int32_t t) {
  const auto pixel = static_cast<std::size_t>(candidate_[t]);
  const double x = static_cast<double>(pixel % raster_.width());
  const double y = static_cast<double>(pixel / raster_.width());
  Hit h = locateIn(t, x, y);
  if (h.kind == Hit::Kind::Face) h = ontoConstraint(h, x, y);
  BreaklinePoint onto;
  if (h.kind == Hit::Kind::Face && !projected_[pixel] && breaklinePointNear(h, x, y, onto)) {
    triangles_ += 2;
    return insertBreaklinePoint(pixel, onto);
  }
  if (h.kind == Hit::Kind::Vertex) {  // a vertex not made from this pixel sits on it
    skip_[pixel] = 1;
    measureTriangle(t);
    return true;
  }
  if (h.kind != Hit::Kind::Face && h.kind != Hit::Kind::Edge) return false;
  triangles_ += 2;
  return insertPixel(pixel, h);
}

bool GreedyMesher::insertSegmentCandidate(std::uint32_t s) {
  const std::uint32_t a = segments_[s].a, b = segments_[s].b;
  const auto pixel = static_cast<std::size_t>(segments_[s].pixel);
  const std::int32_t e = edgeBetween(a, b);
  if (e < 0) return false;
  triangles_ += 1;
  if (!insertPixel(pixel, {Hit::Kind::Edge, e})) return false;
  const std::uint32_t v = d_.vertexCount() - 1;
  segments_[s].b = v;
  const std::uint32_t next = segments_.add(v, b);
  measureSegment(s);
  measureSegment(next);
  return true;
}

std::int32_t GreedyMesher::edgeBetween(std::uint32_t a, std::uint32_t b) const {
  const std::int32_t e = topo_.edgeAround(vertexEdge_[a], b);
  if (e >= 0) return e;
  return topo_.edgeAround(vertexEdge_[b], a);
}

bool GreedyMesher::insertPixel(std::size_t pixel, const Hit& h) {
  skip_[pixel] = 1;
  return insertVertex(static_cast<double>(pixel % raster_.width()),
                      static_cast<double>(pixel / raster_.width()), raster_.at(pixel), false, h);
}

bool GreedyMesher::insertVertex(double x, double y, double z, bool given, const Hit& h) {
  const std::uint32_t v = d_.vertexCount();
  // The edge split, for the listener: its ends, and whether it was constrained or on the hull.
  std::uint32_t a = kGhost, b = kGhost;
  bool onSubsegment = false;
  if (h.kind == Hit::Kind::Edge) {
    a = topo_.tri[h.edge];
    b = topo_.tri[nextEdge(h.edge)];
    onSubsegment =
        topo_.fixed[h.edge] || topo_.isGhost(h.edge / 3) || topo_.isGhost(topo_.adj[h.edge] / 3);
  }
  d_.xy.push_back(x);
  d_.xy.push_back(y);
  z_.push_back(z);
  given_.push_back(given);
  if (d_.insertLocated(h, v) != v) {
    d_.xy.resize(d_.xy.size() - 2);
    z_.pop_back();
    given_.pop_back();
    return false;
  }
  ++stats_.insertions;
  const std::int32_t from = afterInsert(v);
  if (listener_.inserted) listener_.inserted(listener_.context, from, a, b, onSubsegment);
  return true;
}

// The triangles around v are the ones the insertion changed: each takes its winding from the
// unchanged triangle beyond its outer edge, tells its corners where they are, and is measured.
std::int32_t GreedyMesher::afterInsert(std::uint32_t v) {
  grow();
  const std::int32_t last = d_.lastTriangle();
  std::int32_t from = 3 * last;
  while (topo_.tri[from] != v) ++from;
  star_.clear();
  std::int32_t e = from;
  do {
    star_.push_back(e);
    e = topo_.adj[prevEdge(e)];
  } while (e != from);
  for (const std::int32_t h : star_) {
    const std::int32_t t = h / 3, outer = nextEdge(h);
    if (rings_) {
      if (topo_.isGhost(t)) {
        winding_[t] = 0;
      } else {
        const std::int32_t g = topo_.adj[outer];
        winding_[t] = winding_[g / 3];
        if (topo_.fixed[outer])
          winding_[t] += d_.constraints.windingAcross(topo_.tri[g], topo_.tri[nextEdge(g)]);
      }
    }
    if (topo_.tri[outer] != kGhost) vertexEdge_[topo_.tri[outer]] = outer;
  }
  vertexEdge_[v] = from;
  for (const std::int32_t h : star_) measureTriangle(h / 3);
  return from;
}

std::int32_t GreedyMesher::edgeOutOf(std::uint32_t v) const {
  const std::int32_t e = vertexEdge_[v];
  if (e >= 0 && e < 3 * topo_.slotCount() && topo_.tri[e] == v) return e;
  return -1;
}

// A half-edge out of v if the triangles that removing v would make keep every pixel in them
// (v's own included) within the bound, else -1. Hull vertices, the ends of constrained edges
// and vertices outside the rings never are: tiles keep their borders, breaklines their chains.
std::int32_t GreedyMesher::removableEdge(std::uint32_t v) {
  const std::int32_t out = edgeOutOf(v);
  if (out < 0 || (rings_ && !inside(out / 3)) || !d_.plannedRemoval(v, out, plan_)) return -1;
  const double z = z_[v], bound = limits_.maxError;
  const double* xy = d_.xy.data();
  const auto corner = [&](std::uint32_t u) { return Corner{xy[2 * u], xy[2 * u + 1], z_[u]}; };
  const double x = xy[2 * v], y = xy[2 * v + 1];
  // v's own pixel first, against the planned triangle that holds it: the pixel that most
  // often keeps it (greedy insertion put it in for its error).
  for (std::size_t k = 0; k < plan_.size(); k += 3) {
    const Corner a = corner(plan_[k]), b = corner(plan_[k + 1]), c = corner(plan_[k + 2]);
    if (orient2d(a.x, a.y, b.x, b.y, x, y) == Sign::Negative ||
        orient2d(b.x, b.y, c.x, c.y, x, y) == Sign::Negative ||
        orient2d(c.x, c.y, a.x, a.y, x, y) == Sign::Negative)
      continue;
    Plane plane;
    if (planeOf(a, b, c, plane) && !(std::fabs(z - plane.at(x, y)) <= bound)) return -1;
    break;
  }
  const std::size_t pixel =
      raster_.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
  skip_[pixel] = 0;
  for (std::size_t k = 0; k < plan_.size(); k += 3) {
    const ScanResult r = scanTriangle(corner(plan_[k]), corner(plan_[k + 1]), corner(plan_[k + 2]),
                                      raster_, skip_.data(), &blocks_, &scratch_);
    stats_.scannedPixels += r.scanned;
    if (r.pixel >= 0 && r.error > limits_.maxError) {
      skip_[pixel] = 1;
      return -1;
    }
  }
  return out;
}

// The triangle in slot from now lies in slot to (a removal freed it): its measurement, queue
// entry and winding follow, and its corners learn where it is.
void GreedyMesher::moveSlot(std::int32_t from, std::int32_t to) {
  const bool queued = candidate_[from] >= 0 && error_[from] > limits_.maxError;
  error_[to] = error_[from];
  candidate_[to] = candidate_[from];
  std::copy(&corners_[3 * from], &corners_[3 * from] + 3, &corners_[3 * to]);
  if (rings_) winding_[to] = winding_[from];
  triangleQueue_.remove(static_cast<std::uint32_t>(to));
  if (queued) {
    triangleQueue_.remove(static_cast<std::uint32_t>(from));
    triangleQueue_.set(static_cast<std::uint32_t>(to), error_[to], triangleRank(to));
  }
  for (std::int32_t e = 3 * to; e < 3 * to + 3; ++e)
    if (topo_.tri[e] != kGhost) vertexEdge_[topo_.tri[e]] = e;
}

std::uint64_t GreedyMesher::decimate(Status& status) {
  if (!triangleQueue_.empty() || !segmentQueue_.empty()) return 0;  // a limit stopped it
  std::uint64_t removed = 0;
  const std::uint32_t end = d_.vertexCount();
  for (std::uint32_t v = firstInserted_; v < end; ++v) {
    const std::int32_t out = removableEdge(v);
    if (out < 0) continue;
    const std::int32_t winding = rings_ ? winding_[out / 3] : 0;
    status = d_.removeVertex(v, out);
    if (!status.ok()) return removed;
    ++removed;
    triangles_ -= 2;
    for (const auto& [from, to] : d_.movedSlots()) moveSlot(from, to);
    // Every new triangle is one of the star's, inside when they were; a triangle the
    // removal's flips made other than planned (cocircular pixels) is measured all the same,
    // and queued if it misses the bound.
    for (const std::int32_t t : d_.removalSlots()) {
      if (rings_) winding_[t] = winding;
      for (std::int32_t e = 3 * t; e < 3 * t + 3; ++e) vertexEdge_[topo_.tri[e]] = e;
      measureTriangle(t);
    }
  }
  return removed;
}

double GreedyMesher::maxError() const {
  double worst = 0;
  for (std::int32_t t = 0; t < topo_.slotCount(); ++t)
    if (inside(t)) worst = std::max(worst, error_[t]);
  for (std::size_t s = 0; s < segments_.size(); ++s) worst = std::max(worst, segments_[s].error);
  return worst;
}

}  // namespace geocdt::terrain
