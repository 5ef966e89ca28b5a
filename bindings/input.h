#pragma once
// A call's input, written by JS straight into buffers that the binding owns: JS sizes them
// with resize(), then copies each caller array in with one TypedArray.set() at their
// addresses. No other copy is made on the way to the core. The coordinates are kept as
// std::vector<double> so that the core can adopt them by move once it takes them that way.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geocdt/triangulation.h"
#include "heap_vectors.h"

namespace geocdt::wasm {

class Input {
 public:
  // x, y of the points (of the incremental calls: of this call's points or polyline).
  std::vector<double> points;
  // The polylines in GeoArrow's layout: polyline i has the points lineOffsets[i] ..
  // lineOffsets[i + 1] of lineCoords (x, y interleaved); lineOffsets has lineCount + 1 entries.
  std::vector<double> lineCoords;
  std::vector<std::uint32_t> lineOffsets;
  // Polygons, for region labels: polygon j has the polylines polygonOffsets[j] ..
  // polygonOffsets[j + 1] - 1. Empty when the call has none (not even an empty list).
  std::vector<std::uint32_t> polygonOffsets;
  // Values: valuesPerPoint per input point (the points, then the polylines' points), or empty.
  std::vector<double> values;
  // The heights of triangulateRaster()'s raster, row by row.
  std::vector<double> raster;
  // The vertex ids of a batch edit (removePoints).
  std::vector<std::uint32_t> ids;

  // Sizes the arrays for JS to fill (the numbers arrive as doubles: JS may ask for more than
  // size_t holds); polygonCount -1: no polygons. false when memory runs out; everything is
  // freed then.
  bool resize(double pointCount, double linePointCount, double lineCount, double polygonCount,
              double valueCount);
  std::uintptr_t pointsAddress() const { return heapAddress(points); }
  std::uintptr_t lineCoordsAddress() const { return heapAddress(lineCoords); }
  std::uintptr_t lineOffsetsAddress() const { return heapAddress(lineOffsets); }
  std::uintptr_t polygonOffsetsAddress() const { return heapAddress(polygonOffsets); }
  std::uintptr_t valuesAddress() const { return heapAddress(values); }
  // Sizes the raster's heights (after resize(), which frees them); false when memory runs out.
  bool resizeRaster(double pixels);
  std::uintptr_t rasterAddress() const { return heapAddress(raster); }
  // Sizes the ids (freed by clear()); false when memory runs out.
  bool resizeIds(double count);
  std::uintptr_t idsAddress() const { return heapAddress(ids); }

  // The first i where lineOffsets breaks the layout, or -1: lineOffsets[0] is 0, no offset is
  // below the one before it, and the last one is the number of points in lineCoords.
  double badOffset() const;
  // The first i where polygonOffsets breaks its layout, or -1: no offset below the one before
  // it, none past polylineCount.
  double badPolygonOffset(double polylineCount) const;
  bool hasPolygons() const { return !polygonOffsets.empty(); }
  // The polygon of each polyline up to the last that has one, -1 for the others.
  std::vector<std::int32_t> polylinePolygons() const;

  std::size_t pointCount() const { return points.size() / 2; }
  std::size_t linePointCount() const { return lineCoords.size() / 2; }
  std::size_t lineCount() const { return lineOffsets.empty() ? 0 : lineOffsets.size() - 1; }
  // One view per polyline into lineCoords (once badOffset() is -1).
  std::vector<PolylineView> polylines() const;

  void clear();             // frees the buffers
  void clearCoordinates();  // frees the points and polylines, keeps polygons and values
};

}  // namespace geocdt::wasm
