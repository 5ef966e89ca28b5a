#pragma once
// Polygons as they are written out: closed rings (the first point repeated last), an outer ring
// counter-clockwise then its holes clockwise, many cells' polygons one after the other.
// Consecutive equal points (zero-length edges, which ties leave) are dropped, and so is a ring
// left with fewer than three points (zero area), with its holes if it was an outer ring.
#include <cstdint>
#include <vector>

#include "exact/bisector_predicates.h"

namespace geocdt {

struct CellPolygons {
  std::vector<XY> points;
  std::vector<std::uint32_t> ringEnds;     // ring i ends at points[ringEnds[i]]
  std::vector<std::uint32_t> polygonEnds;  // polygon j ends at ring polygonEnds[j]

  void clear() {
    points.clear();
    ringEnds.clear();
    polygonEnds.clear();
  }
  std::uint32_t ringCount() const { return static_cast<std::uint32_t>(ringEnds.size()); }
  std::uint32_t polygonCount() const { return static_cast<std::uint32_t>(polygonEnds.size()); }

  // A ring is begun, given point by point, then ended: ending returns whether it was kept.
  void beginRing() { ringStart_ = static_cast<std::uint32_t>(points.size()); }
  void add(XY p) {
    if (points.size() == ringStart_ || points.back() != p) points.push_back(p);
  }
  bool endRing() {
    while (points.size() > ringStart_ + 1 && points.back() == points[ringStart_]) points.pop_back();
    if (points.size() < ringStart_ + 3) {
      points.resize(ringStart_);
      return false;
    }
    points.push_back(points[ringStart_]);
    ringEnds.push_back(static_cast<std::uint32_t>(points.size()));
    return true;
  }
  // After the outer ring and the holes of a polygon (if its outer ring was kept).
  void endPolygon() { polygonEnds.push_back(ringCount()); }
  // Drops the rings since ring `first` (an outer ring that was not kept leaves its holes).
  void dropRingsFrom(std::uint32_t first) {
    points.resize(first == 0 ? 0 : ringEnds[first - 1]);
    ringEnds.resize(first);
  }

 private:
  std::uint32_t ringStart_ = 0;
};

}  // namespace geocdt
