#include "terrain/breakline_pieces.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geocdt::terrain {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The part of segment p -> q inside [0, maxX] x [0, maxY] (Liang and Barsky): parameters
// t0 <= t1, and the side each end was cut at (-1: not cut; 0..3: x = 0, x = maxX, y = 0,
// y = maxY). False when the segment misses the rectangle.
struct Clip {
  double t0 = 0, t1 = 1;
  int side0 = -1, side1 = -1;
};

bool clip(double px, double py, double qx, double qy, double maxX, double maxY, Clip& c) {
  const double dx = qx - px, dy = qy - py;
  const double step[4] = {-dx, dx, -dy, dy};
  const double room[4] = {px, maxX - px, py, maxY - py};
  for (int k = 0; k < 4; ++k) {
    if (step[k] == 0) {
      if (room[k] < 0) return false;
      continue;
    }
    const double t = room[k] / step[k];
    if (step[k] < 0) {
      if (t > c.t1) return false;
      if (t > c.t0) c.t0 = t, c.side0 = k;
    } else {
      if (t < c.t0) return false;
      if (t < c.t1) c.t1 = t, c.side1 = k;
    }
  }
  return true;
}

class Cutter {
 public:
  Cutter(const PixelFrame& frame, const RasterSampler& raster, BreaklinePieces& out)
      : frame_(frame), raster_(raster), out_(out) {}

  void cut(const PolylineView& line, const double* heights, std::uint32_t index) {
    open_ = false;
    for (std::size_t k = 0; k + 1 < line.count; ++k) {
      const double* p = line.xy + 2 * k;
      const double px = frame_.pixelX(p[0]), py = frame_.pixelY(p[1]);
      const double qx = frame_.pixelX(p[2]), qy = frame_.pixelY(p[3]);
      Clip c;
      if (!clip(px, py, qx, qy, raster_.width() - 1.0, raster_.height() - 1.0, c)) {
        close();
        continue;
      }
      const double zp = heights ? heights[k] : kNaN, zq = heights ? heights[k + 1] : kNaN;
      if (!open_ || c.side0 >= 0) {
        close();
        start(index);
        add(c.side0 < 0 ? px : at(px, qx, c.t0), c.side0 < 0 ? py : at(py, qy, c.t0), c.side0,
            c.side0 < 0 ? zp : at(zp, zq, c.t0), c.side0 < 0 ? p : nullptr);
      }
      add(c.side1 < 0 ? qx : at(px, qx, c.t1), c.side1 < 0 ? qy : at(py, qy, c.t1), c.side1,
          c.side1 < 0 ? zq : at(zp, zq, c.t1), c.side1 < 0 ? p + 2 : nullptr);
      if (c.side1 >= 0) close();
    }
    close();
  }

 private:
  static double at(double a, double b, double t) { return a + (b - a) * t; }

  void start(std::uint32_t index) {
    open_ = true;
    out_.breakline.push_back(index);
  }

  // A point in pixels; one cut at a side lies exactly on it.
  void add(double x, double y, int side, double z, const double* original) {
    const double maxX = raster_.width() - 1.0, maxY = raster_.height() - 1.0;
    x = side == 0 ? 0 : side == 1 ? maxX : std::clamp(x, 0.0, maxX);
    y = side == 2 ? 0 : side == 3 ? maxY : std::clamp(y, 0.0, maxY);
    out_.xy.push_back(x);
    out_.xy.push_back(y);
    out_.given.push_back(!std::isnan(z));
    out_.z.push_back(std::isnan(z) ? raster_.sample(x, y) : z);
    out_.original.push_back(original ? original[0] : kNaN);
    out_.original.push_back(original ? original[1] : kNaN);
  }

  // Ends the open piece: one point alone is dropped, and a closed one is cut in two at its
  // last point away from its ends (a ring would bound an area: the mesh would leave out what
  // it holds where there is no data elsewhere).
  void close() {
    if (!open_) return;
    open_ = false;
    const std::uint32_t first = out_.offsets.back();
    const auto end = static_cast<std::uint32_t>(out_.z.size());
    if (end - first < 2) {
      drop(first);
      return;
    }
    const double* xy = out_.xy.data();
    const bool closed = end - first >= 3 && xy[2 * first] == xy[2 * (end - 1)] &&
                        xy[2 * first + 1] == xy[2 * (end - 1) + 1];
    if (!closed) {
      out_.offsets.push_back(end);
      return;
    }
    // Points first .. k, then k .. end - 1, k repeated: neither part closed. (Before the last
    // segment would not do: a ring may end with its first point repeated.)
    std::uint32_t k = end - 2;
    while (k > first && xy[2 * k] == xy[2 * first] && xy[2 * k + 1] == xy[2 * first + 1]) --k;
    if (k == first) {  // every point the same: no segment to constrain
      out_.offsets.push_back(end);
      return;
    }
    out_.xy.insert(out_.xy.begin() + 2 * (k + 1), {out_.xy[2 * k], out_.xy[2 * k + 1]});
    out_.original.insert(out_.original.begin() + 2 * (k + 1),
                         {out_.original[2 * k], out_.original[2 * k + 1]});
    out_.z.insert(out_.z.begin() + (k + 1), out_.z[k]);
    out_.given.insert(out_.given.begin() + (k + 1), out_.given[k]);
    out_.offsets.push_back(k + 1);
    out_.offsets.push_back(end + 1);
    out_.breakline.push_back(out_.breakline.back());
  }

  void drop(std::uint32_t first) {
    out_.xy.resize(2 * std::size_t{first});
    out_.original.resize(2 * std::size_t{first});
    out_.z.resize(first);
    out_.given.resize(first);
    out_.breakline.pop_back();
  }

  const PixelFrame& frame_;
  const RasterSampler& raster_;
  BreaklinePieces& out_;
  bool open_ = false;
};

}  // namespace

BreaklinePieces cutBreaklines(const PolylineView* lines, std::size_t count, const double* heights,
                              const PixelFrame& frame, const RasterSampler& raster) {
  BreaklinePieces out;
  Cutter cutter(frame, raster, out);
  std::size_t at = 0;
  for (std::size_t i = 0; i < count; ++i) {
    cutter.cut(lines[i], heights ? heights + at : nullptr, static_cast<std::uint32_t>(i));
    at += lines[i].count;
  }
  return out;
}

}  // namespace geocdt::terrain
