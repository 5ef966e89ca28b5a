#include "geocdt/triangulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/in_parallel.h"
#include "invalid_coordinate.h"
#include "out_of_memory.h"
#include "refine/refinement.h"
#include "triangulation_state.h"
#include "values/interpolation.h"
#include "values/rasterize.h"

namespace geocdt {

namespace {

// Checked side by side on `threads` threads for large inputs: the least index found wins.
Status checkCoordinates(const double* xy, std::size_t count, const char* what,
                        std::uint32_t threads) {
  if (count > 0 && xy == nullptr)
    return {StatusCode::InvalidArgument, std::string(what) + ": null coordinates with a count"};
  const std::size_t n = 2 * count;
  std::size_t i = n;
  if (kThreadsBuilt && threads > 1 && n >= kParallelLoop) {
    std::vector<std::size_t> found(threads);
    inParallel(threads, [&](std::uint32_t k) {
      const std::size_t last = n * (k + 1) / threads;
      found[k] = firstInvalidCoordinate(xy, n * k / threads, last);
      if (found[k] == last) found[k] = n;
    });
    i = *std::min_element(found.begin(), found.end());
  } else {
    i = firstInvalidCoordinate(xy, 0, n);
  }
  if (i == n) return Status::success();
  const double v = xy[i];
  const std::size_t point = i / 2;
  return {StatusCode::InvalidCoordinate,
          std::string(what) + " " + std::to_string(point) + " has " +
              describeInvalidCoordinate(v, i % 2 == 1),
          point};
}

}  // namespace

Triangulation::Triangulation(const Options& options) : state_(std::make_unique<State>(options)) {}
Triangulation::~Triangulation() = default;
Triangulation::Triangulation(Triangulation&&) noexcept = default;
Triangulation& Triangulation::operator=(Triangulation&&) noexcept = default;

std::size_t Triangulation::vertexCount() const {
  const Delaunay& d = state_->delaunay;
  return d.vertexCount() - d.stats.removed;
}
const std::vector<double>& Triangulation::points() const { return state_->delaunay.xy; }
Stats Triangulation::stats() const {
  Stats s = state_->delaunay.stats;
  s.gridSize = state_->delaunay.gridSize();
  VertexValues& values = state_->values;
  s.valueDuplicates = values.duplicates();
  if (values.active()) {
    values.update(state_->delaunay, nullptr);
    s.valueDisagreements = values.disagreements();
  }
  return s;
}
std::uint32_t Triangulation::valuesPerPoint() const { return state_->values.perPoint(); }
bool Triangulation::hasValues() const { return state_->values.active(); }
std::size_t Triangulation::polylineCount() const {
  return state_->delaunay.constraints.polylineCount;
}

std::size_t Triangulation::triangleCount() const {
  const Topology& topo = state_->delaunay.topo;
  std::size_t n = 0;
  for (std::int32_t t = 0; t < topo.slotCount(); ++t)
    if (!topo.isGhost(t)) ++n;
  return n;
}

Status Triangulation::insertPoints(const double* xy, std::size_t count, std::uint32_t* vertexIds,
                                   const double* values) {
  const Status s = checkCoordinates(xy, count, "point", state_->delaunay.options().threads);
  if (!s.ok()) return s;
  std::vector<std::uint32_t> scratch;
  std::uint32_t* ids = idsFor(vertexIds, count, scratch);
  return recordInsertion(*state_, insertCheckedPoints(xy, count, ids, values), ids, count,
                         kPointVertex, 0);
}

Status Triangulation::insertPoints(std::vector<double>&& xy, std::uint32_t* vertexIds,
                                   const double* values) {
  const Status s =
      checkCoordinates(xy.data(), xy.size() / 2, "point", state_->delaunay.options().threads);
  if (!s.ok()) return s;
  const std::size_t count = xy.size() / 2;
  std::vector<std::uint32_t> scratch;
  std::uint32_t* ids = idsFor(vertexIds, count, scratch);
  return recordInsertion(*state_, insertCheckedPoints(xy.data(), count, ids, values, &xy), ids,
                         count, kPointVertex, 0);
}

Status Triangulation::insertCheckedPoints(const double* xy, std::size_t count,
                                          std::uint32_t* vertexIds, const double* values,
                                          std::vector<double>* adopt) {
  State& state = *state_;
  Delaunay& d = state.delaunay;
  if (count >= kGhost - 2 - d.vertexCount())
    return {StatusCode::InvalidArgument, "too many points: at most 4294967293 vertices"};
  return catchOutOfMemory(
      [&] {
        std::vector<std::uint32_t> scratch;
        std::uint32_t* ids = vertexIds;
        if (ids == nullptr) {
          scratch.resize(count);
          ids = scratch.data();
        }
        state.changed();
        Status s = adopt ? d.insertBatch(std::move(*adopt), ids)
                         : d.insertBatch(xy, static_cast<std::uint32_t>(count), ids);
        if (s.ok()) state.values.record(ids, count, values, d.vertexCount());
        if (s.ok()) s = insertPendingSegments(d, state.options);
        return s;
      },
      [&] { state.clear(); });
}

Location Triangulation::locate(double x, double y) const {
  Location loc;
  if (!std::isfinite(x) || !std::isfinite(y)) {
    loc.kind = Location::Kind::Invalid;
    return loc;
  }
  Delaunay& d = state_->delaunay;
  const Hit h = d.locate(x, y, true);
  const Topology& topo = d.topo;
  if (h.kind == Hit::Kind::Empty || h.kind == Hit::Kind::Failed) return loc;
  if (!state_->slotMapValid) {
    state_->slotToTriangle = slotIndices(topo);
    state_->slotMapValid = true;
  }
  std::int32_t e = h.edge;
  switch (h.kind) {
    case Hit::Kind::Outside:
      loc.kind = Location::Kind::Outside;
      loc.vertices[0] = topo.tri[e];
      loc.vertices[1] = topo.tri[nextEdge(e)];
      return loc;
    case Hit::Kind::Vertex:
      loc.kind = Location::Kind::Vertex;
      loc.vertices[0] = topo.tri[e];
      // Turn around the vertex until a real triangle holds it.
      for (int guard = 0; topo.isGhost(e / 3) && guard < 3; ++guard) e = topo.adj[prevEdge(e)];
      break;
    case Hit::Kind::Edge:
      loc.kind = Location::Kind::Edge;
      loc.vertices[0] = topo.tri[e];
      loc.vertices[1] = topo.tri[nextEdge(e)];
      if (topo.isGhost(e / 3)) e = topo.adj[e];
      break;
    default: loc.kind = Location::Kind::Face; break;
  }
  loc.triangle = state_->slotToTriangle[e / 3];
  if (loc.kind == Location::Kind::Face)
    for (int k = 0; k < 3; ++k) loc.vertices[k] = topo.tri[3 * (e / 3) + k];
  return loc;
}

namespace {

// The mesh with its values (before the export, which may move the topology out).
Mesh exportWithValues(Triangulation::State& state, const MeshOptions& options, bool consume) {
  Mesh values;
  if (state.values.active()) state.values.update(state.delaunay, &values);
  if (consume) state.delaunay.constraints.dropSegments();  // the values were their last use
  Mesh m = exportMesh(state.delaunay, options, consume, state.windings);
  m.values = std::move(values.values);
  m.derivedVertices = std::move(values.derivedVertices);
  m.derivedOffsets = std::move(values.derivedOffsets);
  m.derivedParents = std::move(values.derivedParents);
  m.derivedWeights = std::move(values.derivedWeights);
  dropRemovedVertices(state.delaunay, m);
  return m;
}

}  // namespace

Status Triangulation::refine(const RefineOptions& options) {
  const std::string error = refineOptionsError(options);
  if (!error.empty()) return {StatusCode::InvalidArgument, error};
  State& state = *state_;
  state.changed();
  return catchOutOfMemory(
      [&] {
        const std::size_t before = state.delaunay.steiner.size();
        const Status s = refineTriangulation(state.delaunay, options, &state.windings);
        for (std::size_t i = before; i < state.delaunay.steiner.size(); ++i)
          state.edit.mark(&state.delaunay.steiner[i].vertex, 1, kSteinerVertex);
        state.edit.steinerStale = true;
        // Steiner vertices interpolate their values linearly from where they were placed.
        if (state.values.active()) {
          for (std::size_t i = before; i < state.delaunay.steiner.size(); ++i) {
            const SteinerVertex& v = state.delaunay.steiner[i];
            state.values.derive(v.vertex, v.parents, v.weights, v.parents[2] == kNoVertex ? 2 : 3);
          }
          state.values.invalidate();
        }
        return s;
      },
      [&] { state.clear(); });
}

Mesh Triangulation::mesh(const MeshOptions& options) const {
  return exportWithValues(*state_, options, false);
}

Mesh Triangulation::release(const MeshOptions& options) {
  state_->delaunay.dropGrid();
  Mesh m = exportWithValues(*state_, options, true);
  state_->clear();
  return m;
}

void Triangulation::interpolate(const double* xy, std::size_t count, Interpolation method,
                                double* out) const {
  State& state = *state_;
  static const std::vector<double> none;
  const std::vector<double>& values =
      state.values.active() ? state.values.update(state.delaunay, nullptr) : none;
  interpolateValues(state.delaunay, values, state.values.perPoint(), xy, count, method, out);
}

namespace {

// One shot: insertPoints(t, ids) inserts the points, then the polylines follow.
template <typename InsertPoints>
Status triangulateWith(std::size_t count, InsertPoints insertPoints, const PolylineView* polylines,
                       std::size_t polylineCount, const Options& options,
                       const MeshOptions& meshOptions, Mesh& out,
                       std::vector<std::uint32_t>* inputToVertex, const double* values,
                       const RefineOptions* refine) {
  if (polylineCount > 0 && polylines == nullptr)
    return {StatusCode::InvalidArgument, "null polylines with a count"};
  Triangulation t(options);
  std::vector<std::uint32_t> ids;
  const Status s = catchOutOfMemory(
      [&] {
        std::size_t total = count;
        for (std::size_t i = 0; i < polylineCount; ++i) total += polylines[i].count;
        ids.resize(total);
        Status inserted = insertPoints(t, ids.data());
        if (inserted.ok() && polylineCount > 0)
          inserted = t.insertPolylines(polylines, polylineCount, ids.data() + count,
                                       values ? values + count * options.valuesPerPoint : nullptr);
        if (inserted.ok() && refine) {
          RefineOptions r = *refine;
          r.keep = meshOptions.keep;
          r.fill = meshOptions.fill;
          inserted = t.refine(r);
        }
        if (inserted.ok()) out = t.release(meshOptions);
        return inserted;
      },
      [] {});  // t goes with this call
  if (s.ok() && inputToVertex) inputToVertex->swap(ids);
  return s;
}

}  // namespace

Status triangulate(const double* xy, std::size_t count, const PolylineView* polylines,
                   std::size_t polylineCount, const Options& options,
                   const MeshOptions& meshOptions, Mesh& out,
                   std::vector<std::uint32_t>* inputToVertex, const double* values,
                   const RefineOptions* refine) {
  return triangulateWith(
      count,
      [&](Triangulation& t, std::uint32_t* ids) { return t.insertPoints(xy, count, ids, values); },
      polylines, polylineCount, options, meshOptions, out, inputToVertex, values, refine);
}

Status triangulate(std::vector<double>&& xy, const PolylineView* polylines,
                   std::size_t polylineCount, const Options& options,
                   const MeshOptions& meshOptions, Mesh& out,
                   std::vector<std::uint32_t>* inputToVertex, const double* values,
                   const RefineOptions* refine) {
  return triangulateWith(
      xy.size() / 2,
      [&](Triangulation& t, std::uint32_t* ids) {
        return t.insertPoints(std::move(xy), ids, values);
      },
      polylines, polylineCount, options, meshOptions, out, inputToVertex, values, refine);
}

Status Triangulation::rasterize(const RasterGrid& grid, Interpolation method, float* out) const {
  if (!(grid.minX < grid.maxX) || !(grid.minY < grid.maxY) || !std::isfinite(grid.minX) ||
      !std::isfinite(grid.maxX) || !std::isfinite(grid.minY) || !std::isfinite(grid.maxY))
    return {StatusCode::InvalidArgument, "raster bounds must be finite with min < max"};
  const std::uint32_t k = state_->values.perPoint();
  const std::size_t width = grid.width, height = grid.height;
  std::fill(out, out + width * height * k, std::numeric_limits<float>::quiet_NaN());
  if (width == 0 || height == 0 || !hasValues()) return Status::success();
  const double dx = (grid.maxX - grid.minX) / static_cast<double>(width);
  const double dy = (grid.maxY - grid.minY) / static_cast<double>(height);
  if (method == Interpolation::Natural) {
    // One query per pixel, in row order: each walks a step or two from the previous one.
    std::vector<double> row(2 * width), values(width * k);
    for (std::size_t j = 0; j < height; ++j) {
      for (std::size_t i = 0; i < width; ++i) {
        row[2 * i] = grid.minX + (static_cast<double>(i) + 0.5) * dx;
        row[2 * i + 1] = grid.maxY - (static_cast<double>(j) + 0.5) * dy;
      }
      interpolate(row.data(), width, method, values.data());
      std::copy(values.begin(), values.end(), out + j * width * k);
    }
    return Status::success();
  }
  const std::vector<double>& values = state_->values.update(state_->delaunay, nullptr);
  rasterizeLinear(state_->delaunay, values, k, grid, out);
  return Status::success();
}

}  // namespace geocdt
