#pragma once
// Snap rounding of the constraints, for the tangles where computing each crossing and
// checking that it fits gets lost: vertices a few ulps apart, every crossing rounding onto
// the same few doubles.
//
// Every vertex (input point or rounded crossing) owns the box of points that round to it;
// a segment passes through the vertex of every box it meets, in order along it. For a
// segment whose doubles are evenly spaced (the usual case: within one binade on each axis)
// the box is the rounding box itself; otherwise it is widened to the largest spacing the
// segment spans, so that whatever lies between a segment and its chain is a box the
// segment meets, hence on the chain: a vertex never changes sides, which is what keeps the
// crossings (Hobby; Guibas and Marimont; the widening is what makes uneven spacing work).
// Each vertex of a chain lies within sqrt(2)/2 spacings of its segment, each link between
// two of them too, well inside the documented bound of two spacings. Where links still
// cross (uneven spacing), both bend through the rounded crossing, taking with them every
// vertex that lies between a bent link and its segment; where that bend would pass a vertex
// over, through an end of one of the two links instead (tests/fuzz/findings/README.md).
#include <cstdint>

#include "delaunay/delaunay.h"

namespace geocdt {

// Rebuilds d from its first `keep` vertices and every segment in its constraint store:
// the vertices keep their ids, rounded crossings come after them, and each segment becomes
// its snap-rounded chain. Vertices from `keep` on (crossings added since) are dropped.
// Where links of the chains still cross (uneven spacing of doubles) and are bent through new
// vertices, it starts again with those vertices as hot pixels, at most 8 rounds.
Status snapRoundConstraints(Delaunay& d, std::uint32_t keep, const Options& options);

}  // namespace geocdt
