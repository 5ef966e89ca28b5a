#pragma once
// What each constrained edge carries: the input polylines it came from (several where they
// overlap), one input segment it lies on (to compute crossings from the original geometry),
// and its net winding, which decides inside and outside, with each polyline's share of it
// where several overlap (region labels need it: two countries' rings along a shared border
// run opposite ways and net zero). Keyed by the undirected vertex pair, so it survives the
// flips and re-triangulations that move half-edges around.
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

// One of an edge's further polylines and its share of the winding, which runs the same way
// as the winding of the EdgeSource that lists it. The first polyline's share is the rest.
struct PolylineWinding {
  std::uint32_t polyline;
  std::int32_t winding;
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
  // Where each segment starts among the points of every polyline inserted, numbered across
  // polylines in insertion order (segment i runs from that point to the next), or kNoSegment
  // past 2^32 - 2.
  std::vector<std::uint32_t> segmentStarts;
  std::vector<PendingSegment> pending;
  std::uint32_t polylineCount = 0;
  std::uint64_t polylinePoints = 0;  // points of every polyline inserted so far

  static std::uint64_t key(std::uint32_t u, std::uint32_t v) {
    if (u > v) std::swap(u, v);
    return static_cast<std::uint64_t>(u) << 32 | v;
  }

  // Marks u-v with src, whose winding runs from u to v; merges with what u-v carries.
  // Entries hold their windings from the lower vertex id to the higher.
  void mark(std::uint32_t u, std::uint32_t v, EdgeSource src) {
    const std::int32_t sign = u > v ? -1 : 1;
    src.winding *= sign;
    const auto [entry, fresh] = edges_.insert(key(u, v), src);
    if (fresh) {
      if (src.extra >= 0) entry->extra = copyExtra(src.extra, sign);
      return;
    }
    EdgeSource& e = *entry;
    e.winding += src.winding;
    std::int32_t first = src.winding;  // src's first polyline: what its extras leave
    if (src.extra >= 0)
      for (const PolylineWinding& p : extras_[src.extra]) first -= sign * p.winding;
    addPolyline(e, src.polyline, first);
    if (src.extra >= 0) {
      const std::vector<PolylineWinding> more = extras_[src.extra];  // extras_ may grow
      for (const PolylineWinding& p : more) addPolyline(e, p.polyline, sign * p.winding);
    }
  }

  // Removes u-v and returns what it carried, winding from u to v. The extras list now belongs
  // to the returned source alone (mark copies it), so it is turned around in place.
  EdgeSource take(std::uint32_t u, std::uint32_t v) {
    EdgeSource src = *edges_.find(key(u, v));
    edges_.erase(key(u, v));
    if (u > v) {
      src.winding = -src.winding;
      if (src.extra >= 0)
        for (PolylineWinding& p : extras_[src.extra]) p.winding = -p.winding;
    }
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
      for (const PolylineWinding& p : extras_[e.extra]) f(p.polyline);
  }

  // f(polyline, winding) for each polyline of a stored edge, its share of the winding from
  // the lower vertex id to the higher.
  template <typename F>
  void forEachPolylineWinding(const EdgeSource& e, F&& f) const {
    std::int32_t first = e.winding;
    if (e.extra >= 0)
      for (const PolylineWinding& p : extras_[e.extra]) {
        first -= p.winding;
        f(p.polyline, p.winding);
      }
    f(e.polyline, first);
  }

  std::size_t edgeCount() const { return edges_.size(); }
  void clear() {
    edges_.clear();
    extras_.clear();
    segments.clear();
    segmentStarts.clear();
    pending.clear();
    polylineCount = 0;
    polylinePoints = 0;
  }

 private:
  // Adds polyline p's share w to e, whose total already includes it.
  void addPolyline(EdgeSource& e, std::uint32_t p, std::int32_t w) {
    if (e.polyline == p) return;  // the first polyline's share is what the others leave
    if (e.extra < 0) {
      e.extra = static_cast<std::int32_t>(extras_.size());
      extras_.emplace_back();
    }
    std::vector<PolylineWinding>& list = extras_[e.extra];
    for (PolylineWinding& q : list)
      if (q.polyline == p) {
        q.winding += w;
        return;
      }
    list.push_back({p, w});
  }
  std::int32_t copyExtra(std::int32_t from, std::int32_t sign) {
    std::vector<PolylineWinding> copy = extras_[from];
    for (PolylineWinding& p : copy) p.winding *= sign;
    extras_.push_back(std::move(copy));
    return static_cast<std::int32_t>(extras_.size() - 1);
  }

  EdgeMap<EdgeSource> edges_;
  std::vector<std::vector<PolylineWinding>> extras_;
};

}  // namespace geocdt
