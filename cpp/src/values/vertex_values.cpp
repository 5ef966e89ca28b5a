#include "values/vertex_values.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geocdt {

namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

// Two doubles that are equal, NaN included.
bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

}  // namespace

void VertexValues::grow(std::uint32_t vertexCount) {
  if (!active_) return;
  values_.resize(static_cast<std::size_t>(vertexCount) * perPoint_, kNoValue);
  given_.resize(vertexCount, 0);
}

void VertexValues::record(const std::uint32_t* ids, std::size_t count, const double* values,
                          std::uint32_t vertexCount) {
  fresh_ = false;
  if (!active_ && values == nullptr) return;
  if (!active_) {
    active_ = true;
    // Polyline points inserted before values were first given: their vertices are unknown,
    // and had no values anyway.
    polylinePointVertex_.assign(polylinePoints_, kGhost);
  }
  grow(vertexCount);
  const std::size_t k = perPoint_;
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t v = ids[i];
    double* to = values_.data() + v * k;
    const double* from = values ? values + i * k : nullptr;
    bool none = true;  // the vertex has no values yet, or only NaN: the point's values go in
    for (std::size_t j = 0; j < k && none && given_[v]; ++j) none = std::isnan(to[j]);
    if (none) {
      given_[v] = 1;
      for (std::size_t j = 0; j < k; ++j) to[j] = from ? from[j] : kNoValue;
      continue;
    }
    if (from == nullptr) continue;
    bool differs = false;
    for (std::size_t j = 0; j < k; ++j) differs |= !same(to[j], from[j]);
    duplicates_ += differs;
  }
}

void VertexValues::recordPolylinePoints(const std::uint32_t* ids, std::size_t count) {
  polylinePoints_ += count;
  if (active_) polylinePointVertex_.insert(polylinePointVertex_.end(), ids, ids + count);
}

void VertexValues::derive(std::uint32_t v, const std::uint32_t* parents, const double* weights,
                          std::size_t count) {
  fresh_ = false;
  explicitVertices_.push_back(v);
  explicitParents_.insert(explicitParents_.end(), parents, parents + count);
  explicitWeights_.insert(explicitWeights_.end(), weights, weights + count);
  explicitOffsets_.push_back(static_cast<std::uint32_t>(explicitParents_.size()));
}

// (vertex, input segment) for every derived vertex on a constrained edge, sorted.
std::vector<std::uint64_t> VertexValues::segmentsThroughDerived(const Delaunay& d) const {
  const Topology& topo = d.topo;
  const ConstraintStore& store = d.constraints;
  std::vector<std::uint64_t> pairs;
  for (std::size_t e = 0; e < topo.tri.size(); ++e) {
    if (!topo.fixed[e]) continue;
    const std::uint32_t u = topo.tri[e], w = topo.tri[nextEdge(static_cast<std::int32_t>(e))];
    if (u == kGhost || w == kGhost || given_[u]) continue;  // w: from its own half-edge
    const EdgeSource* src = store.find(u, w);
    if (src == nullptr) continue;
    store.forEachSegment(
        *src, [&](std::uint32_t s) { pairs.push_back(static_cast<std::uint64_t>(u) << 32 | s); });
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

// Vertex v's parents along the input segments through it, pairs[next ..) while they are v's
// (next moves past them): each segment's ends, weighted by v's projection on it, the segments
// averaged. False when no segment has ends with values to give.
inline bool VertexValues::deriveAlongSegments(const Delaunay& d, std::uint32_t v,
                                              const std::vector<std::uint64_t>& pairs,
                                              std::size_t& next, Derivations& out) {
  const std::size_t k = perPoint_;
  const double* p = d.xy.data();
  const std::size_t from = out.parents.size();
  std::vector<double>& along = out.along;
  along.clear();
  double largest = 0;
  for (; next < pairs.size() && (pairs[next] >> 32) == v; ++next) {
    const std::uint32_t start =
        d.constraints.segmentStarts[static_cast<std::uint32_t>(pairs[next])];
    if (start == kNoSegment || start + 1 >= polylinePointVertex_.size()) continue;
    const std::uint32_t s0 = polylinePointVertex_[start], s1 = polylinePointVertex_[start + 1];
    if (s0 == kGhost || s1 == kGhost) continue;
    // The vertex's projection on the segment between its ends (a crossing moved by rounding
    // still gets values between theirs).
    const double dx = p[2 * s1] - p[2 * s0], dy = p[2 * s1 + 1] - p[2 * s0 + 1];
    const double length2 = dx * dx + dy * dy;
    double t = length2 > 0
                   ? ((p[2 * v] - p[2 * s0]) * dx + (p[2 * v + 1] - p[2 * s0 + 1]) * dy) / length2
                   : 0;
    t = std::min(1.0, std::max(0.0, t));
    out.parents.push_back(s0);
    out.weights.push_back(1 - t);
    out.parents.push_back(s1);
    out.weights.push_back(t);
    for (std::size_t j = 0; j < k; ++j) {
      const double f0 = values_[s0 * k + j], f1 = values_[s1 * k + j];
      along.push_back(f0 + t * (f1 - f0));
      largest = std::max({largest, std::fabs(f0), std::fabs(f1)});
    }
  }
  const std::size_t segments = (out.parents.size() - from) / 2;
  if (segments == 0) return false;
  for (std::size_t q = from; q < out.parents.size(); ++q)
    out.weights[q] /= static_cast<double>(segments);
  bool disagree = false;
  for (std::size_t j = 0; j < k && !disagree; ++j)
    for (std::size_t s = 1; s < segments && !disagree; ++s)
      disagree = std::fabs(along[s * k + j] - along[j]) > 1e-9 * largest;
  disagreements_ += disagree;
  return true;
}

// Vertex v's values: its parents' from out.parents[from ..), weighted.
inline void VertexValues::evaluate(std::uint32_t v, const Derivations& out, std::size_t from) {
  const std::size_t k = perPoint_;
  double* to = values_.data() + v * k;
  for (std::size_t j = 0; j < k; ++j) to[j] = 0;
  for (std::size_t q = from; q < out.parents.size(); ++q)
    for (std::size_t j = 0; j < k; ++j) to[j] += out.weights[q] * values_[out.parents[q] * k + j];
}

// The derived vertices in vertex order, merged from two sorted lists: the explicit
// derivations (each vertex's last one winning, and overriding the constraints') and the
// vertices on input segments.
const std::vector<double>& VertexValues::update(const Delaunay& d, Mesh* mesh) {
  if (!active_ || (fresh_ && mesh == nullptr)) return values_;
  const std::uint32_t n = d.vertexCount();
  grow(n);
  const std::vector<std::uint64_t> pairs = segmentsThroughDerived(d);
  Derivations out;
  disagreements_ = 0;
  std::size_t next = 0, nextExplicit = 0;
  std::vector<std::uint32_t> order(explicitVertices_.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return explicitVertices_[a] < explicitVertices_[b];
  });
  for (;;) {
    const std::uint32_t a =
        next < pairs.size() ? static_cast<std::uint32_t>(pairs[next] >> 32) : kGhost;
    const std::uint32_t b =
        nextExplicit < order.size() ? explicitVertices_[order[nextExplicit]] : kGhost;
    const std::uint32_t v = std::min(a, b);
    if (v == kGhost) break;
    const std::size_t from = out.parents.size();
    if (b == v) {
      std::uint32_t i = order[nextExplicit];
      while (nextExplicit < order.size() && explicitVertices_[order[nextExplicit]] == v)
        i = order[nextExplicit++];
      while (next < pairs.size() && (pairs[next] >> 32) == v) ++next;
      if (v >= n || given_[v]) continue;
      for (std::uint32_t q = explicitOffsets_[i]; q < explicitOffsets_[i + 1]; ++q) {
        out.parents.push_back(explicitParents_[q]);
        out.weights.push_back(explicitWeights_[q]);
      }
    } else if (!deriveAlongSegments(d, v, pairs, next, out)) {
      continue;
    }
    out.vertices.push_back(v);
    out.offsets.push_back(static_cast<std::uint32_t>(out.parents.size()));
    evaluate(v, out, from);
  }
  fresh_ = true;
  if (mesh != nullptr) {
    mesh->values = values_;
    mesh->derivedVertices = std::move(out.vertices);
    mesh->derivedOffsets = std::move(out.offsets);
    mesh->derivedParents = std::move(out.parents);
    mesh->derivedWeights = std::move(out.weights);
  }
  return values_;
}

void VertexValues::clear() {
  const std::uint32_t perPoint = perPoint_;
  *this = VertexValues(perPoint);
}

}  // namespace geocdt
