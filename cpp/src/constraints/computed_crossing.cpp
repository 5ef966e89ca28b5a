// Crossings::Computed: where a piece of the segment being inserted crosses a constrained
// edge, the crossing of the two input segments is computed, rounded, and checked to fit.
// Three outcomes, tried in order:
//
//  1. Split: the rounded crossing x lies strictly inside the two triangles of the crossed
//     edge r-l (and is no vertex): x splits r-l, and the piece a-b becomes a-x, x-b.
//
//              b                          b
//         c1   :                     c1   :
//        /  \  :                    /  \  |
//       r----+--l        ==>       r----x--l
//        \  / :                     \  /  |
//         c2  :                      c2   :
//             a                           a
//
//  2. Through a vertex: x rounds next to a vertex (within 1e-12 of the shorter piece), or
//     lies outside the two triangles (thin ones): both constraints pass through one vertex
//     w, that one or a new vertex at x, unless that would make one double back.
//
//              b                     b
//              :                     |
//       r------+-w---l   ==>    r----w----l
//              :                     |
//              a                     a
//
//  3. Meet at an end: no crossing point fits (the two are collinear within rounding, so
//     the crossing of their lines means nothing): one constraint bends through the end of
//     the other that lies within its span and nearest to its line.
//
//       a ················ b           a ····· r ····· b
//             r ─────────────── l  ==>         r ─────────── l
//
// A tangle of vertices a few ulps apart can send these round in circles, or leave a chain
// beyond the guarantee: the caller then snap-rounds (snap_rounding.h).
#include <cmath>
#include <utility>

#include "constraints/segment_inserter.h"
#include "exact/euclidean_norm.h"
#include "exact/exact_geometry.h"
#include "geocdt/predicates.h"

namespace geocdt {

namespace {

// How far v lies from the line through u0 and u1, times 2^scale: a choice between nearby
// vertices, in double (alike on every platform), on coordinates scaled so that their
// differences neither underflow nor overflow.
double offLine(const double* p, std::uint32_t v, std::uint32_t u0, std::uint32_t u1, int scale) {
  const auto at = [&](std::uint32_t i) { return std::ldexp(p[i], scale); };
  const double dx = at(2 * u1) - at(2 * u0), dy = at(2 * u1 + 1) - at(2 * u0 + 1);
  const double cross = dx * (at(2 * v + 1) - at(2 * u0 + 1)) - dy * (at(2 * v) - at(2 * u0));
  return std::fabs(cross) / euclideanNorm(dx, dy);
}

}  // namespace

// Where (x, y) lies along g's direction, compared with vertex u: the sign of the projection
// of their difference, exactly (near the end of a segment 1e-63 long, a vertex 1e-182 away
// must still compare apart).
int SegmentInserter::Crossing::beyond(const double* p, const InputSegment& g, double x, double y,
                                      std::uint32_t u) {
  return signAlong(g, p[2 * u], p[2 * u + 1], x, y);
}

// Between lo and hi along g's direction: beyond one and short of the other.
bool SegmentInserter::Crossing::between(const double* p, const InputSegment& g, double x, double y,
                                        std::uint32_t lo, std::uint32_t hi) {
  return beyond(p, g, x, y, lo) * beyond(p, g, x, y, hi) < 0;
}

bool SegmentInserter::Crossing::fits(const double* p, double x, double y) const {
  return between(p, ab, x, y, piece.a, piece.b) && between(p, cd, x, y, r, l);
}

std::uint32_t SegmentInserter::resolveCrossing(const Piece& piece, std::int32_t h) {
  const Topology& topo = d_.topo;
  const ConstraintStore& store = d_.constraints;
  const double* p = d_.xy.data();
  Crossing c;
  c.piece = piece;
  c.h = h;
  c.r = topo.tri[h];
  c.l = topo.tri[nextEdge(h)];
  c.c1 = topo.tri[prevEdge(h)];
  c.c2 = topo.tri[prevEdge(topo.adj[h])];
  const EdgeSource* crossedSource = store.find(c.r, c.l);
  const InputSegment edge{p[2 * c.r], p[2 * c.r + 1], p[2 * c.l], p[2 * c.l + 1]};
  c.ab = store.geometry(piece.src.segment, d_.xy);
  c.cd = crossedSource ? store.geometry(crossedSource->segment, d_.xy) : edge;
  // Two input segments meet at one vertex: once their crossing has one, later crossings of
  // their pieces (after rounding bent them) go there too, so no run of ever new vertices.
  c.pair = ConstraintStore::key(piece.src.segment, crossedSource ? crossedSource->segment : kGhost);
  // Both chains may now leave their segments, unless the crossing splits (see split).
  const std::size_t untouched = touchedSegments_.size();
  const auto touch = [&](std::uint32_t i) { touchedSegments_.push_back(i); };
  store.forEachSegment(piece.src, touch);
  const std::size_t crossedFrom = touchedSegments_.size();
  if (crossedSource) store.forEachSegment(*crossedSource, touch);

  // Whether every segment of the piece crosses every segment of the crossed edge, exactly.
  const auto allCross = [&] {
    const std::size_t end = touchedSegments_.size();
    for (std::size_t i = untouched; i < crossedFrom; ++i)
      for (std::size_t j = crossedFrom; j < end; ++j)
        if (!crossProperly(store.geometry(touchedSegments_[i], d_.xy),
                           store.geometry(touchedSegments_[j], d_.xy)))
          return false;
    return crossedFrom < end;
  };

  // The crossing point: where the pair met before; else the crossing of the two input
  // segments, unless rounding and earlier bends put it outside the two pieces that cross
  // here; then the crossing of the pieces.
  double x = 0, y = 0;
  bool ofPieces = false;  // found from the pieces: the input segments may not cross at all
  std::uint32_t w = kGhost;
  if (const std::uint32_t* met = met_.find(c.pair); met && *met < d_.vertexCount()) {
    w = *met;
    x = p[2 * w];
    y = p[2 * w + 1];
  } else if (!roundedLineCrossing(c.ab, c.cd, x, y) || !c.fits(p, x, y)) {
    const InputSegment part{p[2 * piece.a], p[2 * piece.a + 1], p[2 * piece.b], p[2 * piece.b + 1]};
    if (!roundedLineCrossing(part, edge, x, y) || !c.fits(p, x, y)) return meetAtAnEnd(c, x, y);
    ofPieces = true;
  }

  // Snapping is for rounding, relative to the shorter of the two pieces that cross here
  // (an input segment can be 1e76 long and still cross a short one).
  const auto distance = [&](std::uint32_t v) {
    return euclideanNorm(p[2 * v] - x, p[2 * v + 1] - y);
  };
  const auto length = [&](std::uint32_t u, std::uint32_t v) {
    return euclideanNorm(p[2 * v] - p[2 * u], p[2 * v + 1] - p[2 * u + 1]);
  };
  const double snapDistance = 1e-12 * std::min(length(piece.a, piece.b), length(c.r, c.l));
  std::uint32_t nearest = c.r;
  for (const std::uint32_t v : {c.l, piece.a, piece.b})
    if (distance(v) < distance(nearest)) nearest = v;
  const bool near = distance(nearest) <= snapDistance;
  const auto strictlyLeft = [&](std::uint32_t u, std::uint32_t v) {
    return orient2d(p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1], x, y) == Sign::Positive;
  };
  if (w == kGhost && !near && strictlyLeft(c.c1, c.r) && strictlyLeft(c.r, c.c2) &&
      strictlyLeft(c.l, c.c1) && strictlyLeft(c.c2, c.l)) {
    // The crossed constraint bends inside its own two triangles, where no vertex lies: when
    // x was found from the input segments and every segment of one edge crosses every one of
    // the other (an edge can hold several, one of them bent onto it: fuzz), nothing for
    // chainsKeepTheGuarantee to check here.
    if (!ofPieces && allCross()) touchedSegments_.resize(untouched);
    return split(c, x, y);
  }

  // Through a vertex: the one x is (nearly) equal to, or a new one wherever x lies.
  if (w == kGhost && near) w = nearest;
  if (w == kGhost) {
    bool failed = false;
    w = addCrossingVertex(x, y, failed);
    if (failed) return kGhost;
    met_.insert(c.pair, w);
    p = d_.xy.data();  // the push may have moved the coordinates
  }
  const double wx = p[2 * w], wy = p[2 * w + 1];
  const bool pieceEnd = w == piece.a || w == piece.b;
  const bool crossedEnd = w == c.r || w == c.l;
  // w would make a constraint double back: meet at an end instead.
  if (!(pieceEnd || Crossing::between(p, c.ab, wx, wy, piece.a, piece.b)) ||
      !(crossedEnd || Crossing::between(p, c.cd, wx, wy, c.r, c.l)))
    return meetAtAnEnd(c, x, y);
  if (!crossedEnd) bendThrough(c.r, c.l, w);
  return pieceEnd ? kGhost : w;
}

std::uint32_t SegmentInserter::split(const Crossing& c, double x, double y) {
  const std::uint32_t v = d_.vertexCount();
  met_.insert(c.pair, v);
  d_.xy.push_back(x);
  d_.xy.push_back(y);
  d_.constraints.split(c.r, c.l, v);
  // The rounded point is near the edge, not on it: the spokes to the two apexes may need
  // flips that a point exactly on the edge would never need.
  const std::int32_t spoke = d_.splitEdge(c.h, v);
  ends_.set(v, spoke);
  for (std::int32_t e = spoke;;) {
    d_.flipStack().push_back(e);
    e = d_.topo.adj[prevEdge(e)];
    if (e == spoke) break;
  }
  d_.restoreDelaunay();
  ++d_.stats.crossings;
  ++d_.stats.inserted;
  return v;
}

std::uint32_t SegmentInserter::meetAtAnEnd(const Crossing& c, double x, double y) {
  const double* p = d_.xy.data();
  // One scale for the four vertices: their largest difference (halved here, which cannot
  // overflow) becomes about 1.
  double largest = 0;
  for (const std::uint32_t v : {c.piece.b, c.r, c.l})
    for (int k = 0; k < 2; ++k)
      largest = std::fmax(largest, std::fabs(0.5 * p[2 * v + k] - 0.5 * p[2 * c.piece.a + k]));
  int scale = 0;
  if (largest > 0) {
    std::frexp(largest, &scale);
    scale = -scale - 1;
  }
  std::uint32_t best = kGhost;
  double bestOff = 0;
  const auto consider = [&](std::uint32_t v, const InputSegment& g, std::uint32_t u0,
                            std::uint32_t u1) {
    // Ends count as within: ends that nearly coincide must be able to meet.
    if (Crossing::beyond(p, g, p[2 * v], p[2 * v + 1], u0) *
            Crossing::beyond(p, g, p[2 * v], p[2 * v + 1], u1) >
        0)
      return;
    const double off = offLine(p, v, u0, u1, scale);
    if (best == kGhost || off < bestOff) {
      best = v;
      bestOff = off;
    }
  };
  consider(c.piece.a, c.cd, c.r, c.l);
  consider(c.piece.b, c.cd, c.r, c.l);
  consider(c.r, c.ab, c.piece.a, c.piece.b);
  consider(c.l, c.ab, c.piece.a, c.piece.b);
  const auto distance = [&](std::uint32_t v) {
    return euclideanNorm(p[2 * v] - x, p[2 * v + 1] - y);
  };
  if (best == kGhost) best = distance(c.r) <= distance(c.l) ? c.r : c.l;
  if (best == c.r || best == c.l) return best;  // the piece bends through it
  bendThrough(c.r, c.l, best);                  // the crossed constraint bends through a piece end
  return kGhost;
}

}  // namespace geocdt
