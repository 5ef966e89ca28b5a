// libFuzzer target: arbitrary bytes as a batch of polygons (rings open or closed, repeated
// points, touching and crossing rings, holes anywhere), through triangulatePolygons(), the
// output held to the exact polygon checker (support/polygon_checks.h: orientation, edges used
// once, border edges on ring segments, inside by the fill rule, constrained Delaunay, and the
// area of triangulate(keep inside) on the same rings). Invalid coordinates must be refused,
// naming the polygon and ring of the first one.
//
// Input: byte 0 = options (bit 0: nonzero fill; bit 1: threads 2), then a PointDecoder header,
// then polygons until the bytes run out: a head byte (1 + low 2 bits rings; bit 7 makes the
// polygon empty) and per ring a length byte (1 + low 4 bits points; bit 7 closes the ring by
// repeating its first point) followed by its points.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "geocdt/polygons.h"
#include "polygon_checks.h"

namespace geocdt::fuzz {
namespace {

constexpr std::size_t kMaxPolygons = 48;
constexpr std::size_t kMaxPoints = 768;

struct Input {
  FillRule fill = FillRule::EvenOdd;
  std::uint32_t threads = 1;
  std::vector<double> xy;
  std::vector<std::uint32_t> rings{0}, polygons{0};

  PolygonBatch batch() const {
    return {xy.data(),        xy.size() / 2,   rings.data(),
            rings.size() - 1, polygons.data(), polygons.size() - 1};
  }
};

Input decode(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Input input;
  const std::uint8_t options = in.byte();
  input.fill = options & 1 ? FillRule::NonZero : FillRule::EvenOdd;
  input.threads = options & 2 ? 2 : 1;
  PointDecoder decoder(in);
  double x, y;
  while (in.remaining() > 0 && input.polygons.size() <= kMaxPolygons &&
         input.xy.size() / 2 < kMaxPoints) {
    const std::uint8_t head = in.byte();
    const int rings = head & 0x80 ? 0 : 1 + (head & 3);
    for (int r = 0; r < rings; ++r) {
      const std::uint8_t length = in.byte();
      const std::size_t first = input.xy.size();
      for (int k = 0; k <= (length & 15); ++k) {
        decoder.next(in, x, y);
        input.xy.push_back(x);
        input.xy.push_back(y);
      }
      if (length & 0x80) input.xy.insert(input.xy.end(), {input.xy[first], input.xy[first + 1]});
      input.rings.push_back(static_cast<std::uint32_t>(input.xy.size() / 2));
    }
    input.polygons.push_back(static_cast<std::uint32_t>(input.rings.size() - 1));
  }
  return input;
}

void print(const Input& input) {
  std::fprintf(stderr, "fill=%s threads=%u\n",
               input.fill == FillRule::EvenOdd ? "EvenOdd" : "NonZero", input.threads);
  for (std::size_t p = 0; p + 1 < input.polygons.size(); ++p) {
    std::fprintf(stderr, "polygon %zu:\n", p);
    for (std::uint32_t r = input.polygons[p]; r < input.polygons[p + 1]; ++r)
      printPoints(("  ring " + std::to_string(r)).c_str(), input.xy.data() + 2 * input.rings[r],
                  input.rings[r + 1] - input.rings[r]);
  }
}

// The ring (an index into the ring offsets) of the first invalid coordinate, or -1.
long firstInvalidRing(const Input& input) {
  for (std::size_t i = 0; i < input.xy.size(); ++i) {
    if (validCoordinate(input.xy[i])) continue;
    const std::uint32_t point = static_cast<std::uint32_t>(i / 2);
    for (std::size_t r = 0; r + 1 < input.rings.size(); ++r)
      if (input.rings[r] <= point && point < input.rings[r + 1]) return static_cast<long>(r);
  }
  return -1;
}

void run(const Input& input) {
  PolygonOptions options;
  options.fill = input.fill;
  options.threads = input.threads;
  PolygonTriangles out;
  PolygonStats stats;
  const Status s = triangulatePolygons(input.batch(), options, out, &stats);
  const long bad = firstInvalidRing(input);
  if (bad >= 0) {
    if (s.code != StatusCode::InvalidCoordinate)
      fail("invalid coordinates not refused: " + s.message);
    if (s.segment != static_cast<std::size_t>(bad))
      fail("the refusal names ring " + std::to_string(s.segment) + ", not ring " +
           std::to_string(bad) + ": " + s.message);
    if (!out.triangles.empty()) fail("a refused batch returned triangles");
    return;
  }
  if (!s.ok()) fail("triangulatePolygons returned an error: " + s.message);
  if (stats.smallPath + stats.general > input.polygons.size() - 1)
    fail("more polygons triangulated than given");
  testing::PolygonCheckOptions check;
  check.fill = input.fill;
  const std::string broken = testing::checkPolygonTriangles(input.batch(), out, check);
  if (!broken.empty()) fail("checkPolygonTriangles: " + broken);
}

}  // namespace
}  // namespace geocdt::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geocdt::fuzz;
  return fuzzOne(data, size, decode, print, run);
}
