#pragma once
// The object behind JS triangulatePolygons() and earcut(): a whole batch in and out in three
// calls (prepare, run, release), whatever the number of polygons. JS writes the caller's
// arrays straight into the buffers prepare() sizes, reads the results from where run() says,
// with one copy each way, and release() frees everything. The addresses and sizes travel
// through a small table in the heap (header()), not as return values, so that a call costs
// three crossings of the embind boundary: the earcut() form pays them for each polygon.
#include <emscripten/val.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geocdt/polygons.h"

namespace geocdt::wasm {

class PolygonCall {
 public:
  // The header's entries, each a uint32: the input buffers' addresses (after prepare), then
  // the results' addresses and element counts (after run).
  enum Slot : int {
    Coords,
    RingOffsets,
    PolygonOffsets,
    Triangles,
    TriangleCount,  // indices, 3 per triangle
    ExtraPoints,
    ExtraCount,  // doubles, 2 per point
    TriangleOffsets,
    OffsetCount,
    SlotCount,
  };

  std::uintptr_t header() const { return reinterpret_cast<std::uintptr_t>(header_.data()); }
  // Sizes the input: coordValues doubles of coordinates (dim per point), rings + 1 ring
  // offsets, polygons + 1 polygon offsets. false when memory runs out (all freed then).
  bool prepare(double coordValues, double rings, double polygons);
  // Triangulates what JS wrote (points of dim coordinates, x and y first); the inputs are
  // freed. Returns whether it succeeded; on failure code() and the rest say why.
  bool run(std::uint32_t dim, FillRule fill, std::uint32_t threads);
  void release();  // frees the inputs and results

  StatusCode code() const { return status_.code; }
  std::string message() const { return status_.message; }
  double index() const;    // the polygon named by a failure, or -1
  double segment() const;  // the ring (an index into ringOffsets), or -1
  emscripten::val stats() const;

 private:
  std::vector<double> coords_;
  std::vector<std::uint32_t> rings_, polygons_;
  PolygonTriangles out_;
  PolygonStats stats_;
  Status status_;
  std::array<std::uint32_t, SlotCount> header_{};
};

}  // namespace geocdt::wasm
