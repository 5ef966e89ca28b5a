// libFuzzer target: Delaunay refinement, with a Steiner cap, of arbitrary free points and
// polylines (open, rings, crossing, overlapping), keep all or inside. The refined mesh must
// pass both halves of the invariant checker, its Steiner records must place their vertices,
// the cap must hold, and every triangle of the refined part must meet the bounds except
// those stats.refineSkipped owns up to.
//
// Input: byte 0 = options (see decodeOptions), byte 1 = minimum angle (low 6 bits, folded
// into 0-40 degrees) and keep inside (bit 6) and a maximum area (bit 7), byte 2 = the cap
// (times 16, plus 1), byte 3 = free point count (low 4 bits), then a PointDecoder header,
// the free points, and polylines until the bytes run out: a length byte (1 + low 4 bits
// points; bit 7 closes it into a ring) followed by its points.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "constraint_invariants.h"
#include "fuzz_input.h"
#include "geocdt/triangulation.h"
#include "invariants.h"
#include "refinement_checks.h"

namespace geocdt::fuzz {
namespace {

constexpr std::size_t kMaxPolylines = 16;
constexpr std::size_t kMaxPoints = 256;

struct Input {
  Options options;
  RefineOptions refine;
  std::vector<double> points;
  testing::Polylines lines;
};

Input decode(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Input input;
  input.options = decodeOptions(in.byte());
  const std::uint8_t b = in.byte();
  input.refine.minAngle = (b & 63) * 40.0 / 63;
  input.refine.keep = b & 64 ? Keep::Inside : Keep::All;
  input.refine.maxSteinerPoints = 16 * static_cast<std::uint64_t>(in.byte()) + 1;
  const bool area = b & 128;
  const std::size_t free = in.byte() & 15;
  PointDecoder decoder(in);
  decodePointsAndPolylines(in, decoder, free, kMaxPolylines, kMaxPoints, input.points, input.lines);
  // A maximum area of about a hundredth of the bounding box's.
  if (area) {
    double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    const auto extend = [&](const std::vector<double>& xy) {
      for (std::size_t k = 0; k + 1 < xy.size(); k += 2) {
        minX = std::min(minX, xy[k]), maxX = std::max(maxX, xy[k]);
        minY = std::min(minY, xy[k + 1]), maxY = std::max(maxY, xy[k + 1]);
      }
    };
    extend(input.points);
    for (const auto& line : input.lines) extend(line);
    const double a = (maxX - minX) * (maxY - minY) / 100;
    if (std::isfinite(a) && a > 0) input.refine.maxArea = a;
  }
  return input;
}

void print(const Input& input) {
  std::fprintf(stderr, "%s minAngle=%.17g maxArea=%.17g cap=%llu keep=%s\n",
               describeOptions(input.options).c_str(), input.refine.minAngle, input.refine.maxArea,
               static_cast<unsigned long long>(input.refine.maxSteinerPoints),
               input.refine.keep == Keep::Inside ? "inside" : "all");
  printPoints("free points", input.points.data(), input.points.size() / 2);
  for (std::size_t i = 0; i < input.lines.size(); ++i)
    printPoints(("polyline " + std::to_string(i)).c_str(), input.lines[i].data(),
                input.lines[i].size() / 2);
}

void run(const Input& input) {
  for (const double v : input.points)
    if (!validCoordinate(v)) return;
  for (const auto& line : input.lines)
    for (const double v : line)
      if (!validCoordinate(v)) return;
  Triangulation t(input.options);
  std::vector<std::uint32_t> ids(input.points.size() / 2);
  if (!t.insertPoints(input.points.data(), ids.size(), ids.data()).ok())
    fail("insertPoints returned an error");
  std::vector<PolylineView> views;
  std::size_t count = 0;
  for (const auto& line : input.lines) {
    views.push_back({line.data(), line.size() / 2});
    count += line.size() / 2;
  }
  std::vector<std::uint32_t> lineIds(count);
  if (!t.insertPolylines(views.data(), views.size(), lineIds.data()).ok())
    fail("insertPolylines returned an error");
  ids.insert(ids.end(), lineIds.begin(), lineIds.end());
  const Status s = t.refine(input.refine);
  if (!s.ok()) fail("refine returned an error: " + s.message);
  const Stats stats = t.stats();
  if (stats.steinerPoints > input.refine.maxSteinerPoints) fail("the cap was passed");
  MeshOptions mo;
  mo.insideFlags = true;
  mo.segmentSources = true;  // each segment's chain as routed, for the checker
  const Mesh m = t.mesh(mo);
  if (m.steiner.size() != stats.steinerPoints) fail("steiner does not list every Steiner point");
  if (m.triangles.empty()) return;
  const std::string broken = testing::checkRefined(
      m, input.points, input.lines, ids, input.refine.minAngle, input.refine.maxArea,
      input.refine.keep == Keep::Inside, stats.refineSkipped);
  if (!broken.empty()) fail(broken);
}

}  // namespace
}  // namespace geocdt::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geocdt::fuzz;
  return fuzzOne(data, size, decode, print, run);
}
