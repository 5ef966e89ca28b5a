#include "constraints/snap_rounding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "constraints/segment_inserter.h"
#include "exact/euclidean_norm.h"
#include "exact/exact_geometry.h"
#include "geocdt/predicates.h"

namespace geocdt {

namespace {

// The half-sizes 2^ex, 2^ey of the boxes a segment is tested against: half the largest
// spacing of doubles on each axis over the segment's extent.
void boxExponents(const InputSegment& s, int& ex, int& ey) {
  ex = spacingExponent(std::fmax(std::fabs(s.ax), std::fabs(s.bx))) - 1;
  ey = spacingExponent(std::fmax(std::fabs(s.ay), std::fabs(s.by))) - 1;
}

// Whether triangle (p, q, r) may meet the rectangle of points within `reach` of s: false only
// when the three corners lie clearly beyond one side of it (a separating-axis test on the
// rectangle's two axes, with a margin: it may say yes to a few more). In a frame scaled by a
// power of two (exactly) to put s's coordinates near 1, so that nothing underflows; corners
// far out may become infinite there, which only puts them further beyond.
bool mayMeet(const InputSegment& s, double reach, const double* p, const double* q,
             const double* r) {
  int exponent = 0;
  std::frexp(std::fmax(std::fmax(std::fabs(s.ax), std::fabs(s.ay)),
                       std::fmax(std::fabs(s.bx), std::fabs(s.by))),
             &exponent);
  const auto scaled = [&](double v) { return std::ldexp(v, -exponent); };
  const double ax = scaled(s.ax), ay = scaled(s.ay);
  const double dx = scaled(s.bx) - ax, dy = scaled(s.by) - ay;
  const double length = std::sqrt(dx * dx + dy * dy);
  if (!(length > 0x1p-900)) return true;
  // A difference of two doubles errs by eps/2 of itself, products and sums by a few eps of
  // theirs, so the distances across and along err by a few eps of |w|: 32 eps with room,
  // plus what underflow in the scaling can take.
  const double reachHere = std::ldexp(reach, -exponent);
  int above = 0, below = 0, before = 0, after = 0;
  for (const double* v : {p, q, r}) {
    const double wx = scaled(v[0]) - ax, wy = scaled(v[1]) - ay;
    const double across = (dx * wy - dy * wx) / length, along = (dx * wx + dy * wy) / length;
    const double margin =
        reachHere + 32 * std::numeric_limits<double>::epsilon() * (std::fabs(wx) + std::fabs(wy)) +
        0x1p-1000;
    above += across > margin;
    below += across < -margin;
    before += along < -margin;
    after += along > length + margin;
  }
  return above < 3 && below < 3 && before < 3 && after < 3;
}

// The real triangles around the origin of half-edge `out` and, through neighbours, every
// real triangle joined to them that `meets` accepts (a region that is convex, or convex
// pieces joined at a vertex, has its triangles connected). `firstVisit(t)` says whether t is
// new to the search.
template <class FirstVisit, class Meets>
void searchTriangles(const Topology& topo, std::int32_t out, FirstVisit firstVisit, Meets meets,
                     std::vector<std::int32_t>& found) {
  found.clear();
  const auto consider = [&](std::int32_t t) {
    if (topo.isGhost(t) || !firstVisit(t)) return;
    if (meets(&topo.tri[3 * t])) found.push_back(t);
  };
  std::int32_t e = out;
  do {
    consider(e / 3);
    e = topo.adj[prevEdge(e)];
  } while (e != out);
  for (std::size_t k = 0; k < found.size(); ++k)
    for (int i = 0; i < 3; ++i) consider(topo.adj[3 * found[k] + i] / 3);
}

// The same with a search of its own, for a few triangles: which were seen is kept in a map.
template <class Meets>
std::vector<std::int32_t> searchTrianglesFrom(const Topology& topo, std::int32_t out, Meets meets) {
  EdgeMap<std::uint8_t> seen;
  std::vector<std::int32_t> found;
  searchTriangles(
      topo, out,
      [&](std::int32_t t) { return seen.insert(static_cast<std::uint32_t>(t), 1).second; }, meets,
      found);
  return found;
}

// The real triangles that may meet the points within `reach` of s, from the triangles around
// s's first end.
void trianglesNear(const Delaunay& d, std::int32_t out, const InputSegment& s, double reach,
                   std::uint32_t mark, std::vector<std::uint32_t>& stamp,
                   std::vector<std::int32_t>& found) {
  const double* xy = d.xy.data();
  searchTriangles(
      d.topo, out,
      [&](std::int32_t t) {
        if (stamp[t] == mark) return false;
        stamp[t] = mark;
        return true;
      },
      [&](const std::uint32_t* v) {
        return mayMeet(s, reach, xy + 2 * v[0], xy + 2 * v[1], xy + 2 * v[2]);
      },
      found);
}

// Vertices strictly between s and a link of chain (strictly between the link's ends along s,
// off s's line on one side and on the other side of the link) join the chain, until none is
// left (iterated snap rounding), so that no vertex changes sides. Each such vertex lies
// nearer to s than the link's ends. Those that join leave `others`.
void joinVerticesBetween(const InputSegment& s, std::vector<std::uint32_t>& chain,
                         std::vector<std::uint32_t>& others, const double* xy) {
  const auto along = [&](std::uint32_t u, std::uint32_t v) {
    return signAlong(s, xy[2 * u], xy[2 * u + 1], xy[2 * v], xy[2 * v + 1]);
  };
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t k = 0; k + 1 < chain.size() && !grew; ++k) {
      const std::uint32_t u = chain[k], v = chain[k + 1];
      for (std::size_t m = 0; m < others.size(); ++m) {
        const std::uint32_t w = others[m];
        if (along(u, w) <= 0 || along(w, v) <= 0) continue;
        const double wx = xy[2 * w], wy = xy[2 * w + 1];
        const int offLine = int(orient2d(s.ax, s.ay, s.bx, s.by, wx, wy));
        if (offLine == 0 ||
            int(orient2d(xy[2 * u], xy[2 * u + 1], xy[2 * v], xy[2 * v + 1], wx, wy)) != -offLine)
          continue;
        chain.insert(chain.begin() + static_cast<std::ptrdiff_t>(k + 1), w);
        others.erase(others.begin() + static_cast<std::ptrdiff_t>(m));
        grew = true;
        break;
      }
    }
  }
}

// The chain of segment s from vertex a to vertex b among the candidate vertices near it:
// those whose rounding cells s meets, strictly between a and b along s, in order along it.
// Where the spacing of doubles changes along s (a binade's end), a cell can be smaller than
// the distance from s at which a link passes, so a vertex could end up strictly between s
// and a link: it joins the chain too (joinVerticesBetween).
void chainOf(const InputSegment& s, std::uint32_t a, std::uint32_t b,
             const std::vector<std::uint32_t>& candidates, const double* xy,
             std::vector<std::uint32_t>& chain) {
  const auto along = [&](std::uint32_t u, std::uint32_t v) {
    return signAlong(s, xy[2 * u], xy[2 * u + 1], xy[2 * v], xy[2 * v + 1]);
  };
  chain.clear();
  std::vector<std::uint32_t> others;
  for (const std::uint32_t v : candidates) {
    if (v == a || v == b) continue;
    if (along(a, v) <= 0 || along(v, b) <= 0) continue;
    (segmentMeetsCell(s, xy[2 * v], xy[2 * v + 1]) ? chain : others).push_back(v);
  }
  std::sort(chain.begin(), chain.end(), [&](std::uint32_t u, std::uint32_t v) {
    const int order = along(u, v);
    if (order != 0) return order > 0;
    return xy[2 * u] != xy[2 * v] ? xy[2 * u] < xy[2 * v] : xy[2 * u + 1] < xy[2 * v + 1];
  });
  chain.insert(chain.begin(), a);
  chain.push_back(b);
  // Where the spacing is even along s, no vertex lies strictly between s and a link (every
  // point there lies within a cell's reach of s, so its own cell meets s).
  const auto even = [](double a, double b) {
    const double nearest = (a < 0) != (b < 0) ? 0 : std::fmin(std::fabs(a), std::fabs(b));
    return spacingAt(nearest) == spacingAt(std::fmax(std::fabs(a), std::fabs(b)));
  };
  if (even(s.ax, s.bx) && even(s.ay, s.by)) return;
  joinVerticesBetween(s, chain, others, xy);
}

struct RoundedCrossing {
  double x, y;
  bool operator<(const RoundedCrossing& o) const { return x != o.x ? x < o.x : y < o.y; }
};

}  // namespace

// Crossings::Snapped: links of snap-rounded chains never cross where the spacing of doubles
// is even; where it is not, two links may. Then both pass through one vertex: that of the
// rounding cell of their crossing (ISR's step) or an end of one of the links (below), which
// must keep the guarantee for both input segments, or this is a bug to report.
bool SegmentInserter::snapCrossing(const Piece& piece, std::int32_t h) {
  const ConstraintStore& store = d_.constraints;
  const std::uint32_t r = d_.topo.tri[h], l = d_.topo.tri[nextEdge(h)];
  const EdgeSource* crossed = store.find(r, l);
  if (!crossed) {
    error_ = {StatusCode::InternalError, "a constrained edge without a source"};
    return false;
  }
  const std::uint32_t crossedSegment = crossed->segment;
  const double* p = d_.xy.data();
  const InputSegment link{p[2 * piece.a], p[2 * piece.a + 1], p[2 * piece.b], p[2 * piece.b + 1]};
  const InputSegment edge{p[2 * r], p[2 * r + 1], p[2 * l], p[2 * l + 1]};
  const InputSegment g = store.geometry(piece.src.segment, d_.xy);
  const InputSegment t = store.geometry(crossedSegment, d_.xy);
  // Whether both chains keep the guarantee through (x, y): within each bound, and at an end
  // of each link or strictly between its ends along its segment.
  const auto keeps = [&](double x, double y) {
    const auto fits = [&](const InputSegment& s, std::uint32_t from, std::uint32_t to) {
      if (!withinDistance(s, x, y, chainBoundExponent(s))) return false;
      const auto at = [&](std::uint32_t v) { return p[2 * v] == x && p[2 * v + 1] == y; };
      if (at(from) || at(to)) return true;
      return signAlong(s, p[2 * from], p[2 * from + 1], x, y) *
                 signAlong(s, x, y, p[2 * to], p[2 * to + 1]) >
             0;
    };
    return fits(g, piece.a, piece.b) && fits(t, r, l);
  };
  // Whether bending both links through (x, y) sweeps over a vertex: one in the closed
  // triangle between a link and its bent path, its corners aside.
  const auto sweeps = [&](double x, double y) {
    return bendSweepsAVertex(piece.a, x, y, piece.b) || bendSweepsAVertex(r, x, y, l);
  };
  // The rounded crossing, where it keeps the guarantee and passes no vertex over; else an
  // end of either link that does (fuzz: in a tangle of sliver cells the rounded crossing lay
  // beyond a vertex on which another chain's link ended, and the bent path went round that
  // link); else the rounded crossing if it keeps the guarantee (its bend then takes the
  // vertices between with it).
  double x, y;
  roundedCrossing(link, edge, x, y);
  std::uint32_t w = kGhost;
  const bool roundedKeeps = keeps(x, y);
  if (!roundedKeeps || sweeps(x, y))
    for (const std::uint32_t v : {l, r, piece.b, piece.a})
      if (w == kGhost && keeps(p[2 * v], p[2 * v + 1]) && !sweeps(p[2 * v], p[2 * v + 1])) w = v;
  if (w == kGhost && roundedKeeps) {
    bool failed = false;
    w = addCrossingVertex(x, y, failed);
    if (failed) {
      error_ = d_.lastError();
      return false;
    }
  }
  if (w == kGhost) {
    error_ = {StatusCode::InternalError,
              "snap rounding found no vertex within the bound where two links cross"};
    return false;
  }
  // Both bend through w, and through any vertex the bend would otherwise pass over (fuzz: a
  // link bent past the end of another segment's chain, which then crossed it). The piece is
  // replaced by its links, the first on top; the crossed link's go above it.
  const std::size_t at = pieces_.size() - 1;
  std::vector<std::uint32_t> path;
  if (w != piece.a && w != piece.b) path = bentLink(g, piece.a, w, piece.b);
  if (w != r && w != l) {  // (else w split it already: it lay on it)
    const std::vector<std::uint32_t> bent = bentLink(t, r, w, l);
    bendAlong(bent.data(), bent.size());
  }
  if (path.empty()) return true;  // the piece stays as it is; the crossed link moved
  pieces_.erase(pieces_.begin() + static_cast<std::ptrdiff_t>(at));
  std::vector<Piece> links;
  for (std::size_t k = path.size() - 1; k > 0; --k)
    links.push_back({path[k - 1], path[k], piece.src});
  pieces_.insert(pieces_.begin() + static_cast<std::ptrdiff_t>(at), links.begin(), links.end());
  return true;
}

bool SegmentInserter::bendSweepsAVertex(std::uint32_t u, double wx, double wy, std::uint32_t v) {
  const double* p = d_.xy.data();
  const double ux = p[2 * u], uy = p[2 * u + 1], vx = p[2 * v], vy = p[2 * v + 1];
  if ((wx == ux && wy == uy) || (wx == vx && wy == vy)) return false;  // no bend
  const int turn = int(orient2d(ux, uy, wx, wy, vx, vy));
  const double minX = std::fmin(std::fmin(ux, vx), wx), maxX = std::fmax(std::fmax(ux, vx), wx);
  const double minY = std::fmin(std::fmin(uy, vy), wy), maxY = std::fmax(std::fmax(uy, vy), wy);
  const auto inside = [&](double x, double y) {
    if ((x == ux && y == uy) || (x == vx && y == vy) || (x == wx && y == wy)) return false;
    if (x < minX || x > maxX || y < minY || y > maxY) return false;
    const int a = int(orient2d(ux, uy, wx, wy, x, y)), b = int(orient2d(wx, wy, vx, vy, x, y));
    const int c = int(orient2d(vx, vy, ux, uy, x, y));
    if (turn == 0) return a == 0 && b == 0 && c == 0;  // the bend runs along the link
    return a * turn >= 0 && b * turn >= 0 && c * turn >= 0;
  };
  // The triangles that meet the triangle's box, from u's (a convex region: connected).
  const std::int32_t out = edgeOutOf(u);
  if (out < 0) return true;
  const std::vector<std::int32_t> found =
      searchTrianglesFrom(d_.topo, out, [&](const std::uint32_t* c) {
        double lox = INFINITY, hix = -INFINITY, loy = INFINITY, hiy = -INFINITY;
        for (int k = 0; k < 3; ++k) {
          lox = std::fmin(lox, p[2 * c[k]]), hix = std::fmax(hix, p[2 * c[k]]);
          loy = std::fmin(loy, p[2 * c[k] + 1]), hiy = std::fmax(hiy, p[2 * c[k] + 1]);
        }
        return lox <= maxX && hix >= minX && loy <= maxY && hiy >= minY;
      });
  for (const std::int32_t t : found)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t c = d_.topo.tri[3 * t + k];
      if (inside(p[2 * c], p[2 * c + 1])) return true;
    }
  return false;
}

std::vector<std::uint32_t> SegmentInserter::bentLink(const InputSegment& g, std::uint32_t u,
                                                     std::uint32_t w, std::uint32_t v) {
  // Such vertices lie within g's bound of the new links (between g and a link whose ends are
  // within it): the corners of the triangles that may meet those regions, found by a search
  // from u's triangles (the regions are convex and joined at w, so their triangles are too).
  const double* p = d_.xy.data();
  const double reach = std::ldexp(1.0, chainBoundExponent(g));
  const InputSegment first{p[2 * u], p[2 * u + 1], p[2 * w], p[2 * w + 1]};
  const InputSegment second{p[2 * w], p[2 * w + 1], p[2 * v], p[2 * v + 1]};
  std::vector<std::uint32_t> path{u, w, v};
  const std::int32_t out = edgeOutOf(u);
  if (out < 0) return path;
  const std::vector<std::int32_t> found =
      searchTrianglesFrom(d_.topo, out, [&](const std::uint32_t* c) {
        const double *c0 = p + 2 * c[0], *c1 = p + 2 * c[1], *c2 = p + 2 * c[2];
        return mayMeet(first, reach, c0, c1, c2) || mayMeet(second, reach, c0, c1, c2);
      });
  std::vector<std::uint32_t> others;
  for (const std::int32_t t : found)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t c = d_.topo.tri[3 * t + k];
      if (c != u && c != w && c != v) others.push_back(c);
    }
  std::sort(others.begin(), others.end());
  others.erase(std::unique(others.begin(), others.end()), others.end());
  // (The link may run against g's direction: the growth runs along it.)
  const bool backward = signAlong(g, p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1]) < 0;
  if (backward) std::reverse(path.begin(), path.end());
  joinVerticesBetween(g, path, others, p);
  if (backward) std::reverse(path.begin(), path.end());
  return path;
}

namespace {

Status finishSnapRounding(Delaunay& d, std::uint32_t keep, Delaunay& fresh);

// The geometry of segment i of fresh (its ends keep their ids and coordinates there).
InputSegment segmentOf(const Delaunay& fresh, std::size_t i) {
  return fresh.constraints.geometry(static_cast<std::uint32_t>(i), fresh.xy);
}

// What one round learns of the segments (snapRoundOnce's steps): the triangles near each,
// sorted as (triangle, segment), and the vertices each may pass through.
struct SnapRound {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> slotSegment;
  std::vector<std::vector<std::uint32_t>> candidates;  // per segment, with repeats
};

// The hot pixels that are vertices: the first keep vertices of d, with their ids (those removed
// by edits stay removed), and d's segments in fresh's store.
Status startRound(const Delaunay& d, std::uint32_t keep, Delaunay& fresh) {
  const Status status = fresh.insertKeepingIds(d.xy.data(), keep);
  if (!status.ok()) return status;
  ConstraintStore& store = fresh.constraints;
  store.segments = d.constraints.segments;
  store.segmentStarts = d.constraints.segmentStarts;
  store.polylinePoints = d.constraints.polylinePoints;
  store.firstSegment = d.constraints.firstSegment;
  store.ring = d.constraints.ring;
  store.polylineCount = d.constraints.polylineCount;
  store.reserve(store.segments.size(), fresh.vertexCount());
  return Status::success();
}

// The triangles near each segment, searched from a half-edge out of its first vertex: their
// corners are the vertices it may pass through, and two segments that cross share one of
// them.
Status findNearTriangles(Delaunay& fresh, SnapRound& round) {
  const ConstraintStore& store = fresh.constraints;
  const std::size_t n = store.segments.size();
  VertexEdges ends;
  ends.build(fresh);
  std::vector<std::int32_t> outOf(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!store.live(static_cast<std::uint32_t>(i))) continue;
    outOf[i] = ends.find(fresh, store.segments[i].a);
    if (outOf[i] < 0) return {StatusCode::InternalError, "snap rounding lost the end of a segment"};
  }
  std::vector<std::uint32_t> stamp(fresh.topo.slotCount(),
                                   std::numeric_limits<std::uint32_t>::max());
  std::vector<std::int32_t> found;
  round.candidates.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!store.live(static_cast<std::uint32_t>(i))) continue;
    int ex, ey;
    const InputSegment s = segmentOf(fresh, i);
    boxExponents(s, ex, ey);
    const double reach = euclideanNorm(std::ldexp(1.0, ex), std::ldexp(1.0, ey));
    trianglesNear(fresh, outOf[i], s, reach, static_cast<std::uint32_t>(i), stamp, found);
    for (const std::int32_t t : found) {
      round.slotSegment.push_back({static_cast<std::uint32_t>(t), static_cast<std::uint32_t>(i)});
      for (int k = 0; k < 3; ++k) round.candidates[i].push_back(fresh.topo.tri[3 * t + k]);
    }
  }
  std::sort(round.slotSegment.begin(), round.slotSegment.end());
  return Status::success();
}

// Rounded crossings of the segments that cross properly (pairs near a common triangle), and
// the extra hot pixels, sorted and without repeats.
std::vector<RoundedCrossing> roundedCrossings(const Delaunay& fresh, const SnapRound& round,
                                              const std::vector<double>& extra) {
  const auto& slotSegment = round.slotSegment;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t from = 0; from < slotSegment.size();) {
    std::size_t to = from;
    while (to < slotSegment.size() && slotSegment[to].first == slotSegment[from].first) ++to;
    for (std::size_t a = from; a < to; ++a)
      for (std::size_t b = a + 1; b < to; ++b)
        pairs.push_back({slotSegment[a].second, slotSegment[b].second});
    from = to;
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<RoundedCrossing> crossings;
  for (const auto& [i, j] : pairs) {
    const InputSegment s = segmentOf(fresh, i), t = segmentOf(fresh, j);
    if (!crossProperly(s, t)) continue;
    RoundedCrossing c{};
    roundedCrossing(s, t, c.x, c.y);
    crossings.push_back(c);
  }
  for (std::size_t k = 0; k + 1 < extra.size(); k += 2) {
    RoundedCrossing c{};
    c.x = extra[k];
    c.y = extra[k + 1];
    crossings.push_back(c);
  }
  std::sort(crossings.begin(), crossings.end());
  crossings.erase(std::unique(crossings.begin(), crossings.end(),
                              [](const RoundedCrossing& a, const RoundedCrossing& b) {
                                return a.x == b.x && a.y == b.y;
                              }),
                  crossings.end());
  return crossings;
}

// Each new crossing joins the candidates of the segments near the triangles holding it; then
// all are inserted, numbered from keep on.
Status insertCrossings(Delaunay& fresh, std::uint32_t keep,
                       const std::vector<RoundedCrossing>& crossings, SnapRound& round) {
  const auto near = [&](std::int32_t t, std::uint32_t v) {
    const std::uint32_t slot = static_cast<std::uint32_t>(t);
    auto it = std::lower_bound(round.slotSegment.begin(), round.slotSegment.end(),
                               std::pair<std::uint32_t, std::uint32_t>{slot, 0});
    for (; it != round.slotSegment.end() && it->first == slot; ++it)
      round.candidates[it->second].push_back(v);
  };
  std::vector<std::size_t> added;  // indices into crossings
  for (std::size_t c = 0; c < crossings.size(); ++c) {
    const Hit h = fresh.locate(crossings[c].x, crossings[c].y, true);
    if (h.kind == Hit::Kind::Vertex) continue;  // an existing vertex: already a candidate
    const std::uint32_t v = keep + static_cast<std::uint32_t>(added.size());
    added.push_back(c);
    near(h.edge / 3, v);
    if (h.kind == Hit::Kind::Edge) near(fresh.topo.adj[h.edge] / 3, v);
  }
  for (const std::size_t c : added) {
    const std::uint32_t v = fresh.vertexCount();
    fresh.xy.push_back(crossings[c].x);
    fresh.xy.push_back(crossings[c].y);
    if (fresh.insertVertex(v) != v)
      return {StatusCode::InternalError, "snap rounding could not insert a rounded crossing"};
  }
  return Status::success();
}

// Each segment's chain through its candidates, inserted link by link. bent: as snapRoundOnce's.
Status insertChains(Delaunay& fresh, SnapRound& round, bool& bent) {
  const ConstraintStore& store = fresh.constraints;
  VertexEdges ends;
  ends.build(fresh);  // with the rounded crossings
  SegmentInserter inserter(fresh, ends, Crossings::Snapped);
  std::vector<std::uint32_t> chain;
  const std::uint32_t hotPixels = fresh.vertexCount();
  for (std::size_t i = 0; i < store.segments.size(); ++i) {
    if (!store.live(static_cast<std::uint32_t>(i))) continue;
    std::vector<std::uint32_t>& list = round.candidates[i];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    chainOf(segmentOf(fresh, i), store.segments[i].a, store.segments[i].b, list, fresh.xy.data(),
            chain);
    const EdgeSource src = store.sourceOf(static_cast<std::uint32_t>(i));
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      if (inserter.insert(chain[k], chain[k + 1], src) == Outcome::Broken) {
        bent = true;
        return inserter.error();
      }
    }
  }
  bent = fresh.vertexCount() > hotPixels;
  return Status::success();
}

// One round of snap rounding into fresh: hot pixels are the first keep vertices of d, the
// rounded crossings of the segments, and extra (x, y pairs: vertices that bent crossing links
// in an earlier round). bent tells whether links crossed and were bent through new vertices,
// which chains routed before them may not pass through: then another round is due.
Status snapRoundOnce(const Delaunay& d, std::uint32_t keep, const std::vector<double>& extra,
                     Delaunay& fresh, bool& bent) {
  bent = false;
  SnapRound round;
  Status status = startRound(d, keep, fresh);
  if (status.ok()) status = findNearTriangles(fresh, round);
  if (status.ok())
    status = insertCrossings(fresh, keep, roundedCrossings(fresh, round, extra), round);
  if (status.ok()) status = insertChains(fresh, round, bent);
  return status;
}

}  // namespace

// Iterated: where links crossed and were bent through new vertices, the round starts again
// with those vertices as hot pixels too, so that every chain is routed through them (the
// hot pixels only grow, and each round is bounded; after the last round the result stands
// or its error is reported).
Status snapRoundConstraints(Delaunay& d, std::uint32_t keep, const Options& options) {
  constexpr int kRounds = 8;
  std::vector<double> extra;
  std::set<std::pair<double, double>> hot;
  for (int round = 0;; ++round) {
    Delaunay fresh(options);
    bool bent = false;
    const Status status = snapRoundOnce(d, keep, extra, fresh, bent);
    if (bent && round + 1 < kRounds) {
      // Every vertex past the input points becomes a hot pixel of the next round.
      const std::size_t before = hot.size();
      for (std::size_t k = 2 * static_cast<std::size_t>(keep); k + 1 < fresh.xy.size(); k += 2)
        hot.insert({fresh.xy[k], fresh.xy[k + 1]});
      if (hot.size() > before) {
        extra.clear();
        for (const auto& [x, y] : hot) {
          extra.push_back(x);
          extra.push_back(y);
        }
        continue;
      }
    }
    if (!status.ok()) return status;
    return finishSnapRounding(d, keep, fresh);
  }
}

namespace {

// d becomes fresh, with d's counts carried over.
Status finishSnapRounding(Delaunay& d, std::uint32_t keep, Delaunay& fresh) {
  // The old triangulation's counts, less the crossings it added in the attempt that failed,
  // plus those snap rounding added.
  const std::uint32_t dropped = d.vertexCount() - keep, rounded = fresh.vertexCount() - keep;
  Stats stats = d.stats;
  stats.inserted = stats.inserted - dropped + rounded;
  stats.crossings = stats.crossings - dropped + rounded;
  stats.walkSteps += fresh.stats.walkSteps;
  stats.locates += fresh.stats.locates;
  stats.flips += fresh.stats.flips;
  stats.walkFallbacks += fresh.stats.walkFallbacks;
  stats.segments += fresh.stats.segments;
  ++stats.snapRoundings;
  fresh.stats = stats;
  d = std::move(fresh);
  return Status::success();
}

}  // namespace

}  // namespace geocdt
