// libFuzzer target: arbitrary bytes as a small raster, no-data pixels and breaklines, through
// geocdt::triangulateRaster() with any mix of maxError, limits, decimate and minAngle. The
// mesh must be valid (constrained Delaunay, counter-clockwise, no gap), cover exactly the
// grid cells with data, and, without limits, hold every pixel within maxError (checked over
// every pixel by terrain_checks, independently of the mesher) but for those under given
// breakline heights. Cut into two tiles sharing a column, where the documented conditions
// hold, both tiles must have the same vertices and heights on it.
//
// Input: byte 0 = width (1 + low 5 bits), byte 1 = height (likewise), byte 2 = options (bits
// 0-1: how bytes become heights, bit 2: no data, bit 3: decimate, bit 4: minAngle, bit 5:
// given breakline heights, bit 6: maxTriangles, bit 7: maxVertices), byte 3 = maxError (in
// 64ths; 0 is 0), byte 4 = minAngle (10 + low 5 bits / 1.5 degrees) and the limits (2 + the
// byte), then a byte per pixel, row by row, then breaklines until the bytes run out: a
// length byte (2 + low 2 bits points; bit 2: on pixel positions, bit 3: the last point
// repeated) and two bytes a point, then with given heights a byte a point (255: none).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "geocdt/terrain.h"
#include "invariants.h"
#include "terrain_checks.h"

namespace geocdt::fuzz {
namespace {

constexpr std::size_t kMaxLines = 6;

struct Input {
  std::uint32_t width = 1, height = 1;
  std::vector<double> heights;
  std::vector<std::uint8_t> valid;  // empty: every pixel has data
  TerrainOptions options;
  std::vector<std::vector<double>> lines;
  std::vector<double> lineHeights;  // one a point, NaN where the raster's is taken
  bool given = false;
};

// A pixel's height from a byte: small integers (plateaus and steps, ties everywhere), tenths,
// a ramp with noise, or two levels (cliffs).
double heightOf(std::uint8_t mode, std::uint8_t b, std::uint32_t i, std::uint32_t j) {
  switch (mode & 3) {
    case 0: return b & 15;
    case 1: return (b - 128) * 0.1;
    case 2: return 0.25 * i + 0.5 * j + (b & 7) * 0.125;
    default: return b & 1 ? 40.0 : 0.0;
  }
}

Input decode(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Input input;
  input.width = 1 + (in.byte() & 31);
  input.height = 1 + (in.byte() & 31);
  const std::uint8_t flags = in.byte();
  TerrainOptions& o = input.options;
  o.maxError = in.byte() / 64.0;
  const std::uint8_t extra = in.byte();
  o.hasNoData = flags & 4;
  o.noDataValue = -1;
  o.decimate = flags & 8;
  if (flags & 16) o.minAngle = 10 + (extra & 31) / 1.5;
  input.given = flags & 32;
  if (flags & 64) o.maxTriangles = 2 + extra;
  if (flags & 128) o.maxVertices = 2 + extra;
  for (std::uint32_t j = 0; j < input.height; ++j)
    for (std::uint32_t i = 0; i < input.width; ++i) {
      const std::uint8_t b = in.byte();
      // No data: 254 as noDataValue, 255 as NaN (and any height that comes out as -1).
      if (o.hasNoData && b >= 254)
        input.heights.push_back(b == 254 ? o.noDataValue : std::nan(""));
      else
        input.heights.push_back(heightOf(flags, b, i, j));
    }
  if (o.hasNoData)
    for (std::size_t p = 0; p < input.heights.size(); ++p)
      if (std::isnan(input.heights[p]) || input.heights[p] == o.noDataValue) {
        if (input.valid.empty()) input.valid.assign(input.heights.size(), 1);
        input.valid[p] = 0;
      }
  // Breakline points from 2 pixels outside the raster to 2 pixels past it.
  const auto coordinate = [](std::uint8_t b, std::uint32_t n) { return b * (n + 4) / 255.0 - 2; };
  while (in.remaining() > 0 && input.lines.size() < kMaxLines) {
    const std::uint8_t head = in.byte();
    std::vector<double> line;
    for (int k = 2 + (head & 3); k > 0; --k) {
      double x = coordinate(in.byte(), input.width), y = coordinate(in.byte(), input.height);
      if (head & 4) x = std::round(x), y = std::round(y);
      line.insert(line.end(), {x, y});
    }
    if (head & 8) line.insert(line.end(), {line[line.size() - 2], line.back()});
    if (input.given)
      for (std::size_t k = 0; k < line.size() / 2; ++k) {
        const std::uint8_t b = in.byte();
        input.lineHeights.push_back(b == 255 ? std::nan("") : b * 0.1);
      }
    input.lines.push_back(std::move(line));
  }
  return input;
}

void print(const Input& input) {
  const TerrainOptions& o = input.options;
  std::fprintf(stderr,
               "raster %ux%u maxError=%.17g noData=%d decimate=%d minAngle=%.17g "
               "maxTriangles=%llu maxVertices=%llu given=%d\nheights:",
               input.width, input.height, o.maxError, o.hasNoData, o.decimate, o.minAngle,
               static_cast<unsigned long long>(o.maxTriangles),
               static_cast<unsigned long long>(o.maxVertices), input.given);
  for (const double h : input.heights) std::fprintf(stderr, " %.17g", h);
  std::fprintf(stderr, "\n");
  for (std::size_t i = 0; i < input.lines.size(); ++i)
    printPoints(("breakline " + std::to_string(i)).c_str(), input.lines[i].data(),
                input.lines[i].size() / 2);
  if (input.given) {
    std::fprintf(stderr, "breakline heights:");
    for (const double h : input.lineHeights) std::fprintf(stderr, " %.17g", h);
    std::fprintf(stderr, "\n");
  }
}

// The vertices of m on column x, with their heights, in order.
std::vector<std::array<double, 2>> onColumn(const Mesh& m, double x) {
  std::vector<std::array<double, 2>> out;
  for (std::size_t v = 0; v < m.points.size() / 2; ++v)
    if (m.points[2 * v] == x) out.push_back({m.points[2 * v + 1], m.values[v]});
  std::sort(out.begin(), out.end());
  return out;
}

// Under the documented conditions (web/API.md, "Tiles that match along their borders": the
// same maxError, no limits, no minAngle, data next to the border; here no breaklines
// either), the raster cut into two tiles that share column c: both must have the same
// vertices and heights on it as each other.
void tilesMatch(const Input& input) {
  const TerrainOptions& o = input.options;
  if (input.width < 3 || !input.lines.empty() || o.maxTriangles > 0 || o.maxVertices > 0 ||
      o.minAngle > 0 || o.hasNoData)
    return;
  const std::uint32_t c = input.width / 2;
  Mesh tile[2];
  for (int k = 0; k < 2; ++k) {
    const std::uint32_t from = k == 0 ? 0 : c, width = k == 0 ? c + 1 : input.width - c;
    std::vector<double> heights;
    for (std::uint32_t j = 0; j < input.height; ++j)
      for (std::uint32_t i = 0; i < width; ++i)
        heights.push_back(input.heights[j * input.width + from + i]);
    const Status s =
        triangulateRaster({heights.data(), width, input.height}, nullptr, 0, nullptr, o, tile[k]);
    if (!s.ok()) fail("a tile: triangulateRaster returned an error: " + s.message);
  }
  if (onColumn(tile[0], c) != onColumn(tile[1], 0))
    fail("two tiles sharing column " + std::to_string(c) + " have different vertices on it");
}

void run(const Input& input) {
  tilesMatch(input);
  std::vector<PolylineView> views;
  for (const auto& line : input.lines) views.push_back({line.data(), line.size() / 2});
  Mesh m;
  TerrainStats stats;
  const Status s = triangulateRaster(
      {input.heights.data(), input.width, input.height}, views.data(), views.size(),
      input.given ? input.lineHeights.data() : nullptr, input.options, m, &stats);
  if (!s.ok()) fail("triangulateRaster returned an error: " + s.message);
  if (m.values.size() != m.points.size() / 2) fail("not one height a vertex");
  if (m.triangles.empty()) return;
  testing::CheckOptions check;
  check.hull = input.valid.empty();
  if (const std::string broken = testing::checkTriangulation(m, check); !broken.empty())
    fail(broken);
  const std::vector<std::uint8_t> exempt =
      input.given
          ? testing::underGivenHeights(m, input.heights, input.width, input.height, input.lines)
          : std::vector<std::uint8_t>{};
  const testing::RasterErrors e =
      testing::rasterErrors(m, input.heights, input.width, input.height, input.valid, exempt);
  if (!e.problem.empty()) fail(e.problem);
  const TerrainOptions& o = input.options;
  if (o.maxTriangles > 0 || o.maxVertices > 0) return;  // the bound holds only without limits
  const double bound = std::max(o.maxError, 1e-9);
  if (e.maxError > bound * (1 + 1e-12) + 1e-9)
    fail("a pixel " + std::to_string(e.maxError) + " from the surface, maxError " +
         std::to_string(o.maxError));
  if (stats.maxError > bound) fail("stats.maxError " + std::to_string(stats.maxError));
}

}  // namespace
}  // namespace geocdt::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geocdt::fuzz;
  return fuzzOne(data, size, decode, print, run);
}
