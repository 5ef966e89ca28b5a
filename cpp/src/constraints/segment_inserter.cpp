#include "constraints/segment_inserter.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "exact/exact_geometry.h"
#include "geocdt/predicates.h"

namespace geocdt {

Outcome SegmentInserter::broken(const char* what) {
  error_ = {StatusCode::InternalError, what};
  return Outcome::Broken;
}

Outcome SegmentInserter::insert(std::uint32_t u, std::uint32_t v, const EdgeSource& src) {
  pieces_.clear();
  pieces_.push_back({u, v, src});
  // Each round either inserts a piece, adds a vertex or re-routes a crossed constraint.
  // Re-routing adds nothing, so a run of them is how a cycle between rounded crossings in a
  // tangle shows: real data needs at most 2 per segment (Natural Earth, GSHHG, US counties);
  // 16 hands the segment over to snap rounding early. The round bound is a safety net.
  const std::uint64_t budget = 1000 + 8 * static_cast<std::uint64_t>(d_.vertexCount());
  std::uint32_t reroutes = 0;
  for (std::uint64_t round = 0; !pieces_.empty(); ++round) {
    if (round > budget || (reroutes > 16 && crossings_ == Crossings::Computed)) {
      if (crossings_ == Crossings::Computed) return Outcome::GaveUp;
      return broken("snap-rounded links kept crossing each other");
    }
    const Piece piece = pieces_.back();
    if (piece.a == piece.b) {
      pieces_.pop_back();
      continue;
    }
    // Off its input segment (at a rounded crossing), the piece goes back onto it at the
    // first vertex exactly on it: collinear chains inserted before then hold this one too.
    InputSegment g{};
    const bool off = crossings_ == Crossings::Computed && offSegment(piece, g);
    if (off) {
      const std::int32_t back = edgeBackOntoSegment(piece, g);
      if (back >= 0) {
        markConstrained(back, piece.src);
        pieces_.back().a = d_.topo.tri[nextEdge(back)];
        ++d_.stats.segments;
        continue;
      }
    }
    const Walk w = walk(piece.a, piece.b, off ? &g : nullptr);
    if (w.via != kGhost) {  // split at it: first a -> via, then via -> b
      pieces_.back() = {w.via, piece.b, piece.src};
      pieces_.push_back({piece.a, w.via, piece.src});
      continue;
    }
    if (w.reached == kGhost && w.blocking < 0)
      return broken("lost the segment while walking along it");
    if (w.blocking >= 0 && crossings_ == Crossings::Snapped) {
      if (!snapCrossing(piece, w.blocking)) return Outcome::Broken;
      continue;  // the piece and the crossed link re-routed
    }
    if (w.blocking >= 0) {
      const std::size_t depth = pieces_.size();
      const std::uint32_t vertices = d_.vertexCount();
      const std::uint32_t x = resolveCrossing(piece, w.blocking);
      if (d_.vertexCount() == vertices) ++reroutes;
      if (x == kGhost) continue;  // the crossed constraint now bends through this piece's end
      // Split this piece at x: first a -> x, then x -> b, below any re-routed pieces.
      pieces_[depth - 1] = {x, piece.b, piece.src};
      pieces_.insert(pieces_.begin() + static_cast<std::ptrdiff_t>(depth), {piece.a, x, piece.src});
      continue;
    }
    if (w.existing >= 0) {
      markConstrained(w.existing, piece.src);
    } else if (!flipIn(piece.a, w.reached, piece.src)) {
      return broken("re-triangulating along a segment failed");
    }
    // Through a vertex on the segment where an earlier call bent another chain, off that
    // chain's segment: the two chains meet there though the segments may not: checked.
    if (w.reached != piece.b && chainBendsAt(w.reached))
      d_.constraints.forEachSegment(piece.src,
                                    [&](std::uint32_t i) { touchedSegments_.push_back(i); });
    // Done with the piece when it reached its end (most do): popped at once, where writing
    // its new start and reading the piece back in the next round stalled on the store.
    if (w.reached == piece.b) {
      pieces_.pop_back();
    } else {
      pieces_.back().a = w.reached;
    }
    ++d_.stats.segments;
  }
  return Outcome::Inserted;
}

bool SegmentInserter::offSegment(const Piece& piece, InputSegment& g) const {
  const ConstraintStore& store = d_.constraints;
  if (piece.src.segment >= store.segments.size()) return false;  // (a seam's borders)
  // Most pieces start at their segment's first vertex: on it, without a test.
  const SegmentEnds& ends = store.segments[piece.src.segment];
  if (piece.a == ends.a || piece.a == ends.b) return false;
  g = store.geometry(piece.src.segment, d_.xy);
  const double* p = d_.xy.data();
  return orient2d(g.ax, g.ay, g.bx, g.by, p[2 * piece.a], p[2 * piece.a + 1]) != Sign::Zero;
}

bool SegmentInserter::onAndBetween(const InputSegment& g, std::uint32_t v, double px, double py,
                                   double qx, double qy) const {
  if (v == kGhost) return false;
  const double vx = d_.xy[2 * v], vy = d_.xy[2 * v + 1];
  return orient2d(g.ax, g.ay, g.bx, g.by, vx, vy) == Sign::Zero &&
         signAlong(g, px, py, vx, vy) > 0 && signAlong(g, vx, vy, qx, qy) >= 0;
}

std::int32_t SegmentInserter::edgeBackOntoSegment(const Piece& piece, const InputSegment& g) {
  const std::int32_t start = edgeOutOf(piece.a);
  if (start < 0) return -1;
  const double* p = d_.xy.data();
  const double ax = p[2 * piece.a], ay = p[2 * piece.a + 1];
  const double bx = p[2 * piece.b], by = p[2 * piece.b + 1];
  std::int32_t e = start, best = -1;
  double nx = bx, ny = by;  // the nearest found so far (b itself, at first)
  do {
    const std::uint32_t w = d_.topo.tri[nextEdge(e)];
    // onAndBetween tests w against the nearest so far: not past it. Strictly nearer:
    if (onAndBetween(g, w, ax, ay, nx, ny) &&
        (best < 0 || signAlong(g, p[2 * w], p[2 * w + 1], nx, ny) > 0)) {
      best = e;
      nx = p[2 * w];
      ny = p[2 * w + 1];
    }
    e = d_.topo.adj[prevEdge(e)];
  } while (e != start);
  return best;
}

bool SegmentInserter::chainBendsAt(std::uint32_t v) {
  const std::int32_t start = edgeOutOf(v);
  if (start < 0) return true;  // (not met: v was just reached) check, to be safe
  const double x = d_.xy[2 * v], y = d_.xy[2 * v + 1];
  const ConstraintStore& store = d_.constraints;
  bool bends = false;
  const auto passes = [&](std::uint32_t i) {  // exactly through v (ends included), or bent
    const InputSegment s = store.geometry(i, d_.xy);
    const bool inBox = std::min(s.ax, s.bx) <= x && x <= std::max(s.ax, s.bx) &&
                       std::min(s.ay, s.by) <= y && y <= std::max(s.ay, s.by);
    bends = bends || !inBox || orient2d(s.ax, s.ay, s.bx, s.by, x, y) != Sign::Zero;
  };
  std::int32_t e = start;
  do {
    if (d_.topo.fixed[e]) {
      const EdgeSource* src = store.find(v, d_.topo.tri[nextEdge(e)]);
      if (src) store.forEachSegment(*src, passes);
    }
    e = d_.topo.adj[prevEdge(e)];
  } while (e != start && !bends);
  return bends;
}

std::int32_t SegmentInserter::edgeOutOf(std::uint32_t a) {
  // The piece before usually ended at a: its edge's twin starts here.
  if (hint_ >= 0 && hint_ < 3 * d_.topo.slotCount() && d_.topo.tri[hint_] == a) return hint_;
  return ends_.find(d_, a);
}

void SegmentInserter::markConstrained(std::int32_t e, const EdgeSource& src) {
  Topology& t = d_.topo;
  hint_ = t.adj[e];  // starts at the far end, where the next piece starts
  ends_.set(t.tri[e], e);
  ends_.set(t.tri[hint_], hint_);
  t.fixed[e] = 1;
  t.fixed[t.adj[e]] = 1;
  d_.constraints.mark(t.tri[e], t.tri[nextEdge(e)], src);
}

SegmentInserter::Walk SegmentInserter::walk(std::uint32_t a, std::uint32_t b,
                                            const InputSegment* onto) {
  Walk result;
  const double* p = d_.xy.data();
  const Topology& topo = d_.topo;
  const double ax = p[2 * a], ay = p[2 * a + 1], bx = p[2 * b], by = p[2 * b + 1];
  const int axis = ax != bx ? 0 : 1;
  const bool increasing = axis == 0 ? ax < bx : ay < by;
  const auto ahead = [&](std::uint32_t x) {  // x collinear with a, b: on a's side toward b?
    const double c = p[2 * x + axis], s = axis == 0 ? ax : ay;
    return increasing ? c > s : c < s;
  };
  const auto side = [&](std::uint32_t x) {
    return orient2d(ax, ay, bx, by, p[2 * x], p[2 * x + 1]);
  };

  crossed_.clear();
  const std::int32_t start = edgeOutOf(a);
  if (start < 0) return result;
  std::int32_t e = start, h = -1;
  do {  // most segments are edges already: a turn around a comparing ids finds them
    if (topo.tri[nextEdge(e)] == b) {
      result.reached = b;
      result.existing = e;
      return result;
    }
    e = topo.adj[prevEdge(e)];
  } while (e != start);
  do {  // turn around a to find the triangle the segment enters, or an edge along it
    const std::uint32_t x = topo.tri[nextEdge(e)], y = topo.tri[prevEdge(e)];
    if (x != kGhost) {
      if (x == b) {
        result.reached = b;
        result.existing = e;
        return result;
      }
      const Sign sx = side(x);
      if (sx == Sign::Zero && ahead(x)) {
        result.reached = x;
        result.existing = e;
        return result;
      }
      if (y != kGhost && sx == Sign::Negative && side(y) == Sign::Positive) {
        h = nextEdge(e);
        break;
      }
    }
    e = topo.adj[prevEdge(e)];
  } while (e != start);
  if (h < 0) return result;

  for (;;) {  // cross edges h = right -> left until a vertex on the segment
    if (topo.fixed[h]) {
      result.blocking = h;
      return result;
    }
    crossed_.push_back(h);
    const std::int32_t f = topo.adj[h];
    const std::uint32_t c = topo.tri[prevEdge(f)];
    if (c == kGhost) return Walk{};
    if (c == b) {
      result.reached = b;
      return result;
    }
    const Sign sc = side(c);
    if (sc == Sign::Zero) {
      result.reached = c;
      return result;
    }
    if (onto && onAndBetween(*onto, c, ax, ay, bx, by)) {
      result.via = c;
      return result;
    }
    h = sc == Sign::Negative ? prevEdge(f) : nextEdge(f);
  }
}

// Sloan's flips: flip crossed edges whose quad is convex until none crosses a -> w; edges
// that still cross are met again on the next walk. Then Lawson flips restore the Delaunay
// property around every triangle touched. Dangling constrained edges inside the crossed
// region are never crossed, so they need no special case.
bool SegmentInserter::flipIn(std::uint32_t a, std::uint32_t w, const EdgeSource& src) {
  Topology& topo = d_.topo;
  const double* p = d_.xy.data();
  const auto orient = [p](std::uint32_t u, std::uint32_t v, std::uint32_t x) {
    return orient2d(p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1], p[2 * x], p[2 * x + 1]);
  };
  touched_.clear();
  queue_.clear();
  for (const std::int32_t h : crossed_) queue_.push_back({topo.tri[h], topo.tri[nextEdge(h)], h});
  // Sloan: a crossed edge in a convex quad is flipped; its new diagonal goes to the back
  // of the queue while it still crosses; a non-convex one waits its turn again. FIFO order
  // is what makes this terminate.
  const std::uint64_t bound = 1000 + 64 * static_cast<std::uint64_t>(queue_.size()) * queue_.size();
  for (std::uint64_t step = 0; !queue_.empty(); ++step) {
    if (step > bound) return false;
    QueuedEdge q = queue_.front();
    queue_.pop_front();
    std::int32_t h = q.hint;
    if (topo.tri[h] != q.u || topo.tri[nextEdge(h)] != q.v) h = findEdge(q.u, q.v);
    if (h < 0) return false;
    const std::int32_t f = topo.adj[h];
    const std::uint32_t x = q.u, y = q.v, v = topo.tri[prevEdge(h)], d = topo.tri[prevEdge(f)];
    if (orient(v, x, d) != Sign::Positive || orient(d, y, v) != Sign::Positive) {
      queue_.push_back({x, y, h});
      continue;
    }
    topo.flip(h);
    ends_.set(x, nextEdge(f));  // x and y lose half-edges h and f (see Topology::flip)
    ends_.set(y, nextEdge(h));
    touched_.push_back(h / 3);
    touched_.push_back(f / 3);
    // The new diagonal v-d (now prevEdge(h)) crosses a-w when v and d lie strictly apart.
    if (v != a && v != w && d != a && d != w) {
      const Sign sv = orient(a, w, v), sd = orient(a, w, d);
      if (sv != Sign::Zero && sd != Sign::Zero && sv != sd) queue_.push_back({v, d, prevEdge(h)});
    }
  }
  const std::int32_t e = findEdge(a, w);
  if (e < 0) return false;
  markConstrained(e, src);
  d_.setLastTriangle(e / 3);
  // Lawson: every edge of every touched triangle, flips spreading to their neighbours.
  std::vector<std::int32_t>& stack = d_.flipStack();
  for (const std::int32_t t : touched_)
    for (int k = 0; k < 3; ++k) stack.push_back(3 * t + k);
  d_.restoreDelaunay();
  return true;
}

std::uint32_t SegmentInserter::addCrossingVertex(double x, double y, bool& failed) {
  std::uint32_t w = d_.vertexCount();
  d_.xy.push_back(x);
  d_.xy.push_back(y);
  const std::uint32_t got = d_.insertVertex(w);
  if (got == w) {
    ends_.setFromTriangle(d_.topo, w, d_.lastTriangle());
    ++d_.stats.crossings;
    return w;
  }
  d_.xy.resize(2 * static_cast<std::size_t>(w));  // (x, y) was a vertex already
  failed = got == kGhost;
  return got;
}

void SegmentInserter::bendThrough(std::uint32_t r, std::uint32_t l, std::uint32_t w) {
  const std::uint32_t path[3] = {r, w, l};
  bendAlong(path, 3);
}

void SegmentInserter::bendAlong(const std::uint32_t* path, std::size_t count) {
  const std::uint32_t r = path[0], l = path[count - 1];
  const std::int32_t e = findEdge(r, l);
  if (e < 0) return;
  const EdgeSource moved = d_.constraints.take(r, l);
  d_.topo.fixed[e] = d_.topo.fixed[d_.topo.adj[e]] = 0;
  for (std::size_t k = 0; k + 1 < count; ++k) pieces_.push_back({path[k], path[k + 1], moved});
  d_.flipStack().push_back(e);  // no longer constrained: it may have to flip now
  d_.restoreDelaunay();
}

std::int32_t SegmentInserter::findEdge(std::uint32_t u, std::uint32_t v) {
  return d_.topo.edgeAround(edgeOutOf(u), v);
}

}  // namespace geocdt
