#pragma once
// A constrained Delaunay triangulation built by incremental insertion.
//
// Layout (delaunator's): triangle t has vertices triangles[3t..3t+2], counter-clockwise
// with y up; half-edge e runs from triangles[e] to triangles[next(e)] and belongs to
// triangle e / 3; halfedges[e] is its twin, or -1 on the convex hull.
//
// Internally the hull is closed by a ghost vertex at infinity, so every half-edge has a
// twin and the result is the exact Delaunay triangulation covering the convex hull. Users
// never see ghost triangles: mesh() and release() return only real ones.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "geocdt/status.h"

namespace geocdt {

enum class InsertionOrder : std::uint8_t {
  Input,    // the paper's: insert in the order given
  Hilbert,  // spatially sorted along a Hilbert curve
  Brio,     // biased randomized rounds growing 8-fold, each Hilbert-sorted
};

// Where the walk of each insertion starts. locate() and the first point of every batch
// always start from the grid, which every insertion keeps up to date.
enum class LocateStart : std::uint8_t {
  Grid,          // the dynamic uniform grid's cell hint (Skvortsov)
  LastTriangle,  // the triangle of the previous insertion
};

// What a long call is busy with, for progress reports.
enum class Phase : std::uint8_t {
  Sort,         // ordering a batch of points along the Hilbert curve
  Points,       // inserting them
  Constraints,  // inserting constraint segments
  Export,       // building the caller's arrays
};

// An optional progress report: report(context, phase, done, total), called from outer loops
// only, at cheap checkpoints (every 4096 points, every 256 segments, each step of an export).
// A plain function pointer, so that an absent report costs one test per checkpoint.
struct Progress {
  void (*report)(void* context, Phase phase, std::size_t done, std::size_t total) = nullptr;
  void* context = nullptr;

  void operator()(Phase phase, std::size_t done, std::size_t total) const {
    if (report != nullptr) report(context, phase, done, total);
  }
};

// When constraint crossings are snap-rounded (see snapRounding below).
enum class SnapRounding : std::uint8_t {
  WhenNeeded,  // only where computed crossings would break the guarantee (tangles)
  Always,      // every call: each call then rebuilds the triangulation (for tests, mostly)
};

struct Options {
  // Brio flips about a third less than Hilbert: in Hilbert order each point lands next to the
  // empty part of the domain, where the hull's long triangles are (bench/EXPERIMENTS.md, P3).
  InsertionOrder order = InsertionOrder::Brio;
  LocateStart start = LocateStart::LastTriangle;
  // The grid doubles per axis when inserted points exceed gridDensity * m * m. 8 walks least,
  // with a cell per 4-8 points, about 1 byte per point (README, "How it works").
  double gridDensity = 8.0;
  Progress progress;
  // Crossings are computed from the input segments and checked to fit; where that would
  // move a constraint farther than the guarantee allows, the constraints are snap-rounded
  // instead (README, "How it works").
  SnapRounding snapRounding = SnapRounding::WhenNeeded;
  // Values carried per point (elevation, depth, any attribute): the insertions' `values`
  // arguments hold this many per point. Nothing is stored until values are first given.
  std::uint32_t valuesPerPoint = 1;
  // Threads for a large batch of points into an empty triangulation: the points are cut into
  // this many vertical strips, triangulated side by side and joined along their seams (the
  // same triangles as one thread, README "How it works"); the coordinate check and the
  // export of a large mesh are shared out too. 1 runs everything on the calling thread; so
  // does a batch too small to pay for the threads.
  std::uint32_t threads = 1;
};

// How interpolate() and rasterize() blend vertex values.
enum class Interpolation : std::uint8_t {
  Linear,   // barycentric in the triangle that holds the query
  Natural,  // Sibson's natural neighbour: areas the query's Voronoi cell steals
};

enum class FillRule : std::uint8_t { EvenOdd, NonZero };
enum class Keep : std::uint8_t { All, Inside };

struct MeshOptions {
  Keep keep = Keep::All;              // Inside drops triangles outside every ring
  FillRule fill = FillRule::EvenOdd;  // how rings decide inside (of each polygon too)
  bool insideFlags = false;           // fill Mesh::inside

  // Region labels: with regions, Mesh::regions names the polygon that holds each triangle.
  // A polygon is the set of polylines that polylinePolygons maps to its id (any number >= 0):
  // polylinePolygons[p] for polyline p, -1 for none, and none for polylines past its end.
  // Its inside is where its own rings give an inside by the fill rule, whatever the other
  // polylines do; polylines of no polygon, and open polylines, still constrain but bound no
  // region. Where several polygons hold a triangle (nested or overlapping), its region is the
  // smallest of them: the least area (its triangles' areas summed), then the fewest
  // triangles, then the lowest id. A polygon nested in another has less area or, equal in
  // floating point, fewer triangles, so nesting always gives the innermost polygon.
  bool regions = false;
  std::vector<std::int32_t> polylinePolygons;

  // Fill Mesh::segmentOffsets and Mesh::segmentSources: the input segments each constrained
  // edge lies on, for callers that need a segment's exact chain (tests check chains with it).
  bool segmentSources = false;
};

// Mesh::steinerParents' third entry for a Steiner vertex placed on an edge.
inline constexpr std::uint32_t kNoVertex = 0xFFFFFFFFu;

// Delaunay refinement (Triangulation::refine): Steiner vertices are added until every
// triangle of the refined part has its area at most maxArea and all its angles at least
// minAngle, except the angles the input does not allow (see Stats::refineSkipped).
struct RefineOptions {
  // Degrees, in [0, 60). Up to about 20.7 degrees refinement provably ends; beyond it the
  // cap ends it when nothing else does (30 degrees ends on real data, 34 mostly does).
  double minAngle = 20.0;
  double maxArea = 0.0;  // squared input units; 0 (or infinity) for no bound
  // A hard cap on the Steiner vertices one call adds. 0 means the default: 64 per vertex
  // before refinement, plus 4 per maxArea of the domain's area, plus 1024 (at every angle:
  // a safety net below kProvenAngle, which one input has needed).
  std::uint64_t maxSteinerPoints = 0;
  Keep keep = Keep::All;  // Inside refines only the inside of the rings; outside stays as is
  FillRule fill = FillRule::EvenOdd;
};

// The largest minimum angle for which Delaunay refinement with concentric shells is proven
// to end (Shewchuk): arcsin(1 / (2 sqrt 2)), about 20.7 degrees.
inline constexpr double kProvenAngle = 20.7;

// What a triangulation hands out: plain arrays the caller owns.
struct Mesh {
  std::vector<double> points;             // x0, y0, x1, y1, ... per vertex
  std::vector<std::uint32_t> triangles;   // 3 per triangle
  std::vector<std::int32_t> halfedges;    // 1 per half-edge
  std::vector<std::uint8_t> constrained;  // 1 per half-edge on an input constraint
  // Provenance: constraintEdges lists one half-edge per constrained edge; the polylines it
  // came from are sources[sourceOffsets[i] .. sourceOffsets[i + 1]) (sourceOffsets has one
  // entry more than constraintEdges, [0] when there are none; segmentOffsets alike).
  std::vector<std::uint32_t> constraintEdges;
  std::vector<std::uint32_t> sourceOffsets;
  std::vector<std::uint32_t> sources;
  // With MeshOptions::segmentSources: the input segments whose chains hold constrained edge
  // constraintEdges[i] are segmentSources[segmentOffsets[i] .. segmentOffsets[i + 1]).
  // Segments are numbered across polylines in insertion order, zero-length ones (a point
  // repeated, or two input points that became one vertex) skipped.
  std::vector<std::uint32_t> segmentOffsets;
  std::vector<std::uint32_t> segmentSources;
  std::vector<std::uint8_t> inside;  // 1 per triangle when MeshOptions::insideFlags
  // 1 per triangle when MeshOptions::regions: its polygon (see there), or -1 outside every one.
  std::vector<std::int32_t> regions;
  // Values, once an insertion gave some: Options::valuesPerPoint numbers per vertex. A vertex
  // that input points became has the values of the first of them whose values are not all NaN
  // (the others' values are dropped, those that differ counted in Stats::valueDuplicates);
  // NaN for points inserted without values.
  // A derived vertex (a constraint crossing; a Steiner point) has the weighted sum of its
  // parents' values, as listed below.
  std::vector<double> values;
  // Derivation of values, filled with `values`: vertex derivedVertices[i] is the sum over j in
  // [derivedOffsets[i], derivedOffsets[i + 1]) of derivedWeights[j] times the values of vertex
  // derivedParents[j] (parents are vertices with values of their own or derived earlier in
  // this list). A crossing's parents are the ends of each input segment through it, weighted
  // by its projection on the segment, the segments averaged. Vertices listed nowhere here
  // have values of their own.
  std::vector<std::uint32_t> derivedVertices;
  std::vector<std::uint32_t> derivedOffsets;
  std::vector<std::uint32_t> derivedParents;
  std::vector<double> derivedWeights;
  // Refinement's Steiner vertices, in the order they were added: steiner[i] is a vertex id,
  // placed between the vertices steinerParents[3i..3i+2] (a triangle's corners, or an edge's
  // two ends and kNoVertex) with barycentric weights steinerWeights[3i..3i+2] (summing to 1;
  // 0 for kNoVertex) at the time it was added: a value given at the parents interpolates
  // linearly to it. A Steiner vertex on a constrained edge splits it; both halves keep the
  // edge's provenance.
  std::vector<std::uint32_t> steiner;
  std::vector<std::uint32_t> steinerParents;
  std::vector<double> steinerWeights;
  // Once vertices were removed (Triangulation::removePoint, removePolyline), the vertices
  // are renumbered without gaps in the arrays above: vertexIds[i] is the id of vertex i (what
  // the insertions returned, what locate() names). Empty when nothing was removed: vertex i
  // is then id i.
  std::vector<std::uint32_t> vertexIds;
};

// A raster for rasterize(): width x height pixels over [minX, maxX] x [minY, maxY]. Pixel
// (column i, row j) samples the centre x = minX + (i + 0.5) * (maxX - minX) / width,
// y = maxY - (j + 0.5) * (maxY - minY) / height: row 0 is the top (north-up, as images).
struct RasterGrid {
  double minX = 0, minY = 0, maxX = 0, maxY = 0;
  std::uint32_t width = 0, height = 0;
};

// A polyline given as 2 * count doubles. A ring repeats its first point at its end.
struct PolylineView {
  const double* xy = nullptr;
  std::size_t count = 0;
};

struct Location {
  // The values are stable: the bindings pass them on as integers.
  enum class Kind : std::uint8_t {
    Empty,    // fewer than three non-collinear vertices: there are no triangles
    Outside,  // strictly outside the convex hull
    Face,     // strictly inside triangle
    Edge,     // on the edge between vertices[0] and vertices[1] (inside the hull)
    Vertex,   // equal to vertex vertices[0]
    Invalid,  // x or y is NaN or infinite: not a position, whatever the triangulation holds
  };
  Kind kind = Kind::Empty;
  // Index into mesh().triangles / 3, or -1 when outside, empty or invalid.
  std::int64_t triangle = -1;
  std::uint32_t vertices[3] = {0, 0, 0};
};

struct Stats {
  std::uint64_t inserted = 0;    // points that became vertices
  std::uint64_t duplicates = 0;  // points equal to an existing vertex
  std::uint64_t walkSteps = 0;   // triangles visited by point location
  std::uint64_t locates = 0;     // point locations performed
  std::uint64_t flips = 0;
  std::uint64_t walkFallbacks = 0;  // visibility walks that hit their step bound and gave
                                    // way to a scan of every triangle
  std::uint32_t gridSize = 0;       // current m of the m x m grid
  std::uint64_t crossings = 0;      // vertices added where constraints cross
  std::uint64_t polylines = 0;
  std::uint64_t segments = 0;  // constraint segments inserted
  // Times the constraints were snap-rounded because computed crossings would have broken
  // the guarantee (tangles of vertices a few ulps apart; never on real data so far).
  std::uint64_t snapRoundings = 0;
  // Input points equal to a vertex that already had values (not all NaN), carrying other
  // values: dropped, the first values stay.
  std::uint64_t valueDuplicates = 0;
  // Derived vertices whose input segments give values that differ (beyond 1e-9 of the
  // largest magnitude involved): they get the mean. Counted over the current mesh.
  std::uint64_t valueDisagreements = 0;
  // Refinement, over all refine() calls: Steiner vertices added; triangles of the refined
  // part that miss minAngle or maxArea when the last call ended (where two input segments
  // meet at a smaller angle than minAngle, the triangles in that corner keep it, though not
  // a size beyond maxArea; when the cap ended the call, what was left too); and whether the
  // cap ended the last call.
  std::uint64_t steinerPoints = 0;
  std::uint64_t refineSkipped = 0;
  bool refineCapped = false;
  // Threads that triangulated the last batch of points (1 when it ran on one thread).
  std::uint64_t threads = 1;
  // Vertices removed by edits (removePoint, removePolyline, and the crossings and Steiner
  // points those take with them). A moved vertex is not counted.
  std::uint64_t removed = 0;
};

// One Triangulation serves one thread at a time. Its const functions leave the mesh as it
// is, but locate() is not a pure read (see there): calls on one Triangulation must not
// overlap, const or not. Separate Triangulations share nothing.
class Triangulation {
 public:
  explicit Triangulation(const Options& options = {});
  ~Triangulation();
  Triangulation(Triangulation&&) noexcept;
  Triangulation& operator=(Triangulation&&) noexcept;

  // Inserts count points (xy holds 2*count doubles). vertexIds, if not null, receives
  // count ids: the vertex each point became or equals. Nothing is inserted when any
  // coordinate is invalid; the status names the first offending point.
  // values, if not null, holds Options::valuesPerPoint numbers per point (any, NaN included).
  Status insertPoints(const double* xy, std::size_t count, std::uint32_t* vertexIds = nullptr,
                      const double* values = nullptr);
  // The same for points in a buffer the triangulation takes over (count = xy.size() / 2).
  // While the triangulation has no vertices, the buffer becomes its coordinate array as it
  // is, with no copy: a caller that writes the points into a std::vector (the WebAssembly
  // binding, straight into wasm memory) holds them once, and points() and the released
  // mesh's points are that memory, duplicates closed up. Otherwise the points are appended
  // and the buffer is freed. On invalid coordinates nothing is inserted and xy is left as it
  // was.
  Status insertPoints(std::vector<double>&& xy, std::uint32_t* vertexIds = nullptr,
                      const double* values = nullptr);

  // Inserts a polyline as constraints: its points, then its segments, split where they
  // cross earlier constraints. Its polyline id is polylineCount() before the call.
  // vertexIds, if not null, receives count ids. Nothing is inserted on invalid input.
  // values: as insertPoints', one set per point of the polyline.
  Status insertPolyline(const double* xy, std::size_t count, std::uint32_t* vertexIds = nullptr,
                        const double* values = nullptr);
  // Inserts several polylines at once: all their points in one spatially sorted batch,
  // then their segments in order. vertexIds receives one id per point of every polyline, and
  // values holds one set per point of every polyline.
  Status insertPolylines(const PolylineView* polylines, std::size_t count,
                         std::uint32_t* vertexIds = nullptr, const double* values = nullptr);
  // The same for polylines in GeoArrow's layout in a buffer the triangulation takes over:
  // polyline i has the points offsets[i] .. offsets[i + 1] of xy (x, y interleaved); offsets
  // has count + 1 entries, from 0 to xy.size() / 2. The buffer goes into the point batch as
  // insertPoints(std::vector<double>&&) takes its points (no copy while the triangulation
  // has no vertices) and is not read again: the segments need only the points' vertex ids.
  // On invalid input nothing is inserted and xy is left as it was.
  Status insertPolylines(std::vector<double>&& xy, const std::uint32_t* offsets, std::size_t count,
                         std::uint32_t* vertexIds = nullptr, const double* values = nullptr);
  std::size_t polylineCount() const;

  // Where (x, y) lies in the triangulation. const because the mesh does not change; but the
  // call moves the walk's start hints (the grid cell of (x, y) and the last triangle) to
  // the triangle found, adds to stats().locates and walkSteps, and may rebuild a cached
  // triangle numbering. Hence the one-thread-at-a-time rule above. A NaN or infinite x or y
  // answers Kind::Invalid (Empty means only that there are no triangles yet).
  Location locate(double x, double y) const;

  // Values at count query points xy into out (valuesPerPoint() numbers per query): NaN
  // outside the convex hull, at NaN or infinite coordinates, and everywhere while no values
  // were given. Linear is exact at vertices and continuous everywhere; Natural too, and has
  // linear precision (it reproduces linear functions). Natural neighbours are those the query
  // sees without crossing a constrained edge; on a constrained or hull edge both methods
  // interpolate linearly along the edge, and Natural gives Linear's value where the query sees
  // such an edge at an angle within 1e-6 of a straight one (digits would cancel there). Queries are
  // located from the grid's cell hint, which each query moves to the triangle found: consecutive
  // nearby queries walk a step or two. Not a pure read, like locate().
  void interpolate(const double* xy, std::size_t count, Interpolation method, double* out) const;
  // The surface sampled on a raster: out receives width * height * valuesPerPoint() floats,
  // row by row from the top, NaN outside the convex hull. Linear scan-converts triangle by
  // triangle; Natural interpolates each pixel (queries in row order).
  Status rasterize(const RasterGrid& grid, Interpolation method, float* out) const;
  std::uint32_t valuesPerPoint() const;
  bool hasValues() const;  // whether any insertion gave values

  // Editing, in place (README, "Editing"). Ids stay valid until their vertex is removed, and
  // a removed id is never given again; Mesh::vertexIds names each output vertex's id. After
  // any edits the triangulation is the constrained Delaunay triangulation of what remains:
  // where no four points are cocircular, the one triangulate() gives for the remaining input
  // (in tangles that needed snap rounding, the one that inserting the remaining polylines
  // again gives). An id or polyline that names nothing now (removed, out of range) is
  // reported as InvalidArgument and changes nothing.
  //
  // A refined triangulation can be edited: an edit drops the Steiner points it invalidates
  // (those placed from a vertex removed or moved, directly or through other Steiner points,
  // and those on a removed polyline's edges); refine() again restores the quality there.
  //
  // Removes a point inserted with insertPoints. While a polyline has it among its points, the
  // vertex stays as that polyline's and *removed (if not null) is false; otherwise the vertex
  // goes, chains that only passed through it are joined again, and *removed is true. Costs
  // the vertex's degree plus the constraints through it.
  Status removePoint(std::uint32_t id, bool* removed = nullptr);
  // Removes the points ids[0..count) as removePoint would, one after the other, in an order
  // of its own: along a Hilbert curve of their places, so that consecutive removals touch
  // nearby memory (in random order they cost about 40% more). *removed (if not null)
  // receives how many vertices went; the others stay as polylines' (hasVertex tells which).
  // Every id is checked first, as removePoint checks it, and none may come twice: the first
  // bad one is reported with its index in ids, and nothing changes. A failure midway (out of
  // memory, which clears the triangulation as removePoint does) leaves the removals before
  // it done.
  Status removePoints(const std::uint32_t* ids, std::size_t count, std::size_t* removed = nullptr);
  // Removes polyline `polyline` (numbered in insertion order; the others keep their
  // numbers): its edges are freed and made Delaunay again, its vertices that no point and no
  // other polyline has go, and so do the crossings and Steiner points on it that nothing
  // else needs, the polylines split there joined again. Costs its length and crossings.
  Status removePolyline(std::size_t polyline);
  // Moves vertex id (a point's, or a polyline's: the polylines through it follow, crossing
  // what they now cross) to (x, y), which must be a valid coordinate and not another point's
  // or polyline vertex's place. About a removal plus an insertion; within its star (a drag),
  // a free point, or a polyline vertex with nothing along its segments, takes flips only.
  Status movePoint(std::uint32_t id, double x, double y);
  bool hasVertex(std::uint32_t id) const;  // whether id names a vertex now
  bool hasPolyline(std::size_t polyline) const;

  std::size_t vertexCount() const;    // vertices now (ids given, less those removed)
  std::size_t triangleCount() const;  // real triangles
  // Coordinates by vertex id (NaN for removed ids).
  const std::vector<double>& points() const;
  Stats stats() const;  // a copy of the counters as they are now

  // Delaunay refinement of what is there now (see RefineOptions). Later insertions leave the
  // quality to a later call. An invalid option is reported, and nothing changes.
  Status refine(const RefineOptions& options = {});

  Mesh mesh(const MeshOptions& options = {}) const;  // a compact copy, no ghost triangles
  Mesh release(const MeshOptions& options = {});     // the same; leaves this empty

 private:
  // insertPoints without checking the coordinates again (insertPolylines checked them);
  // with adopt, the points are *adopt's, taken over.
  Status insertCheckedPoints(const double* xy, std::size_t count, std::uint32_t* vertexIds,
                             const double* values, std::vector<double>* adopt = nullptr);
  // insertPolylines, from the polylines' views (whose coordinates are read only until their
  // points are in) or, with adopt, from *adopt's points, taken over.
  Status insertPolylineBatch(const PolylineView* polylines, std::size_t count,
                             std::uint32_t* vertexIds, const double* values,
                             std::vector<double>* adopt);

 public:
  struct State;  // internal: named here so that the implementation's helpers can take it

 private:
  friend struct StateAccess;  // the facade's helpers that work on the state (terrain)
  std::unique_ptr<State> state_;
};

// One shot: points first, then polylines in order. inputToVertex, if not null, gets one
// vertex id per input point (points first, then each polyline's points). With refine, the
// triangulation is refined before export (its keep and fill are meshOptions').
Status triangulate(const double* xy, std::size_t count, const PolylineView* polylines,
                   std::size_t polylineCount, const Options& options,
                   const MeshOptions& meshOptions, Mesh& out,
                   std::vector<std::uint32_t>* inputToVertex = nullptr,
                   const double* values = nullptr, const RefineOptions* refine = nullptr);
// values, if not null: Options::valuesPerPoint numbers per input point, in the same order.
// The same with the points in a buffer it takes over (see insertPoints(std::vector&&)):
// out.points is then that buffer's memory unless polylines add points. On invalid
// coordinates xy is left as it was.
Status triangulate(std::vector<double>&& xy, const PolylineView* polylines,
                   std::size_t polylineCount, const Options& options,
                   const MeshOptions& meshOptions, Mesh& out,
                   std::vector<std::uint32_t>* inputToVertex = nullptr,
                   const double* values = nullptr, const RefineOptions* refine = nullptr);

}  // namespace geocdt
