#pragma once
// The domain that cells are clipped to, held as its boundary: closed loops with the domain on
// their left, which meet only at shared vertices (a vertex where loops touch is one vertex, so
// boundary segments never cross). A box, the sites' convex hull, or the inside of rings by a
// fill rule, taken from their constrained triangulation: crossings, overlaps and shared
// borders of the rings are resolved there, and the domain is the union of its inside
// triangles.
#include <cstdint>
#include <vector>

#include "exact/bisector_predicates.h"
#include "geocdt/status.h"
#include "geocdt/triangulation.h"

namespace geocdt {

struct Domain {
  std::vector<XY> points;                         // every loop's vertices, loop after loop
  std::vector<std::uint32_t> loopOffsets{0};      // loop i: points[loopOffsets[i] .. [i + 1])
  double area = 0;                                // of the inside, in doubles
  double minX = 0, minY = 0, maxX = 0, maxY = 0;  // bounds of the points, when there are any

  std::uint32_t loopCount() const { return static_cast<std::uint32_t>(loopOffsets.size() - 1); }
  bool empty() const { return points.empty(); }
  // The vertex after point k (a global index) in its loop, given the loop.
  std::uint32_t next(std::uint32_t k, std::uint32_t loop) const {
    return k + 1 == loopOffsets[loop + 1] ? loopOffsets[loop] : k + 1;
  }
  void addLoop(const std::vector<XY>& loop);
};

// [xmin, ymin, xmax, ymax], xmin < xmax and ymin < ymax.
Domain boxDomain(const double box[4]);

// The inside of the rings by the fill rule (open polylines bound nothing; they still cut the
// triangles, harmlessly). threads: for the rings' points.
Status ringDomain(const PolylineView* rings, std::size_t count, FillRule fill,
                  std::uint32_t threads, Domain& out);

// The convex polygon with the given vertices in counter-clockwise order (none when fewer than
// three).
Domain convexDomain(const std::vector<XY>& hull);

}  // namespace geocdt
