#pragma once
// One checker for every test: the properties a valid (constrained) Delaunay triangulation
// must have, decided with exact predicates. Returns "" when all hold, else the first failure.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geocdt/triangulation.h"

namespace geocdt::testing {

struct CheckOptions {
  // Input points that must be vertices: x, y pairs and the vertex id each one got.
  const std::vector<double>* inputXY = nullptr;
  const std::vector<std::uint32_t>* inputToVertex = nullptr;
  bool delaunay = true;  // check local Delaunay of unconstrained interior edges
  // The boundary is the convex hull (one convex loop, Euler's count); false for a mesh of
  // part of it (keep inside, a terrain's area with data), whose boundary is not checked.
  bool hull = true;
};

std::string checkTriangulation(const Mesh& mesh, const CheckOptions& options = {});

// Hull vertex count of the mesh (boundary loop length), for tests that predict it.
std::size_t hullSize(const Mesh& mesh);

// The triangles as a sorted list, each turned to start at its least vertex: two meshes of the
// same points have the same triangles when these are equal.
std::vector<std::array<std::uint32_t, 3>> triangleSet(const Mesh& mesh);

}  // namespace geocdt::testing
