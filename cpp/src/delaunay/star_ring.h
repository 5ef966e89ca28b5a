#pragma once
// The border of a removed vertex's star as a polygon to cut into triangles again: its
// vertices counter-clockwise, linked in a list that loses a vertex with each ear cut off, and
// for each polygon edge the half-edge outside it that the triangle made on it is twinned
// with. Kept by the Delaunay engine between removals so that a removal allocates nothing.
#include <array>
#include <cstdint>
#include <vector>

namespace geocdt {

struct StarRing {
  std::vector<std::uint32_t> vertex;  // the ring, counter-clockwise (kGhost for the ghost)
  std::vector<std::int32_t> slot;     // the star's slots
  std::vector<std::int32_t> carrier;  // per node: the half-edge beyond edge node -> next
  std::vector<std::uint8_t> fixed;    // per node: that edge's constrained flag
  std::vector<std::int32_t> next, prev;
  std::vector<double> key;                         // per node: its ear's priority (cutInterior)
  std::vector<std::int32_t> diagonals;             // new edges inside the polygon, for Lawson flips
  std::vector<std::int32_t> border;                // the half-edges outside the polygon's edges
  std::size_t used = 0;                            // slots filled so far
  std::vector<std::uint32_t>* plan = nullptr;      // a planned removal's corners: nothing written
  std::vector<std::int32_t> made;                  // after a removal: the slots it filled
  std::vector<std::array<std::int32_t, 2>> moved;  // and {from, to} of triangles it moved

  void clear() {
    vertex.clear();
    slot.clear();
    carrier.clear();
    fixed.clear();
    diagonals.clear();
    border.clear();
    made.clear();
    moved.clear();
    used = 0;
  }
};

}  // namespace geocdt
