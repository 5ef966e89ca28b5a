// The embind surface. Numbers, byte addresses, the enums' names and three small classes cross
// it: bulk data moves through the heap in one copy each way (web/kernel.js), never element by
// element.
#include <emscripten/bind.h>
#include <malloc.h>

#include <string>

#include "incremental.h"
#include "input.h"
#include "names.h"
#include "one_shot.h"
#include "output.h"
#include "polygons.h"
#include "terrain.h"
#include "voronoi.h"

namespace geocdt::wasm {
namespace {

// Bytes handed out by malloc and not yet freed: lets tests prove that calls leak nothing.
// mallinfo's fields are int: read them as unsigned, since the heap may pass 2 GB.
double allocatedBytes() { return static_cast<unsigned>(mallinfo().uordblks); }

// The allocator's high-water mark of memory taken from the system.
double peakBytes() { return static_cast<unsigned>(mallinfo().usmblks); }

// The names of the Output's arrays, indexed by Field. Not an embind enum: an enum's
// `values` property would hide the field of that name.
emscripten::val fieldNames() {
  emscripten::val names = emscripten::val::array();
  for (int i = 0; jsName(static_cast<Field>(i)) != nullptr; ++i)
    names.call<void>("push", std::string(jsName(static_cast<Field>(i))));
  return names;
}

ElementType fieldType(int field) { return elementType(static_cast<Field>(field)); }

// Registers every value of an enum numbered 0, 1, 2, ... under its jsName().
template <typename Enum>
void registerEnum(const char* name) {
  emscripten::enum_<Enum> e(name);
  for (int i = 0; jsName(static_cast<Enum>(i)) != nullptr; ++i)
    e.value(jsName(static_cast<Enum>(i)), static_cast<Enum>(i));
}

}  // namespace
}  // namespace geocdt::wasm

EMSCRIPTEN_BINDINGS(geocdt) {
  using namespace emscripten;
  using namespace geocdt;
  using namespace geocdt::wasm;

  registerEnum<StatusCode>("StatusCode");
  registerEnum<Location::Kind>("LocationKind");
  registerEnum<Keep>("Keep");
  registerEnum<FillRule>("FillRule");
  registerEnum<Phase>("Phase");
  registerEnum<Interpolation>("Interpolation");
  registerEnum<VoronoiClip>("VoronoiClip");
  registerEnum<ElementType>("ElementType");
  function("fieldNames", &fieldNames);
  function("elementType", &fieldType);
  constant("maxCoordinate", kMaxCoordinate);

  class_<Output>("Output")
      .constructor<>()
      .function("objectAddress", &Output::objectAddress)
      .function("data", &Output::data)
      .function("size", &Output::size)
      .function("code", &Output::code)
      .function("message", &Output::message)
      .function("index", &Output::index)
      .function("segment", &Output::segment)
      .function("stats", &Output::statsObject)
      .function("terrainStats", &Output::terrainStats)
      .function("voronoiStats", &Output::voronoiStats)
      .function("clear", &Output::clear);

  class_<Input>("Input")
      .constructor<>()
      .function("resize", &Input::resize)
      .function("pointsAddress", &Input::pointsAddress)
      .function("lineCoordsAddress", &Input::lineCoordsAddress)
      .function("lineOffsetsAddress", &Input::lineOffsetsAddress)
      .function("polygonOffsetsAddress", &Input::polygonOffsetsAddress)
      .function("valuesAddress", &Input::valuesAddress)
      .function("resizeRaster", &Input::resizeRaster)
      .function("rasterAddress", &Input::rasterAddress)
      .function("resizeIds", &Input::resizeIds)
      .function("idsAddress", &Input::idsAddress)
      .function("badOffset", &Input::badOffset)
      .function("badPolygonOffset", &Input::badPolygonOffset)
      .function("clear", &Input::clear);

  class_<Incremental>("Incremental")
      .constructor<std::uint32_t, std::uint32_t>()
      .function("insertPoints", &Incremental::insertPoints)
      .function("insertPolyline", &Incremental::insertPolyline)
      .function("mesh", &Incremental::mesh)
      .function("stats", &Incremental::stats)
      .function("refine", &Incremental::refine)
      .function("locate", &Incremental::locate)
      .function("interpolate", &Incremental::interpolate)
      .function("rasterize", &Incremental::rasterize)
      .function("valuesPerPoint", &Incremental::valuesPerPoint)
      .function("hasValues", &Incremental::hasValues)
      .function("removePoints", &Incremental::removePoints)
      .function("removePolyline", &Incremental::removePolyline)
      .function("hasVertex", &Incremental::hasVertex)
      .function("hasPolyline", &Incremental::hasPolyline)
      .function("vertexCount", &Incremental::vertexCount)
      .function("triangleCount", &Incremental::triangleCount)
      .function("polylineCount", &Incremental::polylineCount)
      .function("objectAddress", &Incremental::objectAddress);

  class_<PolygonCall>("PolygonCall")
      .constructor<>()
      .function("header", &PolygonCall::header)
      .function("prepare", &PolygonCall::prepare)
      .function("run", &PolygonCall::run)
      .function("release", &PolygonCall::release)
      .function("code", &PolygonCall::code)
      .function("message", &PolygonCall::message)
      .function("index", &PolygonCall::index)
      .function("segment", &PolygonCall::segment)
      .function("stats", &PolygonCall::stats);

  value_object<RasterOptions>("RasterOptions")
      .field("maxError", &RasterOptions::maxError)
      .field("maxTriangles", &RasterOptions::maxTriangles)
      .field("maxVertices", &RasterOptions::maxVertices)
      .field("hasNoData", &RasterOptions::hasNoData)
      .field("noData", &RasterOptions::noData)
      .field("minAngle", &RasterOptions::minAngle)
      .field("decimate", &RasterOptions::decimate)
      .field("hasBbox", &RasterOptions::hasBbox)
      .field("minX", &RasterOptions::minX)
      .field("minY", &RasterOptions::minY)
      .field("maxX", &RasterOptions::maxX)
      .field("maxY", &RasterOptions::maxY);

  function("triangulateInto", &triangulateInto);
  function("triangulateRasterInto", &triangulateRasterInto);
  function("voronoiInto", &voronoiInto);
  function("allocatedBytes", &allocatedBytes);
  function("peakBytes", &peakBytes);
}
