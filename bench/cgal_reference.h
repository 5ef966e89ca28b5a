#pragma once
// CGAL, the reference the benchmark compares geocdt against, measured in the same run.
// Built from cgal_reference.cpp when CMake finds CGAL, else from cgal_reference_missing.cpp.
#include <cstdint>
#include <string>
#include <vector>

#include "measurement.h"
#include "polyline_file.h"

namespace bench {

bool cgalAvailable();
std::string cgalDescription();  // the CGAL version, or why there is none

// Delaunay_triangulation_2 with Exact_predicates_inexact_constructions_kernel, built by
// its range insert (which sorts spatially).
bool cgalDelaunay(const std::vector<double>& xy, Sample& sample, std::string& error);

enum class CgalKernel {
  Inexact,  // Exact_predicates_inexact_constructions_kernel: crossings rounded by CGAL
  Exact,    // Exact_predicates_exact_constructions_kernel: exact crossings, output rounded
};

// Constrained_Delaunay_triangulation_2 with Exact_predicates_tag. The points phase inserts
// the free points and every polyline point in spatial order (as CGAL's own
// insert_constraints does); the edge phase inserts every segment by its vertex handles.
// The result is checked with countBadTriangles on its double coordinates.
bool cgalConstrained(const std::vector<double>& freePoints,
                     const geocdt::testing::PolylineSet& polylines, CgalKernel kernel,
                     Sample& sample, std::string& error);

// Counts clockwise (flipped) and collinear (zero-area) triangles by exact orientation:
// CGAL's when available, else geocdt's own predicate.
void countBadTriangles(const std::vector<double>& xy, const std::vector<std::uint32_t>& triangles,
                       Sample& sample);

}  // namespace bench
