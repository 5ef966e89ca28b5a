#include "incremental.h"

#include <numeric>
#include <utility>

#include "guard.h"
#include "one_shot.h"

namespace geocdt::wasm {

Incremental::Incremental(std::uint32_t valuesPerPoint, std::uint32_t threads)
    : valuesPerPoint_(valuesPerPoint), threads_(threads), triangulation_(options()) {}

Options Incremental::options() {
  Options options;
  options.valuesPerPoint = valuesPerPoint_;
  options.threads = threads_;
  options.progress = relay_.hook();
  return options;
}

bool Incremental::insertPoints(Output& out, Input& input, emscripten::val onProgress) {
  return insert(out, input, false, std::move(onProgress));
}

bool Incremental::insertPolyline(Output& out, Input& input, emscripten::val onProgress) {
  return insert(out, input, true, std::move(onProgress));
}

bool Incremental::insert(Output& out, Input& input, bool polyline, emscripten::val onProgress) {
  out.clear();
  const std::size_t count = input.pointCount();
  relay_.start(std::move(onProgress), count);
  bool ok = guarded(
      out,
      [&] {
        out.vertexIds.resize(count);
        const double* values = input.values.empty() ? nullptr : input.values.data();
        if (polyline)
          return triangulation_.insertPolyline(input.points.data(), count, out.vertexIds.data(),
                                               values);
        return triangulation_.insertPoints(std::move(input.points), out.vertexIds.data(), values);
      },
      "out of memory: the triangulation needs more than the 4 GB a WebAssembly module can "
      "address; it was cleared");
  input.clear();
  relay_.finish();
  if (out.status.code == StatusCode::OutOfMemory) {
    // An insertion cut short by an exception may leave the topology half-updated: start over
    // from an empty, valid triangulation rather than hand out a broken one.
    triangulation_ = Triangulation(options());
  }
  if (!ok) out.vertexIds.clear();
  return ok;
}

bool Incremental::mesh(Output& out, Input& input, Keep keep, FillRule fill, bool insideFlags,
                       bool segmentSources, emscripten::val onProgress) {
  out.clear();
  relay_.start(std::move(onProgress), 0);
  const bool ok = guarded(
      out,
      [&] {
        out.mesh = triangulation_.mesh(meshOptions(keep, fill, insideFlags, segmentSources, input));
        out.stats = triangulation_.stats();
        // Each output vertex's id (vertex i is id i until something was removed).
        out.vertexIds = std::move(out.mesh.vertexIds);
        if (out.vertexIds.empty()) {
          out.vertexIds.resize(out.mesh.points.size() / 2);
          std::iota(out.vertexIds.begin(), out.vertexIds.end(), 0u);
        }
        return Status::success();
      },
      "out of memory while copying the triangulation out; it is unchanged");
  input.clear();
  relay_.finish();
  return ok;
}

int Incremental::removePoint(Output& out, double id) {
  bool removed = false;
  const char* oom = "out of memory while editing: the triangulation was cleared";
  if (!guarded(
          out, [&] { return triangulation_.removePoint(static_cast<std::uint32_t>(id), &removed); },
          oom))
    return -1;
  return removed ? 1 : 0;
}

double Incremental::removePoints(Output& out, Input& input) {
  std::size_t removed = 0;
  const bool ok = guarded(
      out,
      [&] { return triangulation_.removePoints(input.ids.data(), input.ids.size(), &removed); },
      "out of memory while editing: the triangulation was cleared");
  input.clear();
  return ok ? static_cast<double>(removed) : -1;
}

bool Incremental::removePolyline(Output& out, double polyline) {
  return guarded(
      out, [&] { return triangulation_.removePolyline(static_cast<std::size_t>(polyline)); },
      "out of memory while editing: the triangulation was cleared");
}

bool Incremental::movePoint(Output& out, double id, double x, double y) {
  return guarded(
      out, [&] { return triangulation_.movePoint(static_cast<std::uint32_t>(id), x, y); },
      "out of memory while editing: the triangulation was cleared");
}

void Incremental::interpolate(Output& out, Input& input, Interpolation method) {
  out.clear();
  guarded(
      out,
      [&] {
        const std::size_t count = input.pointCount();
        out.mesh.values.resize(count * triangulation_.valuesPerPoint());
        triangulation_.interpolate(input.points.data(), count, method, out.mesh.values.data());
        return Status::success();
      },
      "out of memory: no room for the interpolated values");
  input.clear();
}

bool Incremental::rasterize(Output& out, double minX, double minY, double maxX, double maxY,
                            double width, double height, Interpolation method) {
  out.clear();
  return guarded(
      out,
      [&] {
        RasterGrid grid{minX,
                        minY,
                        maxX,
                        maxY,
                        static_cast<std::uint32_t>(width),
                        static_cast<std::uint32_t>(height)};
        out.raster.resize(static_cast<std::size_t>(grid.width) * grid.height *
                          triangulation_.valuesPerPoint());
        return triangulation_.rasterize(grid, method, out.raster.data());
      },
      "out of memory: the raster does not fit in the 4 GB a WebAssembly module can address");
}

bool Incremental::refine(Output& out, Keep keep, FillRule fill, double minAngle, double maxArea,
                         double maxSteinerPoints) {
  out.clear();
  const bool ok = guarded(
      out,
      [&] {
        return triangulation_.refine(
            refineOptions(keep, fill, minAngle, maxArea, maxSteinerPoints));
      },
      "out of memory: the triangulation needs more than the 4 GB a WebAssembly module can "
      "address; it was cleared");
  if (out.status.code == StatusCode::OutOfMemory) triangulation_ = Triangulation(options());
  return ok;
}

void Incremental::locate(double x, double y, std::uintptr_t into) const {
  const Location location = triangulation_.locate(x, y);
  int vertices = 0;
  switch (location.kind) {
    case Location::Kind::Face: vertices = 3; break;
    case Location::Kind::Outside:
    case Location::Kind::Edge: vertices = 2; break;
    case Location::Kind::Vertex: vertices = 1; break;
    default: break;
  }
  auto* slots = reinterpret_cast<double*>(into);
  slots[0] = static_cast<double>(location.kind);
  slots[1] = static_cast<double>(location.triangle);
  slots[2] = vertices;
  for (int i = 0; i < 3; ++i) slots[3 + i] = location.vertices[i];
}

}  // namespace geocdt::wasm
