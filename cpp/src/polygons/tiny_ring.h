#pragma once
// Polygons of one ring with three or four distinct points (half a city tile's polygons are
// buildings like that), triangulated without building a triangulation: a triangle as it is,
// a convex quad split along its Delaunay diagonal, a concave one from its reflex corner: the
// constrained Delaunay triangulation of the ring, by exact orientation and in-circle tests.
#include <cstdint>
#include <vector>

namespace geocdt {

// xy: the ring's n points (x, y pairs), closed or open. Appends its inside triangles
// (counter-clockwise, indices base + the first local index of each position) to out and
// returns true; returns false (out as it was) for anything else: more points, points
// repeated out of turn, collinear corners, or a ring that crosses itself.
bool triangulateTinyRing(const double* xy, std::uint32_t n, std::uint32_t base,
                         std::vector<std::uint32_t>& out);

}  // namespace geocdt
