// libFuzzer target: arbitrary bytes as sites and a domain (a box, the sites' hull, or rings),
// through geocdt::voronoi(), and the cells held to voronoi_checks: they tile the domain, share
// their edges, keep their vertices nearest their own site, and hold sample points exactly when
// those are nearest their site.
//
// Input: byte 0 = clip (bits 0-1: box, hull, rings, rings), fill rule (bit 2), one or two of
// Lloyd's steps (bits 3-4); byte 1 = site count (1 + low 6 bits); then a PointDecoder header,
// the sites, and for a box two corners, for rings rings until the bytes run out: a length byte
// (3 + low 3 bits points, closed) followed by its points.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "geocdt/voronoi.h"
#include "voronoi_checks.h"

namespace geocdt::fuzz {
namespace {

constexpr std::size_t kMaxRings = 16;

struct Input {
  VoronoiOptions options;
  std::vector<double> sites;
  std::vector<std::vector<double>> rings;
};

Input decode(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Input input;
  const std::uint8_t b = in.byte();
  static constexpr VoronoiClip kClips[4] = {VoronoiClip::Box, VoronoiClip::Hull, VoronoiClip::Rings,
                                            VoronoiClip::Rings};
  input.options.clip = kClips[b & 3];
  input.options.fill = (b >> 2) & 1 ? FillRule::NonZero : FillRule::EvenOdd;
  input.options.lloydIterations = (b >> 3) & 3;
  const std::size_t count = 1 + (in.byte() & 63);
  PointDecoder decoder(in);
  double x, y;
  for (std::size_t i = 0; i < count; ++i) {
    decoder.next(in, x, y);
    input.sites.insert(input.sites.end(), {x, y});
  }
  if (input.options.clip == VoronoiClip::Box) {
    double x1, y1;
    decoder.next(in, x, y);
    decoder.next(in, x1, y1);
    input.options.box[0] = std::min(x, x1);
    input.options.box[1] = std::min(y, y1);
    input.options.box[2] = std::max(x, x1);
    input.options.box[3] = std::max(y, y1);
  }
  while (input.options.clip == VoronoiClip::Rings && in.remaining() > 0 &&
         input.rings.size() < kMaxRings) {
    const std::size_t points = 3 + (in.byte() & 7);
    std::vector<double> ring;
    for (std::size_t k = 0; k < points; ++k) {
      decoder.next(in, x, y);
      ring.insert(ring.end(), {x, y});
    }
    ring.insert(ring.end(), {ring[0], ring[1]});
    input.rings.push_back(std::move(ring));
  }
  return input;
}

void print(const Input& input) {
  static const char* kClipNames[3] = {"Rings", "Hull", "Box"};
  const VoronoiOptions& o = input.options;
  std::fprintf(stderr, "clip=%s fill=%s lloyd=%u box=%.17g,%.17g,%.17g,%.17g\n",
               kClipNames[static_cast<int>(o.clip)],
               o.fill == FillRule::EvenOdd ? "EvenOdd" : "NonZero", o.lloydIterations, o.box[0],
               o.box[1], o.box[2], o.box[3]);
  printPoints("sites", input.sites.data(), input.sites.size() / 2);
  for (const auto& ring : input.rings) printPoints("ring", ring.data(), ring.size() / 2);
}

bool valid(const std::vector<double>& xy) {
  return std::all_of(xy.begin(), xy.end(), validCoordinate);
}

void run(const Input& input) {
  const VoronoiOptions& o = input.options;
  std::vector<PolylineView> views;
  for (const auto& ring : input.rings) views.push_back({ring.data(), ring.size() / 2});
  VoronoiCells cells;
  const Status s =
      voronoi(input.sites.data(), input.sites.size() / 2, views.data(), views.size(), o, cells);
  bool ringsValid = true;
  for (const auto& ring : input.rings) ringsValid = ringsValid && valid(ring);
  const std::vector<double> box(o.box, o.box + 4);
  const bool boxValid = valid(box) && o.box[0] < o.box[2] && o.box[1] < o.box[3];
  if (!valid(input.sites) || !ringsValid) {
    if (s.code != StatusCode::InvalidCoordinate)
      fail("invalid coordinates were taken: " + s.message);
    return;
  }
  if (o.clip == VoronoiClip::Box && !boxValid) {
    if (s.code != StatusCode::InvalidArgument) fail("a bad box was taken: " + s.message);
    return;
  }
  if (o.clip == VoronoiClip::Rings && views.empty()) {
    if (s.code != StatusCode::InvalidArgument) fail("rings clip without rings: " + s.message);
    return;
  }
  if (!s.ok()) fail("voronoi: " + s.message);
  testing::CheckDomain domain = o.clip == VoronoiClip::Box ? testing::boxCheckDomain(o.box)
                                : o.clip == VoronoiClip::Hull
                                    ? testing::hullCheckDomain(input.sites)
                                    : testing::ringCheckDomain(views, o.fill);
  // With Lloyd's steps the cells are those of the moved sites, in the first hull.
  const std::vector<double>& sites = o.lloydIterations > 0 ? cells.sites : input.sites;
  const std::string broken = testing::checkVoronoi(cells, sites, domain, 200, 1e-9);
  if (!broken.empty()) fail(broken);
}

}  // namespace
}  // namespace geocdt::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geocdt::fuzz;
  return fuzzOne(data, size, decode, print, run);
}
