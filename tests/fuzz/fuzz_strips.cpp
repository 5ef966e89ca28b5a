// libFuzzer target: the threaded insertion (Options::threads), which only a first batch of
// at least 2 x 16,384 points reaches. The bytes give a tile of points (the other targets'
// point modes: lattices, ulp grids, duplicates, any magnitude), copied over a k x k pattern
// of offsets into more than 33,000 points; the offsets' step may be zero (every copy on the
// first: duplicates), less than the tile (copies overlap) or more. Each input is
// triangulated on 1, 2 and 3 threads (2 twice where strips ran), held to the checker, and
// compared.
//
// Input: byte 0 = options (see decodeOptions), byte 1 = the offsets' step on each axis (low
// and high 4 bits, in sixteenths of the tile's extent), then a PointDecoder header and the
// tile's points until the bytes run out.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "geocdt/triangulation.h"
#include "invariants.h"

namespace geocdt::fuzz {
namespace {

constexpr std::size_t kMaxTile = 256;
constexpr std::size_t kMinPoints = 33000;  // two strips of 16,384 and a little more

struct Input {
  Options options;
  std::vector<double> xy;
};

Input decode(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Input input;
  input.options = decodeOptions(in.byte());
  const std::uint8_t step = in.byte();
  PointDecoder points(in);
  std::vector<double> tile;
  while (in.remaining() > 0 && tile.size() < 2 * kMaxTile) {
    double x, y;
    points.next(in, x, y);
    if (!validCoordinate(x) || !validCoordinate(y)) continue;  // fuzz_points covers refusals
    tile.push_back(x);
    tile.push_back(y);
  }
  if (tile.empty()) return input;
  double minX = tile[0], maxX = tile[0], minY = tile[1], maxY = tile[1];
  for (std::size_t i = 0; i < tile.size(); i += 2) {
    minX = std::min(minX, tile[i]), maxX = std::max(maxX, tile[i]);
    minY = std::min(minY, tile[i + 1]), maxY = std::max(maxY, tile[i + 1]);
  }
  // Steps in sixteenths of the extent; a tile of one point or one line gets the other
  // axis's extent (or 1), so that copies still spread.
  double width = maxX - minX, height = maxY - minY;
  if (!(width > 0)) width = height > 0 ? height : 1;
  if (!(height > 0)) height = width;
  const double stepX = width * (step & 15) / 16, stepY = height * (step >> 4) / 16;
  const std::size_t n = tile.size() / 2;
  const std::size_t copies = (kMinPoints + n - 1) / n;
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(double(copies))));
  for (std::size_t c = 0; c < side * side; ++c) {
    const double dx = stepX * double(c % side), dy = stepY * double(c / side);
    for (std::size_t i = 0; i < tile.size(); i += 2) {
      const double x = tile[i] + dx, y = tile[i + 1] + dy;
      if (!validCoordinate(x) || !validCoordinate(y)) continue;  // copies that overflowed
      input.xy.push_back(x);
      input.xy.push_back(y);
    }
  }
  return input;
}

void print(const Input& input) {
  std::fprintf(stderr, "%s, %zu points\n", describeOptions(input.options).c_str(),
               input.xy.size() / 2);
  printPoints("points", input.xy.data(), std::min<std::size_t>(input.xy.size() / 2, 512));
}

struct Result {
  Mesh mesh;
  std::vector<std::uint32_t> ids;
  Stats stats;
};

Result triangulateOn(const Input& input, std::uint32_t threads) {
  Options options = input.options;
  options.threads = threads;
  Triangulation t(options);
  Result r;
  r.ids.resize(input.xy.size() / 2);
  const Status s = t.insertPoints(input.xy.data(), r.ids.size(), r.ids.data());
  if (!s.ok()) fail(std::to_string(threads) + " threads: " + s.message);
  r.stats = t.stats();
  r.mesh = t.mesh();
  testing::CheckOptions check;
  check.inputXY = &input.xy;
  check.inputToVertex = &r.ids;
  const std::string broken = testing::checkTriangulation(r.mesh, check);
  if (!broken.empty()) fail(std::to_string(threads) + " threads: " + broken);
  return r;
}

void run(const Input& input) {
  if (input.xy.size() / 2 < kMinPoints) return;
  const Result one = triangulateOn(input, 1);
  const auto oneSet = testing::triangleSet(one.mesh);
  for (const std::uint32_t threads : {2u, 3u}) {
    const Result many = triangulateOn(input, threads);
    const std::string with = std::to_string(threads) + " threads ";
    // Vertices are numbered as one thread numbers them, whatever the strips did.
    if (many.ids != one.ids) fail(with + "numbered the input points differently");
    if (many.mesh.points != one.mesh.points) fail(with + "gave other vertices");
    // Any Delaunay triangulation of the points has as many triangles (the hull is the same);
    // the same set only where no four points are cocircular, which the checker cannot say
    // here, so a differing set is only compared by count (the checker held both to Delaunay).
    const auto set = testing::triangleSet(many.mesh);
    if (set.size() != oneSet.size())
      fail(with + "gave " + std::to_string(set.size()) + " triangles, one thread " +
           std::to_string(oneSet.size()));
    if (printRequested())
      std::fprintf(stderr, "%u threads: %llu ran\n", threads,
                   static_cast<unsigned long long>(many.stats.threads));
    if (threads != 2 || many.stats.threads < 2) continue;
    // Run to run, the same arrays (where strips ran).
    const Result again = triangulateOn(input, threads);
    if (again.mesh.triangles != many.mesh.triangles || again.mesh.halfedges != many.mesh.halfedges)
      fail(with + "gave other triangles on a second run");
  }
}

}  // namespace
}  // namespace geocdt::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geocdt::fuzz;
  return fuzzOne(data, size, decode, print, run);
}
