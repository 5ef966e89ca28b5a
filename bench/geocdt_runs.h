#pragma once
// One repetition of each geocdt measurement. Input preparation is outside the timed parts.
#include <string>
#include <vector>

#include "geocdt/triangulation.h"
#include "measurement.h"
#include "polyline_file.h"

namespace bench {

// Builds the Delaunay triangulation of xy; pointSeconds times the build, and the walk
// statistics come from the triangulation's Stats.
bool geocdtDelaunay(const std::vector<double>& xy, const geocdt::Options& options, Sample& sample,
                    std::string& error);

// The wasm binding's case: the caller writes the points into a heap buffer (counted in the
// peak, not timed), which the triangulation adopts, then the mesh is handed out. Times
// insertPoints and release together, as one call of the binding does.
bool geocdtDelaunayAdopted(const std::vector<double>& xy, Sample& sample, std::string& error);

// The same, then times two things the insertion order alone cannot speed up: inserting
// `late` points into the finished triangulation (edgeSeconds) and locating `queries`
// (extraSeconds). lateWalkSteps/lateLocates count the late inserts.
bool geocdtDelaunayThenLate(const std::vector<double>& xy, const std::vector<double>& late,
                            const std::vector<double>& queries, const geocdt::Options& options,
                            Sample& sample, std::string& error);

enum class ConstrainedCalls {
  // As the paper's Table I splits the time: all free points and polyline points by
  // insertPoints (pointSeconds), then all polylines by insertPolylines (edgeSeconds), which
  // finds their points again as duplicates.
  PointsThenPolylines,
  // What a user calls: insertPoints for the free points, then one insertPolylines
  // (edgeSeconds) that inserts the polyline points and segments.
  OneCall,
};

// A constrained triangulation. The result is checked for flipped and zero-area triangles.
bool geocdtConstrained(const std::vector<double>& freePoints,
                       const geocdt::testing::PolylineSet& polylines, ConstrainedCalls calls,
                       Sample& sample, std::string& error, const geocdt::Options& options = {});

}  // namespace bench
