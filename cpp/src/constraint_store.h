#pragma once
// What each constrained edge carries: the input polylines it came from (several where they
// overlap), one input segment it lies on (to compute crossings from the original geometry),
// and its net winding, which decides inside and outside. Keyed by the undirected vertex
// pair, so it survives the flips and re-triangulations that move half-edges around.
#include <cstdint>
#include <utility>
#include <vector>

#include "edge_map.h"

namespace geocdt {

struct EdgeSource {
  std::uint32_t segment = 0;   // index into ConstraintStore::segments
  std::int32_t winding = 0;    // ring traversals along the edge's direction minus against it
  std::uint32_t polyline = 0;  // the first polyline
  std::int32_t extra = -1;     // index of more polylines in the store, or -1
};

struct InputSegment {
  double ax, ay, bx, by;
};

// A segment given before the triangulation had triangles (all points collinear so far).
struct PendingSegment {
  std::uint32_t u, v;
  EdgeSource src;
  std::uint32_t polyline, index;  // where it came from, for error messages
};

class ConstraintStore {
 public:
  std::vector<InputSegment> segments;
  std::vector<PendingSegment> pending;
  std::uint32_t polylineCount = 0;

  static std::uint64_t key(std::uint32_t u, std::uint32_t v) {
    if (u > v) std::swap(u, v);
    return static_cast<std::uint64_t>(u) << 32 | v;
  }

  // Marks u-v with src, whose winding runs from u to v; merges with what u-v carries.
  void mark(std::uint32_t u, std::uint32_t v, EdgeSource src) {
    if (u > v) src.winding = -src.winding;
    const auto [entry, fresh] = edges_.insert(key(u, v), src);
    if (fresh) {
      if (src.extra >= 0) entry->extra = copyExtra(src.extra);
      return;
    }
    EdgeSource& e = *entry;
    e.winding += src.winding;
    addPolyline(e, src.polyline);
    if (src.extra >= 0) {
      const std::vector<std::uint32_t> more = extras_[src.extra];
      for (const std::uint32_t p : more) addPolyline(e, p);
    }
  }

  // Removes u-v and returns what it carried, winding from u to v.
  EdgeSource take(std::uint32_t u, std::uint32_t v) {
    EdgeSource src = *edges_.find(key(u, v));
    edges_.erase(key(u, v));
    if (u > v) src.winding = -src.winding;
    return src;
  }

  // Edge u-v was split at w: both halves carry what u-v carried.
  void split(std::uint32_t u, std::uint32_t v, std::uint32_t w) {
    if (!edges_.find(key(u, v))) return;
    const EdgeSource src = take(u, v);
    mark(u, w, src);
    mark(w, v, src);
  }

  const EdgeSource* find(std::uint32_t u, std::uint32_t v) const { return edges_.find(key(u, v)); }

  // Winding change met when crossing from the left of u->v to its right.
  std::int32_t windingAcross(std::uint32_t u, std::uint32_t v) const {
    const EdgeSource* e = find(u, v);
    if (!e) return 0;
    return u < v ? -e->winding : e->winding;
  }

  template <typename F>
  void forEachPolyline(const EdgeSource& e, F&& f) const {
    f(e.polyline);
    if (e.extra >= 0)
      for (const std::uint32_t p : extras_[e.extra]) f(p);
  }

  std::size_t edgeCount() const { return edges_.size(); }
  void clear() {
    edges_.clear();
    extras_.clear();
    segments.clear();
    pending.clear();
    polylineCount = 0;
  }

 private:
  void addPolyline(EdgeSource& e, std::uint32_t p) {
    if (e.polyline == p) return;
    if (e.extra < 0) {
      e.extra = static_cast<std::int32_t>(extras_.size());
      extras_.emplace_back();
    }
    std::vector<std::uint32_t>& list = extras_[e.extra];
    for (const std::uint32_t q : list)
      if (q == p) return;
    list.push_back(p);
  }
  std::int32_t copyExtra(std::int32_t from) {
    const std::vector<std::uint32_t> copy = extras_[from];
    extras_.push_back(copy);
    return static_cast<std::int32_t>(extras_.size() - 1);
  }

  EdgeMap<EdgeSource> edges_;
  std::vector<std::vector<std::uint32_t>> extras_;
};

}  // namespace geocdt
