#include "constraints/constraint_editor.h"

#include <algorithm>
#include <string>

namespace geocdt {

namespace {

bool names(const ConstraintStore& store, const EdgeSource& e, std::uint32_t segment) {
  bool found = false;
  store.forEachSegment(e, [&](std::uint32_t i) { found = found || i == segment; });
  return found;
}

}  // namespace

void ConstraintEditor::detachSegment(std::uint32_t s, std::vector<std::uint32_t>& vertices) {
  ConstraintStore& store = d_.constraints;
  const SegmentEnds ends = store.segments[s];
  const std::uint32_t polyline = store.sourceOf(s).polyline;
  if (!d_.built()) {  // the pending segments hold it
    std::vector<PendingSegment>& pending = store.pending;
    for (std::size_t k = 0; k < pending.size();) {
      bool emptied = false;
      if (store.dropPair(pending[k].src, polyline, s, emptied)) {
        vertices.push_back(pending[k].u);
        vertices.push_back(pending[k].v);
      }
      if (emptied) {
        pending.erase(pending.begin() + static_cast<std::ptrdiff_t>(k));
      } else {
        ++k;
      }
    }
    return;
  }
  // Every constrained edge naming s that is reached from its first vertex through such
  // edges: its chain, and any route left behind by a bend (see chain_check.cpp).
  Topology& topo = d_.topo;
  seen_.clear();
  frontier_.clear();
  found_.clear();
  const std::int32_t start = ends_.find(d_, ends.a);
  if (start < 0) return;
  frontier_.push_back({ends.a, start});
  seen_.insert(ends.a, 1);
  for (std::size_t k = 0; k < frontier_.size(); ++k) {
    const auto [c, out] = frontier_[k];
    vertices.push_back(c);
    std::int32_t e = out;
    do {
      const std::uint32_t w = topo.tri[nextEdge(e)];
      if (topo.fixed[e] && w != kGhost) {
        const EdgeSource* src = store.find(c, w);
        if (src && names(store, *src, s)) {
          if (c < w) found_.push_back(e);
          if (seen_.insert(w, 1).second) frontier_.push_back({w, topo.adj[e]});
        }
      }
      e = topo.adj[prevEdge(e)];
    } while (e != out);
  }
  std::vector<std::int32_t>& stack = d_.flipStack();
  for (const std::int32_t e : found_) {
    bool emptied = false;
    store.dropPair(topo.tri[e], topo.tri[nextEdge(e)], polyline, s, emptied);
    if (!emptied) continue;
    topo.fixed[e] = topo.fixed[topo.adj[e]] = 0;
    stack.push_back(e);
  }
}

void ConstraintEditor::queueSegment(std::uint32_t s) {
  const ConstraintStore& store = d_.constraints;
  addPiece(store.segments[s].a, store.segments[s].b, store.sourceOf(s));
}

void ConstraintEditor::addPiece(std::uint32_t u, std::uint32_t w, const EdgeSource& src) {
  pieces_.push_back({u, w, src, true});
  ++live_;
  for (const std::uint32_t end : {u, w}) {
    std::int32_t& head = *firstAtEnd_.insert(end, -1).first;
    nextAtEnd_.push_back(head);
    head = static_cast<std::int32_t>(nextAtEnd_.size() - 1);  // entry 2 * piece + (end == w)
  }
}

bool ConstraintEditor::takeLinks(std::uint32_t v, std::int32_t out) {
  ConstraintStore& store = d_.constraints;
  Topology& topo = d_.topo;
  bool freed = false;
  std::int32_t e = out;
  do {
    if (topo.fixed[e]) {
      freed = true;
      const std::uint32_t w = topo.tri[nextEdge(e)];
      const EdgeSource src = store.take(v, w);  // winding from v to w
      store.forEachPair(src,
                        [&](std::uint32_t polyline, std::uint32_t segment, std::int32_t winding) {
                          // forEachPair gives shares from the lower id to the higher; take() turned
                          // the list around when v > w, so they run from v to w here.
                          links_.push_back({segment, polyline, w, winding});
                        });
      topo.fixed[e] = topo.fixed[topo.adj[e]] = 0;
    }
    e = topo.adj[prevEdge(e)];
  } while (e != out);
  return freed;
}

void ConstraintEditor::takePendingLinks(std::uint32_t v) {
  ConstraintStore& store = d_.constraints;
  std::vector<PendingSegment>& pending = store.pending;
  for (std::size_t k = 0; k < pending.size();) {
    const PendingSegment p = pending[k];
    if (p.u != v && p.v != v) {
      ++k;
      continue;
    }
    const std::uint32_t other = p.u == v ? p.v : p.u;
    const std::int32_t sign = p.u == v ? 1 : -1;  // the source's windings run from u to v
    // A pending source's shares run from u to v (as marked): forEachPair's "lower to
    // higher" reading is the source's own direction here.
    store.forEachPair(p.src,
                      [&](std::uint32_t polyline, std::uint32_t segment, std::int32_t winding) {
                        links_.push_back({segment, polyline, other, sign * winding});
                      });
    pending.erase(pending.begin() + static_cast<std::ptrdiff_t>(k));
  }
}

// Each chain at v has two links, one each way: joined into the piece that skips v.
Status ConstraintEditor::joinLinks(std::uint32_t v) {
  // Queued pieces ending at v die and give their links.
  if (const std::int32_t* head = firstAtEnd_.find(v)) {
    for (std::int32_t k = *head; k >= 0; k = nextAtEnd_[k]) {
      Piece& p = pieces_[k / 2];
      if (!p.live || (p.u != v && p.w != v)) continue;
      p.live = false;
      --live_;
      const bool fromU = p.u == v;
      links_.push_back({p.src.segment, p.src.polyline, fromU ? p.w : p.u,
                        fromU ? p.src.winding : -p.src.winding});
    }
  }
  std::sort(links_.begin(), links_.end(), [](const Link& a, const Link& b) {
    return a.segment != b.segment ? a.segment < b.segment : a.other < b.other;
  });
  Status status;
  for (std::size_t k = 0; k < links_.size();) {
    std::size_t j = k;
    while (j < links_.size() && links_[j].segment == links_[k].segment) ++j;
    if (j - k != 2) {
      unpaired_ = true;
      status = {StatusCode::InternalError,
                "removing vertex " + std::to_string(v) + ": segment " +
                    std::to_string(links_[k].segment) + " ends there",
                v};
      break;
    }
    const Link& a = links_[k];
    const Link& b = links_[k + 1];
    EdgeSource src;
    src.segment = a.segment;
    src.polyline = a.polyline;
    src.winding = -a.winding;  // from a.other to v, which runs on to b.other
    addPiece(a.other, b.other, src);
    k = j;
  }
  links_.clear();
  return status;
}

Status ConstraintEditor::removeVertex(std::uint32_t v, bool moving) {
  links_.clear();
  if (!d_.built()) {
    takePendingLinks(v);
    const Status joined = joinLinks(v);
    if (!joined.ok()) return joined;
    return d_.removeVertex(v, -1, moving, true);
  }
  const std::int32_t out = ends_.find(d_, v);
  if (out < 0) {
    return {StatusCode::InternalError,
            "removing vertex " + std::to_string(v) + ": not in the triangulation", v};
  }
  const bool freed = takeLinks(v, out);
  const Status joined = joinLinks(v);
  if (!joined.ok()) return joined;
  return d_.removeVertex(v, out, moving, freed, &ends_);
}

Outcome ConstraintEditor::insertQueued() {
  SegmentInserter inserter(d_, ends_);
  Outcome outcome = Outcome::Inserted;
  for (const Piece& p : pieces_) {
    if (!p.live) continue;
    if (!d_.built()) {
      d_.constraints.pending.push_back({p.u, p.w, p.src, p.src.polyline, 0});
      continue;
    }
    outcome = inserter.insert(p.u, p.w, p.src);
    if (outcome == Outcome::Broken) error_ = inserter.error();
    if (outcome != Outcome::Inserted) break;
  }
  pieces_.clear();
  firstAtEnd_.clear();
  nextAtEnd_.clear();
  live_ = 0;
  touched_ = inserter.touchedSegments();
  return outcome;
}

}  // namespace geocdt
