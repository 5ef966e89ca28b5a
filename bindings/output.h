#pragma once
// What one call hands back to JS. The arrays stay in the wasm heap only until JS has copied
// each of them out with a single slice; clear() then frees them, so no heap view outlives
// the call that made it.
#include <emscripten/val.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geocdt/status.h"
#include "geocdt/terrain.h"
#include "geocdt/triangulation.h"
#include "geocdt/voronoi.h"

namespace geocdt::wasm {

// The arrays an Output holds. JS finds them by the names and element types below (passed on
// by module.cpp), so this is the only list of them.
enum class Field : int {
  Points,
  Triangles,
  Halfedges,
  Constrained,
  ConstraintEdges,
  SourceOffsets,
  Sources,
  Inside,
  Regions,
  Values,
  InputToVertex,
  VertexIds,
  Raster,
  Steiner,
  SteinerParents,
  SteinerWeights,
  SegmentOffsets,
  SegmentSources,
  // voronoi()'s cells, and its sites where Lloyd's relaxation moved them
  Coords,
  RingOffsets,
  PolygonOffsets,
  SiteOffsets,
  Sites,
};

// Named after the JS typed array that holds such elements (Float64Array, ...).
enum class ElementType : int { Float64, Float32, Int32, Uint32, Uint8 };

const char* jsName(Field field);  // nullptr past the last field
const char* jsName(ElementType type);
ElementType elementType(Field field);

class Output {
 public:
  // With values: mesh.values, the values of each vertex (of interpolate(): of each query).
  Mesh mesh;
  std::vector<float> raster;  // of rasterize()
  std::vector<std::uint32_t> inputToVertex;
  std::vector<std::uint32_t> vertexIds;  // of the last incremental insertion
  VoronoiCells cells;                    // of voronoi()
  Status status;
  Stats stats;
  TerrainStats terrain;  // of triangulateRaster()

  // Byte address and element count of one array in the wasm heap (field: a Field's number).
  std::uintptr_t data(int field) const;
  std::size_t size(int field) const;

  StatusCode code() const { return status.code; }
  std::string message() const { return status.message; }
  // kNoIndex becomes -1 so that JS sees a plain number.
  double index() const;
  double segment() const;
  // The statistics as a JS object, one property per counter.
  emscripten::val statsObject() const;
  // triangulateRaster()'s measurements as a JS object.
  emscripten::val terrainStats() const;
  // voronoi()'s statistics, the same way.
  emscripten::val voronoiStats() const;

  void clear();  // frees every array: the heap returns to where it was before the call
  // Where this object lives, for the plain editing exports (edit_calls.cpp).
  std::uintptr_t objectAddress() const { return reinterpret_cast<std::uintptr_t>(this); }
};

// Stats as a JS object: the one list of the statistics' names.
emscripten::val statsObject(const Stats& stats);

}  // namespace geocdt::wasm
