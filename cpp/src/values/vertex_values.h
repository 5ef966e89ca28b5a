#pragma once
// Values carried by the vertices: those the input points gave, and those derived for vertices
// no input point became (constraint crossings, Steiner points), as weighted sums of
// their parents' values.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "delaunay/delaunay.h"

namespace geocdt {

class VertexValues {
 public:
  explicit VertexValues(std::uint32_t perPoint) : perPoint_(perPoint) {}

  std::uint32_t perPoint() const { return perPoint_; }
  bool active() const { return active_; }

  // The points that became vertices ids[0..count) carry values (perPoint each), or none
  // (null: NaN, unless the vertex already has values). A vertex keeps the first values it
  // gets; later different ones are counted in duplicates(). Nothing is stored before the
  // first call with values.
  void record(const std::uint32_t* ids, std::size_t count, const double* values,
              std::uint32_t vertexCount);
  // The vertices of the polyline points inserted (in insertion order, across polylines), for
  // the ends of the input segments that derived values interpolate along.
  void recordPolylinePoints(const std::uint32_t* ids, std::size_t count);

  // The hook for vertices that are neither input points nor on a constraint (Steiner points
  // of refinement): vertex v gets the sum of weights[k] times the values of parents[k]. The
  // parents must be older vertices. Such a derivation overrides the one from constraints.
  void derive(std::uint32_t v, const std::uint32_t* parents, const double* weights,
              std::size_t count);

  // Fills the values of every derived vertex of d (every vertex no input point became), and
  // returns the values of all vertices; mesh, if not null, receives the derivations. Counts
  // disagreements among the segments through a crossing.
  const std::vector<double>& update(const Delaunay& d, Mesh* mesh);
  void invalidate() { fresh_ = false; }
  const std::vector<double>& values() const { return values_; }

  std::uint64_t duplicates() const { return duplicates_; }
  std::uint64_t disagreements() const { return disagreements_; }
  void clear();

 private:
  void grow(std::uint32_t vertexCount);
  // update()'s derivations, in the Mesh's layout (derivedVertices, ...).
  struct Derivations {
    std::vector<std::uint32_t> vertices, offsets{0}, parents;
    std::vector<double> weights;
    std::vector<double> along;  // scratch: each segment's values at a vertex, k per segment
  };
  std::vector<std::uint64_t> segmentsThroughDerived(const Delaunay& d) const;
  bool deriveAlongSegments(const Delaunay& d, std::uint32_t v,
                           const std::vector<std::uint64_t>& pairs, std::size_t& next,
                           Derivations& out);
  void evaluate(std::uint32_t v, const Derivations& out, std::size_t from);

  std::uint32_t perPoint_;
  bool active_ = false;
  bool fresh_ = false;
  std::vector<double> values_;       // perPoint_ per vertex
  std::vector<std::uint8_t> given_;  // 1 per vertex whose values came from an input point
  std::vector<std::uint32_t> polylinePointVertex_;
  std::uint64_t polylinePoints_ = 0;  // polyline points inserted, recorded or not
  // Explicit derivations (derive()), in the Mesh's layout.
  std::vector<std::uint32_t> explicitVertices_, explicitOffsets_{0}, explicitParents_;
  std::vector<double> explicitWeights_;
  std::uint64_t duplicates_ = 0, disagreements_ = 0;
};

}  // namespace geocdt
