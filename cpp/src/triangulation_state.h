#pragma once
// What a Triangulation holds: the Delaunay engine (with the constraints inserted into it), the
// values carried by the vertices, and what the export may reuse.
#include <cstdint>
#include <vector>

#include "delaunay/delaunay.h"
#include "geocdt/triangulation.h"
#include "values/vertex_values.h"

namespace geocdt {

struct Triangulation::State {
  explicit State(const Options& options)
      : options(options), delaunay(options), values(options.valuesPerPoint) {}
  Options options;    // for snap rounding, which builds the triangulation again
  Delaunay delaunay;  // owns the constraints too
  VertexValues values;
  // Slot -> index in mesh().triangles / 3, rebuilt on demand after a change.
  std::vector<std::int32_t> slotToTriangle;
  bool slotMapValid = false;
  // Each slot's winding number as refine() left them (it keeps them up to date as it
  // goes), for the export; empty once anything else changes the triangles.
  std::vector<std::int32_t> windings;
  void changed() {
    slotMapValid = false;
    windings.clear();
  }
  // Empty again: after release(), and after running out of memory midway through a change.
  void clear() {
    delaunay.clear();
    values.clear();
    changed();
  }
};

// Builds the caller's arrays from the internal slots: ghost triangles dropped. With
// consume, the arrays are moved out and compacted in place, leaving delaunay to be cleared.
// windings, unless empty, are every slot's (see slotWindings), known already.
Mesh exportMesh(Delaunay& delaunay, const MeshOptions& options, bool consume,
                const std::vector<std::int32_t>& windings = {});
// Inserts the segments that waited for the triangulation to have triangles.
Status insertPendingSegments(Delaunay& delaunay, const Options& options);
// Index of each slot among the exported triangles, or -1 for ghost triangles.
std::vector<std::int32_t> slotIndices(const Topology& topo);

}  // namespace geocdt
