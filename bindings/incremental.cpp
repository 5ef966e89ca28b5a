#include "incremental.h"

#include "guard.h"
#include "one_shot.h"

namespace geocdt::wasm {

bool Incremental::insertPoints(Output& out, std::uintptr_t xy, std::size_t count) {
  return insert(out, xy, count, false);
}

bool Incremental::insertPolyline(Output& out, std::uintptr_t xy, std::size_t count) {
  return insert(out, xy, count, true);
}

bool Incremental::insert(Output& out, std::uintptr_t xy, std::size_t count, bool polyline) {
  out.clear();
  const auto* coords = reinterpret_cast<const double*>(xy);
  bool ok = guarded(
      out,
      [&] {
        out.vertexIds.resize(count);
        return polyline ? triangulation_.insertPolyline(coords, count, out.vertexIds.data())
                        : triangulation_.insertPoints(coords, count, out.vertexIds.data());
      },
      "out of memory: the triangulation needs more than the 4 GB a WebAssembly module can "
      "address; it was cleared");
  if (out.status.code == StatusCode::OutOfMemory) {
    // An insertion cut short by an exception may leave the topology half-updated: start over
    // from an empty, valid triangulation rather than hand out a broken one.
    triangulation_ = Triangulation();
  }
  if (!ok) out.vertexIds.clear();
  return ok;
}

bool Incremental::mesh(Output& out, int keep, int fill, bool insideFlags) const {
  out.clear();
  return guarded(
      out,
      [&] {
        out.mesh = triangulation_.mesh(meshOptions(keep, fill, insideFlags));
        out.stats = triangulation_.stats();
        return Status::success();
      },
      "out of memory while copying the triangulation out; it is unchanged");
}

void Incremental::locate(double x, double y, std::uintptr_t into) const {
  Location location = triangulation_.locate(x, y);
  auto* slots = reinterpret_cast<double*>(into);
  slots[0] = static_cast<double>(location.kind);
  slots[1] = static_cast<double>(location.triangle);
  for (int i = 0; i < 3; ++i) slots[2 + i] = location.vertices[i];
}

}  // namespace geocdt::wasm
