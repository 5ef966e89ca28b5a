#pragma once
// What each constrained edge carries: the input polylines it came from (several where they
// overlap), the input segments whose chains hold it (the first to compute crossings from the
// original geometry, all to check the chains), and its net winding, which decides inside and
// outside, with each segment's share of it where several overlap (region labels need it: two
// countries' rings along a shared border run opposite ways and net zero). Keyed by the
// undirected vertex pair, so it survives the flips and re-triangulations that move half-edges
// around.
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "exact/input_segment.h"
#include "mesh/edge_map.h"
#include "mesh/extra_members.h"

namespace geocdt {

// A polyline point index past what 32 bits number (see ConstraintStore::segmentStarts).
inline constexpr std::uint32_t kNoSegment = 0xFFFFFFFFu;
// The ends of a segment whose polyline was removed.
inline constexpr std::uint32_t kRemovedSegment = 0xFFFFFFFFu;

struct EdgeSource {
  std::uint32_t segment = 0;   // the first input segment: index into ConstraintStore::segments
  std::int32_t winding = 0;    // ring traversals along the edge's direction minus against it
  std::uint32_t polyline = 0;  // the first polyline
  std::int32_t extra = -1;     // the first of more polylines and segments in the store, or -1
};

// An input segment as the store keeps it: its end vertices. Input vertices keep their ids
// and coordinates for the triangulation's life (crossings only add vertices after them, and
// snap rounding rebuilds with the same ids), so their coordinates are the segment's exact
// input geometry: 8 bytes a segment instead of the 32 of its coordinates.
struct SegmentEnds {
  std::uint32_t a, b;
};

// A segment given before the triangulation had triangles (all points collinear so far).
struct PendingSegment {
  std::uint32_t u, v;
  EdgeSource src;
  std::uint32_t polyline, index;  // where it came from, for error messages
};

class ConstraintStore {
 public:
  std::vector<SegmentEnds> segments;
  // Where each segment starts among the points of every polyline inserted, numbered across
  // polylines in insertion order (segment i runs from that point to the next), or kNoSegment
  // past 2^32 - 2.
  std::vector<std::uint32_t> segmentStarts;
  std::vector<PendingSegment> pending;
  std::uint32_t polylineCount = 0;
  std::uint64_t polylinePoints = 0;  // points of every polyline inserted so far
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

  // Segment i's input geometry, from the coordinates xy of the vertices.
  InputSegment geometry(std::uint32_t i, const std::vector<double>& xy) const {
    const SegmentEnds& s = segments[i];
    return {xy[2 * s.a], xy[2 * s.a + 1], xy[2 * s.b], xy[2 * s.b + 1]};
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
    std::int32_t first = src.winding;  // src's first pair's share: what its extras leave
    for (std::int32_t k = src.extra; k >= 0; k = members_[k].next)
      first -= sign * members_[k].winding;
    add(e, src.polyline, src.segment, first);
    // By index: adding to e appends to the pool, which never moves what it holds.
    for (std::int32_t k = src.extra; k >= 0; k = members_[k].next) {
      const ExtraMember m = members_[k];
      add(e, m.polyline, m.segment, sign * m.winding);
    }
  }

  // Removes u-v and returns what it carried, winding from u to v. The extras list now belongs
  // to the returned source alone (mark copies it), so it is turned around in place.
  EdgeSource take(std::uint32_t u, std::uint32_t v) {
    EdgeSource src = *edges_.find(key(u, v));
    edges_.erase(key(u, v));
    if (u > v) {
      src.winding = -src.winding;
      for (std::int32_t k = src.extra; k >= 0; k = members_[k].next)
        members_[k].winding = -members_[k].winding;
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

  // Editing: takes the pair (polyline, segment) off edge u-v, with its share of the winding.
  // Returns false when the edge does not carry it; sets emptied (and erases the edge) when it
  // was the edge's last pair.
  bool dropPair(std::uint32_t u, std::uint32_t v, std::uint32_t polyline, std::uint32_t segment,
                bool& emptied) {
    emptied = false;
    EdgeSource* e = edges_.find(key(u, v));
    if (e == nullptr || !dropPair(*e, polyline, segment, emptied)) return false;
    if (emptied) edges_.erase(key(u, v));
    return true;
  }
  // The same on a source held outside the table (a pending segment's).
  bool dropPair(EdgeSource& e, std::uint32_t polyline, std::uint32_t segment, bool& emptied) {
    emptied = false;
    if (e.polyline == polyline && e.segment == segment) {
      if (e.extra < 0) {
        emptied = true;
        return true;
      }
      // The first extra pair takes the first place: the total less this pair's share.
      std::int32_t extras = 0;
      for (std::int32_t k = e.extra; k >= 0; k = members_[k].next) extras += members_[k].winding;
      const ExtraMember promoted = members_[e.extra];
      e.winding = extras;
      e.polyline = promoted.polyline;
      e.segment = promoted.segment;
      e.extra = promoted.next;
      return true;
    }
    for (std::int32_t k = e.extra, before = -1; k >= 0; before = k, k = members_[k].next) {
      const ExtraMember m = members_[k];
      if (m.polyline != polyline || m.segment != segment) continue;
      e.winding -= m.winding;
      (before < 0 ? e.extra : members_[before].next) = m.next;
      return true;
    }
    return false;
  }
  // f(lower, higher, source) for every constrained edge (windings from lower to higher).
  template <typename F>
  void forEachEdge(F&& f) const {
    edges_.forEach([&](std::uint64_t k, const EdgeSource& e) {
      f(static_cast<std::uint32_t>(k >> 32), static_cast<std::uint32_t>(k), e);
    });
  }
  // Forgets every constrained edge, keeping the extra pairs they listed (pending segments
  // made from them hold their lists).
  void clearEdges() { edges_.clear(); }
  // Whether segment i is still an input segment (its polyline was not removed).
  bool live(std::uint32_t i) const { return segments[i].a != kRemovedSegment; }

  const EdgeSource* find(std::uint32_t u, std::uint32_t v) const { return edges_.find(key(u, v)); }
  const EdgeSource* find(std::uint64_t edgeKey) const { return edges_.find(edgeKey); }
  // Brings the entries of n keys into the cache before they are looked up (EdgeMap::touch).
  std::uint64_t touch(const std::uint64_t* keys, std::size_t n) const {
    return edges_.touch(keys, n);
  }
  // Brings the first extra member of n found edges (or null) into the cache, so that the
  // misses overlap across the edges.
  std::uint64_t touchExtras(const EdgeSource* const* found, std::size_t n) const {
    if (members_.empty()) return 0;
    std::uint64_t any = 0;
    for (std::size_t k = 0; k < n; ++k) {
      // No branch on whether an edge has extras: the others read member 0.
      const std::int32_t extra = found[k] ? found[k]->extra : -1;
      any |= members_[std::max(extra, 0)].polyline;
    }
    return any;
  }

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
    for (std::int32_t k = e.extra; k >= 0; k = members_[k].next) {
      const std::uint32_t p = members_[k].polyline;
      bool seen = p == e.polyline;
      for (std::int32_t j = e.extra; j != k && !seen; j = members_[j].next)
        seen = members_[j].polyline == p;
      if (!seen) f(p);
    }
  }

  // f(polyline, segment, winding) for each pair of a stored edge, with its share of the
  // winding from the lower vertex id to the higher.
  template <typename F>
  void forEachPair(const EdgeSource& e, F&& f) const {
    std::int32_t first = e.winding;
    for (std::int32_t k = e.extra; k >= 0; k = members_[k].next) {
      first -= members_[k].winding;
      f(members_[k].polyline, members_[k].segment, members_[k].winding);
    }
    f(e.polyline, e.segment, first);
  }

  // Every input segment whose chain holds the edge (several where segments overlap or were
  // routed through the same vertices).
  template <typename F>
  void forEachSegment(const EdgeSource& e, F&& f) const {
    f(e.segment);
    for (std::int32_t k = e.extra; k >= 0; k = members_[k].next) f(members_[k].segment);
  }

  // f(polyline, winding) for each (polyline, segment) pair of a stored edge, with its share
  // of the winding from the lower vertex id to the higher (a polyline may come more than
  // once, its shares adding up).
  template <typename F>
  void forEachPolylineWinding(const EdgeSource& e, F&& f) const {
    std::int32_t first = e.winding;
    for (std::int32_t k = e.extra; k >= 0; k = members_[k].next) {
      first -= members_[k].winding;
      f(members_[k].polyline, members_[k].winding);
    }
    f(e.polyline, first);
  }

  std::size_t edgeCount() const { return edges_.size(); }
  void scatter() { edges_.scatter(); }
  // Room for edges in all, between vertex ids mostly below idBound (see EdgeSlot).
  void reserve(std::size_t edges, std::uint64_t idBound) {
    edges_.orderIds(idBound);
    edges_.reserve(edges);
  }

  // The polylines of every edge beyond its first, counted with repeats (and those of lists
  // no edge holds any more): with edgeCount(), a bound on the provenance an export lists.
  std::size_t extraMembers() const { return members_.size(); }
  // Frees what only inserting segments needs (their ends and starts), keeping what an
  // export reads (each edge's polylines and windings): for an export that ends the
  // triangulation, where the heap peaks.
  void dropSegments() {
    segments = std::vector<SegmentEnds>();
    segmentStarts = std::vector<std::uint32_t>();
    pending = std::vector<PendingSegment>();
  }

  void clear() {
    edges_.clear();
    members_.clear();
    segments.clear();
    segmentStarts.clear();
    pending.clear();
    polylineCount = 0;
    polylinePoints = 0;
    firstSegment.clear();
    ring.clear();
  }

 private:
  // Adds the pair (polyline, segment) with its share of the winding to e, whose total
  // already includes it; each pair is listed once, in the order pairs first came.
  void add(EdgeSource& e, std::uint32_t polyline, std::uint32_t segment, std::int32_t winding) {
    if (polyline == e.polyline && segment == e.segment) return;
    std::int32_t last = -1;
    for (std::int32_t k = e.extra; k >= 0; k = members_[k].next) {
      ExtraMember& q = members_[k];
      if (q.polyline == polyline && q.segment == segment) {
        q.winding += winding;
        return;
      }
      last = k;
    }
    const std::int32_t added = members_.append({polyline, segment, winding, -1});
    (last < 0 ? e.extra : members_[last].next) = added;
  }
  // A copy of the list from `from`, windings times sign; returns its first member.
  std::int32_t copyExtra(std::int32_t from, std::int32_t sign) {
    std::int32_t first = -1, last = -1;
    for (std::int32_t k = from; k >= 0; k = members_[k].next) {
      ExtraMember m = members_[k];
      m.winding *= sign;
      m.next = -1;
      const std::int32_t added = members_.append(m);
      (last < 0 ? first : members_[last].next) = added;
      last = added;
    }
    return first;
  }

  EdgeMap<EdgeSource, EdgeSlot> edges_;
  // What edges carry beyond their first polyline and segment: more (polyline, segment)
  // pairs, each with its share of the winding (the first pair's share is what they leave),
  // as lists linked through one pool. Shared borders make hundreds of thousands of short
  // lists: a vector each cost an allocation each (which in wasm had malloc optimised during
  // a first call) and more memory than its members (bench/EXPERIMENTS.md, C39).
  ExtraMembers members_;
};

}  // namespace geocdt
