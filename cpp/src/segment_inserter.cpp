#include "segment_inserter.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "exact_geometry.h"
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
    const Walk w = walk(piece.a, piece.b);
    if (w.reached == kGhost && w.blocking < 0)
      return broken("lost the segment while walking along it");
    if (w.blocking >= 0) {
      const std::size_t depth = pieces_.size();
      const std::uint32_t vertices = d_.vertexCount();
      bool failed = false;
      const std::uint32_t x = crossings_ == Crossings::Computed
                                  ? resolveCrossing(piece, w.blocking)
                                  : snapCrossing(piece, w.blocking, failed);
      if (failed) return Outcome::Broken;
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
    pieces_.back().a = w.reached;
    ++d_.stats.segments;
  }
  return Outcome::Inserted;
}

std::int32_t SegmentInserter::edgeOutOf(std::uint32_t a) {
  // The piece before usually ended at a: its edge's twin starts here.
  if (hint_ >= 0 && hint_ < 3 * d_.topo.slotCount() && d_.topo.tri[hint_] == a) return hint_;
  // Pieces follow each other, so the last triangle is usually next to a.
  const Hit h = d_.locate(d_.xy[2 * a], d_.xy[2 * a + 1], false);
  return h.kind == Hit::Kind::Vertex ? h.edge : -1;
}

void SegmentInserter::markConstrained(std::int32_t e, const EdgeSource& src) {
  Topology& t = d_.topo;
  hint_ = t.adj[e];  // starts at the far end, where the next piece starts
  t.fixed[e] = 1;
  t.fixed[t.adj[e]] = 1;
  d_.constraints.mark(t.tri[e], t.tri[nextEdge(e)], src);
}

SegmentInserter::Walk SegmentInserter::walk(std::uint32_t a, std::uint32_t b) {
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

namespace {

// Where the lines through (a, b) and (c, d) meet, in floating point. In long double, whose
// exponent range keeps the products of tiny coordinates (1e-171 squared) from underflowing.
// The point is p + s * (direction of p's segment) for an end p of one segment, with s
// found from an end q of the other. Rounding moves it by about |q - p| (through the
// cancellation in s's numerator) plus |s| times the direction (through the step from p),
// so the pair (p, q) that makes the least of both is used: from the far end of a
// 1e67-long segment, one rounding of s moved the point by 1e47.
bool lineCrossing(const InputSegment& ab, const InputSegment& cd, double& x, double& y) {
  using L = long double;
  const L ex = (L)ab.bx - ab.ax, ey = (L)ab.by - ab.ay, fx = (L)cd.bx - cd.ax,
          fy = (L)cd.by - cd.ay;
  const L denominator = ex * fy - ey * fx;
  const L lengthE = std::hypot(ex, ey), lengthF = std::hypot(fx, fy);
  L bestError = 0, bestX = 0, bestY = 0;
  bool found = false;
  // p moves along (dx, dy); q is on the other line, whose direction is (gx, gy).
  const auto tryPair = [&](L px, L py, L dx, L dy, L length, L qx, L qy, L gx, L gy, L sign) {
    const L u = (qx - px) * gy, v = (qy - py) * gx;
    const L s = sign * (u - v) / denominator;
    const L error =
        (std::fabs(u) + std::fabs(v)) / std::fabs(denominator) * length + std::fabs(s) * length;
    if (!(found && bestError <= error)) {
      found = true;
      bestError = error;
      bestX = px + s * dx;
      bestY = py + s * dy;
    }
  };
  for (const auto& [qx, qy] : {std::pair<L, L>{cd.ax, cd.ay}, std::pair<L, L>{cd.bx, cd.by}}) {
    tryPair(ab.ax, ab.ay, ex, ey, lengthE, qx, qy, fx, fy, 1);
    tryPair(ab.bx, ab.by, ex, ey, lengthE, qx, qy, fx, fy, 1);
  }
  for (const auto& [qx, qy] : {std::pair<L, L>{ab.ax, ab.ay}, std::pair<L, L>{ab.bx, ab.by}}) {
    tryPair(cd.ax, cd.ay, fx, fy, lengthF, qx, qy, ex, ey, -1);
    tryPair(cd.bx, cd.by, fx, fy, lengthF, qx, qy, ex, ey, -1);
  }
  x = static_cast<double>(bestX);
  y = static_cast<double>(bestY);
  return std::isfinite(x) && std::isfinite(y);
}

}  // namespace

std::uint32_t SegmentInserter::resolveCrossing(const Piece& piece, std::int32_t h) {
  Topology& topo = d_.topo;
  ConstraintStore& store = d_.constraints;
  const double* p = d_.xy.data();
  const std::uint32_t r = topo.tri[h], l = topo.tri[nextEdge(h)];
  const std::uint32_t c1 = topo.tri[prevEdge(h)], c2 = topo.tri[prevEdge(topo.adj[h])];
  const auto segmentOf = [p](std::uint32_t u, std::uint32_t v) {
    return InputSegment{p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1]};
  };
  const EdgeSource* crossedSource = store.find(r, l);
  // Both chains may now leave their segments, unless the crossing fits (see below).
  const std::size_t untouched = touchedSegments_.size();
  const auto touch = [&](std::uint32_t i) { touchedSegments_.push_back(i); };
  store.forEachSegment(piece.src, touch);
  if (crossedSource) store.forEachSegment(*crossedSource, touch);
  const InputSegment ab = store.segments[piece.src.segment];
  const InputSegment cd = crossedSource ? store.segments[crossedSource->segment] : segmentOf(r, l);
  // Where (x, y) lies along a segment's direction, compared with vertex u: the sign of the
  // projection of their difference. Differences, not positions: near the end of a segment
  // 1e-63 long, a vertex 1e-182 away must still compare apart. In long double, whose
  // exponent range keeps products of subnormal differences from underflowing.
  const auto beyond = [&](const InputSegment& g, double x, double y, std::uint32_t u) {
    const long double t = ((long double)x - p[2 * u]) * ((long double)g.bx - g.ax) +
                          ((long double)y - p[2 * u + 1]) * ((long double)g.by - g.ay);
    return (t > 0) - (t < 0);
  };
  // Between lo and hi along g's direction: beyond one and short of the other.
  const auto between = [&](const InputSegment& g, double x, double y, std::uint32_t lo,
                           std::uint32_t hi) {
    return beyond(g, x, y, lo) * beyond(g, x, y, hi) < 0;
  };
  const auto fits = [&](double x, double y) {
    return between(ab, x, y, piece.a, piece.b) && between(cd, x, y, r, l);
  };

  // The crossing of the two original input segments, unless rounding and earlier bends put
  // it outside the two pieces that actually cross here: then the crossing of the pieces.
  double x = 0, y = 0;  // the crossing point, once found
  bool ofPieces = false;  // found from the pieces: the input segments may not cross at all
  const auto distance = [&](std::uint32_t v) { return std::hypot(p[2 * v] - x, p[2 * v + 1] - y); };
  // When no crossing point fits (the two are collinear within rounding, and the crossing of
  // their lines means nothing), the constraints meet at one of the four ends instead: the
  // one within the other's span and nearest to its line.
  const auto meetAtAnEnd = [&]() -> std::uint32_t {
    const auto offLine = [&](std::uint32_t v, std::uint32_t u0, std::uint32_t u1) {
      const long double dx = (long double)p[2 * u1] - p[2 * u0],
                        dy = (long double)p[2 * u1 + 1] - p[2 * u0 + 1];
      const long double cross = dx * ((long double)p[2 * v + 1] - p[2 * u0 + 1]) -
                                dy * ((long double)p[2 * v] - p[2 * u0]);
      return std::fabs(cross) / std::sqrt(dx * dx + dy * dy);
    };
    std::uint32_t best = kGhost;
    long double bestOff = 0;
    const auto consider = [&](std::uint32_t v, const InputSegment& g, std::uint32_t u0,
                              std::uint32_t u1) {
      // Ends count as within: ends that nearly coincide must be able to meet.
      if (beyond(g, p[2 * v], p[2 * v + 1], u0) * beyond(g, p[2 * v], p[2 * v + 1], u1) > 0) return;
      const long double off = offLine(v, u0, u1);
      if (best == kGhost || off < bestOff) {
        best = v;
        bestOff = off;
      }
    };
    consider(piece.a, cd, r, l);
    consider(piece.b, cd, r, l);
    consider(r, ab, piece.a, piece.b);
    consider(l, ab, piece.a, piece.b);
    if (best == kGhost) best = distance(r) <= distance(l) ? r : l;
    if (best == r || best == l) return best;  // the piece bends through it
    const std::int32_t e = findEdge(r, l);    // the crossed constraint bends through a piece end
    if (e >= 0) {
      const EdgeSource moved = store.take(r, l);
      topo.fixed[e] = topo.fixed[topo.adj[e]] = 0;
      pieces_.push_back({r, best, moved});
      pieces_.push_back({best, l, moved});
      d_.flipStack().push_back(e);
      d_.restoreDelaunay();
    }
    return kGhost;
  };
  // Two input segments meet at one vertex: once their crossing has one, later crossings of
  // their pieces (after rounding bent them) go there too, so no run of ever new vertices.
  const std::uint64_t pair =
      ConstraintStore::key(piece.src.segment, crossedSource ? crossedSource->segment : kGhost);
  std::uint32_t w = kGhost;
  if (const std::uint32_t* met = met_.find(pair); met && *met < d_.vertexCount()) {
    w = *met;
    x = p[2 * w];
    y = p[2 * w + 1];
  } else if (!lineCrossing(ab, cd, x, y) || !fits(x, y)) {
    if (!lineCrossing(segmentOf(piece.a, piece.b), segmentOf(r, l), x, y) || !fits(x, y))
      return meetAtAnEnd();
    ofPieces = true;
  }
  const auto strictlyLeft = [&](std::uint32_t u, std::uint32_t v) {
    return orient2d(p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1], x, y) == Sign::Positive;
  };
  // Snapping is for rounding, relative to the shorter of the two pieces that cross here
  // (an original segment can be 1e76 long and still cross a short one).
  const auto length = [&](std::uint32_t u, std::uint32_t v) {
    return std::hypot(p[2 * v] - p[2 * u], p[2 * v + 1] - p[2 * u + 1]);
  };
  const double snapDistance = 1e-12 * std::min(length(piece.a, piece.b), length(r, l));
  std::uint32_t nearest = r;
  for (const std::uint32_t v : {l, piece.a, piece.b})
    if (distance(v) < distance(nearest)) nearest = v;
  const bool near = distance(nearest) <= snapDistance;

  if (w == kGhost && !near && strictlyLeft(c1, r) && strictlyLeft(r, c2) && strictlyLeft(l, c1) &&
      strictlyLeft(c2, l)) {
    // The usual case: the point splits the crossed edge.
    const std::uint32_t v = d_.vertexCount();
    met_.insert(pair, v);
    d_.xy.push_back(x);
    d_.xy.push_back(y);
    store.split(r, l, v);
    // The rounded point is near the edge, not on it: the spokes to the two apexes may need
    // flips that a point exactly on the edge would never need.
    const std::int32_t spoke = d_.splitEdge(h, v);
    for (std::int32_t e = spoke;;) {
      d_.flipStack().push_back(e);
      e = topo.adj[prevEdge(e)];
      if (e == spoke) break;
    }
    d_.restoreDelaunay();
    ++d_.stats.crossings;
    ++d_.stats.inserted;
    // The crossed constraint bends inside its own two triangles, where no vertex lies, and
    // (found from them) the two segments cross at v: nothing for chainsKeepTheGuarantee to
    // check here.
    if (!ofPieces) touchedSegments_.resize(untouched);
    return v;
  }
  // Otherwise both constraints pass through one vertex w: the one the point is (nearly)
  // equal to, or a new one inserted wherever the point lies (thin triangles).
  if (w == kGhost && near) w = nearest;
  if (w == kGhost) {
    w = d_.vertexCount();
    d_.xy.push_back(x);
    d_.xy.push_back(y);
    const std::uint32_t got = d_.insertVertex(w);
    if (got != w) {
      d_.xy.resize(2 * static_cast<std::size_t>(w));
      if (got == kGhost) return kGhost;
      w = got;
    } else {
      ++d_.stats.crossings;
    }
    p = d_.xy.data();  // the push may have moved the coordinates
    met_.insert(pair, w);
  }
  const double wx = p[2 * w], wy = p[2 * w + 1];  // (after the push: p was refreshed)
  const bool pieceEnd = w == piece.a || w == piece.b;
  const bool crossedEnd = w == r || w == l;
  const bool pieceOk = pieceEnd || between(ab, wx, wy, piece.a, piece.b);
  const bool crossedOk = crossedEnd || between(cd, wx, wy, r, l);
  // w would make a constraint double back: meet at an end instead.
  if (!pieceOk || !crossedOk) return meetAtAnEnd();
  if (!crossedEnd) {
    const std::int32_t e = findEdge(r, l);
    if (e >= 0) {
      const EdgeSource moved = store.take(r, l);
      topo.fixed[e] = topo.fixed[topo.adj[e]] = 0;
      pieces_.push_back({r, w, moved});
      pieces_.push_back({w, l, moved});
      d_.flipStack().push_back(e);  // no longer constrained: it may have to flip now
      d_.restoreDelaunay();
    }
  }
  return pieceEnd ? kGhost : w;
}

std::uint32_t SegmentInserter::snapCrossing(const Piece& piece, std::int32_t h, bool& failed) {
  Topology& topo = d_.topo;
  ConstraintStore& store = d_.constraints;
  const std::uint32_t r = topo.tri[h], l = topo.tri[nextEdge(h)];
  const EdgeSource* crossed = store.find(r, l);
  if (!crossed) {
    failed = true;
    error_ = {StatusCode::InternalError, "a constrained edge without a source"};
    return kGhost;
  }
  const EdgeSource crossedSource = *crossed;
  const double* p = d_.xy.data();
  const auto segmentOf = [&](std::uint32_t u, std::uint32_t v) {
    return InputSegment{p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1]};
  };
  // The links cross in one point, inside both: its rounding box's vertex, found or added.
  double x, y;
  roundedCrossing(segmentOf(piece.a, piece.b), segmentOf(r, l), x, y);
  std::uint32_t w = d_.vertexCount();
  d_.xy.push_back(x);
  d_.xy.push_back(y);
  const std::uint32_t got = d_.insertVertex(w);
  if (got != w) {
    d_.xy.resize(2 * static_cast<std::size_t>(w));
    if (got == kGhost) {
      failed = true;
      error_ = d_.lastError();
      return kGhost;
    }
    w = got;
  } else {
    ++d_.stats.crossings;
  }
  p = d_.xy.data();
  // The guarantee holds for both input segments, or this is a bug to report.
  const InputSegment& s = store.segments[piece.src.segment];
  const InputSegment& t = store.segments[crossedSource.segment];
  const double wx = p[2 * w], wy = p[2 * w + 1];
  const auto keeps = [&](const InputSegment& g, std::uint32_t from, std::uint32_t to) {
    if (!withinDistance(g, wx, wy, chainBoundExponent(g))) return false;
    if (w == from || w == to) return true;
    return signAlong(g, p[2 * from], p[2 * from + 1], wx, wy) *
               signAlong(g, wx, wy, p[2 * to], p[2 * to + 1]) >
           0;
  };
  if (!keeps(s, piece.a, piece.b) || !keeps(t, r, l)) {
    failed = true;
    error_ = {StatusCode::InternalError,
              "snap rounding found no vertex within the bound where two links cross"};
    return kGhost;
  }
  // The crossed link bends through w, unless w split it already (it lay on it).
  if (w != r && w != l) {
    const std::int32_t e = findEdge(r, l);
    if (e >= 0) {
      const EdgeSource moved = store.take(r, l);
      topo.fixed[e] = topo.fixed[topo.adj[e]] = 0;
      pieces_.push_back({r, w, moved});
      pieces_.push_back({w, l, moved});
      d_.flipStack().push_back(e);
      d_.restoreDelaunay();
    }
  }
  return w == piece.a || w == piece.b ? kGhost : w;
}

std::int32_t SegmentInserter::findEdge(std::uint32_t u, std::uint32_t v) {
  const std::int32_t start = edgeOutOf(u);
  if (start < 0) return -1;
  std::int32_t e = start;
  do {
    if (d_.topo.tri[nextEdge(e)] == v) return e;
    e = d_.topo.adj[prevEdge(e)];
  } while (e != start);
  return -1;
}

}  // namespace geocdt
