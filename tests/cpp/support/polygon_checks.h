#pragma once
// The checker of triangulatePolygons(), polygon by polygon, with exact predicates:
//  - offsets: triangleOffsets has a start per polygon plus one, never decreasing, ending at the
//    triangle count; every index names an input point or an extra point;
//  - every triangle strictly counter-clockwise (y up);
//  - each directed edge (by position) used once in its polygon;
//  - every edge on the border of the polygon's triangles (its twin unused) lies on a ring
//    segment (within the crossings' rounding bound where it ends at an extra point);
//  - every triangle inside by the fill rule: the winding number of a point strictly inside it,
//    counted exactly against the ring segments, none of which may pass through it;
//  - constrained Delaunay: an edge shared by two of the polygon's triangles and on no ring
//    segment has the fourth point outside or on the circle through the other three;
//  - the area inside, in rationals, equals that of geocdt::triangulate(rings, keep inside) with
//    the same fill rule.
// Returns "" when all hold, else the first failure, naming the polygon.
#include <string>

#include "geocdt/polygons.h"

namespace geocdt::testing {

struct PolygonCheckOptions {
  FillRule fill = FillRule::EvenOdd;
  bool compareArea = true;  // the reference triangulation (the slowest part)
};

std::string checkPolygonTriangles(const PolygonBatch& batch, const PolygonTriangles& out,
                                  const PolygonCheckOptions& options = {});

}  // namespace geocdt::testing
