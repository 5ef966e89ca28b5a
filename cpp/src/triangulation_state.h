#pragma once
// What a Triangulation holds: the Delaunay engine (with the constraints inserted into it), the
// values carried by the vertices, and what the export may reuse.
#include <cstdint>
#include <vector>

#include "delaunay/delaunay.h"
#include "delaunay/vertex_edges.h"
#include "geocdt/triangulation.h"
#include "mesh/edge_map.h"
#include "values/vertex_values.h"

namespace geocdt {

// What a vertex is to the editing calls (bits; none: a crossing).
enum VertexKind : std::uint8_t {
  kPointVertex = 1,     // a point of insertPoints
  kPolylineVertex = 2,  // a point of a polyline
  kSteinerVertex = 4,   // added by refinement
};

// What editing needs beyond the triangulation: each vertex's kind, which polylines were
// removed, the vertex of each polyline without a segment (all its points equal), whether
// the constraints are snap-rounded, and the Steiner points placed from each vertex.
struct EditState {
  std::vector<std::uint8_t> kinds;            // per vertex id
  std::vector<std::uint8_t> polylineRemoved;  // per polyline
  EdgeMap<std::uint32_t> lonePolylines;       // polyline -> its one vertex
  EdgeMap<std::uint32_t> loneUses;            // vertex -> lone polylines on it
  bool snapped = false;
  std::uint64_t snapRoundings = 0;  // Stats::snapRoundings when last looked at
  // Steiner children: parent -> first index into steinerLinks (child, next), rebuilt from
  // Delaunay::steiner when stale (after refine()).
  EdgeMap<std::int32_t> steinerFirst;
  std::vector<std::pair<std::uint32_t, std::int32_t>> steinerLinks;
  bool steinerStale = true;
  VertexEdges ends;  // a half-edge out of each vertex, once something was edited (hints)

  std::uint8_t kind(std::uint32_t v) const { return v < kinds.size() ? kinds[v] : 0; }
  void mark(const std::uint32_t* ids, std::size_t count, std::uint8_t kind) {
    for (std::size_t i = 0; i < count; ++i) {
      if (ids[i] >= kinds.size()) kinds.resize(ids[i] + std::size_t{1}, 0);
      kinds[ids[i]] |= kind;
    }
  }
  void clear() { *this = EditState(); }
};

struct Triangulation::State {
  explicit State(const Options& options)
      : options(options), delaunay(options), values(options.valuesPerPoint) {}
  Options options;    // for snap rounding, which builds the triangulation again
  Delaunay delaunay;  // owns the constraints too
  VertexValues values;
  EditState edit;
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
    edit.clear();
    changed();
  }
};

// The state of a Triangulation, for the facade's functions that build on one (terrain).
struct StateAccess {
  static Triangulation::State& of(Triangulation& t) { return *t.state_; }
};

// Builds the caller's arrays from the internal slots: ghost triangles dropped. With
// consume, the arrays are moved out and compacted in place, leaving delaunay to be cleared.
// windings, unless empty, are every slot's (see slotWindings), known already.
Mesh exportMesh(Delaunay& delaunay, const MeshOptions& options, bool consume,
                const std::vector<std::int32_t>& windings = {});
// Inserts the segments that waited for the triangulation to have triangles.
Status insertPendingSegments(Delaunay& delaunay, const Options& options);
// Editing's bookkeeping after an insertion returned `inserted` (editing.cpp): the kinds of
// the vertices ids[0..count), and for polylines (the call's, numbered from firstPolyline on)
// the vertex of each without a segment. Returns `inserted`.
Status recordInsertion(Triangulation::State& state, const Status& inserted,
                       const std::uint32_t* ids, std::size_t count, std::uint8_t kind,
                       std::size_t firstPolyline, const PolylineView* polylines = nullptr);
// vertexIds, or else scratch sized to count.
inline std::uint32_t* idsFor(std::uint32_t* vertexIds, std::size_t count,
                             std::vector<std::uint32_t>& scratch) {
  if (vertexIds != nullptr) return vertexIds;
  scratch.resize(count);
  return scratch.data();
}
// Renumbers m's vertices without the removed ones and fills m.vertexIds (mesh_compaction.cpp).
void dropRemovedVertices(const Delaunay& d, Mesh& m);

// Index of each slot among the exported triangles, or -1 for ghost triangles.
std::vector<std::int32_t> slotIndices(const Topology& topo);

}  // namespace geocdt
