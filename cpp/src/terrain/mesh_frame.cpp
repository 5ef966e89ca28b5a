#include "terrain/mesh_frame.h"

#include <algorithm>
#include <cmath>

namespace geocdt::terrain {

namespace {

// Renumbers the vertices some triangle has, in their order; drops the others.
void dropUnusedVertices(Mesh& m, FrameInput& in) {
  const std::size_t n = m.points.size() / 2;
  std::vector<std::uint32_t> id(n, kNoVertex);
  for (const std::uint32_t v : m.triangles) id[v] = 0;
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (id[v] != 0) continue;
    id[v] = next;
    m.points[2 * next] = m.points[2 * v];
    m.points[2 * next + 1] = m.points[2 * v + 1];
    in.z[next] = in.z[v];
    in.original[2 * next] = in.original[2 * v];
    in.original[2 * next + 1] = in.original[2 * v + 1];
    ++next;
  }
  m.points.resize(2 * std::size_t{next});
  in.z.resize(next);
  in.original.resize(2 * std::size_t{next});
  for (std::uint32_t& v : m.triangles) v = id[v];
}

// Triangle (a, b, c) becomes (a, c, b): half-edge 3t + k becomes 3t + 2 - k.
std::int32_t reversed(std::int32_t e) { return e < 0 ? e : e - e % 3 + 2 - e % 3; }

void reverseTriangles(Mesh& m) {
  const std::size_t halfEdges = m.triangles.size();
  for (std::size_t t = 0; t < halfEdges; t += 3) std::swap(m.triangles[t + 1], m.triangles[t + 2]);
  std::vector<std::int32_t> adj(halfEdges);
  std::vector<std::uint8_t> fixed(halfEdges);
  for (std::size_t e = 0; e < halfEdges; ++e) {
    const auto to = static_cast<std::size_t>(reversed(static_cast<std::int32_t>(e)));
    adj[to] = reversed(m.halfedges[e]);
    fixed[to] = m.constrained[e];
  }
  m.halfedges.swap(adj);
  m.constrained.swap(fixed);
  for (std::uint32_t& e : m.constraintEdges)
    e = static_cast<std::uint32_t>(reversed(static_cast<std::int32_t>(e)));
}

// Sources renumbered, each edge's listed once.
void renameSources(Mesh& m, const std::vector<std::uint32_t>& sourceOf) {
  std::vector<std::uint32_t> sources;
  std::vector<std::uint32_t> offsets{0};
  sources.reserve(m.sources.size());
  for (std::size_t i = 0; i + 1 < m.sourceOffsets.size(); ++i) {
    const std::size_t first = sources.size();
    for (std::uint32_t k = m.sourceOffsets[i]; k < m.sourceOffsets[i + 1]; ++k)
      sources.push_back(sourceOf[m.sources[k]]);
    std::sort(sources.begin() + static_cast<std::ptrdiff_t>(first), sources.end());
    sources.erase(std::unique(sources.begin() + static_cast<std::ptrdiff_t>(first), sources.end()),
                  sources.end());
    offsets.push_back(static_cast<std::uint32_t>(sources.size()));
  }
  m.sources.swap(sources);
  m.sourceOffsets.swap(offsets);
}

}  // namespace

void frameMesh(Mesh& m, FrameInput in, const PixelFrame& frame) {
  if (in.dropUnused) dropUnusedVertices(m, in);
  const std::size_t n = m.points.size() / 2;
  for (std::size_t v = 0; v < n; ++v) {
    if (!std::isnan(in.original[2 * v])) {
      m.points[2 * v] = in.original[2 * v];
      m.points[2 * v + 1] = in.original[2 * v + 1];
    } else {
      m.points[2 * v] = frame.mapX(m.points[2 * v]);
      m.points[2 * v + 1] = frame.mapY(m.points[2 * v + 1]);
    }
  }
  if (frame.mapped()) reverseTriangles(m);
  renameSources(m, in.sourceOf);
  m.values = std::move(in.z);
  m.segmentOffsets.clear();
  m.segmentSources.clear();
  m.derivedVertices.clear();
  m.derivedOffsets.clear();
  m.derivedParents.clear();
  m.derivedWeights.clear();
  m.steiner.clear();
  m.steinerParents.clear();
  m.steinerWeights.clear();
}

}  // namespace geocdt::terrain
