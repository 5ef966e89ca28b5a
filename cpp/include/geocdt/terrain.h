#pragma once
// Terrain: a triangulated irregular network (TIN) from a heightmap, by greedy insertion
// (Garland and Heckbert): the pixel farthest from the surface goes in next (once the mesh has
// 8,000 triangles, the farthest within each 64-pixel tile, tile after tile, for the cache),
// until every pixel is within maxError of it. Breaklines stay chains of constrained edges, pixels
// without data are left out, and minAngle refines the triangles' shapes.
//
// Coordinates: vertices sit on pixel positions, x the column and y the row (row 0 first), so
// that the mesh is made in exact small integers; a bbox maps them to map coordinates at the
// end. Seams: the vertices on each edge of the raster depend only on that edge's pixels (and
// on breaklines ending there), so two tiles that share a border row or column of pixels get
// the same vertices along it when they stop by maxError (README, "Terrain").
#include <cstddef>
#include <cstdint>
#include <limits>

#include "geocdt/status.h"
#include "geocdt/triangulation.h"

namespace geocdt {

// width * height heights, row by row from row 0.
struct RasterView {
  const double* heights = nullptr;
  std::uint32_t width = 0, height = 0;
};

struct TerrainOptions {
  // The largest distance, in height units, from any pixel's height to the surface at its
  // position (the surface interpolated linearly in its triangle). 0 keeps every pixel that
  // is not exactly on the surface already.
  double maxError = 0;
  // Stop earlier, when the next insertion would pass either (0: no limit). Insertions go
  // largest error first, so the mesh is the best greedy one of that size. The corners, the
  // breaklines and the boundary of the valid area go in whatever the limits say, and
  // refinement (minAngle) may add vertices past them.
  std::uint64_t maxTriangles = 0;
  std::uint64_t maxVertices = 0;
  // Pixels whose height equals noDataValue (and NaN pixels) have no data: the mesh covers
  // the union of the grid cells whose four corners have data, bounded by constrained edges.
  bool hasNoData = false;
  double noDataValue = std::numeric_limits<double>::quiet_NaN();
  // After greedy insertion, remove the vertices it inserted that later ones made needless:
  // each interior one whose removal keeps every pixel within maxError goes (one pass, in
  // the order they went in). Fewer triangles for the same bound, at some more time. Not with
  // maxTriangles or maxVertices once they stop the insertions; hull, border, breakline and
  // no-data boundary vertices always stay (tiles still match along their borders).
  bool decimate = false;
  // Delaunay refinement to this smallest angle in degrees (0: none), with the heights of its
  // Steiner points read from the raster; the error bound still holds after it.
  double minAngle = 0;
  // Map coordinates of the mesh: pixel (0, 0) at (minX, maxY), pixel (width - 1, height - 1)
  // at (maxX, minY), as a north-up image's row 0 is its top. Without it, the points are
  // pixel positions. Breaklines are given in the same coordinates as the result.
  bool hasBbox = false;
  double minX = 0, minY = 0, maxX = 0, maxY = 0;
};

// What a call measured on its result.
struct TerrainStats {
  double maxError = 0;              // the largest error left, over every pixel the mesh covers
  std::uint64_t insertions = 0;     // pixels inserted by the greedy loop
  std::uint64_t decimated = 0;      // of them, removed again by decimate
  std::uint64_t scannedPixels = 0;  // pixel errors computed, rescans included
  std::uint64_t steinerPoints = 0;  // added by refinement
  std::uint32_t refineRounds = 0;   // refinements (8 at most), each followed by insertions
  // Triangles of the result below minAngle: where breaklines meet each other or the raster's
  // edges at a smaller angle, or run closer than 1/16 pixel (whose pieces refinement does not
  // split), and what the pixels put back after the last round made.
  std::uint64_t refineSkipped = 0;
};

// Triangulates raster. breaklines (count of them, in the result's coordinates) are kept as
// chains of constrained edges; breaklineHeights, if not null, gives one height per breakline
// point (all breaklines' points in order), NaN for "read it from the raster" (bilinear in the
// pixels around it). The result has the layout of triangulate()'s, with one value per
// vertex (its height) in out.values; a constrained edge's sources name the breaklines it
// lies on, and count (the number of breaklines) for the boundary of the area with data.
// A raster of one row or column has no triangles: its vertices are its simplified profile.
Status triangulateRaster(const RasterView& raster, const PolylineView* breaklines,
                         std::size_t count, const double* breaklineHeights,
                         const TerrainOptions& options, Mesh& out, TerrainStats* stats = nullptr);

}  // namespace geocdt
