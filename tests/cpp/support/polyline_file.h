#pragma once
// Binary dataset files shared by the tests and the benchmarks. All numbers little-endian.
//
//   .gpl  polylines:  "GPL1", uint32 P, uint32 count[P], then float64 x, y of every point
//                     of every polyline in order.
//   .gpt  points:     "GPT1", uint64 n, then n float64 x, y pairs.
//   .gpg  polygons:   "GPG1", uint32 G, uint32 count[G]: polygon g has the next count[g]
//                     polylines of the .gpl file of the same name.
//
// The scripts in scripts/datasets write these files; a ring repeats its first point last.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geocdt/triangulation.h"

namespace geocdt::testing {

// All polylines in one flat array: polyline i owns points [offsets[i], offsets[i + 1]).
struct PolylineSet {
  std::vector<double> xy;                 // 2 per point
  std::vector<std::uint32_t> offsets{0};  // polylineCount() + 1 entries

  std::size_t polylineCount() const { return offsets.size() - 1; }
  std::size_t pointCount() const { return xy.size() / 2; }
  std::size_t pointCount(std::size_t i) const { return offsets[i + 1] - offsets[i]; }
  PolylineView view(std::size_t i) const { return {xy.data() + 2 * offsets[i], pointCount(i)}; }
  std::vector<PolylineView> views() const;
  // Segments between consecutive points of each polyline (zero-length ones included).
  std::size_t segmentCount() const;

  void add(const double* xy, std::size_t count);
};

// Each returns an empty string on success, or a message naming the file and the problem.
std::string readPolylineFile(const std::string& path, PolylineSet& out);
std::string writePolylineFile(const std::string& path, const PolylineSet& set);
std::string readPointFile(const std::string& path, std::vector<double>& xy);
std::string writePointFile(const std::string& path, const std::vector<double>& xy);
// The polygon of each polyline, as MeshOptions::polylinePolygons takes it.
std::string readPolygonFile(const std::string& path, std::vector<std::int32_t>& polylinePolygons);

}  // namespace geocdt::testing
