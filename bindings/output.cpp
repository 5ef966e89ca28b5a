#include "output.h"

#include <iterator>

#include "heap_vectors.h"

// A Field without its case below is an error, not a warning.
#pragma clang diagnostic error "-Wswitch"

namespace geocdt::wasm {
namespace {

double indexOrMinusOne(std::size_t i) { return i == kNoIndex ? -1.0 : static_cast<double>(i); }

// Every counter of Stats, under its own name: the names JS sees are the C++ ones.
struct StatField {
  const char* name;
  double (*read)(const Stats&);
};
#define GEOCDT_STAT(field)                                              \
  {                                                                     \
#field, [](const Stats& s) { return static_cast<double>(s.field); } \
  }
constexpr StatField kStatFields[] = {
    GEOCDT_STAT(inserted),
    GEOCDT_STAT(duplicates),
    GEOCDT_STAT(walkSteps),
    GEOCDT_STAT(locates),
    GEOCDT_STAT(flips),
    GEOCDT_STAT(walkFallbacks),
    GEOCDT_STAT(gridSize),
    GEOCDT_STAT(crossings),
    GEOCDT_STAT(polylines),
    GEOCDT_STAT(segments),
    GEOCDT_STAT(snapRoundings),
    GEOCDT_STAT(valueDuplicates),
    GEOCDT_STAT(valueDisagreements),
    GEOCDT_STAT(steinerPoints),
    GEOCDT_STAT(refineSkipped),
    GEOCDT_STAT(refineCapped),
    GEOCDT_STAT(threads),
    GEOCDT_STAT(removed),
};
#undef GEOCDT_STAT
// Every counter takes 8 bytes (gridSize with its padding): a counter added to Stats and not
// listed above fails here.
static_assert(sizeof(Stats) == 8 * std::size(kStatFields),
              "list the new Stats counter in kStatFields, web/index.d.ts and web/API.md");

}  // namespace

const char* jsName(Field field) {
  switch (field) {
    case Field::Points: return "points";
    case Field::Triangles: return "triangles";
    case Field::Halfedges: return "halfedges";
    case Field::Constrained: return "constrained";
    case Field::ConstraintEdges: return "constraintEdges";
    case Field::SourceOffsets: return "sourceOffsets";
    case Field::Sources: return "sources";
    case Field::Inside: return "inside";
    case Field::Regions: return "regions";
    case Field::Values: return "values";
    case Field::InputToVertex: return "inputToVertex";
    case Field::VertexIds: return "vertexIds";
    case Field::Raster: return "raster";
    case Field::Steiner: return "steiner";
    case Field::SteinerParents: return "steinerParents";
    case Field::SteinerWeights: return "steinerWeights";
    case Field::SegmentOffsets: return "segmentOffsets";
    case Field::SegmentSources: return "segmentSources";
    case Field::Coords: return "coords";
    case Field::RingOffsets: return "ringOffsets";
    case Field::PolygonOffsets: return "polygonOffsets";
    case Field::SiteOffsets: return "siteOffsets";
    case Field::Sites: return "sites";
  }
  return nullptr;
}

const char* jsName(ElementType type) {
  switch (type) {
    case ElementType::Float64: return "Float64";
    case ElementType::Float32: return "Float32";
    case ElementType::Int32: return "Int32";
    case ElementType::Uint32: return "Uint32";
    case ElementType::Uint8: return "Uint8";
  }
  return nullptr;
}

ElementType elementType(Field field) {
  switch (field) {
    case Field::Points:
    case Field::Values:
    case Field::SteinerWeights:
    case Field::Coords:
    case Field::Sites: return ElementType::Float64;
    case Field::Raster: return ElementType::Float32;
    case Field::Halfedges:
    case Field::Regions: return ElementType::Int32;
    case Field::Constrained:
    case Field::Inside: return ElementType::Uint8;
    case Field::Triangles:
    case Field::ConstraintEdges:
    case Field::SourceOffsets:
    case Field::Sources:
    case Field::InputToVertex:
    case Field::VertexIds:
    case Field::Steiner:
    case Field::SteinerParents:
    case Field::SegmentOffsets:
    case Field::SegmentSources:
    case Field::RingOffsets:
    case Field::PolygonOffsets:
    case Field::SiteOffsets: return ElementType::Uint32;
  }
  return ElementType::Uint32;
}

std::uintptr_t Output::data(int field) const {
  switch (static_cast<Field>(field)) {
    case Field::Points: return heapAddress(mesh.points);
    case Field::Triangles: return heapAddress(mesh.triangles);
    case Field::Halfedges: return heapAddress(mesh.halfedges);
    case Field::Constrained: return heapAddress(mesh.constrained);
    case Field::ConstraintEdges: return heapAddress(mesh.constraintEdges);
    case Field::SourceOffsets: return heapAddress(mesh.sourceOffsets);
    case Field::Sources: return heapAddress(mesh.sources);
    case Field::Inside: return heapAddress(mesh.inside);
    case Field::Regions: return heapAddress(mesh.regions);
    case Field::Values: return heapAddress(mesh.values);
    case Field::InputToVertex: return heapAddress(inputToVertex);
    case Field::VertexIds: return heapAddress(vertexIds);
    case Field::Raster: return heapAddress(raster);
    case Field::Steiner: return heapAddress(mesh.steiner);
    case Field::SteinerParents: return heapAddress(mesh.steinerParents);
    case Field::SteinerWeights: return heapAddress(mesh.steinerWeights);
    case Field::SegmentOffsets: return heapAddress(mesh.segmentOffsets);
    case Field::SegmentSources: return heapAddress(mesh.segmentSources);
    case Field::Coords: return heapAddress(cells.coords);
    case Field::RingOffsets: return heapAddress(cells.ringOffsets);
    case Field::PolygonOffsets: return heapAddress(cells.polygonOffsets);
    case Field::SiteOffsets: return heapAddress(cells.siteOffsets);
    case Field::Sites: return heapAddress(cells.sites);
  }
  return 0;
}

std::size_t Output::size(int field) const {
  switch (static_cast<Field>(field)) {
    case Field::Points: return mesh.points.size();
    case Field::Triangles: return mesh.triangles.size();
    case Field::Halfedges: return mesh.halfedges.size();
    case Field::Constrained: return mesh.constrained.size();
    case Field::ConstraintEdges: return mesh.constraintEdges.size();
    case Field::SourceOffsets: return mesh.sourceOffsets.size();
    case Field::Sources: return mesh.sources.size();
    case Field::Inside: return mesh.inside.size();
    case Field::Regions: return mesh.regions.size();
    case Field::Values: return mesh.values.size();
    case Field::InputToVertex: return inputToVertex.size();
    case Field::VertexIds: return vertexIds.size();
    case Field::Raster: return raster.size();
    case Field::Steiner: return mesh.steiner.size();
    case Field::SteinerParents: return mesh.steinerParents.size();
    case Field::SteinerWeights: return mesh.steinerWeights.size();
    case Field::SegmentOffsets: return mesh.segmentOffsets.size();
    case Field::SegmentSources: return mesh.segmentSources.size();
    case Field::Coords: return cells.coords.size();
    case Field::RingOffsets: return cells.ringOffsets.size();
    case Field::PolygonOffsets: return cells.polygonOffsets.size();
    case Field::SiteOffsets: return cells.siteOffsets.size();
    case Field::Sites: return cells.sites.size();
  }
  return 0;
}

double Output::index() const { return indexOrMinusOne(status.index); }
double Output::segment() const { return indexOrMinusOne(status.segment); }

emscripten::val statsObject(const Stats& stats) {
  emscripten::val object = emscripten::val::object();
  for (const StatField& f : kStatFields) object.set(f.name, f.read(stats));
  return object;
}

emscripten::val Output::statsObject() const { return wasm::statsObject(stats); }

emscripten::val Output::terrainStats() const {
  emscripten::val object = emscripten::val::object();
  object.set("maxError", terrain.maxError);
  object.set("insertions", static_cast<double>(terrain.insertions));
  object.set("decimated", static_cast<double>(terrain.decimated));
  object.set("scannedPixels", static_cast<double>(terrain.scannedPixels));
  object.set("steinerPoints", static_cast<double>(terrain.steinerPoints));
  object.set("refineRounds", static_cast<double>(terrain.refineRounds));
  object.set("refineSkipped", static_cast<double>(terrain.refineSkipped));
  return object;
}

emscripten::val Output::voronoiStats() const {
  const VoronoiStats& s = cells.stats;
  emscripten::val object = emscripten::val::object();
  object.set("domainArea", s.domainArea);
  object.set("crossings", static_cast<double>(s.crossings));
  object.set("clippedCells", static_cast<double>(s.clippedCells));
  object.set("lloydIterations", s.lloydIterations);
  object.set("lloydMovement", s.lloydMovement);
  object.set("threads", s.threads);
  return object;
}

void Output::clear() {
  freeVector(mesh.points);
  freeVector(mesh.triangles);
  freeVector(mesh.halfedges);
  freeVector(mesh.constrained);
  freeVector(mesh.constraintEdges);
  freeVector(mesh.sourceOffsets);
  freeVector(mesh.sources);
  freeVector(mesh.segmentOffsets);
  freeVector(mesh.segmentSources);
  freeVector(mesh.inside);
  freeVector(mesh.regions);
  freeVector(mesh.values);
  freeVector(mesh.derivedVertices);
  freeVector(mesh.derivedOffsets);
  freeVector(mesh.derivedParents);
  freeVector(mesh.derivedWeights);
  freeVector(raster);
  freeVector(inputToVertex);
  freeVector(vertexIds);
  cells = VoronoiCells();
  status = Status::success();
  stats = Stats{};
  terrain = TerrainStats{};
}

}  // namespace geocdt::wasm
