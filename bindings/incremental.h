#pragma once
// The object behind the JS Triangulation class: a core Triangulation that results are
// copied from (never released) so that insertions can go on.
#include <cstddef>
#include <cstdint>

#include "geocdt/triangulation.h"
#include "output.h"

namespace geocdt::wasm {

class Incremental {
 public:
  // out.vertexIds receives one vertex id per point.
  bool insertPoints(Output& out, std::uintptr_t xy, std::size_t count);
  bool insertPolyline(Output& out, std::uintptr_t xy, std::size_t count);
  bool mesh(Output& out, int keep, int fill, bool insideFlags) const;
  void stats(Output& out) const { out.stats = triangulation_.stats(); }

  // Writes kind, triangle, and three vertex ids as five doubles at into.
  void locate(double x, double y, std::uintptr_t into) const;

  double vertexCount() const { return static_cast<double>(triangulation_.vertexCount()); }
  double triangleCount() const { return static_cast<double>(triangulation_.triangleCount()); }
  double polylineCount() const { return static_cast<double>(triangulation_.polylineCount()); }

 private:
  bool insert(Output& out, std::uintptr_t xy, std::size_t count, bool polyline);

  Triangulation triangulation_;
};

}  // namespace geocdt::wasm
