#pragma once
// How the fuzz targets turn arbitrary bytes into geometry. Random doubles are almost never
// collinear, cocircular or equal, so most modes put points on small lattices, where those
// cases are the rule, and the lattice modes can also repeat, nudge and bisect earlier points.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "geocdt/status.h"
#include "geocdt/triangulation.h"

namespace geocdt::fuzz {

// Past the end every read gives zeros, so any byte string decodes to something.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::size_t remaining() const { return size_ - pos_; }
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  // Eight bytes, least significant first (as a little-endian machine stores a double).
  double rawDouble() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= std::uint64_t{byte()} << (8 * i);
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

inline bool validCoordinate(double v) { return std::isfinite(v) && std::fabs(v) <= kMaxCoordinate; }

// Any double into the accepted range, keeping sign and mantissa, so that folded raw input
// still spans every magnitude from subnormal to about 8e149.
inline double foldIntoRange(double v) {
  if (std::isnan(v)) return 0;
  if (std::isinf(v)) return std::copysign(kMaxCoordinate, v);
  int exponent = 0;
  const double mantissa = std::frexp(v, &exponent);
  if (exponent > 498) exponent %= 498;  // 2^498 < 1e150
  return std::ldexp(mantissa, exponent);
}

enum class PointMode : std::uint8_t {
  Raw,        // 16 bytes: two doubles as they are, possibly NaN, infinite or too large
  Folded,     // 16 bytes: two doubles folded into the valid range
  SmallGrid,  // 1 byte: a point of the 16 x 16 integer grid
  Lattice,    // 2 bytes: a point of a 32 x 32 lattice, or an earlier point reused
  // 1 byte: a point of an 8 x 8 grid of neighbouring doubles, a few ulps wide, around an
  // offset: where every crossing rounds onto the same few doubles (snap rounding's ground).
  // Chosen by SmallGrid's mode bits with bit 2 set, so older seeds keep their meaning.
  TinyGrid,
};

class PointDecoder {
 public:
  // Reads the mode and, for lattices, an origin, a step and a rotation from tables that
  // hold the hard cases: huge offsets with tiny steps, steps that are not binary fractions,
  // and rotations that put lattice lines at irrational-looking slopes.
  explicit PointDecoder(ByteReader& in) {
    std::uint8_t b = in.byte();
    // GEOCDT_FUZZ_MODE=tiny: every input in the tiny-grid mode, to spend a run on tangles.
    static const bool tinyOnly = tinyGridRequested();
    if (tinyOnly) b = static_cast<std::uint8_t>((b & ~3) | 4 | 2);
    mode_ = static_cast<PointMode>(b & 3);
    if (mode_ == PointMode::SmallGrid && (b & 4)) {
      mode_ = PointMode::TinyGrid;
      // Offsets on each axis: zero (subnormal steps), binade ends (1, 2^24, the smallest
      // normal double), and large, small, huge and geographic values.
      static constexpr double kOffsets[16] = {0,
                                              1,
                                              0x1p24,
                                              16000000.25,
                                              -12345.678,
                                              1e-300,
                                              0x1p-1022,
                                              1e100,
                                              -3.5e-7,
                                              6378137.0,
                                              -1e150,
                                              0.5,
                                              179.99999999999997,
                                              -2.0,
                                              1e-5,
                                              0x1p-1074};
      const std::uint8_t o = in.byte(), w = in.byte();
      originX_ = kOffsets[o & 15];
      originY_ = kOffsets[o >> 4];
      ulps_ = 1 << (w & 3);  // the grid's step, in ulps
      return;
    }
    if (mode_ != PointMode::Lattice) return;
    static constexpr double kOrigins[8] = {0,           1,      -12345.678, 1.6e7 + 0.25,
                                           179.9999999, 1e-300, 1e100,      0};
    static constexpr double kSteps[8] = {1, 0.5, 0.1, 1e-3, 1.0 / 3, 1e-9, 1e9, 0x1p-40};
    static constexpr double kRotations[4][2] = {
        {1, 0}, {0.6, 0.8}, {0.7071067811865476, 0.7071067811865476}, {0.96, 0.28}};
    const std::uint8_t o = in.byte(), s = in.byte();
    originX_ = (o & 7) == 7 ? foldIntoRange(in.rawDouble()) : kOrigins[o & 7];
    originY_ = ((o >> 3) & 7) == 7 ? foldIntoRange(in.rawDouble()) : kOrigins[(o >> 3) & 7];
    step_ = kSteps[s & 7];
    cos_ = kRotations[(s >> 3) & 3][0];
    sin_ = kRotations[(s >> 3) & 3][1];
  }

  PointMode mode() const { return mode_; }

  static bool tinyGridRequested() {
    const char* v = std::getenv("GEOCDT_FUZZ_MODE");
    return v != nullptr && std::string(v) == "tiny";
  }

  // The next point; only Raw mode gives invalid coordinates.
  void next(ByteReader& in, double& x, double& y) {
    switch (mode_) {
      case PointMode::Raw:
        x = in.rawDouble();
        y = in.rawDouble();
        break;
      case PointMode::Folded:
        x = foldIntoRange(in.rawDouble());
        y = foldIntoRange(in.rawDouble());
        break;
      case PointMode::SmallGrid: {
        const std::uint8_t b = in.byte();
        x = (b & 15) - 8;
        y = (b >> 4) - 8;
        break;
      }
      case PointMode::Lattice: nextLattice(in, x, y); break;
      case PointMode::TinyGrid: {
        const std::uint8_t b = in.byte();
        x = stepped(originX_, (b & 7) - 3);
        y = stepped(originY_, ((b >> 3) & 7) - 3);
        break;
      }
    }
    history_.push_back(x);
    history_.push_back(y);
  }

 private:
  void nextLattice(ByteReader& in, double& x, double& y) {
    const std::uint8_t a = in.byte(), b = in.byte();
    const int i = a & 31, j = b & 31, op = a >> 5;
    const std::size_t n = history_.size() / 2;
    if (op < 5 || n == 0) {
      x = clamp(originX_ + step_ * (cos_ * i - sin_ * j));
      y = clamp(originY_ + step_ * (sin_ * i + cos_ * j));
      return;
    }
    const std::size_t k = b % n;
    x = history_[2 * k];
    y = history_[2 * k + 1];
    if (op == 6) {  // one ulp away from an earlier point: the near-duplicates of real data
      const double toward = (i & 4) ? INFINITY : -INFINITY;
      if (i & 1) x = clamp(std::nextafter(x, toward));
      if (i & 2) y = clamp(std::nextafter(y, toward));
    } else if (op == 7) {  // the rounded midpoint of two earlier points: on or near an edge
      const std::size_t m = static_cast<std::size_t>(i) % n;
      x = 0.5 * x + 0.5 * history_[2 * m];
      y = 0.5 * y + 0.5 * history_[2 * m + 1];
    }  // op 5: an exact duplicate
  }

  // v moved by k grid steps of ulps_ neighbouring doubles each.
  double stepped(double v, int k) const {
    for (int i = 0; i < std::abs(k) * ulps_; ++i)
      v = std::nextafter(v, k > 0 ? INFINITY : -INFINITY);
    return clamp(v);
  }

  static double clamp(double v) {
    return std::fabs(v) <= kMaxCoordinate ? v : std::copysign(kMaxCoordinate, v);
  }

  PointMode mode_ = PointMode::SmallGrid;
  double originX_ = 0, originY_ = 0, step_ = 1, cos_ = 1, sin_ = 0;
  int ulps_ = 1;
  std::vector<double> history_;
};

// Free points, then polylines until the bytes run out or a limit is reached: a length byte
// (1 + low 4 bits points; bit 7 closes the polyline into a ring) followed by its points.
// fuzz_polylines and fuzz_refine read their geometry this way.
inline void decodePointsAndPolylines(ByteReader& in, PointDecoder& decoder, std::size_t freePoints,
                                     std::size_t maxPolylines, std::size_t maxPoints,
                                     std::vector<double>& points,
                                     std::vector<std::vector<double>>& lines) {
  double x, y;
  for (std::size_t i = 0; i < freePoints; ++i) {
    decoder.next(in, x, y);
    points.push_back(x);
    points.push_back(y);
  }
  std::size_t total = freePoints;
  while (in.remaining() > 0 && lines.size() < maxPolylines && total < maxPoints) {
    const std::uint8_t head = in.byte();
    std::vector<double> line;
    for (std::size_t k = 0; k <= static_cast<std::size_t>(head & 15); ++k) {
      decoder.next(in, x, y);
      line.push_back(x);
      line.push_back(y);
    }
    if (head & 0x80) line.insert(line.end(), {line[0], line[1]});
    total += line.size() / 2;
    lines.push_back(std::move(line));
  }
}

// Triangulation options from one byte: every order, both location starts, grid densities
// that make the grid grow early or late, and (bit 7, unset in older seeds) snap rounding of
// every call.
inline Options decodeOptions(std::uint8_t b) {
  static constexpr double kDensities[4] = {2.0, 0.25, 1.0, 8.0};
  Options o;
  o.order = static_cast<InsertionOrder>(b % 3);
  o.start = (b >> 2) & 1 ? LocateStart::Grid : LocateStart::LastTriangle;
  o.gridDensity = kDensities[(b >> 3) & 3];
  o.snapRounding = b & 0x80 ? SnapRounding::Always : SnapRounding::WhenNeeded;
  return o;
}

inline std::string describeOptions(const Options& o) {
  static const char* kOrders[3] = {"Input", "Hilbert", "Brio"};
  return std::string("order=") + kOrders[static_cast<int>(o.order)] +
         " start=" + (o.start == LocateStart::Grid ? "Grid" : "LastTriangle") +
         " gridDensity=" + std::to_string(o.gridDensity) +
         (o.snapRounding == SnapRounding::Always ? " snapRounding=Always" : "");
}

// Coordinates printed so that they read back bit for bit.
inline void printPoints(const char* label, const double* xy, std::size_t count) {
  std::fprintf(stderr, "%s (%zu points):", label, count);
  for (std::size_t i = 0; i < count; ++i)
    std::fprintf(stderr, " %.17g,%.17g", xy[2 * i], xy[2 * i + 1]);
  std::fprintf(stderr, "\n");
}

// A broken invariant, thrown up to the fuzz entry point, which prints the input and aborts
// so that libFuzzer saves it.
struct Finding {
  std::string what;
};

[[noreturn]] inline void fail(const std::string& what) { throw Finding{what}; }

// Whether a finding stops the run. GEOCDT_FUZZ_ONLY=text stops only on findings whose
// message contains text (to minimize one bug with -minimize_crash); GEOCDT_FUZZ_IGNORE=a|b
// lets findings containing a or b pass (to look past a known bug).
inline bool reportable(const std::string& what) {
  const char* only = std::getenv("GEOCDT_FUZZ_ONLY");
  if (only != nullptr && what.find(only) == std::string::npos) return false;
  const char* ignore = std::getenv("GEOCDT_FUZZ_IGNORE");
  if (ignore == nullptr) return true;
  const std::string list = ignore;
  for (std::size_t from = 0; from <= list.size();) {
    const std::size_t bar = std::min(list.find('|', from), list.size());
    if (bar > from && what.find(list.substr(from, bar - from)) != std::string::npos) return false;
    from = bar + 1;
  }
  return true;
}

// Set GEOCDT_FUZZ_PRINT=1 to print every decoded input, e.g. when replaying a finding.
inline bool printRequested() {
  const char* v = std::getenv("GEOCDT_FUZZ_PRINT");
  return v != nullptr && v[0] == '1';
}

// The body of both entry points: decode, run, and on a reportable finding print the input
// and abort so that libFuzzer keeps it.
template <class Decode, class Print, class Run>
int fuzzOne(const std::uint8_t* data, std::size_t size, Decode decode, Print print, Run run) {
  const auto input = decode(data, size);
  if (printRequested()) print(input);
  try {
    run(input);
  } catch (const Finding& finding) {
    if (!reportable(finding.what)) return 0;
    print(input);
    std::fprintf(stderr, "geocdt fuzz failure: %s\n", finding.what.c_str());
    std::abort();
  }
  return 0;
}

}  // namespace geocdt::fuzz
