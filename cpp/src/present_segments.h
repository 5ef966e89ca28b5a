#pragma once
// Input segments that are already edges, found for a whole batch by one pass over the
// triangles. A polyline's new points have consecutive vertex ids, so most of its segments
// join u and u + 1, and on dense polylines most of those are Delaunay edges already. Turning
// round each segment's first vertex in polyline order to find them, and fixing their two
// half-edges there, missed the cache on nearly every segment; one pass in memory order finds
// and fixes them all (bench/EXPERIMENTS.md, Constraints 37).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "topology.h"

namespace geocdt {

class PresentSegments {
 public:
  // For the new vertices [base, end).
  PresentSegments(std::uint32_t base, std::uint32_t end) : base_(base), state_(end - base, 0) {}

  // Segment u-v of the batch: looked for if its ends are consecutive new ids.
  void expect(std::uint32_t u, std::uint32_t v) {
    const std::uint32_t low = std::min(u, v) - base_;
    if (std::max(u, v) - std::min(u, v) == 1 && low < state_.size()) state_[low] = kExpected;
  }

  // Fixes both half-edges of every expected segment that is an edge of topo.
  void fixPresent(Topology& topo) {
    const std::uint32_t* tri = topo.tri.data();
    std::uint8_t* fixed = topo.fixed.data();
    std::uint8_t* state = state_.data();
    const std::size_t size = state_.size();
    if (size == 0) return;
    for (std::size_t e = 0; e < topo.tri.size(); ++e) {
      const std::uint32_t a = tri[e];
      const std::uint32_t b = tri[static_cast<std::size_t>(nextEdge(static_cast<std::int32_t>(e)))];
      const std::uint32_t low = std::min(a, b) - base_;
      // (A ghost end never passes: kGhost is no vertex's successor.)
      const bool consecutive = (std::max(a, b) - std::min(a, b) == 1) & (low < size);
      // Branch-free: a third of the half-edges on country rings qualify, in no pattern. A
      // half-edge that does not reads and writes back slot 0 unchanged.
      const std::size_t at = consecutive ? low : 0;
      const std::uint8_t s = state[at];
      const bool found = consecutive & (s != 0);
      fixed[e] = static_cast<std::uint8_t>(fixed[e] | found);
      state[at] = static_cast<std::uint8_t>(s | (found ? kFound : 0));
    }
  }

  // Whether u-v was expected and is an edge, its half-edges fixed by fixPresent.
  bool present(std::uint32_t u, std::uint32_t v) const {
    const std::uint32_t low = std::min(u, v) - base_;
    return std::max(u, v) - std::min(u, v) == 1 && low < state_.size() &&
           (state_[low] & kFound) != 0;
  }

 private:
  static constexpr std::uint8_t kExpected = 1, kFound = 2;
  std::uint32_t base_;
  std::vector<std::uint8_t> state_;  // of segment (base + i, base + i + 1)
};

}  // namespace geocdt
