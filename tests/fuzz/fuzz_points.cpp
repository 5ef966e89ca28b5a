// libFuzzer target: arbitrary bytes as points, through the one-shot and the incremental
// API and locate(), with every result held to the invariant checker.
//
// Input: byte 0 = options (see decodeOptions), byte 1 = where the incremental run splits
// its two batches, then a PointDecoder header and points until the bytes run out.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "geocdt/predicates.h"
#include "geocdt/triangulation.h"
#include "invariants.h"

namespace geocdt::fuzz {
namespace {

constexpr std::size_t kMaxPoints = 1024;

struct Input {
  Options options;
  std::size_t split = 0;  // points in the first incremental batch
  std::vector<double> xy;
};

Input decode(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Input input;
  input.options = decodeOptions(in.byte());
  const std::uint8_t split = in.byte();
  PointDecoder points(in);
  while (in.remaining() > 0 && input.xy.size() < 2 * kMaxPoints) {
    double x, y;
    points.next(in, x, y);
    input.xy.push_back(x);
    input.xy.push_back(y);
  }
  input.split = input.xy.size() / 2 * split / 255;
  return input;
}

void print(const Input& input) {
  std::fprintf(stderr, "%s, batches of %zu and %zu points\n",
               describeOptions(input.options).c_str(), input.split,
               input.xy.size() / 2 - input.split);
  printPoints("points", input.xy.data(), input.xy.size() / 2);
}

std::size_t firstInvalidPoint(const std::vector<double>& xy) {
  for (std::size_t i = 0; i < xy.size(); ++i)
    if (!validCoordinate(xy[i])) return i / 2;
  return kNoIndex;
}

std::size_t distinctPoints(const std::vector<double>& xy) {
  std::vector<std::pair<double, double>> p;
  for (std::size_t i = 0; i < xy.size(); i += 2) p.push_back({xy[i], xy[i + 1]});
  std::sort(p.begin(), p.end());
  return static_cast<std::size_t>(std::unique(p.begin(), p.end()) - p.begin());
}

std::string check(const Mesh& mesh, const std::vector<double>& xy,
                  const std::vector<std::uint32_t>& ids) {
  testing::CheckOptions options;
  options.inputXY = &xy;
  options.inputToVertex = &ids;
  return testing::checkTriangulation(mesh, options);
}

// Invalid input is refused as a whole, naming the first bad point, and leaves an existing
// triangulation as it was.
void checkRefused(const Input& input, std::size_t bad) {
  const std::size_t n = input.xy.size() / 2;
  Mesh mesh;
  const Status s = triangulate(input.xy.data(), n, nullptr, 0, input.options, {}, mesh);
  if (s.code != StatusCode::InvalidCoordinate || s.index != bad)
    fail("point " + std::to_string(bad) + " is invalid but triangulate said: " + s.message);

  Triangulation t(input.options);
  std::vector<std::uint32_t> ids(bad);
  if (!t.insertPoints(input.xy.data(), bad, ids.data()).ok()) fail("the valid prefix was refused");
  const std::size_t vertices = t.vertexCount();
  const Status again = t.insertPoints(input.xy.data(), n);
  if (again.code != StatusCode::InvalidCoordinate || again.index != bad)
    fail("insertPoints took invalid point " + std::to_string(bad) + ": " + again.message);
  if (t.vertexCount() != vertices) fail("a refused batch changed the vertex count");
  const std::vector<double> prefix(input.xy.begin(),
                                   input.xy.begin() + 2 * static_cast<std::ptrdiff_t>(bad));
  const std::string broken = check(t.mesh(), prefix, ids);
  if (!broken.empty()) fail("after a refused batch: " + broken);
}

bool hasEdge(const Mesh& m, std::size_t t, std::uint32_t a, std::uint32_t b) {
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t u = m.triangles[3 * t + k], v = m.triangles[3 * t + (k + 1) % 3];
    if ((u == a && v == b) || (u == b && v == a)) return true;
  }
  return false;
}

// What locate() says about (x, y) must be true of the mesh.
std::string checkLocation(const Mesh& m, const Location& loc, double x, double y) {
  const double* p = m.points.data();
  const std::size_t triangles = m.triangles.size() / 3;
  const auto side = [&](std::uint32_t a, std::uint32_t b) {
    return orient2d(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], x, y);
  };
  if (triangles == 0) return loc.kind == Location::Kind::Empty ? "" : "a location in an empty mesh";
  if (loc.kind == Location::Kind::Empty) return "Empty in a mesh with triangles";
  if (loc.kind == Location::Kind::Outside) {
    if (loc.triangle != -1) return "Outside with a triangle";
    // The reported hull edge must have the point strictly beyond it.
    for (std::size_t e = 0; e < m.halfedges.size(); ++e) {
      if (m.halfedges[e] >= 0) continue;
      const std::uint32_t u = m.triangles[e], v = m.triangles[e % 3 == 2 ? e - 2 : e + 1];
      if ((u == loc.vertices[0] && v == loc.vertices[1]) ||
          (u == loc.vertices[1] && v == loc.vertices[0]))
        return side(u, v) == Sign::Negative ? "" : "Outside but not beyond the hull edge given";
    }
    return "Outside names no hull edge";
  }
  if (loc.triangle < 0 || static_cast<std::size_t>(loc.triangle) >= triangles)
    return "triangle index out of range";
  const std::size_t t = static_cast<std::size_t>(loc.triangle);
  const std::uint32_t* v = loc.vertices;
  switch (loc.kind) {
    case Location::Kind::Vertex:
      if (p[2 * v[0]] != x || p[2 * v[0] + 1] != y) return "Vertex at another place";
      for (int k = 0; k < 3; ++k)
        if (m.triangles[3 * t + k] == v[0]) return "";
      return "Vertex not in the triangle given";
    case Location::Kind::Edge:
      if (!hasEdge(m, t, v[0], v[1])) return "Edge not in the triangle given";
      if (side(v[0], v[1]) != Sign::Zero) return "Edge not through the point";
      if (x < std::min(p[2 * v[0]], p[2 * v[1]]) || x > std::max(p[2 * v[0]], p[2 * v[1]]) ||
          y < std::min(p[2 * v[0] + 1], p[2 * v[1] + 1]) ||
          y > std::max(p[2 * v[0] + 1], p[2 * v[1] + 1]))
        return "Edge does not span the point";
      if ((p[2 * v[0]] == x && p[2 * v[0] + 1] == y) || (p[2 * v[1]] == x && p[2 * v[1] + 1] == y))
        return "Edge at one of its vertices";
      return "";
    default:
      for (int k = 0; k < 3; ++k) {
        if (v[k] != m.triangles[3 * t + k]) return "Face vertices differ from the triangle's";
        if (side(v[k], v[(k + 1) % 3]) != Sign::Positive)
          return "Face not strictly containing the point";
      }
      return "";
  }
}

void checkLocate(const Input& input, const Triangulation& t, const Mesh& m,
                 const std::vector<std::uint32_t>& ids) {
  const std::vector<double>& xy = input.xy;
  const std::size_t n = xy.size() / 2;
  const std::size_t probes = std::min<std::size_t>(n, 16);
  for (std::size_t k = 0; k < probes; ++k) {
    const std::size_t i = k * n / probes;
    const double x = xy[2 * i], y = xy[2 * i + 1];
    const Location loc = t.locate(x, y);
    const std::string where = " at input point " + std::to_string(i);
    const std::string broken = checkLocation(m, loc, x, y);
    if (!broken.empty()) fail("locate: " + broken + where);
    if (!m.triangles.empty() && (loc.kind != Location::Kind::Vertex || loc.vertices[0] != ids[i]))
      fail("locate: an input point is not its vertex" + where);
    // Points between inputs land on faces, edges, or outside.
    const std::size_t j = (i * 7 + 3) % n;
    const double mx = 0.5 * x + 0.5 * xy[2 * j], my = 0.5 * y + 0.5 * xy[2 * j + 1];
    const std::string between = checkLocation(m, t.locate(mx, my), mx, my);
    if (!between.empty())
      fail("locate: " + between + " between input points " + std::to_string(i) + " and " +
           std::to_string(j));
  }
}

void run(const Input& input) {
  const std::size_t n = input.xy.size() / 2;
  const std::size_t bad = firstInvalidPoint(input.xy);
  if (bad != kNoIndex) return checkRefused(input, bad);

  Mesh whole;
  std::vector<std::uint32_t> ids;
  const Status s = triangulate(input.xy.data(), n, nullptr, 0, input.options, {}, whole, &ids);
  if (!s.ok()) fail("triangulate: " + s.message);
  std::string broken = check(whole, input.xy, ids);
  if (!broken.empty()) fail("triangulate: " + broken);
  if (whole.points.size() / 2 != distinctPoints(input.xy))
    fail("vertex count is not the distinct point count");

  // Two batches must give the same triangle count (T = 2V - h - 2 with the whole hull).
  Triangulation t(input.options);
  std::vector<std::uint32_t> batchIds(n);
  Status first = t.insertPoints(input.xy.data(), input.split, batchIds.data());
  if (!first.ok()) fail("first batch: " + first.message);
  Status second = t.insertPoints(input.xy.data() + 2 * input.split, n - input.split,
                                 batchIds.data() + input.split);
  if (!second.ok()) fail("second batch: " + second.message);
  const Mesh incremental = t.mesh();
  broken = check(incremental, input.xy, batchIds);
  if (!broken.empty()) fail("two batches: " + broken);
  if (incremental.triangles.size() != whole.triangles.size() ||
      incremental.points.size() != whole.points.size())
    fail("two batches gave another vertex or triangle count than one");
  if (n > 0) checkLocate(input, t, incremental, batchIds);
}

}  // namespace
}  // namespace geocdt::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geocdt::fuzz;
  return fuzzOne(data, size, decode, print, run);
}
