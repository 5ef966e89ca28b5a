// From internal slots to the caller's arrays: ghost triangles dropped, optionally the
// outside triangles too, with provenance, inside flags and region labels.
#include <algorithm>

#include "base/chunks.h"
#include "base/in_parallel.h"
#include "labels/region_labels.h"
#include "labels/slot_windings.h"
#include "triangulation_state.h"

namespace geocdt {

namespace {

// Inside flags of every slot by the fill rule.
std::vector<std::uint8_t> insideSlots(const Delaunay& d, FillRule fill,
                                      const std::vector<std::int32_t>& known) {
  std::vector<std::int32_t> computed;
  if (known.empty()) computed = slotWindings(d);
  const std::vector<std::int32_t>& winding = known.empty() ? computed : known;
  std::vector<std::uint8_t> inside(winding.size(), 0);
  forChunks(0, winding.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) inside[t] = insideByRule(winding[t], fill);
  });
  return inside;
}

}  // namespace

namespace {

// The first slot from `from` on that is not kept (or kept.size()), and the last kept one
// from `from` down (or -1): scans of long runs, each call short enough to be optimised for the
// next one (see chunks.h).
GEOCDT_NOINLINE std::int32_t firstDropped(const std::vector<std::uint8_t>& kept,
                                          std::int32_t from) {
  const auto slots = static_cast<std::int32_t>(kept.size());
  const std::int32_t stop = from + static_cast<std::int32_t>(std::min<std::size_t>(
                                       kChunk, static_cast<std::size_t>(slots - from)));
  while (from < stop && kept[from]) ++from;
  return from;
}

GEOCDT_NOINLINE std::int32_t lastKept(const std::vector<std::uint8_t>& kept, std::int32_t from) {
  const std::int32_t stop = std::max(from - static_cast<std::int32_t>(kChunk), -1);
  while (from > stop && !kept[from]) --from;
  return from;
}

// The order in which compaction fills holes: the last kept slot moves into the first
// dropped one, until they meet. Calls move(from, to) for each move; returns the count kept.
// Not inlined: with keep inside there are as many moves as triangles outside, and this loop
// had the whole export optimised during a first call (bench/EXPERIMENTS.md, F21).
template <typename Move>
GEOCDT_NOINLINE std::int32_t planCompaction(std::vector<std::uint8_t>& kept, Move move) {
  const std::int32_t slots = static_cast<std::int32_t>(kept.size());
  std::int32_t front = 0, back = slots - 1;
  for (;;) {
    while (front < slots && kept[front]) front = firstDropped(kept, front);
    while (back >= 0 && !kept[back]) back = lastKept(kept, back);
    if (front >= back) break;
    move(back, front);
    kept[front] = 1;
    kept[back] = 0;
  }
  std::int32_t count = 0;
  while (count < slots && kept[count]) count = firstDropped(kept, count);
  return count;
}

std::vector<std::uint8_t> realSlots(const std::vector<std::uint32_t>& tri, std::uint32_t threads) {
  std::vector<std::uint8_t> kept(tri.size() / 3);
  forChunksOn(threads, 0, kept.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
      kept[t] = tri[3 * t] != kGhost && tri[3 * t + 1] != kGhost && tri[3 * t + 2] != kGhost;
  });
  return kept;
}

// Drops the slots not kept, in place: twins pointing at a dropped slot become -1, then
// kept triangles from the end fill the holes, their twins told where they went. Only the
// few dropped slots (ghosts, mostly) cost anything beyond one pass. flags and labels, when
// given, hold one value per slot and move with their triangles.
void compact(Mesh& m, std::vector<std::uint8_t>* flags, std::vector<std::int32_t>* labels,
             std::vector<std::uint8_t> kept, std::uint32_t threads) {
  std::vector<std::uint32_t>& tri = m.triangles;
  std::vector<std::int32_t>& adj = m.halfedges;
  std::vector<std::uint8_t>& fixed = m.constrained;
  forChunksOn(threads, 0, kept.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) {
      if (!kept[t]) continue;
      for (std::size_t k = 0; k < 3; ++k) {
        const std::int32_t twin = adj[3 * t + k];
        if (twin >= 0 && !kept[twin / 3]) adj[3 * t + k] = -1;
      }
    }
  });
  const std::int32_t count = planCompaction(kept, [&](std::int32_t back, std::int32_t front) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t from = 3 * back + k, to = 3 * front + k;
      tri[to] = tri[from];
      fixed[to] = fixed[from];
      adj[to] = adj[from];
      if (adj[to] >= 0) adj[adj[to]] = to;
    }
    if (flags) (*flags)[front] = (*flags)[back];
    if (labels) (*labels)[front] = (*labels)[back];
  });
  tri.resize(3 * static_cast<std::size_t>(count));
  adj.resize(3 * static_cast<std::size_t>(count));
  fixed.resize(3 * static_cast<std::size_t>(count));
  if (flags) flags->resize(count);
  if (labels) labels->resize(count);
}

// Whether half-edge e lists its edge's provenance: a constrained edge is listed once, from
// the lower of its two half-edges (a hull edge, twin -1, from its one). No branches: see
// appendProvenance.
bool listsItsEdge(const Mesh& mesh, std::size_t e) {
  // -1 becomes the largest size_t: a hull edge's twin compares above every half-edge.
  const std::size_t twin = static_cast<std::size_t>(mesh.halfedges[e]);
  return (mesh.constrained[e] != 0) & (twin > e);
}

// The provenance of the edges listed from mesh's half-edges [first, last), appended to
// into's arrays (mesh itself or arrays of their own); offsets continue from their last
// entries.
void appendProvenance(const Delaunay& d, Mesh& into, bool segments, std::size_t first,
                      std::size_t last, const Mesh& mesh) {
  // The store's table is far larger than the caches and its entries come in no useful order
  // here: the edges go in batches whose entries are touched first, so that their misses
  // overlap (bench/EXPERIMENTS.md, C38).
  constexpr std::size_t kBatch = 64;
  std::uint32_t edge[kBatch];
  std::uint64_t key[kBatch];
  const EdgeSource* found[kBatch];
  std::size_t n = 0;
  volatile std::uint64_t touched = 0;  // (one per thread: touch's loads are kept through it)
  const auto flush = [&] {
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t e = edge[k];
      const std::uint32_t next = static_cast<std::uint32_t>(nextEdge(static_cast<std::int32_t>(e)));
      key[k] = ConstraintStore::key(mesh.triangles[e], mesh.triangles[next]);
    }
    touched = d.constraints.touch(key, n);
    for (std::size_t k = 0; k < n; ++k) found[k] = d.constraints.find(key[k]);
    touched = touched + d.constraints.touchExtras(found, n);
    for (std::size_t k = 0; k < n; ++k) {
      const EdgeSource* src = found[k];
      if (!src) continue;
      into.constraintEdges.push_back(edge[k]);
      d.constraints.forEachPolyline(*src, [&into](std::uint32_t p) { into.sources.push_back(p); });
      into.sourceOffsets.push_back(static_cast<std::uint32_t>(into.sources.size()));
      if (!segments) continue;
      d.constraints.forEachSegment(*src,
                                   [&into](std::uint32_t i) { into.segmentSources.push_back(i); });
      into.segmentOffsets.push_back(static_cast<std::uint32_t>(into.segmentSources.size()));
    }
    n = 0;
  };
  // Each half-edge is written down and kept (n moved on) only if it lists its edge: a sixth
  // of them on country rings, in no pattern a branch predictor learns: no branch per
  // half-edge (bench/EXPERIMENTS.md, C31).
  forChunks(first, last, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      edge[n] = static_cast<std::uint32_t>(e);
      n += listsItsEdge(mesh, e);
      if (n == kBatch) flush();
    }
  });
  flush();
}

void addProvenance(const Delaunay& d, Mesh& m, bool segments, std::uint32_t threads) {
  const std::size_t edges = d.constraints.edgeCount();
  // n + 1 offsets for n edges, none too: a caller may read offsets[n].
  if (edges == 0) {
    m.sourceOffsets.assign(1, 0);
    if (segments) m.segmentOffsets.assign(1, 0);
    return;
  }
  // Sized at once: the export is where the heap peaks, and doubling on the way would add
  // half again of each array.
  m.constraintEdges.reserve(edges);
  m.sourceOffsets.reserve(edges + 1);
  m.sources.reserve(edges + d.constraints.extraMembers());
  m.sourceOffsets.push_back(0);
  if (segments) m.segmentOffsets.push_back(0);
  const std::size_t halfEdges = m.triangles.size();
  if (!kThreadsBuilt || threads < 2 || edges < kParallelLoop) {
    appendProvenance(d, m, segments, 0, halfEdges, m);
    return;
  }
  // Side by side: each thread lists a range of half-edges into lists of its own (the first
  // range straight into m), which are then appended in order, offsets moved on.
  std::vector<Mesh> parts(threads - 1);
  inParallel(threads, [&](std::uint32_t i) {
    Mesh& into = i == 0 ? m : parts[i - 1];
    const std::size_t first = halfEdges * i / threads, last = halfEdges * (i + 1) / threads;
    if (i > 0) {
      // Sized at once, as above: the edges listed from this range, counted.
      std::size_t listed = 0;
      for (std::size_t e = first; e < last; ++e) listed += listsItsEdge(m, e);
      into.constraintEdges.reserve(listed);
      into.sourceOffsets.reserve(listed + 1);
      into.sources.reserve(listed);
      into.sourceOffsets.push_back(0);
      if (segments) {
        into.segmentSources.reserve(listed);
        into.segmentOffsets.reserve(listed + 1);
        into.segmentOffsets.push_back(0);
      }
    }
    appendProvenance(d, into, segments, first, last, m);
  });
  for (const Mesh& part : parts) {
    const std::uint32_t sourceBase = static_cast<std::uint32_t>(m.sources.size());
    const std::uint32_t segmentBase = static_cast<std::uint32_t>(m.segmentSources.size());
    m.constraintEdges.insert(m.constraintEdges.end(), part.constraintEdges.begin(),
                             part.constraintEdges.end());
    m.sources.insert(m.sources.end(), part.sources.begin(), part.sources.end());
    for (std::size_t k = 1; k < part.sourceOffsets.size(); ++k)
      m.sourceOffsets.push_back(sourceBase + part.sourceOffsets[k]);
    if (!segments) continue;
    m.segmentSources.insert(m.segmentSources.end(), part.segmentSources.begin(),
                            part.segmentSources.end());
    for (std::size_t k = 1; k < part.segmentOffsets.size(); ++k)
      m.segmentOffsets.push_back(segmentBase + part.segmentOffsets[k]);
  }
}

}  // namespace

std::vector<std::int32_t> slotIndices(const Topology& topo) {
  std::vector<std::uint8_t> kept = realSlots(topo.tri, 1);
  std::vector<std::int32_t> index(kept.size(), -1);
  for (std::size_t t = 0; t < kept.size(); ++t)
    if (kept[t]) index[t] = static_cast<std::int32_t>(t);
  planCompaction(kept, [&](std::int32_t back, std::int32_t front) { index[back] = front; });
  return index;
}

Mesh exportMesh(Delaunay& d, const MeshOptions& options, bool consume,
                const std::vector<std::int32_t>& windings) {
  const Progress& progress = d.options().progress;
  progress(Phase::Export, 0, 3);
  const bool classify = options.insideFlags || options.keep == Keep::Inside;
  std::vector<std::uint8_t> inside;
  if (classify) inside = insideSlots(d, options.fill, windings);
  std::vector<std::int32_t> regions;
  if (options.regions) regions = regionSlots(d, options.polylinePolygons, options.fill);
  Mesh m;
  Topology& topo = d.topo;
  if (consume) {
    m.points = std::move(d.xy);
    m.triangles = std::move(topo.tri);
    m.halfedges = std::move(topo.adj);
    m.constrained = std::move(topo.fixed);
  } else {
    m.points = d.xy;
    m.triangles = topo.tri;
    m.halfedges = topo.adj;
    m.constrained = topo.fixed;
  }
  const std::uint32_t threads = d.options().threads;
  std::vector<std::uint8_t> kept = realSlots(m.triangles, threads);
  if (options.keep == Keep::Inside)
    forChunksOn(threads, 0, kept.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t) kept[t] &= inside[t];
    });
  progress(Phase::Export, 1, 3);
  compact(m, classify ? &inside : nullptr, options.regions ? &regions : nullptr, std::move(kept),
          threads);
  if (options.insideFlags) m.inside = std::move(inside);
  if (options.regions) m.regions = std::move(regions);
  progress(Phase::Export, 2, 3);
  addProvenance(d, m, options.segmentSources, threads);
  forChunks(0, d.steiner.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const SteinerVertex& s = d.steiner[i];
      m.steiner.push_back(s.vertex);
      m.steinerParents.insert(m.steinerParents.end(), s.parents, s.parents + 3);
      m.steinerWeights.insert(m.steinerWeights.end(), s.weights, s.weights + 3);
    }
  });
  progress(Phase::Export, 3, 3);
  return m;
}

}  // namespace geocdt
