// Triangulation's constraint API: polylines in, their points as one batch, then their
// segments one by one through the SegmentInserter.
#include <algorithm>
#include <cmath>
#include <string>

#include "base/chunks.h"
#include "constraints/chain_check.h"
#include "constraints/present_segments.h"
#include "constraints/segment_inserter.h"
#include "constraints/snap_rounding.h"
#include "delaunay/vertex_edges.h"
#include "geocdt/triangulation.h"
#include "invalid_coordinate.h"
#include "out_of_memory.h"
#include "triangulation_state.h"

namespace geocdt {

namespace {

Status checkPolyline(const PolylineView& line, std::size_t index) {
  if (line.count > 0 && line.xy == nullptr)
    return {StatusCode::InvalidArgument,
            "polyline " + std::to_string(index) + ": null coordinates with a count", index};
  const std::size_t n = 2 * line.count;
  const std::size_t i = firstInvalidCoordinate(line.xy, 0, n);
  if (i < n) {
    const double v = line.xy[i];
    Status s{StatusCode::InvalidCoordinate,
             "polyline " + std::to_string(index) + " point " + std::to_string(i / 2) + " has " +
                 describeInvalidCoordinate(v, i % 2 == 1),
             index};
    s.segment = i / 2;
    return s;
  }
  return Status::success();
}

Status located(const Status& s, std::size_t polyline, std::size_t segment) {
  Status out = s;
  out.index = polyline;
  out.segment = segment;
  out.message = "polyline " + std::to_string(polyline) + " segment " + std::to_string(segment) +
                ": " + s.message;
  return out;
}

// The half-edges out of every vertex, for a call of many segments: one pass over the
// triangles costs less than locating their ends. A few segments in a large triangulation
// (a line drawn on a map) locate theirs instead.
VertexEdges endsFor(const Delaunay& d, std::size_t segments) {
  VertexEdges ends;
  if (d.built() && 8 * static_cast<std::uint64_t>(segments) >= d.vertexCount()) ends.build(d);
  return ends;
}

// Checks every polyline and counts their points into total.
Status checkPolylines(const PolylineView* polylines, std::size_t count, std::size_t& total) {
  Status checked;
  // In a chunk, not a loop of the caller: compiled to wasm, the rest of the function came to
  // lie inside that loop, and V8 charges its budget for optimised code by the bytes from a
  // loop's start to its back edge (bench/EXPERIMENTS.md, F21).
  forChunks(0, count, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last && checked.ok(); ++i) {
      checked = checkPolyline(polylines[i], i);
      total += polylines[i].count;
    }
  });
  return checked;
}

// At most one segment and one constrained edge a point (fewer where polylines share edges):
// the store's arrays and table at about their final sizes at once, not doubled on the way.
void reserveStore(ConstraintStore& store, std::size_t points, std::size_t polylines,
                  std::uint32_t vertices) {
  store.reserve(store.edgeCount() + points, vertices);
  store.segments.reserve(store.segments.size() + points);
  store.segmentStarts.reserve(store.segmentStarts.size() + points);
  store.firstSegment.reserve(store.firstSegment.size() + polylines);
  store.ring.reserve(store.ring.size() + polylines);
}

// The segments of a batch of polylines whose points are in, in order. A large batch marks the
// segments that are edges already (found in one pass) in a first round, and inserts the
// others (kept in later_) in a second: those may cross the first ones, which are then all in
// the store, as a crossed constraint must be. Where computed crossings would break the
// guarantee, snap rounding takes over the segments.
class BatchSegments {
 public:
  BatchSegments(Delaunay& d, const Options& options, std::size_t points, std::uint32_t firstNew)
      : d_(d),
        store_(d.constraints),
        options_(options),
        progress_(d.options().progress),
        ends_(endsFor(d, points)),
        inserter_(d, ends_),
        points_(points),
        keep_(d.vertexCount()),
        snap_(options.snapRounding == SnapRounding::Always && d.built()),
        twoRounds_(ends_.built() && !snap_),
        present_(firstNew, twoRounds_ ? keep_ : firstNew),
        span_(twoRounds_ ? 2 * points : points) {}

  // ids: the vertex of every point of every polyline.
  Status insert(const PolylineView* polylines, std::size_t count, const std::uint32_t* ids);

 private:
  void expectPresent(const PolylineView* polylines, std::size_t count);
  void addPolyline(std::size_t i, std::size_t pointCount);
  bool addSegment(const PendingSegment& segment);
  void insertLater();

  Delaunay& d_;
  ConstraintStore& store_;
  const Options& options_;
  const Progress& progress_;
  VertexEdges ends_;
  SegmentInserter inserter_;
  std::size_t points_;
  std::uint32_t keep_;  // crossings come after
  bool snap_;           // whether snap rounding takes over the segments
  bool twoRounds_;
  PresentSegments present_;
  std::size_t span_;  // progress: the rounds in turn
  const std::uint32_t* ids_ = nullptr;
  std::size_t offset_ = 0;  // of the next polyline's first point in ids_
  std::size_t segmentsTried_ = 0;
  std::vector<PendingSegment> later_;
  Status broken_;
};

// The loops over polylines call a function per polyline (a chunk of 1), and the second round
// one per chunk of segments: insert() runs once a call, and its own loops would spend the
// engine's budget for optimised code on it, whose long compile only took a core from a first
// call (chunks.h; bench/EXPERIMENTS.md, F21).
Status BatchSegments::insert(const PolylineView* polylines, std::size_t count,
                             const std::uint32_t* ids) {
  ids_ = ids;
  if (twoRounds_) expectPresent(polylines, count);
  forChunks(
      0, count,
      [&](std::size_t first, std::size_t last) {
        // A polyline's count only: its points are in.
        for (std::size_t i = first; i < last && broken_.ok(); ++i)
          addPolyline(i, polylines[i].count);
      },
      1);
  if (!broken_.ok()) return broken_;
  insertLater();
  if (!broken_.ok()) return broken_;
  std::vector<PendingSegment>().swap(later_);
  // Computed crossings stay where every chain that met one keeps the guarantee.
  if (!snap_ && d_.built()) snap_ = !chainsKeepTheGuarantee(d_, inserter_.touchedSegments(), ends_);
  if (snap_) {
    const Status s = snapRoundConstraints(d_, keep_, options_);
    if (!s.ok()) return s;
  }
  progress_(Phase::Constraints, points_, points_);
  return Status::success();
}

// The first round's pass: which segments join consecutive new vertices, to be found as edges.
void BatchSegments::expectPresent(const PolylineView* polylines, std::size_t count) {
  std::size_t at = 0;
  forChunks(
      0, count,
      [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
          for (std::size_t k = 0; k + 1 < polylines[i].count; ++k)
            present_.expect(ids_[at + k], ids_[at + k + 1]);
          at += polylines[i].count;
        }
      },
      1);
  present_.fixPresent(d_.topo);
}

// Polyline i, of pointCount points: its segments into the store, then in.
void BatchSegments::addPolyline(std::size_t i, std::size_t pointCount) {
  const std::uint32_t* lineIds = ids_ + offset_;
  offset_ += pointCount;
  const std::uint64_t firstPoint = store_.polylinePoints;
  store_.polylinePoints += pointCount;
  const bool ring = pointCount >= 3 && lineIds[0] == lineIds[pointCount - 1];
  const std::uint32_t id = store_.startPolyline(ring);
  ++d_.stats.polylines;
  for (std::size_t k = 0; k + 1 < pointCount; ++k) {
    if ((++segmentsTried_ & 255) == 0)
      progress_(Phase::Constraints, offset_ - pointCount + k, span_);
    const std::uint32_t u = lineIds[k], v = lineIds[k + 1];
    if (u == v) continue;  // a repeated point: nothing to constrain
    EdgeSource src;
    src.segment = static_cast<std::uint32_t>(store_.segments.size());
    src.winding = ring ? 1 : 0;
    src.polyline = id;
    store_.segments.push_back({u, v});
    store_.segmentStarts.push_back(
        static_cast<std::uint32_t>(std::min<std::uint64_t>(firstPoint + k, kNoSegment)));
    if (!addSegment({u, v, src, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k)}))
      return;
  }
}

// A stored segment: waits for triangles, for snap rounding or for the second round, is
// marked where it is an edge already, or goes in. False when it broke an invariant.
bool BatchSegments::addSegment(const PendingSegment& segment) {
  if (!d_.built()) {
    store_.pending.push_back(segment);
    return true;
  }
  if (snap_) return true;  // stored: snap rounding inserts it with all the others
  if (twoRounds_) {
    if (present_.present(segment.u, segment.v)) {
      store_.mark(segment.u, segment.v, segment.src);
      ++d_.stats.segments;
    } else {
      later_.push_back(segment);
    }
    return true;
  }
  const Outcome outcome = inserter_.insert(segment.u, segment.v, segment.src);
  if (outcome == Outcome::Broken) {
    broken_ = located(inserter_.error(), segment.polyline, segment.index);
    return false;
  }
  snap_ = outcome == Outcome::GaveUp;
  return true;
}

// The second round: the segments that were not edges yet.
void BatchSegments::insertLater() {
  forChunks(0, later_.size(), [&](std::size_t first, std::size_t last) {
    for (std::size_t j = first; j < last && !snap_ && broken_.ok(); ++j) {
      if ((j & 255) == 255)
        progress_(Phase::Constraints, points_ + j * points_ / later_.size(), span_);
      const PendingSegment& p = later_[j];
      const Outcome outcome = inserter_.insert(p.u, p.v, p.src);
      if (outcome == Outcome::Broken) broken_ = located(inserter_.error(), p.polyline, p.index);
      snap_ = outcome == Outcome::GaveUp;
    }
  });
}

}  // namespace

Status insertPendingSegments(Delaunay& d, const Options& options) {
  ConstraintStore& store = d.constraints;
  if (!d.built() || store.pending.empty()) return Status::success();
  std::vector<PendingSegment> pending;
  pending.swap(store.pending);
  const std::uint32_t keep = d.vertexCount();  // crossings come after
  if (options.snapRounding == SnapRounding::Always) return snapRoundConstraints(d, keep, options);
  VertexEdges ends = endsFor(d, pending.size());
  SegmentInserter inserter(d, ends);
  for (const PendingSegment& s : pending) {
    const Outcome outcome = inserter.insert(s.u, s.v, s.src);
    if (outcome == Outcome::Broken) return located(inserter.error(), s.polyline, s.index);
    if (outcome == Outcome::GaveUp) return snapRoundConstraints(d, keep, options);
  }
  if (!chainsKeepTheGuarantee(d, inserter.touchedSegments(), ends))
    return snapRoundConstraints(d, keep, options);
  return Status::success();
}

Status Triangulation::insertPolyline(const double* xy, std::size_t count, std::uint32_t* vertexIds,
                                     const double* values) {
  const PolylineView line{xy, count};
  return insertPolylines(&line, 1, vertexIds, values);
}

Status Triangulation::insertPolylines(const PolylineView* polylines, std::size_t count,
                                      std::uint32_t* vertexIds, const double* values) {
  if (count > 0 && polylines == nullptr)
    return {StatusCode::InvalidArgument, "null polylines with a count"};
  std::size_t total = 0;
  for (std::size_t i = 0; i < count; ++i) total += polylines[i].count;
  std::vector<std::uint32_t> scratch;
  std::uint32_t* ids = idsFor(vertexIds, total, scratch);
  const std::size_t before = polylineCount();
  return recordInsertion(*state_, insertPolylineBatch(polylines, count, ids, values, nullptr), ids,
                         total, kPolylineVertex, before, polylines);
}

Status Triangulation::insertPolylines(std::vector<double>&& xy, const std::uint32_t* offsets,
                                      std::size_t count, std::uint32_t* vertexIds,
                                      const double* values) {
  if (count > 0 && offsets == nullptr)
    return {StatusCode::InvalidArgument, "null offsets with a count"};
  const std::size_t points = xy.size() / 2;
  if (xy.size() % 2 != 0 || (offsets != nullptr && offsets[0] != 0) ||
      (count > 0 && offsets[count] != points) || (count == 0 && points != 0))
    return {StatusCode::InvalidArgument,
            "polyline offsets must run from 0 to the number of points in the buffer"};
  std::vector<PolylineView> views(count);
  std::size_t decreasing = count;  // the first polyline that ends before it starts, if any
  forChunks(0, count, [&](std::size_t begin, std::size_t end) {
    if (decreasing != count) return;
    for (std::size_t i = begin; i < end; ++i) {
      if (offsets[i + 1] < offsets[i]) {
        decreasing = i;
        return;
      }
      views[i] = {xy.data() + 2 * static_cast<std::size_t>(offsets[i]),
                  offsets[i + 1] - offsets[i]};
    }
  });
  if (decreasing < count)
    return {StatusCode::InvalidArgument,
            "polyline offsets must not decrease (offset " + std::to_string(decreasing + 1) + ")",
            decreasing};
  std::vector<std::uint32_t> scratch;
  std::uint32_t* ids = idsFor(vertexIds, points, scratch);
  const std::size_t before = polylineCount();
  return recordInsertion(*state_, insertPolylineBatch(views.data(), count, ids, values, &xy), ids,
                         points, kPolylineVertex, before, views.data());
}

Status Triangulation::insertPolylineBatch(const PolylineView* polylines, std::size_t count,
                                          std::uint32_t* vertexIds, const double* values,
                                          std::vector<double>* adopt) {
  std::size_t total = 0;
  const Status checked = checkPolylines(polylines, count, total);
  if (!checked.ok()) return checked;
  Delaunay& d = state_->delaunay;
  const Status s = catchOutOfMemory(
      [&] {
        std::vector<std::uint32_t> scratch;
        std::uint32_t* ids = vertexIds;
        if (ids == nullptr) {
          scratch.resize(total);
          ids = scratch.data();
        }
        const std::uint32_t firstNew = d.vertexCount();
        // All points first, in one spatially sorted batch.
        Status inserted;
        if (adopt) {
          inserted = insertCheckedPoints(adopt->data(), total, ids, values, adopt);
        } else if (count == 1) {
          inserted = insertCheckedPoints(polylines[0].xy, polylines[0].count, ids, values);
        } else {
          std::vector<double> all;
          all.reserve(2 * total);
          for (std::size_t i = 0; i < count; ++i)
            all.insert(all.end(), polylines[i].xy, polylines[i].xy + 2 * polylines[i].count);
          inserted = insertCheckedPoints(all.data(), total, ids, values);
        }
        if (!inserted.ok()) return inserted;
        state_->values.recordPolylinePoints(ids, total);
        state_->changed();
        // Then their segments.
        reserveStore(d.constraints, total, count, d.vertexCount());
        return BatchSegments(d, state_->options, total, firstNew).insert(polylines, count, ids);
      },
      [&] { state_->clear(); });
  if (!s.ok()) return s;
  return insertPendingSegments(d, state_->options);
}

}  // namespace geocdt
