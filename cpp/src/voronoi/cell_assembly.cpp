#include "voronoi/cell_assembly.h"

#include <algorithm>
#include <cmath>

#include "exact/fixed_point.h"
#include "voronoi/crossing_point.h"
#include "voronoi/perturbation.h"

namespace geocdt {
namespace {

// Twice the signed area of the ring p[0 .. n) (not closed), from differences to its first point;
// magnitude, if asked for, gets the sum of its products' sizes (for an error bound).
double twiceArea(const XY* p, std::size_t n, double* magnitude = nullptr) {
  double twice = 0, size = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double ax = p[i].x - p[0].x, ay = p[i].y - p[0].y;
    const double bx = p[i + 1].x - p[0].x, by = p[i + 1].y - p[0].y;
    twice += ax * by - ay * bx;
    size += std::fabs(ax * by) + std::fabs(ay * bx);
  }
  if (magnitude != nullptr) *magnitude = size;
  return twice;
}

// Where q lies against the ring p[0 .. n) (not closed), exactly: 1 inside, 0 outside, -1 on it.
int locateInRing(const XY* p, std::size_t n, XY q) {
  int winding = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const XY a = p[i], b = p[i + 1 == n ? 0 : i + 1];
    const Sign o = orient2d(a.x, a.y, b.x, b.y, q.x, q.y);
    if (o == Sign::Zero && std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) &&
        std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y))
      return -1;
    if (a.y <= q.y) {
      if (b.y > q.y && o == Sign::Positive) ++winding;
    } else if (b.y <= q.y && o == Sign::Negative) {
      --winding;
    }
  }
  return winding != 0 ? 1 : 0;
}

// Whether the ring p[0 .. n) (not closed) runs counter-clockwise: the sign of its area, from
// doubles where their error bound decides it, else exactly. Its area in doubles can underflow
// to zero, and a loop that touches itself at a vertex has no corner to read the sign from.
bool counterClockwise(const XY* p, std::size_t n) {
  double magnitude = 0;
  const double twice = twiceArea(p, n, &magnitude);
  // Differences, products and sums each err by 2^-53 of what they add, products that
  // underflow by 2^-1075.
  const auto count = static_cast<double>(n);
  const double bound = 8 * count * 0x1p-53 * magnitude + count * 0x1p-1070;
  if (std::fabs(twice) > bound) return twice > 0;
  int base = 1 << 20;
  for (std::size_t i = 0; i < n; ++i)
    base = std::min({base, fixed::unitExponent(p[i].x), fixed::unitExponent(p[i].y)});
  if (base == 1 << 20) return false;  // every point at the origin
  fixed::Number sum;
  for (std::size_t i = 0; i < n; ++i) {
    const XY a = p[i], b = p[i + 1 == n ? 0 : i + 1];
    sum = fixed::sum(sum, fixed::product(fixed::fixed(a.x, base), fixed::fixed(b.y, base)));
    sum = fixed::difference(sum, fixed::product(fixed::fixed(b.x, base), fixed::fixed(a.y, base)));
  }
  return fixed::signOf(sum) == Sign::Positive;
}

}  // namespace

Status CellAssembler::assemble(std::uint32_t v, const std::int32_t* pieces, std::size_t count,
                               CellPolygons& out) {
  site_ = diagram_.point(v);
  collectEdges(v);
  pieces_.clear();
  events_.clear();
  scratch_.clear();
  rings_.clear();
  isOuter_.clear();
  for (std::size_t i = 0; i < count; ++i) {
    const Piece& p = walk_.pieces[pieces[i]];
    const auto local = static_cast<std::int32_t>(pieces_.size());
    pieces_.push_back(&p);
    if (p.exit < 0) continue;
    const std::int32_t entryEdge = diagram_.twin(walk_.crossings[p.entry].edge);
    events_.push_back({local, p.exit, rankOf(walk_.crossings[p.exit].edge), true});
    events_.push_back({local, p.entry, rankOf(entryEdge), false});
  }
  if (!events_.empty()) {
    Status s = sortEvents();
    if (s.ok()) s = traceRings();
    if (!s.ok()) return s;
  }
  addLoops();
  if (events_.empty()) addWholeCell(v);
  placeHoles();
  write(out);
  return Status::success();
}

void CellAssembler::collectEdges(std::uint32_t v) {
  edges_.clear();
  const std::int32_t first = diagram_.outEdge(v);
  std::int32_t e = first;
  do {
    edges_.push_back(e);
    e = diagram_.turn(e);
  } while (e != first);
}

std::int32_t CellAssembler::rankOf(std::int32_t outEdge) const {
  const auto at = std::find(edges_.begin(), edges_.end(), outEdge);
  return static_cast<std::int32_t>(at - edges_.begin());
}

// Counter-clockwise around the cell: by edge, then along the edge (the direction n of
// crossesFurther). Rounded points further apart than their error bounds are in order as they
// are; nearer ones are compared exactly.
bool CellAssembler::eventBefore(const Event& a, const Event& b) const {
  if (a.rank != b.rank) return a.rank < b.rank;
  const Crossing& x = walk_.crossings[a.crossing];
  const Crossing& y = walk_.crossings[b.crossing];
  const XY t = diagram_.point(diagram_.target(edges_[a.rank]));
  const int axis = bisectorAxis(site_, t);
  const double along = axis == 0 ? site_.y - t.y : t.x - site_.x;  // n's dominant component
  const double ahead = axis == 0 ? y.at.x - x.at.x : y.at.y - x.at.y;
  const double slack = (x.error + y.error) * (1 + 0x1p-40);
  if (ahead * along > 0 && std::fabs(ahead) > slack) return true;
  if (ahead * along < 0 && std::fabs(ahead) > slack) return false;
  const std::vector<XY>& p = domain_.points;
  return crossesFurther(site_, t, p[x.from], p[x.to], p[y.from], p[y.to]);
}

Status CellAssembler::sortEvents() {
  std::sort(events_.begin(), events_.end(),
            [this](const Event& a, const Event& b) { return eventBefore(a, b); });
  const std::size_t n = events_.size();
  exitAt_.assign(pieces_.size(), -1);
  for (std::size_t i = 0; i < n; ++i) {
    if (events_[i].exit == events_[(i + 1) % n].exit)
      return {StatusCode::InternalError,
              "voronoi: the boundary's crossings of a cell do not alternate"};
    if (events_[i].exit) exitAt_[events_[i].piece] = static_cast<std::int32_t>(i);
  }
  return Status::success();
}

Status CellAssembler::traceRings() {
  const auto n = static_cast<std::int32_t>(events_.size());
  std::vector<std::uint8_t> used(pieces_.size(), 0);
  for (std::size_t start = 0; start < pieces_.size(); ++start) {
    if (pieces_[start]->exit < 0 || used[start]) continue;
    const auto begin = static_cast<std::uint32_t>(scratch_.size());
    auto p = static_cast<std::int32_t>(start);
    do {
      if (used[p]) return {StatusCode::InternalError, "voronoi: a cell's ring does not close"};
      used[p] = 1;
      const Piece& piece = *pieces_[p];
      scratch_.push_back(walk_.crossings[piece.entry].at);
      emitPiece(piece);
      scratch_.push_back(walk_.crossings[piece.exit].at);
      const std::int32_t i = exitAt_[p], j = (i + 1) % n;
      const Event& next = events_[j];
      emitCorners(events_[i].rank, next.rank, j <= i && next.rank == events_[i].rank);
      p = next.piece;
    } while (p != static_cast<std::int32_t>(start));
    isOuter_.push_back(1);
    finishRing(begin);
  }
  return Status::success();
}

// The cell's corners from the end of edge fromRank to the start of edge toRank.
void CellAssembler::emitCorners(std::int32_t fromRank, std::int32_t toRank, bool allAround) {
  const auto k = static_cast<std::int32_t>(edges_.size());
  std::int32_t count = (toRank - fromRank + k) % k;
  if (count == 0 && allAround) count = k;
  for (std::int32_t m = 0; m < count; ++m)
    scratch_.push_back(diagram_.center(edges_[(fromRank + m) % k] / 3));
}

void CellAssembler::emitPiece(const Piece& p) {
  std::uint32_t k = p.first;
  for (std::uint32_t m = 0; m < p.count; ++m) {
    scratch_.push_back(domain_.points[k]);
    k = domain_.next(k, p.loop);
  }
}

void CellAssembler::addLoops() {
  for (const Piece* p : pieces_) {
    if (p->exit >= 0) continue;
    const auto begin = static_cast<std::uint32_t>(scratch_.size());
    emitPiece(*p);
    const Ring& ring = rings_[finishRing(begin)];
    isOuter_.push_back(counterClockwise(scratch_.data() + ring.begin, ring.end - ring.begin));
  }
}

// A cell with no crossings: wholly inside or outside (then nothing), as its corners are.
void CellAssembler::addWholeCell(std::uint32_t v) {
  if (!sides_.loopsOnlyInside(v)) return;
  const auto begin = static_cast<std::uint32_t>(scratch_.size());
  for (const std::int32_t e : edges_) scratch_.push_back(diagram_.center(e / 3));
  isOuter_.push_back(1);
  finishRing(begin);
}

// Closes up repeated points of the ring scratch_[begin ..) and records it.
std::uint32_t CellAssembler::finishRing(std::uint32_t begin) {
  std::uint32_t end = begin;
  for (std::size_t i = begin; i < scratch_.size(); ++i)
    if (end == begin || scratch_[i] != scratch_[end - 1]) scratch_[end++] = scratch_[i];
  while (end > begin + 1 && scratch_[end - 1] == scratch_[begin]) --end;
  scratch_.resize(end);
  Ring r{begin, end, 0.5 * twiceArea(scratch_.data() + begin, end - begin), {0, 0}, {0, 0}};
  if (end > begin) r.low = r.high = scratch_[begin];
  for (std::uint32_t i = begin; i < end; ++i) {
    r.low = {std::min(r.low.x, scratch_[i].x), std::min(r.low.y, scratch_[i].y)};
    r.high = {std::max(r.high.x, scratch_[i].x), std::max(r.high.y, scratch_[i].y)};
  }
  rings_.push_back(r);
  return static_cast<std::uint32_t>(rings_.size() - 1);
}

// Whether ring `inner` lies inside ring `outer`, by its first point not on `outer` (rings of one
// cell meet only at vertices, so one point decides).
bool CellAssembler::holds(const Ring& outer, const Ring& inner) const {
  if (inner.low.x < outer.low.x || inner.low.y < outer.low.y || inner.high.x > outer.high.x ||
      inner.high.y > outer.high.y)
    return false;
  int where = -1;
  for (std::uint32_t i = inner.begin; i < inner.end && where < 0; ++i)
    where = locateInRing(scratch_.data() + outer.begin, outer.end - outer.begin, scratch_[i]);
  return where == 1;
}

// Each hole goes to the innermost outer ring that holds it (outer rings of one cell nest only
// where an island lies in a lake). Decided by position, not area, which can underflow. Should
// rounding leave a hole in none, it goes to the largest.
void CellAssembler::placeHoles() {
  for (std::size_t h = 0; h < rings_.size(); ++h) {
    if (isOuter_[h]) continue;
    Ring& hole = rings_[h];
    std::int32_t best = -1, largest = -1;
    for (std::size_t o = 0; o < rings_.size(); ++o) {
      const Ring& ring = rings_[o];
      if (!isOuter_[o]) continue;
      if (largest < 0 || ring.area > rings_[largest].area) largest = static_cast<std::int32_t>(o);
      if (best >= 0 && !holds(rings_[best], ring)) continue;
      if (holds(ring, hole)) best = static_cast<std::int32_t>(o);
    }
    hole.container = best >= 0 ? best : largest;
  }
}

void CellAssembler::write(CellPolygons& out) const {
  for (std::size_t o = 0; o < rings_.size(); ++o) {
    if (!isOuter_[o]) continue;
    const std::uint32_t first = out.ringCount();
    out.beginRing();
    for (std::uint32_t i = rings_[o].begin; i < rings_[o].end; ++i) out.add(scratch_[i]);
    if (!out.endRing()) continue;
    for (const Ring& hole : rings_) {
      if (hole.container != static_cast<std::int32_t>(o)) continue;
      out.beginRing();
      for (std::uint32_t i = hole.begin; i < hole.end; ++i) out.add(scratch_[i]);
      out.endRing();
    }
    if (out.ringCount() > first) out.endPolygon();
  }
}

}  // namespace geocdt
