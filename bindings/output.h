#pragma once
// What one call hands back to JS. The arrays stay in the wasm heap only until JS has copied
// each of them out with a single slice; clear() then frees them, so no heap view outlives
// the call that made it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geocdt/status.h"
#include "geocdt/triangulation.h"

namespace geocdt::wasm {

// The order is part of the protocol with web/api.js (OUTPUT_FIELDS).
enum class Field : int {
  Points,
  Triangles,
  Halfedges,
  Constrained,
  ConstraintEdges,
  SourceOffsets,
  Sources,
  Inside,
  InputToVertex,
  VertexIds,
  Count,
};

class Output {
 public:
  Mesh mesh;
  std::vector<std::uint32_t> inputToVertex;
  std::vector<std::uint32_t> vertexIds;  // of the last incremental insertion
  Status status;
  Stats stats;

  // Byte address and element count of one array in the wasm heap.
  std::uintptr_t data(int field) const;
  std::size_t size(int field) const;

  int code() const { return static_cast<int>(status.code); }
  std::string message() const { return status.message; }
  // kNoIndex becomes -1 so that JS sees a plain number.
  double index() const;
  double segment() const;
  double stat(int which) const;

  void clear();  // frees every array: the heap returns to where it was before the call
};

}  // namespace geocdt::wasm
