// After removals, the caller's arrays number the vertices without gaps: a removed vertex's
// place (NaN in the coordinates) closes up, the triangles, values, derivations and Steiner
// lists follow, and Mesh::vertexIds keeps each vertex's id.
#include <cmath>

#include "triangulation_state.h"

namespace geocdt {

namespace {

// Keeps the entries of a list in the Mesh's derivation layout (vertex, then its parents and
// weights from offsets) whose vertex is still there, renumbered.
void compactDerivations(const std::vector<std::uint32_t>& newId, Mesh& m) {
  std::size_t kept = 0, parents = 0;
  std::uint32_t to = m.derivedOffsets.empty() ? 0 : m.derivedOffsets[0];
  for (std::size_t i = 0; i < m.derivedVertices.size(); ++i) {
    const std::uint32_t v = newId[m.derivedVertices[i]];
    // (The offsets are rewritten in place behind the reading: each is read before.)
    const std::uint32_t from = to;
    to = m.derivedOffsets[i + 1];
    if (v == kNoVertex) continue;
    m.derivedVertices[kept] = v;
    for (std::uint32_t q = from; q < to; ++q, ++parents) {
      const std::uint32_t parent = m.derivedParents[q];
      m.derivedParents[parents] = parent == kNoVertex ? kNoVertex : newId[parent];
      m.derivedWeights[parents] = m.derivedWeights[q];
    }
    m.derivedOffsets[++kept] = static_cast<std::uint32_t>(parents);
  }
  m.derivedVertices.resize(kept);
  m.derivedOffsets.resize(m.derivedVertices.empty() && m.derivedOffsets.empty() ? 0 : kept + 1);
  m.derivedParents.resize(parents);
  m.derivedWeights.resize(parents);
}

void compactSteiner(const std::vector<std::uint32_t>& newId, Mesh& m) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < m.steiner.size(); ++i) {
    const std::uint32_t v = newId[m.steiner[i]];
    if (v == kNoVertex) continue;
    m.steiner[kept] = v;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t parent = m.steinerParents[3 * i + k];
      m.steinerParents[3 * kept + k] = parent == kNoVertex ? kNoVertex : newId[parent];
      m.steinerWeights[3 * kept + k] = m.steinerWeights[3 * i + k];
    }
    ++kept;
  }
  m.steiner.resize(kept);
  m.steinerParents.resize(3 * kept);
  m.steinerWeights.resize(3 * kept);
}

}  // namespace

void dropRemovedVertices(const Delaunay& d, Mesh& m) {
  if (d.stats.removed == 0) return;
  const std::size_t n = m.points.size() / 2;
  const std::size_t perPoint = n > 0 ? m.values.size() / n : 0;
  std::vector<std::uint32_t> newId(n, kNoVertex);
  m.vertexIds.clear();
  m.vertexIds.reserve(n - std::min<std::size_t>(n, d.stats.removed));
  for (std::size_t v = 0; v < n; ++v) {
    if (std::isnan(m.points[2 * v])) continue;
    const std::size_t to = m.vertexIds.size();
    newId[v] = static_cast<std::uint32_t>(to);
    m.vertexIds.push_back(static_cast<std::uint32_t>(v));
    m.points[2 * to] = m.points[2 * v];
    m.points[2 * to + 1] = m.points[2 * v + 1];
    for (std::size_t j = 0; j < perPoint; ++j)
      m.values[to * perPoint + j] = m.values[v * perPoint + j];
  }
  const std::size_t kept = m.vertexIds.size();
  m.points.resize(2 * kept);
  m.values.resize(kept * perPoint);
  for (std::uint32_t& v : m.triangles) v = newId[v];
  compactDerivations(newId, m);
  compactSteiner(newId, m);
}

}  // namespace geocdt
