// libFuzzer target: arbitrary bytes as free points and polylines (open, closed, crossing,
// overlapping, with repeated points), inserted through one of several API paths, and the
// result held to both halves of the invariant checker, the inside flags, the region labels
// (polylines 2i and 2i + 1 make polygon i), provenance, and values (interpolated ones too).
//
// Input: byte 0 = options (see decodeOptions), byte 1 = API path (bits 0-1) and fill rule
// (bit 2), byte 2 = free point count (low 4 bits), then a PointDecoder header, the free
// points, and polylines until the bytes run out: a length byte (1 + low 4 bits points;
// bit 7 closes it into a ring) followed by its points.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "constraint_invariants.h"
#include "fuzz_input.h"
#include "geocdt/triangulation.h"
#include "invariants.h"

namespace geocdt::fuzz {
namespace {

constexpr std::size_t kMaxPolylines = 32;
constexpr std::size_t kMaxPoints = 512;

enum class Path : std::uint8_t {
  OneShot,         // triangulate(): points, then all polylines
  EachPolyline,    // insertPoints, then insertPolyline one by one
  PolylinesFirst,  // insertPolylines, then insertPoints
  Mixed,           // half the polylines, the points, then the rest one by one
};

struct Input {
  Options options;
  Path path = Path::OneShot;
  FillRule fill = FillRule::EvenOdd;
  std::vector<double> points;
  testing::Polylines lines;
};

Input decode(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Input input;
  input.options = decodeOptions(in.byte());
  const std::uint8_t b = in.byte();
  input.path = static_cast<Path>(b & 3);
  input.fill = (b >> 2) & 1 ? FillRule::NonZero : FillRule::EvenOdd;
  const std::size_t free = in.byte() & 15;
  PointDecoder decoder(in);
  decodePointsAndPolylines(in, decoder, free, kMaxPolylines, kMaxPoints, input.points, input.lines);
  return input;
}

void print(const Input& input) {
  static const char* kPaths[4] = {"OneShot", "EachPolyline", "PolylinesFirst", "Mixed"};
  std::fprintf(stderr, "%s path=%s fill=%s\n", describeOptions(input.options).c_str(),
               kPaths[static_cast<int>(input.path)],
               input.fill == FillRule::EvenOdd ? "EvenOdd" : "NonZero");
  printPoints("free points", input.points.data(), input.points.size() / 2);
  for (std::size_t i = 0; i < input.lines.size(); ++i)
    printPoints(("polyline " + std::to_string(i)).c_str(), input.lines[i].data(),
                input.lines[i].size() / 2);
}

bool allValid(const Input& input) {
  for (const double v : input.points)
    if (!validCoordinate(v)) return false;
  for (const auto& line : input.lines)
    for (const double v : line)
      if (!validCoordinate(v)) return false;
  return true;
}

struct Built {
  Mesh mesh;
  std::vector<double> inputXY;         // every input point in the order the ids follow
  std::vector<std::uint32_t> ids;      // the vertex of each
  std::vector<std::uint32_t> lineIds;  // the polylines' part of ids, in polyline order
  std::size_t insideKept = 0;          // triangles that Keep::Inside keeps
};

// Runs the input's API path; any failed status is a finding.
Built build(const Input& input) {
  Built out;
  MeshOptions flagged, insideOnly;
  flagged.insideFlags = true;
  flagged.fill = insideOnly.fill = input.fill;
  flagged.regions = true;
  flagged.segmentSources = true;  // each segment's chain as routed, for the checker
  for (std::size_t i = 0; i < input.lines.size(); ++i)
    flagged.polylinePolygons.push_back(static_cast<std::int32_t>(i / 2));
  insideOnly.keep = Keep::Inside;
  Triangulation t(input.options);
  std::vector<PolylineView> views;
  for (const auto& line : input.lines) views.push_back({line.data(), line.size() / 2});
  const std::size_t half = input.path == Path::Mixed ? views.size() / 2 : views.size();
  std::vector<std::uint32_t> pointIds(input.points.size() / 2);

  const auto require = [](const Status& s, const char* call) {
    if (!s.ok()) fail(std::string(call) + " returned an error: " + s.message);
  };
  const auto addPoints = [&] {
    require(t.insertPoints(input.points.data(), pointIds.size(), pointIds.data()), "insertPoints");
    out.inputXY.insert(out.inputXY.end(), input.points.begin(), input.points.end());
    out.ids.insert(out.ids.end(), pointIds.begin(), pointIds.end());
  };
  const auto addLines = [&](std::size_t from, std::size_t to, bool oneByOne) {
    std::size_t count = 0;
    for (std::size_t i = from; i < to; ++i) count += views[i].count;
    std::vector<std::uint32_t> ids(count);
    if (oneByOne) {
      for (std::size_t i = from, offset = 0; i < to; offset += views[i].count, ++i)
        require(t.insertPolyline(views[i].xy, views[i].count, ids.data() + offset),
                "insertPolyline");
    } else if (from < to) {
      require(t.insertPolylines(views.data() + from, to - from, ids.data()), "insertPolylines");
    }
    for (std::size_t i = from; i < to; ++i)
      out.inputXY.insert(out.inputXY.end(), input.lines[i].begin(), input.lines[i].end());
    out.ids.insert(out.ids.end(), ids.begin(), ids.end());
    out.lineIds.insert(out.lineIds.end(), ids.begin(), ids.end());
  };

  switch (input.path) {
    case Path::OneShot: {
      const Status s = triangulate(input.points.data(), pointIds.size(), views.data(), views.size(),
                                   input.options, flagged, out.mesh, &out.ids);
      require(s, "triangulate");
      Mesh inside;
      require(triangulate(input.points.data(), pointIds.size(), views.data(), views.size(),
                          input.options, insideOnly, inside),
              "triangulate (Keep::Inside)");
      out.insideKept = inside.triangles.size() / 3;
      out.inputXY = input.points;
      for (const auto& line : input.lines)
        out.inputXY.insert(out.inputXY.end(), line.begin(), line.end());
      out.lineIds.assign(out.ids.begin() + static_cast<std::ptrdiff_t>(pointIds.size()),
                         out.ids.end());
      return out;
    }
    case Path::EachPolyline:
      addPoints();
      addLines(0, views.size(), true);
      break;
    case Path::PolylinesFirst:
      addLines(0, views.size(), false);
      addPoints();
      break;
    case Path::Mixed:
      addLines(0, half, false);
      addPoints();
      addLines(half, views.size(), true);
      break;
  }
  if (t.polylineCount() != views.size()) fail("polylineCount differs from the polylines inserted");
  out.mesh = t.mesh(flagged);
  out.insideKept = t.mesh(insideOnly).triangles.size() / 3;
  return out;
}

// The power-of-two exponent of the largest |coordinate|, 0 when all are zero.
int magnitudeExponent(const std::vector<double>& xy) {
  double largest = 0;
  for (const double c : xy) largest = std::max(largest, std::fabs(c));
  return largest > 0 ? std::ilogb(largest) : 0;
}

// Exact, except that coordinates far below the largest may underflow: a loss far below the
// allowances here. Coordinates far above it (free points) may become infinite: callers skip them.
std::vector<double> scaled(const std::vector<double>& xy, int exponent) {
  std::vector<double> out;
  for (const double c : xy) out.push_back(std::ldexp(c, -exponent));
  return out;
}

// Reference winding number of (x, y) over the rings, by crossings of a ray towards +x.
int winding(const testing::Polylines& lines, double x, double y) {
  int w = 0;
  for (const auto& line : lines) {
    const std::size_t n = line.size() / 2;
    if (n < 3 || line[0] != line[2 * n - 2] || line[1] != line[2 * n - 1]) continue;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double ax = line[2 * k], ay = line[2 * k + 1], bx = line[2 * k + 2],
                   by = line[2 * k + 3];
      if ((ay > y) == (by > y)) continue;
      if (x < ax + (y - ay) / (by - ay) * (bx - ax)) w += by > ay ? 1 : -1;
    }
  }
  return w;
}

// Inside flags: one per triangle, as many set as Keep::Inside keeps, and agreeing with a
// ray-casting reference at centroids that lie clearly away from every constraint. Region
// labels: -1 where no polygon holds such a centroid by the reference, else one that does.
void checkInside(const Input& input, const Built& b) {
  const Mesh& m = b.mesh;
  const std::size_t triangles = m.triangles.size() / 3;
  if (m.inside.size() != triangles)
    fail(std::to_string(m.inside.size()) + " inside flags for " + std::to_string(triangles) +
         " triangles");
  const std::size_t flagged =
      static_cast<std::size_t>(std::count(m.inside.begin(), m.inside.end(), 1));
  if (flagged != b.insideKept)
    fail(std::to_string(flagged) + " triangles flagged inside but Keep::Inside kept " +
         std::to_string(b.insideKept));
  if (m.regions.size() != triangles)
    fail(std::to_string(m.regions.size()) + " region labels for " + std::to_string(triangles) +
         " triangles");

  // In a frame scaled by a power of two to magnitude ~1, so that tiny inputs do not underflow.
  int exponent = 0;
  for (const auto& line : input.lines) exponent = std::max(exponent, magnitudeExponent(line));
  testing::Polylines lines, rings;
  std::vector<testing::Polylines> polygons((input.lines.size() + 1) / 2);
  for (std::size_t i = 0; i < input.lines.size(); ++i) {
    const auto& line = input.lines[i];
    lines.push_back(scaled(line, exponent));
    // Whether it is a ring is decided before scaling, which can flush subnormals to zero.
    const std::size_t n = line.size() / 2;
    if (n >= 3 && line[0] == line[2 * n - 2] && line[1] == line[2 * n - 1]) {
      rings.push_back(lines.back());
      polygons[i / 2].push_back(lines.back());
    }
  }
  const auto holds = [&](int w) { return input.fill == FillRule::EvenOdd ? (w & 1) != 0 : w != 0; };
  double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
  for (const auto& line : lines)
    for (std::size_t k = 0; k < line.size(); k += 2) {
      minX = std::min(minX, line[k]), maxX = std::max(maxX, line[k]);
      minY = std::min(minY, line[k + 1]), maxY = std::max(maxY, line[k + 1]);
    }
  if (!(minX <= maxX)) return;
  const double clearance = 1e-6 * std::hypot(maxX - minX, maxY - minY) + 1e-12;
  const std::vector<double> p = scaled(m.points, exponent);
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t a = m.triangles[3 * t], c = m.triangles[3 * t + 1],
                        d = m.triangles[3 * t + 2];
    const double x = (p[2 * a] + p[2 * c] + p[2 * d]) / 3,
                 y = (p[2 * a + 1] + p[2 * c + 1] + p[2 * d + 1]) / 3;
    if (!std::isfinite(x) || !std::isfinite(y) ||
        testing::distanceToPolylines(lines, x, y) <= clearance)
      continue;
    const int w = winding(rings, x, y);
    const std::string at = " its centroid (" + std::to_string(std::ldexp(x, exponent)) + ", " +
                           std::to_string(std::ldexp(y, exponent)) + ")";
    if (holds(w) != (m.inside[t] != 0))
      fail("triangle " + std::to_string(t) + " is flagged " + (m.inside[t] ? "inside" : "outside") +
           " but" + at + " has winding " + std::to_string(w));
    const std::int32_t label = m.regions[t];
    bool anyHolds = false;
    for (const auto& polygon : polygons) anyHolds |= holds(winding(polygon, x, y));
    if (label >= static_cast<std::int32_t>(polygons.size()) || label < -1 ||
        (label == -1 && anyHolds) || (label >= 0 && !holds(winding(polygons[label], x, y))))
      fail("triangle " + std::to_string(t) + " has region " + std::to_string(label) + " but" + at +
           (anyHolds ? " lies in a polygon" : " lies in none"));
  }
}

void checkProvenance(const Input& input, const Mesh& m) {
  std::size_t constrainedEdges = 0;
  for (std::size_t e = 0; e < m.constrained.size(); ++e)
    if (m.constrained[e] && (m.halfedges[e] < 0 || static_cast<std::size_t>(m.halfedges[e]) > e))
      ++constrainedEdges;
  if (m.constraintEdges.size() != constrainedEdges)
    fail(std::to_string(constrainedEdges) + " constrained edges but " +
         std::to_string(m.constraintEdges.size()) + " with provenance");
  if (constrainedEdges == 0) return;
  if (m.sourceOffsets.size() != constrainedEdges + 1 || m.sourceOffsets.back() != m.sources.size())
    fail("provenance offsets do not match the sources");
  const double* p = m.points.data();
  for (std::size_t i = 0; i < constrainedEdges; ++i) {
    const std::uint32_t e = m.constraintEdges[i];
    const std::uint32_t u = m.triangles[e], v = m.triangles[e % 3 == 2 ? e - 2 : e + 1];
    if (m.sourceOffsets[i] >= m.sourceOffsets[i + 1])
      fail("a constrained edge without a source polyline");
    for (std::uint32_t k = m.sourceOffsets[i]; k < m.sourceOffsets[i + 1]; ++k) {
      const std::uint32_t line = m.sources[k];
      if (line >= input.lines.size()) fail("provenance names polyline " + std::to_string(line));
      if (!testing::withinBoundOfPolyline(input.lines[line], p[2 * u], p[2 * u + 1], p[2 * v],
                                          p[2 * v + 1]))
        fail("constrained edge " + std::to_string(u) + "-" + std::to_string(v) +
             " is said to come from polyline " + std::to_string(line) +
             " but lies beyond the bound of its segments");
    }
  }
}

// Values: input point i carries (i % 17) / 16. Every vertex's values and every interpolated
// value is a convex combination of those, so lies in [0, 1] up to rounding; NaN only outside
// the hull, or where some vertex has none (a crossing that snap rounding left off every
// constraint).
void checkValues(const Input& input) {
  Triangulation t(input.options);
  std::vector<double> values;
  const auto next = [&values] { values.push_back(static_cast<double>(values.size() % 17) / 16); };
  for (std::size_t i = 0; i < input.points.size(); i += 2) next();
  std::vector<PolylineView> views;
  for (const auto& line : input.lines) {
    views.push_back({line.data(), line.size() / 2});
    for (std::size_t i = 0; i < line.size(); i += 2) next();
  }
  const std::size_t free = input.points.size() / 2;
  if (!t.insertPoints(input.points.data(), free, nullptr, values.data()).ok() ||
      !t.insertPolylines(views.data(), views.size(), nullptr, values.data() + free).ok())
    return;  // build() judged the statuses
  const Mesh m = t.mesh();
  const auto inRange = [](double v) { return v >= -1e-9 && v <= 1 + 1e-9; };
  bool someNaN = false;
  for (std::size_t v = 0; v < m.values.size(); ++v) {
    someNaN |= std::isnan(m.values[v]);
    if (!std::isnan(m.values[v]) && !inRange(m.values[v]))
      fail("vertex " + std::to_string(v) + " has value " + std::to_string(m.values[v]));
  }
  // Queries: the vertices, then edge midpoints and centroids (about 1000 queries at most).
  std::vector<double> q(m.points);
  const double* p = m.points.data();
  for (std::size_t e = 0; e < m.triangles.size() && q.size() < 2048; ++e) {
    const std::uint32_t a = m.triangles[e], b = m.triangles[e % 3 == 2 ? e - 2 : e + 1],
                        c = m.triangles[e % 3 == 0 ? e + 2 : e - 1];
    q.push_back(p[2 * a] / 2 + p[2 * b] / 2);
    q.push_back(p[2 * a + 1] / 2 + p[2 * b + 1] / 2);
    if (e % 3 != 0) continue;
    q.push_back(p[2 * a] / 3 + p[2 * b] / 3 + p[2 * c] / 3);
    q.push_back(p[2 * a + 1] / 3 + p[2 * b + 1] / 3 + p[2 * c + 1] / 3);
  }
  std::vector<double> out(q.size() / 2);
  for (const Interpolation method : {Interpolation::Linear, Interpolation::Natural}) {
    t.interpolate(q.data(), out.size(), method, out.data());
    const char* name = method == Interpolation::Linear ? "linear" : "natural";
    for (std::size_t i = 0; i < out.size(); ++i) {
      const std::string at = std::string(name) + " at (" + std::to_string(q[2 * i]) + ", " +
                             std::to_string(q[2 * i + 1]) + ")";
      if (!std::isnan(out[i])) {
        if (!inRange(out[i])) fail(at + " gives " + std::to_string(out[i]));
        continue;
      }
      const Location::Kind kind = t.locate(q[2 * i], q[2 * i + 1]).kind;
      if (!someNaN && kind != Location::Kind::Outside && kind != Location::Kind::Empty &&
          kind != Location::Kind::Invalid)
        fail(at + " gives NaN inside the hull");
    }
  }
}

void run(const Input& input) {
  if (!allValid(input)) {
    std::vector<PolylineView> views;
    for (const auto& line : input.lines) views.push_back({line.data(), line.size() / 2});
    Mesh mesh;
    const Status s = triangulate(input.points.data(), input.points.size() / 2, views.data(),
                                 views.size(), input.options, {}, mesh);
    if (s.code != StatusCode::InvalidCoordinate)
      fail("invalid coordinates not refused: " + s.message);
    return;
  }
  const Built b = build(input);
  testing::CheckOptions options;
  options.inputXY = &b.inputXY;
  options.inputToVertex = &b.ids;
  std::string broken = testing::checkTriangulation(b.mesh, options);
  if (!broken.empty()) fail("checkTriangulation: " + broken);
  // Without triangles (all points collinear) the mesh has no edges to carry constraints.
  if (!b.mesh.triangles.empty()) broken = testing::checkConstraints(b.mesh, input.lines, b.lineIds);
  if (!broken.empty()) fail("checkConstraints: " + broken);
  checkProvenance(input, b.mesh);
  checkInside(input, b);
  checkValues(input);
}

}  // namespace
}  // namespace geocdt::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geocdt::fuzz;
  return fuzzOne(data, size, decode, print, run);
}
