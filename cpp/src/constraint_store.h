#pragma once
// What each constrained edge carries: the input polylines it came from (several where they
// overlap), the input segments whose chains hold it (the first to compute crossings from the
// original geometry, all to check the chains), and its net winding, which decides inside and
// outside. Keyed by the undirected vertex pair, so it survives the flips and
// re-triangulations that move half-edges around.
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "edge_map.h"

namespace geocdt {

struct EdgeSource {
  std::uint32_t segment = 0;   // the first input segment: index into ConstraintStore::segments
  std::int32_t winding = 0;    // ring traversals along the edge's direction minus against it
  std::uint32_t polyline = 0;  // the first polyline
  std::int32_t extra = -1;     // index of more polylines and segments in the store, or -1
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
  // Per polyline: the index of its first segment and whether it is a ring, so that snap
  // rounding can give each segment its source again (a few bytes per polyline).
  std::vector<std::uint32_t> firstSegment;
  std::vector<std::uint8_t> ring;

  // Starts polyline polylineCount; returns its id.
  std::uint32_t startPolyline(bool isRing) {
    firstSegment.push_back(static_cast<std::uint32_t>(segments.size()));
    ring.push_back(isRing);
    return polylineCount++;
  }

  // What segment i carries when it alone makes an edge: its polyline and winding.
  EdgeSource sourceOf(std::uint32_t i) const {
    const auto after = std::upper_bound(firstSegment.begin(), firstSegment.end(), i);
    EdgeSource src;
    src.segment = i;
    src.polyline = static_cast<std::uint32_t>(after - firstSegment.begin() - 1);
    src.winding = ring[src.polyline] ? 1 : 0;
    return src;
  }

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
    add(e, {src.polyline, src.segment});
    if (src.extra >= 0) {
      const std::vector<Member> more = extras_[src.extra];
      for (const Member m : more) add(e, m);
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

  // Every polyline of the edge, once.
  template <typename F>
  void forEachPolyline(const EdgeSource& e, F&& f) const {
    f(e.polyline);
    if (e.extra < 0) return;
    const std::vector<Member>& more = extras_[e.extra];
    for (std::size_t k = 0; k < more.size(); ++k) {
      const std::uint32_t p = more[k].polyline;
      bool seen = p == e.polyline;
      for (std::size_t j = 0; j < k && !seen; ++j) seen = more[j].polyline == p;
      if (!seen) f(p);
    }
  }

  // Every input segment whose chain holds the edge (several where segments overlap or were
  // routed through the same vertices).
  template <typename F>
  void forEachSegment(const EdgeSource& e, F&& f) const {
    f(e.segment);
    if (e.extra >= 0)
      for (const Member m : extras_[e.extra]) f(m.segment);
  }

  std::size_t edgeCount() const { return edges_.size(); }
  void clear() {
    edges_.clear();
    extras_.clear();
    segments.clear();
    pending.clear();
    polylineCount = 0;
    firstSegment.clear();
    ring.clear();
  }

 private:
  // What an edge carries beyond its first polyline and segment: more (polyline, segment)
  // pairs. One list, allocated when a second pair arrives (as polylines alone were before:
  // shared borders make hundreds of thousands of them), each pair once.
  struct Member {
    std::uint32_t polyline, segment;
  };

  void add(EdgeSource& e, Member m) {
    if (m.polyline == e.polyline && m.segment == e.segment) return;
    if (e.extra < 0) {
      e.extra = static_cast<std::int32_t>(extras_.size());
      extras_.emplace_back();
    }
    std::vector<Member>& list = extras_[e.extra];
    for (const Member q : list)
      if (q.polyline == m.polyline && q.segment == m.segment) return;
    list.push_back(m);
  }
  std::int32_t copyExtra(std::int32_t from) {
    const std::vector<Member> copy = extras_[from];
    extras_.push_back(copy);
    return static_cast<std::int32_t>(extras_.size() - 1);
  }

  EdgeMap<EdgeSource> edges_;
  std::vector<std::vector<Member>> extras_;
};

}  // namespace geocdt
