#pragma once
// The refinement half of the checker: a refined triangulation is a valid constrained
// Delaunay triangulation of its input (the other checkers), and besides, its triangles meet
// the bounds except those the stats own up to, and its Steiner vertices are where their
// records say.
#include <string>
#include <vector>

#include "constraint_invariants.h"
#include "geocdt/triangulation.h"

namespace geocdt::testing {

// Smallest angle of triangle t in degrees, and its area.
double smallestAngle(const Mesh& mesh, std::size_t t);
double triangleArea(const Mesh& mesh, std::size_t t);

// Triangles (of those with inside set, when insideOnly; mesh.inside must be filled) whose
// smallest angle is below minAngle or whose area exceeds maxArea (0: no bound), with a
// relative slack of 1e-9 for the rounding of the measures.
std::size_t countBadTriangles(const Mesh& mesh, double minAngle, double maxArea, bool insideOnly);

// Checks what refinement promises beyond a valid CDT, from the mesh alone: every Steiner
// vertex is a new vertex (id at least firstSteiner), listed once, with weights summing to 1
// that put it (to 1e-9 of its parents' spread) at its coordinates; input points are not
// Steiner vertices. Returns "" when all hold, else the first failure.
std::string checkSteinerRecords(const Mesh& mesh, std::size_t firstSteiner);

// Everything at once for a mesh exported with insideFlags (keep all): both checkers, the
// records, and the bounds (bad triangles at most `allowed`). inputXY are the input points
// (not polylines' points) and ids the vertex of every input point, points first.
std::string checkRefined(const Mesh& mesh, const std::vector<double>& inputXY,
                         const Polylines& polylines, const std::vector<std::uint32_t>& ids,
                         double minAngle, double maxArea, bool insideOnly, std::size_t allowed);

}  // namespace geocdt::testing
