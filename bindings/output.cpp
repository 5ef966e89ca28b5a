#include "output.h"

namespace geocdt::wasm {
namespace {

template <typename T>
std::uintptr_t address(const std::vector<T>& v) {
  return reinterpret_cast<std::uintptr_t>(v.data());
}

template <typename T>
void release(std::vector<T>& v) {
  std::vector<T>().swap(v);
}

double indexOrMinusOne(std::size_t i) { return i == kNoIndex ? -1.0 : static_cast<double>(i); }

}  // namespace

std::uintptr_t Output::data(int field) const {
  switch (static_cast<Field>(field)) {
    case Field::Points: return address(mesh.points);
    case Field::Triangles: return address(mesh.triangles);
    case Field::Halfedges: return address(mesh.halfedges);
    case Field::Constrained: return address(mesh.constrained);
    case Field::ConstraintEdges: return address(mesh.constraintEdges);
    case Field::SourceOffsets: return address(mesh.sourceOffsets);
    case Field::Sources: return address(mesh.sources);
    case Field::Inside: return address(mesh.inside);
    case Field::InputToVertex: return address(inputToVertex);
    case Field::VertexIds: return address(vertexIds);
    case Field::Count: break;
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
    case Field::InputToVertex: return inputToVertex.size();
    case Field::VertexIds: return vertexIds.size();
    case Field::Count: break;
  }
  return 0;
}

double Output::index() const { return indexOrMinusOne(status.index); }
double Output::segment() const { return indexOrMinusOne(status.segment); }

// The order is part of the protocol with web/api.js (STAT_NAMES).
double Output::stat(int which) const {
  switch (which) {
    case 0: return static_cast<double>(stats.inserted);
    case 1: return static_cast<double>(stats.duplicates);
    case 2: return static_cast<double>(stats.walkSteps);
    case 3: return static_cast<double>(stats.locates);
    case 4: return static_cast<double>(stats.flips);
    case 5: return static_cast<double>(stats.walkFallbacks);
    case 6: return static_cast<double>(stats.gridSize);
    case 7: return static_cast<double>(stats.crossings);
    case 8: return static_cast<double>(stats.polylines);
    case 9: return static_cast<double>(stats.segments);
    default: return 0.0;
  }
}

void Output::clear() {
  release(mesh.points);
  release(mesh.triangles);
  release(mesh.halfedges);
  release(mesh.constrained);
  release(mesh.constraintEdges);
  release(mesh.sourceOffsets);
  release(mesh.sources);
  release(mesh.inside);
  release(inputToVertex);
  release(vertexIds);
  status = Status::success();
  stats = Stats{};
}

}  // namespace geocdt::wasm
