#pragma once
// The object behind the JS Triangulation class: a core Triangulation that results are
// copied from (never released) so that insertions can go on.
#include <emscripten/val.h>

#include "geocdt/triangulation.h"
#include "input.h"
#include "output.h"
#include "progress.h"

namespace geocdt::wasm {

class Incremental {
 public:
  // threads: Options::threads, for the first batch of points.
  Incremental(std::uint32_t valuesPerPoint, std::uint32_t threads);
  Incremental(const Incremental&) = delete;  // the triangulation's options point at relay_
  Incremental& operator=(const Incremental&) = delete;

  // Insert the coordinates JS wrote into input.points, with input.values when not empty
  // (freed afterwards); out.vertexIds receives one vertex id per point. onProgress: a JS
  // function (phase, fraction) or undefined.
  bool insertPoints(Output& out, Input& input, emscripten::val onProgress);
  bool insertPolyline(Output& out, Input& input, emscripten::val onProgress);
  // input holds the polygons of region labels, if any (freed afterwards).
  bool mesh(Output& out, Input& input, Keep keep, FillRule fill, bool insideFlags,
            bool segmentSources, emscripten::val onProgress);
  // Values at the points of input.points (freed afterwards) into out.mesh.values.
  void interpolate(Output& out, Input& input, Interpolation method);
  // The raster into out.raster; false (with the status in out) on bad bounds or no memory.
  bool rasterize(Output& out, double minX, double minY, double maxX, double maxY, double width,
                 double height, Interpolation method);
  double valuesPerPoint() const { return triangulation_.valuesPerPoint(); }
  bool hasValues() const { return triangulation_.hasValues(); }

  emscripten::val stats() const { return statsObject(triangulation_.stats()); }
  // Refines the triangulation (see refineOptions in one_shot.h); the status lands in out.
  bool refine(Output& out, Keep keep, FillRule fill, double minAngle, double maxArea,
              double maxSteinerPoints);

  // Writes kind, triangle, the number of vertices that name the place, and those vertex ids
  // as six doubles at into.
  void locate(double x, double y, std::uintptr_t into) const;

  // Editing: the status lands in out when it is not ok. removePoint returns 1 when the
  // vertex went, 0 when it stays as a polyline's, -1 on an error; the others whether they
  // succeeded. Ids come as doubles that JS checked to be integers in [0, 2^32). JS calls
  // removePoint and movePoint through the plain exports of edit_calls.cpp.
  int removePoint(Output& out, double id);
  // The ids JS wrote into input.ids (freed afterwards): the vertices that went, or -1 on an
  // error.
  double removePoints(Output& out, Input& input);
  bool removePolyline(Output& out, double polyline);
  bool movePoint(Output& out, double id, double x, double y);
  bool hasVertex(double id) const {
    return triangulation_.hasVertex(static_cast<std::uint32_t>(id));
  }
  bool hasPolyline(double polyline) const {
    return triangulation_.hasPolyline(static_cast<std::size_t>(polyline));
  }

  // Where this object lives, for the plain editing exports (edit_calls.cpp).
  std::uintptr_t objectAddress() const { return reinterpret_cast<std::uintptr_t>(this); }

  double vertexCount() const { return static_cast<double>(triangulation_.vertexCount()); }
  double triangleCount() const { return static_cast<double>(triangulation_.triangleCount()); }
  double polylineCount() const { return static_cast<double>(triangulation_.polylineCount()); }

 private:
  bool insert(Output& out, Input& input, bool polyline, emscripten::val onProgress);
  Options options();

  std::uint32_t valuesPerPoint_;
  std::uint32_t threads_;
  // Declared before the triangulation, whose options point at it.
  ProgressRelay relay_;
  Triangulation triangulation_;
};

}  // namespace geocdt::wasm
