// triangulateRaster: the terrain layer's parts put together on a Triangulation. The corners
// (or the rings around the area with data) and the breaklines go in through the constraint
// API, then greedy insertion fills in pixels; with minAngle, refinement and greedy insertion
// take turns until the error bound holds on the refined mesh.
#include <algorithm>
#include <cmath>
#include <new>
#include <string>

#include "geocdt/terrain.h"
#include "refine/refiner.h"
#include "terrain/breakline_pieces.h"
#include "terrain/greedy_mesher.h"
#include "terrain/mesh_frame.h"
#include "terrain/pixel_frame.h"
#include "terrain/profile.h"
#include "terrain/raster_sampler.h"
#include "terrain/valid_area.h"
#include "triangulation_state.h"

namespace geocdt {

namespace {

using terrain::RasterSampler;

Status invalidRaster(std::string message, std::size_t index = kNoIndex) {
  return {StatusCode::InvalidArgument, std::move(message), index};
}

Status checkOptions(const RasterView& raster, const TerrainOptions& o) {
  if (raster.width == 0 || raster.height == 0)
    return invalidRaster("the raster must have at least one pixel (width and height from 1 up)");
  if (raster.heights == nullptr) return invalidRaster("raster: null heights");
  if (static_cast<std::uint64_t>(raster.width) * raster.height >= (std::uint64_t{1} << 31))
    return invalidRaster("the raster must have fewer than 2^31 pixels");
  if (!(o.maxError >= 0) || std::isinf(o.maxError))
    return invalidRaster("maxError must be a finite number from 0 up");
  if (!(o.minAngle >= 0 && o.minAngle < 60))
    return invalidRaster("minAngle must be a number of degrees from 0 to less than 60");
  // A single column or row spans no width or height: its bbox may be flat that way.
  const bool wide = raster.width > 1, tall = raster.height > 1;
  if (o.hasBbox && !(std::isfinite(o.minX) && std::isfinite(o.maxX) && std::isfinite(o.minY) &&
                     std::isfinite(o.maxY) && (wide ? o.minX < o.maxX : o.minX <= o.maxX) &&
                     (tall ? o.minY < o.maxY : o.minY <= o.maxY) &&
                     std::fabs(o.minX) <= kMaxCoordinate && std::fabs(o.maxX) <= kMaxCoordinate &&
                     std::fabs(o.minY) <= kMaxCoordinate && std::fabs(o.maxY) <= kMaxCoordinate))
    return invalidRaster(
        "bbox must be finite numbers [minX, minY, maxX, maxY] within 1e150, with minX < maxX "
        "and minY < maxY (minX <= maxX for a single column, minY <= maxY for a single row)");
  // Every pixel on a place of its own: a bbox within ulps of flat maps neighbours together.
  if (o.hasBbox) {
    const terrain::PixelFrame frame(o.minX, o.minY, o.maxX, o.maxY, raster.width, raster.height);
    for (std::uint32_t i = 1; i < raster.width; ++i)
      if (!(frame.mapX(i) > frame.mapX(i - 1.0)))
        return invalidRaster("bbox is too narrow for " + std::to_string(raster.width) +
                             " columns: columns " + std::to_string(i - 1) + " and " +
                             std::to_string(i) + " land on the same x");
    for (std::uint32_t j = 1; j < raster.height; ++j)
      if (!(frame.mapY(j) < frame.mapY(j - 1.0)))
        return invalidRaster("bbox is too low for " + std::to_string(raster.height) +
                             " rows: rows " + std::to_string(j - 1) + " and " + std::to_string(j) +
                             " land on the same y");
  }
  return Status::success();
}

// Which pixels have data: empty when all do. A height that is neither data nor no-data (NaN
// or infinite without noData) is an error naming the pixel.
// largest gets the largest |height| with data.
Status validPixels(const RasterView& raster, const TerrainOptions& o,
                   std::vector<std::uint8_t>& valid, double& largest) {
  const std::size_t n = static_cast<std::size_t>(raster.width) * raster.height;
  largest = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const double h = raster.heights[p];
    const bool noData = o.hasNoData && (h == o.noDataValue || std::isnan(h));
    if (!noData && std::isfinite(h)) {
      largest = std::max(largest, std::fabs(h));
      continue;
    }
    if (!noData) {
      const std::string what = std::isnan(h) ? "NaN" : h > 0 ? "infinite" : "-infinite";
      return {StatusCode::InvalidCoordinate,
              "heights[" + std::to_string(p) + "] (column " + std::to_string(p % raster.width) +
                  ", row " + std::to_string(p / raster.width) + ") is " + what +
                  (std::isnan(h) ? ": pass noData to leave pixels out" : ""),
              p};
    }
    if (valid.empty()) valid.assign(n, 1);
    valid[p] = 0;
  }
  return Status::success();
}

Status checkBreaklines(const PolylineView* lines, std::size_t count, const double* heights) {
  if (count > 0 && lines == nullptr) return invalidRaster("null breaklines with a count");
  std::size_t at = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const PolylineView& line = lines[i];
    if (line.count > 0 && line.xy == nullptr)
      return invalidRaster("breakline " + std::to_string(i) + ": null coordinates with a count", i);
    for (std::size_t k = 0; k < 2 * line.count; ++k) {
      const double v = line.xy[k];
      if (std::isfinite(v) && std::fabs(v) <= kMaxCoordinate) continue;
      Status s{StatusCode::InvalidCoordinate,
               "breakline " + std::to_string(i) + " point " + std::to_string(k / 2) + " has " +
                   (k % 2 ? "y" : "x") + " " +
                   (std::isnan(v)   ? "NaN"
                    : std::isinf(v) ? "infinite"
                                    : "beyond 1e150"),
               i};
      s.segment = k / 2;
      return s;
    }
    for (std::size_t k = 0; heights && k < line.count; ++k)
      if (std::isinf(heights[at + k]))
        return invalidRaster("breakline " + std::to_string(i) + " point " + std::to_string(k) +
                                 ": its height is infinite (NaN reads it from the raster)",
                             i);
    at += line.count;
  }
  return Status::success();
}

// A raster of one row or column: its profile, no triangles.
void profileMesh(const RasterSampler& raster, const terrain::MesherLimits& limits,
                 const terrain::PixelFrame& frame, Mesh& out, TerrainStats& stats) {
  terrain::Profile p = terrain::simplifyProfile(raster, limits);
  out = Mesh();
  out.points = std::move(p.xy);
  for (std::size_t v = 0; v < out.points.size() / 2; ++v) {
    out.points[2 * v] = frame.mapX(out.points[2 * v]);
    out.points[2 * v + 1] = frame.mapY(out.points[2 * v + 1]);
  }
  out.values = std::move(p.z);
  out.sourceOffsets.assign(1, 0);
  stats.maxError = p.maxError;
  stats.scannedPixels = p.scannedPixels;
  stats.insertions = out.values.size();
}

}  // namespace

namespace {

// What the mesh is built from, in pixel positions.
struct Build {
  Triangulation triangulation{[] {
    Options o;
    o.valuesPerPoint = 1;
    return o;
  }()};
  std::vector<double> z;
  std::vector<std::uint8_t> given;  // per vertex: a height given with a breakline
  std::vector<double> original;     // per vertex: the caller's coordinates, or NaN
  std::vector<std::uint32_t> sourceOf;
  bool rings = false;
};

// The corners, or the rings around the area with data; then the breaklines.
Status insertFrame(Build& b, const RasterSampler& raster, terrain::ValidArea area,
                   const terrain::BreaklinePieces& pieces, std::uint32_t breaklineCount) {
  Triangulation& t = b.triangulation;
  const double w = raster.width() - 1.0, h = raster.height() - 1.0;
  Status s;
  if (!b.rings) {
    const double corners[8] = {0, 0, w, 0, 0, h, w, h};
    const double heights[4] = {raster.at(raster.pixel(0, 0)),
                               raster.at(raster.pixel(raster.width() - 1, 0)),
                               raster.at(raster.pixel(0, raster.height() - 1)),
                               raster.at(raster.pixel(raster.width() - 1, raster.height() - 1))};
    s = t.insertPoints(corners, 4, nullptr, heights);
  } else {
    std::vector<double> heights(area.xy.size() / 2);
    for (std::size_t k = 0; k < heights.size(); ++k)
      heights[k] = raster.at(raster.pixel(static_cast<std::uint32_t>(area.xy[2 * k]),
                                          static_cast<std::uint32_t>(area.xy[2 * k + 1])));
    const std::size_t rings = area.ringCount();
    b.sourceOf.assign(rings, breaklineCount);
    s = t.insertPolylines(std::move(area.xy), area.offsets.data(), rings, nullptr, heights.data());
  }
  if (!s.ok() || pieces.count() == 0) return s;
  std::vector<PolylineView> views(pieces.count());
  for (std::size_t k = 0; k < pieces.count(); ++k)
    views[k] = {pieces.xy.data() + 2 * std::size_t{pieces.offsets[k]},
                pieces.offsets[k + 1] - pieces.offsets[k]};
  std::vector<std::uint32_t> ids(pieces.points());
  s = t.insertPolylines(views.data(), views.size(), ids.data(), pieces.z.data());
  if (!s.ok()) return s;
  b.sourceOf.insert(b.sourceOf.end(), pieces.breakline.begin(), pieces.breakline.end());
  const std::size_t n = t.vertexCount();
  b.given.assign(n, 0);
  b.original.assign(2 * n, std::nan(""));
  for (std::size_t k = 0; k < ids.size(); ++k) {
    b.given[ids[k]] |= pieces.given[k];
    if (std::isnan(pieces.original[2 * k])) continue;
    b.original[2 * ids[k]] = pieces.original[2 * k];
    b.original[2 * ids[k] + 1] = pieces.original[2 * k + 1];
  }
  return s;
}

// Heights of every vertex so far: the inserted points carry theirs. A crossing of
// breaklines interpolates along those through it with given heights (the core lists each
// segment through it as a pair of parents, its ends), averaged; with none, it reads the
// raster.
void initialHeights(Build& b, const RasterSampler& raster) {
  Triangulation::State& state = StateAccess::of(b.triangulation);
  Mesh derivations;
  b.z = state.values.update(state.delaunay, &derivations);
  const std::size_t n = b.z.size();
  b.given.resize(n, 0);
  b.original.resize(2 * n, std::nan(""));
  const std::vector<std::uint32_t>& parent = derivations.derivedParents;
  const std::vector<double>& weight = derivations.derivedWeights;
  for (std::size_t i = 0; i < derivations.derivedVertices.size(); ++i) {
    const std::uint32_t v = derivations.derivedVertices[i];
    double sum = 0;
    int segments = 0;
    for (std::uint32_t k = derivations.derivedOffsets[i]; k + 1 < derivations.derivedOffsets[i + 1];
         k += 2) {
      if (!b.given[parent[k]] || !b.given[parent[k + 1]]) continue;
      sum += (weight[k] * b.z[parent[k]] + weight[k + 1] * b.z[parent[k + 1]]) /
             (weight[k] + weight[k + 1]);
      ++segments;
    }
    b.given[v] = segments > 0;
    const double* xy = state.delaunay.xy.data();
    b.z[v] = segments > 0 ? sum / segments : raster.sample(xy[2 * v], xy[2 * v + 1]);
  }
}

// Heights of refinement's Steiner vertices from `first` on: read from the raster, or along a
// constrained edge between two given heights, interpolated.
void steinerHeights(Build& b, const Delaunay& d, std::size_t first, const RasterSampler& raster) {
  const std::size_t n = d.vertexCount();
  b.z.resize(n, 0);
  b.given.resize(n, 0);
  b.original.resize(2 * n, std::nan(""));
  for (std::size_t i = first; i < d.steiner.size(); ++i) {
    const SteinerVertex& s = d.steiner[i];
    const bool alongGiven =
        s.parents[2] == kNoVertex && b.given[s.parents[0]] && b.given[s.parents[1]];
    b.given[s.vertex] = alongGiven;
    b.z[s.vertex] = alongGiven ? s.weights[0] * b.z[s.parents[0]] + s.weights[1] * b.z[s.parents[1]]
                               : raster.sample(d.xy[2 * s.vertex], d.xy[2 * s.vertex + 1]);
  }
}

// Breakline pieces shorter than this (in pixels) are not split by refinement: below a
// raster's resolution more vertices say nothing, and two breaklines that run a hair apart
// (a road digitised twice) would have the gap between them filled with triangles its width,
// millions of them.
constexpr double kShortestSplit = 1.0 / 16;

// Greedy insertion; then with minAngle, rounds of refinement and of insertion where the
// refined mesh misses the bound, until a round inserts nothing (or after a few). One refiner
// serves every round, told of the pixels inserted between them: setting one up again each
// round cost most of what refinement did (bench/EXPERIMENTS.md, TN11).
Status mesh(Build& b, const RasterSampler& raster, const TerrainOptions& o,
            const terrain::MesherLimits& limits, TerrainStats& stats) {
  Delaunay& d = StateAccess::of(b.triangulation).delaunay;
  terrain::GreedyMesher mesher(d, raster, b.z, b.given, b.rings, limits);
  mesher.measure();
  std::uint64_t inserted = 0;
  if (!mesher.run(inserted)) return d.lastError();
  if (o.decimate && d.built()) {
    Status s;
    stats.decimated = mesher.decimate(s);
    if (!s.ok()) return s;
    // (A removal's flips may differ from its plan among cocircular pixels: what misses the
    // bound is queued, and inserted again.)
    if (!mesher.run(inserted)) return d.lastError();
  }
  if (o.minAngle > 0 && d.built()) {
    RefineOptions r;
    r.minAngle = o.minAngle;
    r.keep = b.rings ? Keep::Inside : Keep::All;
    refinement::Refiner refiner(d, r);
    refiner.start();
    refiner.trackChanges();
    refiner.setShortestSplit(kShortestSplit);
    terrain::GreedyMesher::Listener listener;
    listener.context = &refiner;
    listener.inserted = [](void* context, std::int32_t from, std::uint32_t a, std::uint32_t v,
                           bool onSubsegment) {
      static_cast<refinement::Refiner*>(context)->noteInsertion(from, a, v, onSubsegment);
    };
    mesher.listen(listener);
    constexpr std::uint32_t kMaxRounds = 8;
    while (stats.refineRounds < kMaxRounds) {
      const std::size_t before = d.steiner.size();
      const Status s = refiner.resume();
      if (!s.ok()) return s;
      ++stats.refineRounds;
      stats.steinerPoints += d.steiner.size() - before;
      stats.refineSkipped = d.stats.refineSkipped;
      steinerHeights(b, d, before, raster);
      mesher.measure(refiner.changedSlots(), refiner.windings().data());
      if (!mesher.run(inserted)) return d.lastError();
      if (inserted == 0) break;
    }
    // Stopped by the limit: the pixels the last round put back may have made bad triangles,
    // which the refiner was told of but no resume() counted.
    if (inserted > 0) stats.refineSkipped = refiner.countLeft();
  }
  stats.maxError = mesher.maxError();
  stats.insertions = mesher.stats().insertions;
  stats.scannedPixels = mesher.stats().scannedPixels;
  return Status::success();
}

Status build(const RasterSampler& raster, const PolylineView* breaklines, std::size_t count,
             const double* breaklineHeights, const TerrainOptions& o,
             const terrain::MesherLimits& limits, const terrain::PixelFrame& frame, Mesh& out,
             TerrainStats& stats) {
  Build b;
  b.rings = !raster.allValid();
  terrain::ValidArea area;
  if (b.rings) area = terrain::traceValidArea(raster);
  if (b.rings && area.cells == 0) {
    out = Mesh();
    out.sourceOffsets.assign(1, 0);
    return Status::success();
  }
  const terrain::BreaklinePieces pieces =
      terrain::cutBreaklines(breaklines, count, breaklineHeights, frame, raster);
  Status s = insertFrame(b, raster, std::move(area), pieces, static_cast<std::uint32_t>(count));
  if (!s.ok()) return s;
  initialHeights(b, raster);
  s = mesh(b, raster, o, limits, stats);
  if (!s.ok()) return s;
  Delaunay& d = StateAccess::of(b.triangulation).delaunay;
  MeshOptions m;
  m.keep = b.rings ? Keep::Inside : Keep::All;
  out = exportMesh(d, m, true);
  terrain::FrameInput in;
  b.original.resize(out.points.size(), std::nan(""));  // the mesher's pixels have none
  in.z = std::move(b.z);
  in.original = std::move(b.original);
  in.sourceOf = std::move(b.sourceOf);
  in.dropUnused = b.rings || stats.decimated > 0;  // (removed vertices are used by none)
  terrain::frameMesh(out, std::move(in), frame);
  return Status::success();
}

}  // namespace

Status triangulateRaster(const RasterView& raster, const PolylineView* breaklines,
                         std::size_t count, const double* breaklineHeights,
                         const TerrainOptions& options, Mesh& out, TerrainStats* stats) {
  Status s = checkOptions(raster, options);
  if (s.ok()) s = checkBreaklines(breaklines, count, breaklineHeights);
  if (!s.ok()) return s;
  TerrainStats measured;
  try {
    std::vector<std::uint8_t> valid;
    double largest = 0;
    s = validPixels(raster, options, valid, largest);
    if (!s.ok()) return s;
    const RasterSampler sampler(raster.heights, raster.width, raster.height, std::move(valid));
    const terrain::PixelFrame frame =
        options.hasBbox ? terrain::PixelFrame(options.minX, options.minY, options.maxX,
                                              options.maxY, raster.width, raster.height)
                        : terrain::PixelFrame();
    // An error within rounding of the heights is none: a plane stays two triangles.
    const double noise = 0x1p-40 * largest;
    const terrain::MesherLimits limits{std::max(options.maxError, noise), options.maxTriangles,
                                       options.maxVertices};
    if (raster.width == 1 || raster.height == 1) {
      profileMesh(sampler, limits, frame, out, measured);
    } else {
      s = build(sampler, breaklines, count, breaklineHeights, options, limits, frame, out,
                measured);
    }
  } catch (const std::bad_alloc&) {
    return {StatusCode::OutOfMemory,
            "out of memory: the input is too large for the available memory"};
  }
  if (s.ok() && stats) *stats = measured;
  return s;
}

}  // namespace geocdt
