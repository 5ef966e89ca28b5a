// Region labels by flooding faces. A face is a set of triangles joined by unconstrained edges:
// every polygon's winding is the same all over it. The flood starts from the ghost triangles
// (outside every polygon), fills each face without computing anything, and crosses into the
// next face over one of its constrained edges, adding the winding each polygon's rings carry
// across that edge. So the windings are computed once per face, not per triangle or per
// constrained edge, and a triangle costs one visit (bench/EXPERIMENTS.md, L2).
#include "labels/region_labels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <utility>

namespace geocdt {

namespace {

// The polygons a face lies inside, each with its winding (even-odd: 1), sorted by polygon.
using Windings = std::vector<std::pair<std::int32_t, std::int32_t>>;

class FaceStates {
 public:
  explicit FaceStates(FillRule fill) : fill_(fill) { id(Windings{}); }  // 0: outside all

  std::int32_t id(const Windings& w) {
    const auto [at, fresh] = ids_.emplace(w, static_cast<std::int32_t>(states_.size()));
    if (fresh) states_.push_back(w);
    return at->second;
  }
  const Windings& operator[](std::int32_t s) const { return states_[s]; }
  std::int32_t size() const { return static_cast<std::int32_t>(states_.size()); }

  // Adds delta to the winding of polygon in w; a polygon whose winding leaves no inside goes.
  void add(Windings& w, std::int32_t polygon, std::int32_t delta) const {
    auto at = std::lower_bound(w.begin(), w.end(),
                               std::make_pair(polygon, std::numeric_limits<std::int32_t>::min()));
    if (at == w.end() || at->first != polygon) at = w.insert(at, {polygon, 0});
    at->second += delta;
    if (fill_ == FillRule::EvenOdd) at->second = at->second % 2 != 0;
    if (at->second == 0) w.erase(at);
  }

 private:
  FillRule fill_;
  std::map<Windings, std::int32_t> ids_;
  std::vector<Windings> states_;
};

// The face state met by stepping from the triangle of half-edge e across it.
std::int32_t crossEdge(const Delaunay& d, const std::vector<std::int32_t>& polylinePolygons,
                       FaceStates& states, std::int32_t from, std::int32_t e) {
  const std::uint32_t u = d.topo.tri[e], v = d.topo.tri[nextEdge(e)];
  const EdgeSource* src = d.constraints.find(u, v);
  if (src == nullptr) return from;
  Windings w = states[from];
  d.constraints.forEachPolylineWinding(*src, [&](std::uint32_t p, std::int32_t winding) {
    if (winding == 0 || p >= polylinePolygons.size() || polylinePolygons[p] < 0) return;
    // The winding runs from the lower vertex id to the higher; e's triangle lies left of
    // u -> v, and a step from a ring's left to its right takes one turn off.
    states.add(w, polylinePolygons[p], u < v ? -winding : winding);
  });
  return states.id(w);
}

// Each slot's face state; ghost slots are outside every polygon.
std::vector<std::int32_t> faceStates(const Delaunay& d,
                                     const std::vector<std::int32_t>& polylinePolygons,
                                     FaceStates& states) {
  const Topology& topo = d.topo;
  std::vector<std::int32_t> state(topo.slotCount(), -1);
  std::vector<std::int32_t> stack;
  std::vector<std::int32_t> exits;  // constrained half-edges out of flooded faces
  const auto flood = [&](std::int32_t first, std::int32_t s) {
    state[first] = s;
    stack.push_back(first);
    while (!stack.empty()) {
      const std::int32_t t = stack.back();
      stack.pop_back();
      for (std::int32_t e = 3 * t; e < 3 * t + 3; ++e) {
        // Unsigned (every slot has its twins): a cheaper division by 3.
        const std::int32_t next = static_cast<std::int32_t>(std::uint32_t(topo.adj[e]) / 3u);
        if (state[next] >= 0) continue;
        if (topo.fixed[e]) {
          exits.push_back(e);
        } else {
          state[next] = s;
          stack.push_back(next);
        }
      }
    }
  };
  // The ghost triangles form one ring around the hull, joined by edges to the ghost vertex,
  // which are never constrained: one flood from any of them covers them all.
  for (std::int32_t t = 0; t < topo.slotCount(); ++t)
    if (topo.isGhost(t)) {
      flood(t, 0);
      break;
    }
  for (std::size_t i = 0; i < exits.size(); ++i) {
    const std::int32_t e = exits[i], next = topo.adj[e] / 3;
    if (state[next] < 0) flood(next, crossEdge(d, polylinePolygons, states, state[e / 3], e));
  }
  return state;
}

// The label of each face state: its smallest polygon by (area, triangles, id). Only polygons
// that share a face with another are compared, so only the triangles of the faces they lie
// in are measured: none at all when no polygons overlap.
std::vector<std::int32_t> stateLabels(const Delaunay& d, const std::vector<std::int32_t>& state,
                                      const FaceStates& states) {
  std::vector<std::int32_t> label(states.size(), -1);
  std::vector<std::int32_t> compared;
  for (std::int32_t s = 1; s < states.size(); ++s) {
    label[s] = states[s].front().first;
    if (states[s].size() > 1)
      for (const auto& w : states[s]) compared.push_back(w.first);
  }
  if (compared.empty()) return label;
  std::sort(compared.begin(), compared.end());
  compared.erase(std::unique(compared.begin(), compared.end()), compared.end());
  const auto index = [&](std::int32_t polygon) {
    const auto at = std::lower_bound(compared.begin(), compared.end(), polygon);
    return at != compared.end() && *at == polygon ? at - compared.begin() : -1;
  };
  std::vector<std::uint8_t> measured(states.size(), 0);
  for (std::int32_t s = 1; s < states.size(); ++s)
    for (const auto& w : states[s]) measured[s] |= index(w.first) >= 0;

  const Topology& topo = d.topo;
  const double* p = d.xy.data();
  std::vector<double> stateArea(states.size(), 0.0);
  std::vector<std::uint64_t> stateTriangles(states.size(), 0);
  for (std::int32_t t = 0; t < topo.slotCount(); ++t) {
    if (state[t] < 0 || !measured[state[t]] || topo.isGhost(t)) continue;
    const std::uint32_t a = topo.tri[3 * t], b = topo.tri[3 * t + 1], c = topo.tri[3 * t + 2];
    const double cross = (p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) -
                         (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a]);
    stateArea[state[t]] += std::fabs(cross) / 2;
    ++stateTriangles[state[t]];
  }
  // Summed state by state in one order for all polygons: a polygon nested in another is in
  // a subset of its states, and rounding is monotonic, so its sum can never come out larger.
  std::vector<double> area(compared.size(), 0.0);
  std::vector<std::uint64_t> triangles(compared.size(), 0);
  for (std::int32_t s = 1; s < states.size(); ++s)
    for (const auto& w : states[s])
      if (const auto i = index(w.first); i >= 0) {
        area[i] += stateArea[s];
        triangles[i] += stateTriangles[s];
      }
  for (std::int32_t s = 1; s < states.size(); ++s) {
    if (states[s].size() < 2) continue;
    std::ptrdiff_t best = -1;
    for (const auto& w : states[s]) {
      const auto i = index(w.first);
      if (best < 0 || std::tie(area[i], triangles[i], compared[i]) <
                          std::tie(area[best], triangles[best], compared[best]))
        best = i;
    }
    label[s] = compared[best];
  }
  return label;
}

}  // namespace

std::vector<std::int32_t> regionSlots(const Delaunay& d,
                                      const std::vector<std::int32_t>& polylinePolygons,
                                      FillRule fill) {
  FaceStates states(fill);
  std::vector<std::int32_t> state = faceStates(d, polylinePolygons, states);
  const std::vector<std::int32_t> label = stateLabels(d, state, states);
  for (std::int32_t& s : state) s = s < 0 ? -1 : label[s];  // < 0: unreachable, never seen
  return state;
}

}  // namespace geocdt
