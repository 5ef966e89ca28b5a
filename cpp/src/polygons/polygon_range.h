#pragma once
// A contiguous range of a batch's polygons, triangulated one after the other into arrays of
// the range's own: the unit of work a thread takes. Its scratch memory (the small path's, the
// ring offsets) is kept from polygon to polygon, and from range to range on one thread.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geocdt/polygons.h"
#include "polygons/general_polygon.h"
#include "polygons/polygon_cdt.h"

namespace geocdt {

class PolygonRange {
 public:
  // Triangulates polygons [first, last) of batch (checked) into triangles and extras: an
  // extra point's index is batch.pointCount + its place in extras (extras.size() / 2 when it
  // was added). ends[p - first] gets triangles.size() / 3 after polygon p. Adds to stats.
  Status run(const PolygonBatch& batch, FillRule fill, std::size_t first, std::size_t last,
             std::vector<std::uint32_t>& triangles, std::vector<double>& extras,
             std::uint32_t* ends, PolygonStats& stats);

 private:
  PolygonCdt small_;
  GeneralPolygon general_;
  std::vector<std::uint32_t> ringStarts_;
};

}  // namespace geocdt
