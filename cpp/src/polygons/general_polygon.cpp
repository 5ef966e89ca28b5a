#include "polygons/general_polygon.h"

#include <algorithm>
#include <limits>

namespace geocdt {

namespace {

constexpr std::uint32_t kNoIndex32 = std::numeric_limits<std::uint32_t>::max();

}  // namespace

Status GeneralPolygon::triangulate(const double* xy, std::uint32_t n,
                                   const std::uint32_t* ringStarts, std::uint32_t ringCount,
                                   FillRule fill, std::uint32_t base, std::uint32_t extraBase,
                                   std::vector<std::uint32_t>& out, std::vector<double>& extras) {
  closed_.clear();
  pointOf_.clear();
  pointOf_.reserve(n + ringCount);
  views_.clear();
  // Each ring as a closed polyline (the core takes a polyline as a ring when it ends at its
  // first point): an open ring gets its first point again at its end.
  for (std::uint32_t r = 0; r < ringCount; ++r) {
    const std::uint32_t first = ringStarts[r], end = ringStarts[r + 1];
    if (end == first) continue;
    const std::size_t before = pointOf_.size();
    for (std::uint32_t k = first; k < end; ++k) pointOf_.push_back(k);
    const std::uint32_t last = end - 1;
    if (xy[2 * first] != xy[2 * last] || xy[2 * first + 1] != xy[2 * last + 1])
      pointOf_.push_back(first);
    views_.push_back({nullptr, pointOf_.size() - before});
  }
  closed_.resize(2 * pointOf_.size());
  for (std::size_t j = 0; j < pointOf_.size(); ++j) {
    closed_[2 * j] = xy[2 * pointOf_[j]];
    closed_[2 * j + 1] = xy[2 * pointOf_[j] + 1];
  }
  std::size_t at = 0;
  for (PolylineView& view : views_) {
    view.xy = closed_.data() + 2 * at;
    at += view.count;
  }
  ids_.resize(pointOf_.size());
  Triangulation t;
  Status s = t.insertPolylines(views_.data(), views_.size(), ids_.data());
  if (!s.ok()) return s;
  MeshOptions options;
  options.keep = Keep::Inside;
  options.fill = fill;
  const Mesh m = t.release(options);
  indexOf_.assign(m.points.size() / 2, kNoIndex32);
  for (std::size_t j = 0; j < ids_.size(); ++j)  // in local order: the first point wins
    if (indexOf_[ids_[j]] == kNoIndex32) indexOf_[ids_[j]] = base + pointOf_[j];
  for (const std::uint32_t v : m.triangles) {
    if (indexOf_[v] == kNoIndex32) {
      indexOf_[v] = extraBase + static_cast<std::uint32_t>(extras.size() / 2);
      extras.push_back(m.points[2 * v]);
      extras.push_back(m.points[2 * v + 1]);
    }
    out.push_back(indexOf_[v]);
  }
  return Status::success();
}

}  // namespace geocdt
