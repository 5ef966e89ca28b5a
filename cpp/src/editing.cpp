// Triangulation's editing calls: removePoint, removePolyline and movePoint. Each checks its
// arguments before it changes anything, takes the constraints off what changes
// (ConstraintEditor), removes or moves the vertices (Delaunay::removeVertex,
// reinsertVertex), then inserts the joined chains and the moved segments again, computing
// their crossings as a fresh insertion does. Snap-rounded constraints are inserted again
// all together instead: a tangle's rounding depends on all of them.
#include <algorithm>
#include <cmath>
#include <string>

#include "constraints/chain_check.h"
#include "constraints/constraint_editor.h"
#include "constraints/snap_rounding.h"
#include "delaunay/vertex_edges.h"
#include "edit_refusals.h"
#include "geocdt/triangulation.h"
#include "invalid_coordinate.h"
#include "out_of_memory.h"
#include "triangulation_state.h"

namespace geocdt {

namespace {

using State = Triangulation::State;

// f(e) for each half-edge out of v (v in the triangulation); stops when f returns true.
template <typename F>
bool anyEdgeOutOf(Delaunay& d, VertexEdges& ends, std::uint32_t v, F f) {
  const std::int32_t out = ends.find(d, v);
  if (out < 0) return false;
  std::int32_t e = out;
  do {
    if (f(e)) return true;
    e = d.topo.adj[prevEdge(e)];
  } while (e != out);
  return false;
}

// f(segment) for each live segment with an end at v (those of the stored edges around v,
// or of the pending segments), until f returns true.
template <typename F>
bool anySegmentEndingAt(Delaunay& d, VertexEdges& ends, std::uint32_t v, F f) {
  const ConstraintStore& store = d.constraints;
  bool stop = false;
  const auto visit = [&](const EdgeSource& src) {
    store.forEachSegment(src, [&](std::uint32_t i) {
      if (!stop && store.live(i) && (store.segments[i].a == v || store.segments[i].b == v))
        stop = f(i);
    });
    return stop;
  };
  for (const PendingSegment& p : store.pending)
    if ((p.u == v || p.v == v) && visit(p.src)) return true;
  if (!d.built()) return false;
  return anyEdgeOutOf(d, ends, v, [&](std::int32_t e) {
    if (!d.topo.fixed[e]) return false;
    const EdgeSource* src = store.find(v, d.topo.tri[nextEdge(e)]);
    return src != nullptr && visit(*src);
  });
}

bool polylineHasVertex(State& state, VertexEdges& ends, std::uint32_t v) {
  if (const std::uint32_t* uses = state.edit.loneUses.find(v); uses && *uses > 0) return true;
  return anySegmentEndingAt(state.delaunay, ends, v, [](std::uint32_t) { return true; });
}

// Whether v must stay: a point, or a vertex of a polyline still there.
bool needed(State& state, VertexEdges& ends, std::uint32_t v) {
  return (state.edit.kind(v) & kPointVertex) || polylineHasVertex(state, ends, v);
}

// Whether a constraint ends at v or passes through it.
bool carriesConstraints(Delaunay& d, VertexEdges& ends, std::uint32_t v) {
  for (const PendingSegment& p : d.constraints.pending)
    if (p.u == v || p.v == v) return true;
  if (!d.built()) return false;
  return anyEdgeOutOf(d, ends, v, [&](std::int32_t e) { return d.topo.fixed[e] != 0; });
}

// The Steiner points placed from the vertices listed, directly or through other Steiner
// points, appended to the list.
void addSteinerDescendants(State& state, std::vector<std::uint32_t>& vertices) {
  const Delaunay& d = state.delaunay;
  EditState& edit = state.edit;
  if (d.steiner.empty()) return;
  if (edit.steinerStale || edit.steinerLinks.size() > 3 * d.steiner.size()) {
    edit.steinerFirst.clear();
    edit.steinerLinks.clear();
    for (const SteinerVertex& s : d.steiner)
      for (const std::uint32_t parent : s.parents) {
        if (parent == kNoVertex) continue;
        std::int32_t& head = *edit.steinerFirst.insert(parent, -1).first;
        edit.steinerLinks.push_back({s.vertex, head});
        head = static_cast<std::int32_t>(edit.steinerLinks.size() - 1);
      }
    edit.steinerStale = false;
  }
  EdgeMap<std::uint8_t> listed;
  for (const std::uint32_t v : vertices) listed.insert(v, 1);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const std::int32_t* head = edit.steinerFirst.find(vertices[i]);
    for (std::int32_t k = head ? *head : -1; k >= 0; k = edit.steinerLinks[k].second) {
      const std::uint32_t child = edit.steinerLinks[k].first;
      if (!d.isRemoved(child) && listed.insert(child, 1).second) vertices.push_back(child);
    }
  }
}

// The half-edge out of each vertex that edits start from: built by the first edit (one pass
// over the triangles, 4 bytes a vertex), then kept as hints, checked when read. Locating the
// vertex instead walked from the grid's cell through triangles whose corners lie anywhere in
// memory: on 1M points, half the cache misses of a removal (bench/EXPERIMENTS.md, E3).
VertexEdges& editEdges(State& state) {
  VertexEdges& ends = state.edit.ends;
  if (!ends.built() && state.delaunay.built()) {
    ends.build(state.delaunay);
    ends.locateFromGrid();
    state.delaunay.refreshStaleGrid(ends);
  }
  return ends;
}

// Whether v could be edited without the constraint editor, as far as the state around it
// goes: triangles, no pending or snap-rounded constraints, no polyline of v alone, no Steiner
// point placed from v.
bool editsAlone(State& state, std::uint32_t v) {
  Delaunay& d = state.delaunay;
  if (!d.built() || !d.constraints.pending.empty() || state.edit.snapped) return false;
  if (const std::uint32_t* uses = state.edit.loneUses.find(v); uses && *uses > 0) return false;
  if (d.steiner.empty()) return true;
  std::vector<std::uint32_t> placed{v};
  addSteinerDescendants(state, placed);
  return placed.size() == 1;
}

// A half-edge out of v when v is a free vertex: in the triangulation, with no constrained
// edge, no polyline of its own and no Steiner point placed from it; else -1. Such a vertex is
// removed or moved by the Delaunay engine alone (the common case, which pays one location).
std::int32_t freeVertexEdge(State& state, std::uint32_t v) {
  Delaunay& d = state.delaunay;
  if (!editsAlone(state, v)) return -1;
  const std::int32_t out = editEdges(state).find(d, v);
  if (out < 0) return -1;
  if (!d.constrained()) return out;  // (no edge is constrained)
  if (d.topo.fixed[out]) return -1;
  // Round the star both ways at once, until the two meet: each step's triangle is a cache
  // miss that waits for the one before, and two such chains wait side by side.
  const std::vector<std::int32_t>& adj = d.topo.adj;
  std::int32_t left = out, right = out;
  for (;;) {
    left = adj[prevEdge(left)];
    if (left == right) return out;
    right = nextEdge(adj[right]);
    if (d.topo.fixed[left]) return -1;
    if (right == left) return out;
    if (d.topo.fixed[right]) return -1;
  }
}

// A half-edge out of v when v can move within its star by flips alone (Delaunay::
// shiftVertex), else -1: v free, or a polyline vertex each of whose constrained edges is
// whole segments ending at v (no crossing, Steiner point or other vertex along them), which
// stay those segments, crossing nothing, wherever v goes inside its star.
std::int32_t shiftableVertexEdge(State& state, std::uint32_t v) {
  Delaunay& d = state.delaunay;
  if (!d.constrained()) return freeVertexEdge(state, v);
  if (!editsAlone(state, v)) return -1;
  VertexEdges& ends = editEdges(state);
  const ConstraintStore& store = d.constraints;
  const bool split = anyEdgeOutOf(d, ends, v, [&](std::int32_t e) {
    if (!d.topo.fixed[e]) return false;
    const std::uint32_t w = d.topo.tri[nextEdge(e)];
    const EdgeSource* src = store.find(v, w);
    bool whole = src != nullptr;
    if (whole)
      store.forEachSegment(*src, [&](std::uint32_t i) {
        const SegmentEnds& ab = store.segments[i];
        whole = whole && ((ab.a == v && ab.b == w) || (ab.a == w && ab.b == v));
      });
    return !whole;
  });
  return split ? -1 : ends.find(d, v);
}

// Drops from gone[from ..] the Steiner points that must stay (given again as a point or a
// polyline vertex since). Decided before anything goes: a removal queues the chains through
// its vertex in the editor, off the mesh, where needed() no longer sees them.
template <typename Stays>
void keepNeeded(State& state, VertexEdges& ends, std::vector<std::uint32_t>& gone, std::size_t from,
                Stays stays) {
  const auto needs = [&](std::uint32_t v) { return stays(v) || needed(state, ends, v); };
  gone.erase(std::remove_if(gone.begin() + static_cast<std::ptrdiff_t>(from), gone.end(), needs),
             gone.end());
}

// Removes the candidates that nothing needs now, with their Steiner descendants; the
// vertices in `kept` (sorted: the ends of segments taken off to be inserted again) stay.
Status removeUnneeded(State& state, ConstraintEditor& editor, VertexEdges& ends,
                      std::vector<std::uint32_t>& candidates,
                      const std::vector<std::uint32_t>& kept = {}) {
  Delaunay& d = state.delaunay;
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  const auto stays = [&](std::uint32_t v) {
    return std::binary_search(kept.begin(), kept.end(), v);
  };
  std::vector<std::uint32_t> gone;
  for (const std::uint32_t v : candidates)
    if (!stays(v) && v < d.vertexCount() && !d.isRemoved(v) && !needed(state, ends, v))
      gone.push_back(v);
  const std::size_t checked = gone.size();
  addSteinerDescendants(state, gone);
  keepNeeded(state, ends, gone, checked, stays);
  for (const std::uint32_t v : gone) {
    if (d.isRemoved(v)) continue;
    const Status s = editor.removeVertex(v);
    if (!s.ok()) return s;
  }
  return Status::success();
}

// Inserts what the editor queued, keeps the computed crossings where the chains keep the
// guarantee (else snap-rounds, as an insertion does), and inserts the segments that waited
// for triangles.
Status finishEdit(State& state, ConstraintEditor& editor, VertexEdges& ends, std::uint32_t keep) {
  Delaunay& d = state.delaunay;
  bool snap = false;
  if (editor.queued()) {
    const Outcome outcome = editor.insertQueued();
    if (outcome == Outcome::Broken) return editor.error();
    snap = outcome == Outcome::GaveUp;
    if (!snap && d.built() && !editor.touchedSegments().empty())
      snap = !chainsKeepTheGuarantee(d, editor.touchedSegments(), ends);
  }
  if (snap) {
    const Status s = snapRoundConstraints(d, keep, state.options);
    if (!s.ok()) return s;
    state.edit.snapped = true;
    state.edit.steinerStale = true;
  }
  const Status s = insertPendingSegments(d, state.options);
  state.values.invalidate();
  state.changed();
  return s;
}

// Whether vertex v is what a rebuild of the constraints starts from: a point, an end of a
// live segment, or a polyline's only vertex.
std::vector<std::uint8_t> inputVertices(const State& state) {
  const Delaunay& d = state.delaunay;
  const ConstraintStore& store = d.constraints;
  std::vector<std::uint8_t> input(d.vertexCount(), 0);
  for (std::uint32_t v = 0; v < d.vertexCount(); ++v)
    input[v] = !d.isRemoved(v) && (state.edit.kind(v) & kPointVertex);
  for (std::uint32_t i = 0; i < store.segments.size(); ++i)
    if (store.live(i)) input[store.segments[i].a] = input[store.segments[i].b] = 1;
  state.edit.loneUses.forEach([&](std::uint64_t v, std::uint32_t uses) {
    if (uses > 0) input[v] = 1;
  });
  return input;
}

// Snap-rounded constraints after an edit: the triangulation is built again from the input
// vertices left (same ids) and every live segment inserted again, computed crossings first,
// snap rounding only if they still tangle. Crossings and Steiner points are dropped.
Status rebuildConstraints(State& state) {
  Delaunay& d = state.delaunay;
  const std::uint32_t n = d.vertexCount();
  std::vector<double> xy = d.xy;
  const std::vector<std::uint8_t> input = inputVertices(state);
  std::uint64_t removed = 0;
  for (std::uint32_t v = 0; v < n; ++v) {
    if (input[v]) continue;
    removed += !d.isRemoved(v);
    xy[2 * static_cast<std::size_t>(v)] = xy[2 * static_cast<std::size_t>(v) + 1] = NAN;
  }
  Delaunay fresh(state.options);
  Status s = fresh.insertKeepingIds(xy.data(), n);
  if (!s.ok()) return s;
  const ConstraintStore& old = d.constraints;
  ConstraintStore& store = fresh.constraints;
  store.segments = old.segments;
  store.segmentStarts = old.segmentStarts;
  store.polylinePoints = old.polylinePoints;
  store.firstSegment = old.firstSegment;
  store.ring = old.ring;
  store.polylineCount = old.polylineCount;
  Stats stats = d.stats;
  stats.removed += removed;
  fresh.stats = stats;
  VertexEdges ends;
  if (fresh.built()) ends.build(fresh);
  SegmentInserter inserter(fresh, ends);
  bool snap = false;
  for (std::uint32_t i = 0; i < store.segments.size() && !snap; ++i) {
    if (!store.live(i)) continue;
    const EdgeSource src = store.sourceOf(i);
    const SegmentEnds e = store.segments[i];
    if (!fresh.built()) {
      store.pending.push_back({e.a, e.b, src, src.polyline, i - store.firstSegment[src.polyline]});
      continue;
    }
    const Outcome outcome = inserter.insert(e.a, e.b, src);
    if (outcome == Outcome::Broken) return inserter.error();
    snap = outcome == Outcome::GaveUp;
  }
  if (!snap && fresh.built())
    snap = !chainsKeepTheGuarantee(fresh, inserter.touchedSegments(), ends);
  if (snap) s = snapRoundConstraints(fresh, n, state.options);
  if (!s.ok()) return s;
  state.edit.snapped = snap;
  state.edit.steinerStale = true;
  d = std::move(fresh);
  state.values.invalidate();
  state.changed();
  return Status::success();
}

// An edit the editor could not splice (see ConstraintEditor::unpaired) inserts the
// constraints again from the input instead, as one in snap-rounded constraints does.
Status orRebuild(State& state, const ConstraintEditor& editor, const Status& s) {
  return s.ok() || !editor.unpaired() ? s : rebuildConstraints(state);
}

// Moves vertex id to (x, y), whose vertex `there` (or kGhost) nothing needs: the segments
// ending at id are taken off, the vertices only they needed removed, id removed and inserted
// at its new place, and the segments inserted again from it.
// near: a triangle at or near (x, y), for the insertion's walk (-1: none).
Status moveVertex(State& state, std::uint32_t id, double x, double y, std::uint32_t there,
                  std::int32_t near) {
  Delaunay& d = state.delaunay;
  state.changed();
  if (state.edit.snapped) {
    d.xy[2 * static_cast<std::size_t>(id)] = x;
    d.xy[2 * static_cast<std::size_t>(id) + 1] = y;
    return rebuildConstraints(state);
  }
  if (const std::int32_t out = freeVertexEdge(state, id); out >= 0 && there == kGhost) {
    Status s = d.removeVertex(id, out, true, false, &editEdges(state));
    d.xy[2 * static_cast<std::size_t>(id)] = x;
    d.xy[2 * static_cast<std::size_t>(id) + 1] = y;
    if (s.ok()) s = d.reinsertVertex(id, near);
    if (s.ok()) s = insertPendingSegments(d, state.options);  // (if it went collinear and back)
    state.values.invalidate();
    return s;
  }
  VertexEdges& ends = editEdges(state);
  ConstraintEditor editor(d, ends);
  std::vector<std::uint32_t> moved;
  anySegmentEndingAt(d, ends, id, [&](std::uint32_t s) {
    moved.push_back(s);
    return false;
  });
  std::sort(moved.begin(), moved.end());
  moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
  std::vector<std::uint32_t> candidates;
  for (const std::uint32_t s : moved) editor.detachSegment(s, candidates);
  editor.restore();
  if (there != kGhost) candidates.push_back(there);
  // The Steiner points placed from id's old place go too.
  std::vector<std::uint32_t> placed{id};
  addSteinerDescendants(state, placed);
  candidates.insert(candidates.end(), placed.begin() + 1, placed.end());
  std::vector<std::uint32_t> kept{id};
  for (const std::uint32_t segment : moved) {
    kept.push_back(d.constraints.segments[segment].a);
    kept.push_back(d.constraints.segments[segment].b);
  }
  std::sort(kept.begin(), kept.end());
  const std::uint32_t keep = d.vertexCount();
  Status s = removeUnneeded(state, editor, ends, candidates, kept);
  if (s.ok()) s = editor.removeVertex(id, true);
  d.xy[2 * static_cast<std::size_t>(id)] = x;
  d.xy[2 * static_cast<std::size_t>(id) + 1] = y;
  if (!s.ok()) return orRebuild(state, editor, s);
  s = d.reinsertVertex(id, near);
  if (!s.ok()) return s;
  for (const std::uint32_t segment : moved) editor.queueSegment(segment);
  return finishEdit(state, editor, ends, keep);
}

}  // namespace

Status recordInsertion(Triangulation::State& state, const Status& inserted,
                       const std::uint32_t* ids, std::size_t count, std::uint8_t kind,
                       std::size_t firstPolyline, const PolylineView* polylines) {
  EditState& edit = state.edit;
  const Delaunay& d = state.delaunay;
  if (inserted.code == StatusCode::OutOfMemory || d.vertexCount() == 0) {
    edit.clear();  // the triangulation was cleared
    return inserted;
  }
  if (d.stats.snapRoundings != edit.snapRoundings) {
    edit.snapRoundings = d.stats.snapRoundings;
    edit.snapped = true;
    edit.steinerStale = true;
  }
  if (!inserted.ok()) return inserted;
  edit.mark(ids, count, kind);
  if (polylines == nullptr) return inserted;
  // Polylines without a segment (all their points one vertex) keep that vertex themselves.
  const ConstraintStore& store = d.constraints;
  std::size_t at = 0;
  for (std::size_t k = firstPolyline; k < store.polylineCount; ++k) {
    const std::size_t points = polylines[k - firstPolyline].count;
    const std::size_t end =
        k + 1 < store.firstSegment.size() ? store.firstSegment[k + 1] : store.segments.size();
    if (points > 0 && store.firstSegment[k] == end) {
      edit.lonePolylines.insert(static_cast<std::uint32_t>(k), ids[at]);
      ++*edit.loneUses.insert(ids[at], 0).first;
    }
    at += points;
  }
  return inserted;
}

bool Triangulation::hasVertex(std::uint32_t id) const {
  const Delaunay& d = state_->delaunay;
  return id < d.vertexCount() && !d.isRemoved(id);
}

bool Triangulation::hasPolyline(std::size_t polyline) const {
  const EditState& edit = state_->edit;
  return polyline < polylineCount() &&
         !(polyline < edit.polylineRemoved.size() && edit.polylineRemoved[polyline]);
}

Status Triangulation::removePoint(std::uint32_t id, bool* removed) {
  State& state = *state_;
  Delaunay& d = state.delaunay;
  EditState& edit = state.edit;
  if (const Status s = checkId(d, id, "removePoint"); !s.ok()) return s;
  if (!(edit.kind(id) & kPointVertex))
    return invalidEdit("removePoint: vertex " + std::to_string(id) +
                           " is not a point inserted with insertPoints (it is " +
                           describeVertex(edit, id) + ")",
                       id);
  if (removed) *removed = false;
  return catchOutOfMemory(
      [&] {
        edit.kinds[id] &= static_cast<std::uint8_t>(~kPointVertex);
        state.changed();
        if (const std::int32_t out = freeVertexEdge(state, id); out >= 0) {
          if (removed) *removed = true;
          state.values.invalidate();
          return d.removeVertex(id, out, false, false, &editEdges(state));
        }
        VertexEdges& ends = editEdges(state);
        if (polylineHasVertex(state, ends, id)) return Status::success();
        if (removed) *removed = true;
        if (edit.snapped && carriesConstraints(d, ends, id)) return rebuildConstraints(state);
        ConstraintEditor editor(d, ends);
        std::vector<std::uint32_t> gone{id};
        addSteinerDescendants(state, gone);
        keepNeeded(state, ends, gone, 1, [](std::uint32_t) { return false; });
        const std::uint32_t keep = d.vertexCount();
        for (const std::uint32_t v : gone) {
          if (d.isRemoved(v)) continue;
          const Status s = editor.removeVertex(v);
          if (!s.ok()) return orRebuild(state, editor, s);
        }
        return finishEdit(state, editor, ends, keep);
      },
      [&] { state.clear(); });
}

Status Triangulation::removePolyline(std::size_t polyline) {
  State& state = *state_;
  Delaunay& d = state.delaunay;
  EditState& edit = state.edit;
  ConstraintStore& store = d.constraints;
  if (polyline >= polylineCount())
    return invalidEdit("removePolyline: no polyline " + std::to_string(polyline) + " (" +
                           std::to_string(polylineCount()) + " inserted so far)",
                       polyline);
  if (!hasPolyline(polyline))
    return invalidEdit("removePolyline: polyline " + std::to_string(polyline) + " was removed",
                       polyline);
  const std::uint32_t first = store.firstSegment[polyline];
  const auto end = static_cast<std::uint32_t>(polyline + 1 < store.firstSegment.size()
                                                  ? store.firstSegment[polyline + 1]
                                                  : store.segments.size());
  return catchOutOfMemory(
      [&] {
        edit.polylineRemoved.resize(polylineCount(), 0);
        edit.polylineRemoved[polyline] = 1;
        state.changed();
        std::vector<std::uint32_t> candidates;
        if (const std::uint32_t* lone = edit.lonePolylines.find(polyline)) {
          candidates.push_back(*lone);
          --*edit.loneUses.find(*lone);
        }
        VertexEdges& ends = editEdges(state);
        ConstraintEditor editor(d, ends);
        if (!edit.snapped)
          for (std::uint32_t s = first; s < end; ++s) editor.detachSegment(s, candidates);
        for (std::uint32_t s = first; s < end; ++s) {
          candidates.push_back(store.segments[s].a);
          candidates.push_back(store.segments[s].b);
          store.segments[s] = {kRemovedSegment, kRemovedSegment};
        }
        if (edit.snapped) return rebuildConstraints(state);
        editor.restore();
        const std::uint32_t keep = d.vertexCount();
        const Status s = removeUnneeded(state, editor, ends, candidates);
        if (!s.ok()) return orRebuild(state, editor, s);
        return finishEdit(state, editor, ends, keep);
      },
      [&] { state.clear(); });
}

Status Triangulation::movePoint(std::uint32_t id, double x, double y) {
  State& state = *state_;
  Delaunay& d = state.delaunay;
  EditState& edit = state.edit;
  if (const Status s = checkId(d, id, "movePoint"); !s.ok()) return s;
  if (!(edit.kind(id) & (kPointVertex | kPolylineVertex)))
    return invalidEdit("movePoint: vertex " + std::to_string(id) + " is " +
                           describeVertex(edit, id) +
                           ", which moves only with what it was made from",
                       id);
  if (!std::isfinite(x) || !std::isfinite(y) || std::fabs(x) > kMaxCoordinate ||
      std::fabs(y) > kMaxCoordinate) {
    const bool badY = std::isfinite(x) && std::fabs(x) <= kMaxCoordinate;
    return {StatusCode::InvalidCoordinate,
            "movePoint: the new place of vertex " + std::to_string(id) + " has " +
                describeInvalidCoordinate(badY ? y : x, badY),
            id};
  }
  const double* p = d.xy.data();
  if (p[2 * static_cast<std::size_t>(id)] == x && p[2 * static_cast<std::size_t>(id) + 1] == y)
    return Status::success();
  // A free point or a simple polyline vertex moved within its star (a drag, an animation
  // frame) needs only flips; its star holds no other vertex, so nothing can be there. Moves
  // beyond two cells of the point-location grid are ruled out before anything else is read.
  if (d.built() && d.withinTwoCells(p[2 * static_cast<std::size_t>(id)],
                                    p[2 * static_cast<std::size_t>(id) + 1], x, y)) {
    bool shifted = false;
    const Status shift = catchOutOfMemory(
        [&] {
          const std::int32_t out = shiftableVertexEdge(state, id);
          shifted = out >= 0 && d.shiftVertex(id, out, x, y);
          if (shifted) {
            state.changed();
            state.values.invalidate();
          }
          return Status::success();
        },
        [&] { state.clear(); });
    if (!shift.ok() || shifted) return shift;
  }
  // A vertex there already: a crossing or Steiner point goes; a point or polyline vertex
  // stays, and the move is refused.
  std::uint32_t there = kGhost;
  std::int32_t near = -1;
  if (d.built()) {
    const Hit h = d.locate(x, y, true);
    if (h.kind == Hit::Kind::Vertex) there = d.topo.tri[h.edge];
    if (h.edge >= 0) near = h.edge / 3;
  } else {
    for (const std::uint32_t v : d.waiting())
      if (p[2 * static_cast<std::size_t>(v)] == x && p[2 * static_cast<std::size_t>(v) + 1] == y)
        there = v;
  }
  if (there != kGhost && (edit.kind(there) & (kPointVertex | kPolylineVertex)))
    return invalidEdit("movePoint: the new place of vertex " + std::to_string(id) +
                           " is that of vertex " + std::to_string(there) + " (" +
                           describeVertex(edit, there) + ")",
                       id);
  return catchOutOfMemory([&] { return moveVertex(state, id, x, y, there, near); },
                          [&] { state.clear(); });
}

}  // namespace geocdt
