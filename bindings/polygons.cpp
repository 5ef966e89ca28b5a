#include "polygons.h"

#include "heap_reserve.h"
#include "heap_vectors.h"
#include "out_of_memory.h"

namespace geocdt::wasm {

namespace {

// What a batch needs at its peak, by input point beyond its coordinates: the triangles (about
// one a point, 12 bytes) and the offsets; the scratch of the small path is a few pages.
constexpr double kReservePerPolygonPoint = 16;

}  // namespace

bool PolygonCall::prepare(double coordValues, double rings, double polygons) {
  release();
  constexpr double kAddressSpace = 4294967296.0;
  if (8 * coordValues + 4 * (rings + polygons) >= kAddressSpace) return false;
  reserveHeap(8 * coordValues + kReservePerPolygonPoint * coordValues / 2 + 4 * (rings + polygons));
  const Status s = catchOutOfMemory(
      [&] {
        coords_.resize(static_cast<std::size_t>(coordValues));
        rings_.resize(static_cast<std::size_t>(rings) + 1);
        polygons_.resize(static_cast<std::size_t>(polygons) + 1);
        return Status::success();
      },
      [&] { release(); });
  if (!s.ok()) return false;
  header_[Coords] = heapAddress(coords_);
  header_[RingOffsets] = heapAddress(rings_);
  header_[PolygonOffsets] = heapAddress(polygons_);
  return true;
}

bool PolygonCall::run(std::uint32_t dim, FillRule fill, std::uint32_t threads) {
  // earcut's layout: dim numbers a point, x and y first. Closed up to x, y pairs in place.
  const std::size_t points = coords_.size() / (dim < 2 ? 2 : dim);
  if (dim > 2) {
    for (std::size_t i = 0; i < points; ++i) {
      coords_[2 * i] = coords_[dim * i];
      coords_[2 * i + 1] = coords_[dim * i + 1];
    }
  }
  PolygonBatch batch;
  batch.xy = coords_.data();
  batch.pointCount = points;
  batch.ringOffsets = rings_.data();
  batch.ringCount = rings_.size() - 1;
  batch.polygonOffsets = polygons_.data();
  batch.polygonCount = polygons_.size() - 1;
  PolygonOptions options;
  options.fill = fill;
  options.threads = threads;
  status_ = triangulatePolygons(batch, options, out_, &stats_);
  freeVector(coords_);
  freeVector(rings_);
  freeVector(polygons_);
  header_[Triangles] = heapAddress(out_.triangles);
  header_[TriangleCount] = static_cast<std::uint32_t>(out_.triangles.size());
  header_[ExtraPoints] = heapAddress(out_.extraPoints);
  header_[ExtraCount] = static_cast<std::uint32_t>(out_.extraPoints.size());
  header_[TriangleOffsets] = heapAddress(out_.triangleOffsets);
  header_[OffsetCount] = static_cast<std::uint32_t>(out_.triangleOffsets.size());
  return status_.ok();
}

void PolygonCall::release() {
  freeVector(coords_);
  freeVector(rings_);
  freeVector(polygons_);
  out_ = PolygonTriangles();
  stats_ = PolygonStats();
  status_ = Status::success();
  header_.fill(0);
}

double PolygonCall::index() const {
  return status_.index == kNoIndex ? -1.0 : static_cast<double>(status_.index);
}

double PolygonCall::segment() const {
  return status_.segment == kNoIndex ? -1.0 : static_cast<double>(status_.segment);
}

emscripten::val PolygonCall::stats() const {
  emscripten::val o = emscripten::val::object();
  o.set("smallPath", static_cast<double>(stats_.smallPath));
  o.set("general", static_cast<double>(stats_.general));
  o.set("crossings", static_cast<double>(stats_.crossings));
  o.set("threads", static_cast<double>(stats_.threads));
  return o;
}

}  // namespace geocdt::wasm
