// One triangulate() call on a .gpl dataset (its polylines as constraints), for callgrind and
// for comparing two builds: prints the counts and a hash of every output array, so that equal
// lines mean equal output. Under valgrind --tool=callgrind --collect-atstart=no only the call
// itself is counted (reading the file and hashing are not).
// Usage: bench_triangulate FILE.gpl [always]     (always: snap rounding in every call)
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <unordered_set>
#include <vector>

#include "geocdt/triangulation.h"
#include "polyline_file.h"

#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#endif
#endif
#ifndef CALLGRIND_TOGGLE_COLLECT
#define CALLGRIND_TOGGLE_COLLECT
#endif

namespace {

// FNV-1a over the bytes of an array, chained through h.
template <typename T>
std::uint64_t hashArray(std::uint64_t h, const std::vector<T>& a) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(a.data());
  for (std::size_t i = 0; i < a.size() * sizeof(T); ++i) h = (h ^ bytes[i]) * 0x100000001b3ull;
  return h;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE.gpl [always]\n", argv[0]);
    return 2;
  }
  geocdt::testing::PolylineSet set;
  const std::string error = geocdt::testing::readPolylineFile(argv[1], set);
  if (!error.empty()) {
    std::fprintf(stderr, "bench_triangulate: %s\n", error.c_str());
    return 1;
  }
  geocdt::Options options;
  if (argc > 2 && std::strcmp(argv[2], "always") == 0)
    options.snapRounding = geocdt::SnapRounding::Always;
  const std::vector<geocdt::PolylineView> views = set.views();
  geocdt::MeshOptions meshOptions;
  meshOptions.insideFlags = true;  // the rings' windings decide them
  geocdt::Mesh mesh;
  std::vector<std::uint32_t> ids;
  CALLGRIND_TOGGLE_COLLECT;
  const geocdt::Status s =
      geocdt::triangulate(nullptr, 0, views.data(), views.size(), options, meshOptions, mesh, &ids);
  CALLGRIND_TOGGLE_COLLECT;
  if (!s.ok()) {
    std::fprintf(stderr, "bench_triangulate: %s\n", s.message.c_str());
    return 1;
  }
  // Every output vertex is an input point or a crossing.
  const std::size_t inputVertices =
      std::unordered_set<std::uint32_t>(ids.begin(), ids.end()).size();
  std::uint64_t h = 0xcbf29ce484222325ull;
  h = hashArray(h, mesh.points);
  h = hashArray(h, mesh.triangles);
  h = hashArray(h, mesh.halfedges);
  h = hashArray(h, mesh.constrained);
  h = hashArray(h, mesh.constraintEdges);
  h = hashArray(h, mesh.sourceOffsets);
  h = hashArray(h, mesh.sources);
  h = hashArray(h, mesh.inside);
  std::printf(
      "%zu polylines, %zu points: %zu vertices, %zu triangles, %zu crossings, "
      "%zu constrained edges, output hash %016llx\n",
      set.polylineCount(), set.pointCount(), mesh.points.size() / 2, mesh.triangles.size() / 3,
      mesh.points.size() / 2 - inputVertices, mesh.constraintEdges.size(),
      static_cast<unsigned long long>(h));
  return 0;
}
