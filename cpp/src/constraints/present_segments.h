#pragma once
// Input segments that are already edges, found for a whole batch by one pass over the
// triangles. A polyline's new points have consecutive vertex ids, so most of its segments
// join u and u + 1, and on dense polylines most of those are Delaunay edges already. Turning
// round each segment's first vertex in polyline order to find them, and fixing their two
// half-edges there, missed the cache on nearly every segment; one pass in memory order finds
// and fixes them all (bench/EXPERIMENTS.md, C37).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "base/chunks.h"
#include "mesh/topology.h"

namespace geocdt {

class PresentSegments {
 public:
  // For the new vertices [base, end).
  PresentSegments(std::uint32_t base, std::uint32_t end)
      : base_(base), expected_(end - base + 1, 0) {}

  // Segment u-v of the batch: looked for if its ends are consecutive new ids.
  void expect(std::uint32_t u, std::uint32_t v) {
    const std::size_t pair = pairOf(u, v);
    if (pair + 1 < expected_.size()) expected_[pair] = 1;
  }

  // Fixes both half-edges of every expected segment that is an edge of topo.
  void fixPresent(Topology& topo) {
    const std::size_t size = expected_.size() - 1;
    if (size == 0) return;
    found_.assign(size + 1, 0);  // the last byte takes the writes of half-edges that miss
    const std::uint32_t* triangles = topo.tri.data();
    std::uint8_t* fixedFlags = topo.fixed.data();
    const std::uint8_t* expectedPairs = expected_.data();
    std::uint8_t* foundPairs = found_.data();
    const std::uint32_t base = base_;
    forChunks(0, topo.tri.size() / 3, [=](std::size_t begin, std::size_t end) {
      // Locals, not the closure's members: the byte stores below may alias any memory, so
      // members would be loaded again after each of them.
      const std::uint32_t* tri = triangles;
      std::uint8_t* fixed = fixedFlags;
      const std::uint8_t* expected = expectedPairs;
      std::uint8_t* found = foundPairs;
      const std::uint32_t first = base;
      const std::size_t pairs = size;
      // Branch-free: a third of the half-edges on country rings qualify, in no pattern. Reads
      // and writes go to separate arrays, so that no load waits for the store before it.
      const auto consider = [&](std::size_t e, std::uint32_t a, std::uint32_t b) {
        // Past the batch, low reads the last entry, never expected. (A ghost end never
        // passes: kGhost is no vertex's successor.)
        const std::size_t low = std::min<std::size_t>(std::min(a, b) - first, pairs);
        const bool hit = (std::max(a, b) - std::min(a, b) == 1) & (expected[low] != 0);
        fixed[e] = static_cast<std::uint8_t>(fixed[e] | hit);
        found[hit ? low : pairs] = 1;
      };
      for (std::size_t e = 3 * begin; e < 3 * end; e += 3) {
        const std::uint32_t a = tri[e], b = tri[e + 1], c = tri[e + 2];
        consider(e, a, b);
        consider(e + 1, b, c);
        consider(e + 2, c, a);
      }
    });
    std::vector<std::uint8_t>().swap(expected_);  // (the segments go in next: memory peaks)
  }

  // Whether u-v was expected and is an edge, its half-edges fixed by fixPresent.
  bool present(std::uint32_t u, std::uint32_t v) const {
    const std::size_t pair = pairOf(u, v);
    return pair + 1 < found_.size() && found_[pair] != 0;
  }

 private:
  // The index of segment u-v among the batch's pairs (base + i, base + i + 1), or kNoPair.
  // Tested before subtracting: a 32-bit difference that wrapped (u older than the batch)
  // plus one would wrap again to 0 where size_t has 32 bits, as in wasm.
  static constexpr std::size_t kNoPair = static_cast<std::size_t>(-2);
  std::size_t pairOf(std::uint32_t u, std::uint32_t v) const {
    const std::uint32_t low = std::min(u, v);
    if (low < base_ || std::max(u, v) - low != 1) return kNoPair;
    return std::size_t{low} - base_;
  }

  std::uint32_t base_;
  std::vector<std::uint8_t> expected_;  // of segment (base + i, base + i + 1), and a last 0
  std::vector<std::uint8_t> found_;     // the same, found as an edge (the last: misses)
};

}  // namespace geocdt
