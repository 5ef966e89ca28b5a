#include "input.h"

#include "heap_reserve.h"
#include "out_of_memory.h"

namespace geocdt::wasm {

bool Input::resize(double pointCount, double linePointCount, double lineCount, double polygonCount,
                   double valueCount) {
  clear();
  // wasm32's whole address space, in bytes: anything larger cannot be allocated anyway, and
  // the doubles could not be converted to size_t.
  constexpr double kAddressSpace = 4294967296.0;
  if (16 * (pointCount + linePointCount) + 4 * (lineCount + polygonCount) + 8 * valueCount >=
      kAddressSpace)
    return false;
  // Values: the input's, and the vertices' copy in the core.
  reserveHeap(kReservePerPoint * pointCount + kReservePerLinePoint * linePointCount +
              16 * valueCount);
  return catchOutOfMemory(
             [&] {
               points.resize(2 * static_cast<std::size_t>(pointCount));
               lineCoords.resize(2 * static_cast<std::size_t>(linePointCount));
               lineOffsets.resize(static_cast<std::size_t>(lineCount) + 1);
               if (polygonCount >= 0)
                 polygonOffsets.resize(static_cast<std::size_t>(polygonCount) + 1);
               values.resize(static_cast<std::size_t>(valueCount));
               return Status::success();
             },
             [&] { clear(); })
      .ok();
}

namespace {

// v sized to count elements; false (v empty) when that cannot be.
template <typename T>
bool resizeOrEmpty(std::vector<T>& v, double count) {
  std::vector<T>().swap(v);
  if (sizeof(T) * count >= 4294967296.0) return false;
  try {
    v.resize(static_cast<std::size_t>(count));
  } catch (const std::bad_alloc&) {
    return false;
  } catch (const std::length_error&) {
    return false;
  }
  return true;
}

}  // namespace

bool Input::resizeRaster(double pixels) {
  if (8 * pixels >= 4294967296.0) return false;
  // The heights, and a byte a pixel and the mesh the call makes: at most two triangles a pixel.
  reserveHeap(8 * pixels + 1 * pixels + kReservePerPoint * pixels / 2);
  return resizeOrEmpty(raster, pixels);
}

bool Input::resizeIds(double count) { return resizeOrEmpty(ids, count); }

double Input::badOffset() const {
  if (lineOffsets.empty()) return -1;
  if (lineOffsets[0] != 0) return 0;
  const std::size_t end = linePointCount();
  for (std::size_t i = 1; i < lineOffsets.size(); ++i)
    if (lineOffsets[i] < lineOffsets[i - 1] || lineOffsets[i] > end) return static_cast<double>(i);
  if (lineOffsets.back() != end) return static_cast<double>(lineOffsets.size() - 1);
  return -1;
}

double Input::badPolygonOffset(double polylineCount) const {
  for (std::size_t i = 0; i < polygonOffsets.size(); ++i)
    if ((i > 0 && polygonOffsets[i] < polygonOffsets[i - 1]) || polygonOffsets[i] > polylineCount)
      return static_cast<double>(i);
  return -1;
}

std::vector<std::int32_t> Input::polylinePolygons() const {
  if (polygonOffsets.empty()) return {};
  std::vector<std::int32_t> polygonOf(polygonOffsets.back(), -1);
  for (std::size_t j = 0; j + 1 < polygonOffsets.size(); ++j)
    for (std::uint32_t p = polygonOffsets[j]; p < polygonOffsets[j + 1]; ++p)
      polygonOf[p] = static_cast<std::int32_t>(j);
  return polygonOf;
}

std::vector<PolylineView> Input::polylines() const {
  std::vector<PolylineView> views(lineCount());
  for (std::size_t i = 0; i < views.size(); ++i)
    views[i] = {lineCoords.data() + 2 * static_cast<std::size_t>(lineOffsets[i]),
                static_cast<std::size_t>(lineOffsets[i + 1] - lineOffsets[i])};
  return views;
}

void Input::clear() {
  clearCoordinates();
  std::vector<std::uint32_t>().swap(ids);
  std::vector<std::uint32_t>().swap(polygonOffsets);
  std::vector<double>().swap(values);
  std::vector<double>().swap(raster);
}

void Input::clearCoordinates() {
  std::vector<double>().swap(points);
  std::vector<double>().swap(lineCoords);
  std::vector<std::uint32_t>().swap(lineOffsets);
}

}  // namespace geocdt::wasm
