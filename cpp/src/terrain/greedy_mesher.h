#pragma once
// Greedy insertion (Garland and Heckbert, "Fast polygonal approximation of terrains and
// height fields", 1995): every triangle and border segment knows its pixel farthest from the
// surface; the largest of them all goes in next, through the exact incremental core (split,
// then Lawson flips). Every triangle an insertion changes has the new vertex as a corner, so
// only the new vertex's star is scanned again: each pixel is measured again only when its
// triangle changed. Once the mesh outgrows the cache, the largest error goes first tile by
// tile (tile_order.h).
#include <cstdint>
#include <vector>

#include "delaunay/delaunay.h"
#include "terrain/border_segments.h"
#include "terrain/candidate_queue.h"
#include "terrain/height_blocks.h"
#include "terrain/raster_sampler.h"
#include "terrain/tile_order.h"
#include "terrain/triangle_scan.h"

namespace geocdt::terrain {

struct MesherLimits {
  double maxError = 0;
  std::uint64_t maxTriangles = 0;  // 0: none
  std::uint64_t maxVertices = 0;
};

struct MesherStats {
  std::uint64_t insertions = 0;
  std::uint64_t scannedPixels = 0;
};

// A point on a constrained edge: where, its height, and the edge's split.
struct BreaklinePoint {
  double x = 0, y = 0, z = 0;
  bool given = false;
  Hit edge;
};

class GreedyMesher {
 public:
  // z: one height per vertex of d, kept up to date for the vertices the mesher adds; given:
  // per vertex, whether its height came with a breakline (the mesher's own vertices on such a
  // breakline interpolate along it). rings: whether the mesh is bounded by rings (the area
  // with data), whose inside (by the even-odd rule) is the mesh; otherwise every real
  // triangle is.
  GreedyMesher(Delaunay& d, const RasterSampler& raster, std::vector<double>& z,
               std::vector<std::uint8_t>& given, bool rings, const MesherLimits& limits)
      : d_(d),
        topo_(d.topo),
        raster_(raster),
        z_(z),
        given_(given),
        rings_(rings),
        limits_(limits) {
    d_.cocircular = {&GreedyMesher::chooseDiagonal, this};
  }
  ~GreedyMesher() { d_.cocircular = {}; }
  GreedyMesher(const GreedyMesher&) = delete;
  GreedyMesher& operator=(const GreedyMesher&) = delete;

  // Measures every triangle and border segment of the mesh as it is now: at the start, and
  // after anything else changed it, when only the slots that hold another triangle than they
  // did are measured again. windings: every slot's, when the caller has them, else computed
  // here.
  void measure(std::vector<std::int32_t> windings = {});
  // The same after a change that lists the slots it rewrote, some more than once (a
  // refinement round): only those are looked at. windings: every slot's, with rings.
  void measure(const std::vector<std::int32_t>& changed, const std::int32_t* windings);
  // Inserts pixels, largest error first, until none is above maxError or a limit stops it.
  // Returns the number inserted; a failure of the core is in d.lastError() (returns false).
  bool run(std::uint64_t& inserted);

  // Greedy insertion leaves vertices that later ones made needless: each interior vertex it
  // inserted goes where the triangles its removal would make keep every pixel within
  // maxError (one pass, in insertion order). Only after a run that no limit stopped, and
  // before refinement. Returns the vertices removed; a failure of the core in status.
  std::uint64_t decimate(Status& status);

  // Told of every insertion, after it: from, a half-edge out of the new vertex; a, b the ends
  // of the edge it split (kGhost for none) and whether that was a constrained or hull edge.
  // Refinement in rounds listens, to keep its own record of the mesh.
  struct Listener {
    void (*inserted)(void* context, std::int32_t from, std::uint32_t a, std::uint32_t b,
                     bool onSubsegment) = nullptr;
    void* context = nullptr;
  };
  void listen(const Listener& listener) { listener_ = listener; }

  // The largest error left over every pixel the mesh covers.
  double maxError() const;
  std::uint64_t triangleCount() const { return triangles_; }
  const MesherStats& stats() const { return stats_; }

 private:
  bool inside(std::int32_t t) const;
  // Delaunay's choice between the diagonals of a cocircular quad (diagonal_fit.h).
  static bool chooseDiagonal(void* mesher, std::uint32_t a, std::uint32_t b, std::uint32_t d,
                             std::uint32_t p);
  // The queues' ranks (0 until the order is tiled).
  std::uint32_t rankOf(std::uint32_t a, std::uint32_t b, std::uint32_t c) const;
  std::uint32_t triangleRank(std::int32_t t) const;  // of the triangle measured in slot t
  std::uint32_t segmentRank(std::uint32_t s) const;
  void orderByTiles();
  void measureTriangle(std::int32_t t);
  void measureSegment(std::uint32_t s);
  void noteNewVertices();
  void markBoundary();
  void addBoundary(std::uint32_t a, std::uint32_t b);
  // Inserts the pixel at (i, j) as vertex, located by h; false on a failure of the core.
  bool insertPixel(std::size_t pixel, const Hit& h);
  // Inserts vertex (x, y) with height z (given: interpolated along given heights), located by
  // h, and measures its star; false on a failure of the core.
  bool insertVertex(double x, double y, double z, bool given, const Hit& h);
  Hit locateIn(std::int32_t t, double x, double y);
  Hit ontoConstraint(const Hit& face, double x, double y) const;
  // A point of a breakline near the pixel at (x, y) in face h, where that pixel goes first.
  bool breaklinePointNear(const Hit& h, double x, double y, BreaklinePoint& onto) const;
  bool insertBreaklinePoint(std::size_t pixel, const BreaklinePoint& onto);
  double heightOnBreakline(std::uint32_t a, std::uint32_t b, double x, double y, bool& given) const;
  std::int32_t edgeBetween(std::uint32_t a, std::uint32_t b) const;
  // Returns a half-edge out of v.
  std::int32_t afterInsert(std::uint32_t v);
  bool insertTriangleCandidate(std::int32_t t);
  bool insertSegmentCandidate(std::uint32_t s);
  void grow();
  std::int32_t edgeOutOf(std::uint32_t v) const;  // a half-edge out of v, or -1
  std::int32_t removableEdge(std::uint32_t v);    // decimate()'s test
  void moveSlot(std::int32_t from, std::int32_t to);

  Delaunay& d_;
  Topology& topo_;
  const RasterSampler& raster_;
  std::vector<double>& z_;
  std::vector<std::uint8_t>& given_;
  bool rings_;
  MesherLimits limits_;
  Listener listener_;
  MesherStats stats_;
  std::uint64_t triangles_ = 0;  // real triangles of the mesh (inside the rings)
  // Per pixel: 1 for vertices and the border's pixels, which no triangle proposes.
  std::vector<std::uint8_t> skip_;
  std::uint32_t skipped_ = 0;  // the vertices whose pixels skip_ has
  // Per pixel: 1 once a point of a breakline went in for it (breaklinePointNear), so that the
  // pixel itself goes in the next time it is the largest error.
  std::vector<std::uint8_t> projected_;
  // Per slot: its error and candidate pixel, and (with rings) its winding number.
  std::vector<double> error_;
  std::vector<std::int64_t> candidate_;
  std::vector<std::uint32_t> corners_;  // per slot: the triangle its measurement is of
  std::vector<std::int32_t> winding_;
  std::vector<std::int32_t> vertexEdge_;  // per vertex: a half-edge out of it
  std::vector<std::int32_t> star_;
  std::uint32_t firstInserted_ = kGhost;  // the first vertex run() inserted
  std::vector<std::uint32_t> plan_;       // decimate()'s planned triangles
  CandidateQueue triangleQueue_, segmentQueue_;
  TileOrder tiles_{raster_.width(), raster_.height()};
  bool tiled_ = false;  // whether the queues rank by tile
  BorderSegments segments_;
  HeightBlocks blocks_{raster_};  // for scans of large triangles
  ScanScratch scratch_;
};

}  // namespace geocdt::terrain
