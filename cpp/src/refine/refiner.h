#pragma once
// The state of one Delaunay refinement (refinement.cpp): the queues of bad triangles and
// encroached subsegments, and the refiner that works through them.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "base/chunks.h"
#include "delaunay/delaunay.h"
#include "exact/exact_geometry.h"
#include "exact/power_of_two.h"
#include "geocdt/predicates.h"
#include "labels/slot_windings.h"

#if defined(__GNUC__)
#define GEOCDT_ALWAYS_INLINE __attribute__((always_inline))
#else
#define GEOCDT_ALWAYS_INLINE
#endif

namespace geocdt::refinement {

// The index of the lowest set bit of bits != 0.
inline int lowestBit(std::uint64_t bits) {
#if defined(__GNUC__)
  return __builtin_ctzll(bits);
#else
  int k = 0;
  for (; (bits & 1) == 0; bits >>= 1) ++k;
  return k;
#endif
}

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr std::size_t kShortCavity = 16;  // searched as a list, not stamped

// A triangle waiting to be split. The corners tell whether the slot still holds it when its
// turn comes.
struct BadTriangle {
  std::int32_t slot;
  std::uint32_t a, b, c;
  bool skinny;  // queued for its angle, not only its area
};

// Bad triangles in buckets. First those with a corner on a subsegment, worst angle first
// (buckets of sin^2 of the smallest angle, then those bad for their area alone): near small
// input angles that is the order that ends. Then the rest, shortest side first, in buckets
// of half powers of two of its length, as Triangle orders them all: it places fewer Steiner
// points than worst angle first (bench/EXPERIMENTS.md, R7), but everywhere it ran away on
// country borders (R6). The last queued comes first within a bucket, which keeps to the
// neighbourhood just refined. A heap of them all spent most of its time missing the cache.
class BadQueue {
 public:
  static constexpr int kAngleBuckets = 2048, kLengthBuckets = 4096;
  static constexpr std::size_t kBuckets = kAngleBuckets + kLengthBuckets;
  static_assert(kBuckets % 64 == 0, "whole words of occupied bits");
  // boundary: a corner on a subsegment; sin2 (if skinny) in [0, 0.75); lengthExponent: the
  // shortest side's squared length in half powers of two (halfExponent).
  static std::size_t bucket(bool boundary, bool skinny, double sin2, int lengthExponent) {
    if (boundary) {
      const int b = skinny ? static_cast<int>(sin2 * (kAngleBuckets / 0.75)) : kAngleBuckets;
      return static_cast<std::size_t>(std::min(b, kAngleBuckets - 1));
    }
    const int b = lengthExponent + kLengthBuckets / 2;
    return static_cast<std::size_t>(kAngleBuckets + std::clamp(b, 0, kLengthBuckets - 1));
  }
  void push(std::size_t bucket, const BadTriangle& t) {
    buckets_[bucket].push_back(t);
    occupied_[bucket / 64] |= std::uint64_t{1} << (bucket % 64);
    first_ = std::min(first_, bucket);
    ++size_;
  }
  bool empty() const { return size_ == 0; }
  // Moves every waiting triangle to the end of out.
  void drainInto(std::vector<BadTriangle>& out) {
    for (std::size_t b = first_; b < kBuckets; ++b) {
      out.insert(out.end(), buckets_[b].begin(), buckets_[b].end());
      buckets_[b].clear();
    }
    std::fill(std::begin(occupied_), std::end(occupied_), 0);
    first_ = kBuckets;
    size_ = 0;
  }
  // The first bucket that is not empty, found in the bits of the occupied ones: walking the
  // empty buckets one by one cost refinement dearly (bench/EXPERIMENTS.md, R18).
  BadTriangle pop() {
    std::size_t word = first_ / 64;
    std::uint64_t bits = occupied_[word] & (~std::uint64_t{0} << (first_ % 64));
    while (bits == 0) bits = occupied_[++word];
    first_ = 64 * word + static_cast<std::size_t>(lowestBit(bits));
    std::vector<BadTriangle>& bucket = buckets_[first_];
    const BadTriangle t = bucket.back();
    bucket.pop_back();
    if (bucket.empty()) occupied_[word] &= ~(std::uint64_t{1} << (first_ % 64));
    --size_;
    return t;
  }

 private:
  std::vector<std::vector<BadTriangle>> buckets_ = std::vector<std::vector<BadTriangle>>(kBuckets);
  std::uint64_t occupied_[kBuckets / 64] = {};  // a bit per bucket holding triangles
  std::size_t first_ = kBuckets, size_ = 0;
};

// A subsegment waiting to be split: encroached by a vertex, or by a rejected candidate
// (forced: no vertex encroaches it, the candidate would have).
struct Subsegment {
  std::uint32_t u, v;
  bool forced;
};

// Where p projects on a -> b, as the fraction of the way from a, clamped to [0, 1].
double projection(double ax, double ay, double bx, double by, double px, double py);

enum class Outcome { Done, Skipped, Retry, Failed };

// What decides whether a triangle is bad: sin^2 of its smallest angle is cross2 / product
// (twice its area squared, over the product of its two longer sides squared), compared
// without the division for the many that are good.
struct Shape {
  double cross2, product, area;
  double shortest2;  // its shortest side's squared length, in the frame scaled by 2^-scale
  int scale;
  // The shortest side's squared length in half powers of two (2^(2 scale) times the frame's),
  // only needed for the bad ones.
  int lengthExponent() const { return halfExponent(shortest2) + 4 * scale; }
  bool skinny(double sin2Limit) const {
    return product > 0 ? cross2 < sin2Limit * product : sin2Limit > 0;
  }
  double sin2() const { return product > 0 ? cross2 / product : 0; }
};

class Refiner {
 public:
  Refiner(Delaunay& d, const RefineOptions& o)
      : d_(d),
        topo_(d.topo),
        keepAll_(o.keep == Keep::All),
        fill_(o.fill),
        maxArea_(o.maxArea > 0 ? o.maxArea : std::numeric_limits<double>::infinity()),
        minAngle_(o.minAngle) {
    const double s = std::sin(o.minAngle * kPi / 180);
    sin2_ = s * s;
    // Ungor's off-centre sits where the shortest edge subtends minAngle, a little closer
    // (0.475 of the half-edge's cotangent, not 0.5) so that its triangle is not bad again.
    offCentre_ = o.minAngle > 0 ? 0.475 / std::tan(o.minAngle * kPi / 360) : 0;
    cap_ = o.maxSteinerPoints;
  }

  Status run();  // start(), then resume()
  // A refinement in rounds, between which the caller inserts vertices of its own (terrain
  // meshes, whose pixels go back in where refinement left them beyond their error bound):
  // start() sets the refiner up once, and each resume() refines what is bad now. Each
  // insertion of the caller's is told with noteInsertion(): from, a half-edge out of the new
  // vertex; a, b the ends of the edge it split (kGhost for none), a subsegment or not.
  void start();
  Status resume();
  // Counts what is left bad (into Stats::refineSkipped, returned), as each resume() does at
  // its end: after insertions of the caller's that no resume() followed.
  std::uint64_t countLeft();
  void noteInsertion(std::int32_t from, std::uint32_t a, std::uint32_t b, bool onSubsegment);
  // Every slot's winding number, kept up to date (resize to the slots after insertions).
  const std::vector<std::int32_t>& windings() const { return winding_; }
  // From trackChanges() on, each resume() lists the slots it rewrote (some more than once):
  // a caller that keeps its own record of every triangle updates those alone.
  void trackChanges() { trackChanges_ = true; }
  const std::vector<std::int32_t>& changedSlots() const { return changed_; }
  // Subsegments shorter than this are not split (their encroached triangles are left as they
  // are, skipped): where two constraints run closer than a scale that means something (a
  // raster's pixel), refinement would otherwise fill the gap with triangles its width.
  void setShortestSplit(double length) { shortestSplit2_ = length * length; }
  // The slots' windings after run(), kept up to date through it; empty if run() had nothing
  // to refine.
  void takeWindings(std::vector<std::int32_t>& out) {
    out = std::move(winding_);
    if (out.size() != static_cast<std::size_t>(topo_.slotCount())) out.clear();
  }

 private:
  double x(std::uint32_t v) const { return d_.xy[2 * v]; }
  double y(std::uint32_t v) const { return d_.xy[2 * v + 1]; }
  bool ccw(std::uint32_t a, std::uint32_t b, double px, double py) const {
    return orient2d(x(a), y(a), x(b), y(b), px, py) == Sign::Positive;
  }
  // Ghost slots wind 0, which no fill rule takes for inside: only keep all asks about them.
  bool inRegion(std::int32_t t) const {
    return keepAll_ ? !topo_.isGhost(t) : insideByRule(winding_[t], fill_);
  }
  // A constrained edge, or with keep all a hull edge: what refinement must not cross. e is
  // either half-edge; none of a ghost vertex is one.
  bool isSubsegment(std::int32_t e) const {
    return topo_.fixed[e] || (keepAll_ && topo_.isGhost(e / 3) != topo_.isGhost(topo_.adj[e] / 3));
  }
  // The same, from ghostSlot_ (start() only).
  bool startSubsegment(std::int32_t e) const {
    return topo_.fixed[e] || (keepAll_ && ghostSlot_[e / 3] != ghostSlot_[topo_.adj[e] / 3]);
  }
  // The segment a subsegment lies on, and a number naming it: an input segment's index, or
  // past 2^32 the hull edge it comes from; *source, if asked, the constraint store's entry
  // of an input subsegment (where the other segments on it are listed).
  InputSegment segmentOf(std::int32_t e, std::uint64_t& id,
                         const EdgeSource** source = nullptr) const;
  static bool encroachedBy(double ux, double uy, double vx, double vy, double px, double py) {
    return (ux - px) * (vx - px) + (uy - py) * (vy - py) < 0;
  }
  bool encroached(std::int32_t e) const;
  void queueSubsegment(std::int32_t e, bool forced);
  void queueIfEncroached(std::int32_t e) {
    if (encroached(e)) queueSubsegment(e, false);
  }
  // Of a real triangle. Inlined: in wasm, a returned Shape goes through the stack in memory
  // (bench/EXPERIMENTS.md, R15).
  GEOCDT_ALWAYS_INLINE Shape shape(std::int32_t t) const;
  bool holds(const BadTriangle& b) const {  // whether b's slot still holds it
    const std::uint32_t* corner = &topo_.tri[3 * b.slot];
    return corner[0] == b.a && corner[1] == b.b && corner[2] == b.c;
  }
  void checkTriangle(std::int32_t t);
  std::int32_t findEdge(std::uint32_t u, std::uint32_t v) const;
  int constrainedDegree(std::uint32_t u) const;
  bool smallInputAngle(std::uint32_t p, std::uint32_t q) const;  // of the shortest edge p, q
  void rebuild();
  // winding, when given, says the vertex went in inside one region (a cavity's border joined
  // to it): every triangle around it has that winding, none is a ghost, and no spoke is
  // constrained, so only the outer edges are checked for subsegments.
  static constexpr std::int32_t kUnknownWinding = std::numeric_limits<std::int32_t>::min();
  void afterInsert(std::int32_t from, std::int32_t winding = kUnknownWinding);
  void noteCorners(std::int32_t t);
  void checkAround(std::int32_t t);  // the triangle and its subsegments
  void restoreDelaunay(std::vector<std::int32_t>& stack);
  // A subsegment split near its middle (or on a shell), in these steps.
  Outcome splitSubsegment(std::int32_t e, bool forced);
  // The subsegment e being split: its ends a -> b, the apexes c (of e's triangle) and dv (of
  // its twin's), the segment s it lies on with its id (segmentOf), and what that says.
  struct SplitSite {
    std::int32_t e;
    std::uint32_t a, b, c, dv;
    InputSegment s;
    std::uint64_t id;
    const EdgeSource* sources = nullptr;
    bool input;   // s is an input segment (else a hull edge)
    bool hull;    // e is on the hull
    bool shared;  // other input segments' chains hold e too
  };
  SplitSite splitSite(std::int32_t e) const;
  void splitPoint(const SplitSite& site, double& px, double& py) const;
  bool strictlyBetween(const SplitSite& site, const InputSegment& on, double qx, double qy) const;
  bool fitsOthers(const SplitSite& site, double qx, double qy) const;
  bool fitsAt(const SplitSite& site, double qx, double qy) const;
  bool fitsOnHull(const SplitSite& site, double& px, double& py) const;
  void insertSplitPoint(const SplitSite& site, double px, double py);
  // A bad triangle split at its candidate (circumcentre or off-centre), in these steps
  // (triangle_splits.cpp); each runs once a split, inlined as one function was (L1).
  Outcome splitTriangle(const BadTriangle& bad);
  GEOCDT_ALWAYS_INLINE bool candidate(const BadTriangle& bad, double& cx, double& cy,
                                      bool& large) const;
  GEOCDT_ALWAYS_INLINE std::optional<Outcome> walkToCandidate(double cx, double cy,
                                                              std::int32_t& cur, bool& onEdge);
  GEOCDT_ALWAYS_INLINE bool findCavity(std::int32_t cur, double cx, double cy);
  GEOCDT_ALWAYS_INLINE Outcome insertCandidate(std::int32_t cur, bool onEdge, double cx, double cy);
  Outcome insertWithFlips(std::int32_t cur, std::uint32_t v, double cx, double cy);
  // One step of run()'s loop: a subsegment or a bad triangle split (or found gone); and up
  // to kChunk of them in a call of their own (chunks.h).
  enum class Step { Go, Stop, Failed };
  Step refineStep(std::vector<BadTriangle>& retry, std::vector<BadTriangle>& unresolved);
  GEOCDT_NOINLINE Step refineSteps(std::vector<BadTriangle>& retry,
                                   std::vector<BadTriangle>& unresolved);
  void weightsInFace(std::uint32_t (&parent)[3], double (&weight)[3], double cx, double cy) const;
  void edgeWeights(std::uint32_t (&parent)[3], double (&weight)[3], double cx, double cy) const;
  void weightsOnEdge(std::uint32_t (&parent)[3], double (&weight)[3], double cx, double cy) const;
  std::uint32_t newVertex(double px, double py) {
    d_.xy.push_back(px);
    d_.xy.push_back(py);
    return d_.vertexCount() - 1;
  }
  void record(std::uint32_t v, std::uint32_t a, std::uint32_t b, std::uint32_t c, double wa,
              double wb, double wc) {
    d_.steiner.push_back({v, {a, b, c}, {wa, wb, wc}});
    // v is usually the newest vertex: one push_back, not resize's general path.
    if (v < steinerFlag_.size()) {
      steinerFlag_[v] = 1;
    } else {
      steinerFlag_.resize(v, 0);
      steinerFlag_.push_back(1);
    }
    ++added_;
  }
  // The input segment a vertex made by splitting a subsegment lies on (the first segment of
  // the edge it split, which both its subsegments keep), or kNoSegment: smallInputAngle then
  // needs no turn round it and no store lookups.
  std::uint32_t segmentAt(std::uint32_t v) const {
    return v < segmentAt_.size() ? segmentAt_[v] : kNoSegment;
  }
  void noteSegment(std::uint32_t v, std::uint32_t segment) {
    if (segmentAt_.size() <= v) segmentAt_.resize(v + 1, kNoSegment);
    segmentAt_[v] = segment;
  }
  bool onSubsegment(std::uint32_t v) const { return v < onSubsegment_.size() && onSubsegment_[v]; }
  void markOnSubsegment(std::uint32_t v) {
    onSubsegment_.resize(d_.vertexCount(), 0);
    onSubsegment_[v] = 1;
  }
  bool capReached() const { return added_ >= cap_ || d_.vertexCount() >= kGhost - 3; }

  Delaunay& d_;
  Topology& topo_;
  bool keepAll_;
  FillRule fill_;
  double maxArea_, minAngle_, sin2_ = 0, offCentre_ = 0;
  std::uint64_t cap_ = 0, added_ = 0, reported_ = 0;  // reported_: added_ in Stats so far
  bool capped_ = false;
  bool trackChanges_ = false;
  double shortestSplit2_ = 0;              // squared
  std::vector<std::int32_t> changed_;      // the slots the last resume() rewrote
  std::vector<std::int32_t> winding_;      // per slot
  std::vector<std::int32_t> vertexEdge_;   // per vertex: a half-edge out of it
  std::vector<std::uint8_t> steinerFlag_;  // per vertex: 1 for refinement's vertices
  // Per vertex: 1 for an end of a subsegment. Most vertices are on none, and smallInputAngle
  // learns that here instead of turning round them.
  std::vector<std::uint8_t> onSubsegment_;
  std::vector<std::uint8_t> ghostSlot_;   // per slot, during start() only
  std::vector<std::uint32_t> segmentAt_;  // per vertex (see segmentAt)
  std::vector<std::uint32_t> stamp_;  // per slot: the large cavity search (or count) that saw it
  std::uint32_t epoch_ = 0;
  std::vector<Subsegment> subsegments_;
  std::vector<BadTriangle> unresolved_;  // taken from the queue and left as they were
  BadQueue bad_;
  std::unordered_set<std::uint64_t> unsplittable_;
  // With keep all, the hull's edges are segments too: each hull subsegment's original edge.
  std::vector<InputSegment> hull_;
  std::unordered_map<std::uint64_t, std::uint32_t> hullOf_;
  std::vector<std::int32_t> cavity_, around_, boundary_;
};

}  // namespace geocdt::refinement
