// Triangulation's constraint API: polylines in, their points as one batch, then their
// segments one by one through the SegmentInserter.
#include <algorithm>
#include <cmath>
#include <new>
#include <string>

#include "base/chunks.h"
#include "constraints/chain_check.h"
#include "constraints/present_segments.h"
#include "constraints/segment_inserter.h"
#include "constraints/snap_rounding.h"
#include "delaunay/vertex_edges.h"
#include "geocdt/triangulation.h"
#include "invalid_coordinate.h"
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
  Status checked;
  // In a chunk, not a loop of this function: compiled to wasm, the rest of the function came
  // to lie inside that loop, and V8 charges its budget for optimised code by the bytes from a
  // loop's start to its back edge (bench/EXPERIMENTS.md, first call 21).
  forChunks(0, count, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last && checked.ok(); ++i) {
      checked = checkPolyline(polylines[i], i);
      total += polylines[i].count;
    }
  });
  if (!checked.ok()) return checked;
  Delaunay& d = state_->delaunay;
  ConstraintStore& store = d.constraints;
  try {
    std::vector<std::uint32_t> scratch;
    std::uint32_t* ids = vertexIds;
    if (ids == nullptr) {
      scratch.resize(total);
      ids = scratch.data();
    }
    const std::uint32_t firstNew = d.vertexCount();
    // All points first, in one spatially sorted batch.
    Status s;
    if (adopt) {
      s = insertCheckedPoints(adopt->data(), total, ids, values, adopt);
    } else if (count == 1) {
      s = insertCheckedPoints(polylines[0].xy, polylines[0].count, ids, values);
    } else {
      std::vector<double> all;
      all.reserve(2 * total);
      for (std::size_t i = 0; i < count; ++i)
        all.insert(all.end(), polylines[i].xy, polylines[i].xy + 2 * polylines[i].count);
      s = insertCheckedPoints(all.data(), total, ids, values);
    }
    if (!s.ok()) return s;
    state_->values.recordPolylinePoints(ids, total);
    state_->changed();
    // At most one segment and one constrained edge a point (fewer where polylines share
    // edges): the store's arrays and table at about their final sizes at once, not doubled
    // on the way.
    store.reserve(store.edgeCount() + total, d.vertexCount());
    store.segments.reserve(store.segments.size() + total);
    store.segmentStarts.reserve(store.segmentStarts.size() + total);
    store.firstSegment.reserve(store.firstSegment.size() + count);
    store.ring.reserve(store.ring.size() + count);

    VertexEdges ends = endsFor(d, total);
    SegmentInserter inserter(d, ends);
    const Progress& progress = d.options().progress;
    std::size_t segmentsTried = 0;
    const std::uint32_t keep = d.vertexCount();  // crossings come after
    // Whether snap rounding takes over the segments.
    bool snap = state_->options.snapRounding == SnapRounding::Always && d.built();
    // A large batch marks the segments that are edges already (found in one pass) in a first
    // round, and inserts the others (kept in `later`) in a second: those may cross the first
    // ones, which are then all in the store, as a crossed constraint must be.
    const bool twoRounds = ends.built() && !snap;
    std::vector<PendingSegment> later;
    PresentSegments present(firstNew, twoRounds ? keep : firstNew);
    // The loops over polylines call a function per polyline (a chunk of 1), and the second
    // round one per chunk of segments: this function runs once a call, and its own loops
    // would spend the engine's budget for optimised code on it, whose long compile only took
    // a core from a first call (chunks.h; bench/EXPERIMENTS.md, first call 21).
    if (twoRounds) {
      std::size_t at = 0;
      forChunks(
          0, count,
          [&](std::size_t first, std::size_t last) {
            for (std::size_t i = first; i < last; ++i) {
              for (std::size_t k = 0; k + 1 < polylines[i].count; ++k)
                present.expect(ids[at + k], ids[at + k + 1]);
              at += polylines[i].count;
            }
          },
          1);
      present.fixPresent(d.topo);
    }
    const std::size_t span = twoRounds ? 2 * total : total;  // progress: the rounds in turn
    std::size_t offset = 0;
    Status broken;
    forChunks(
        0, count,
        [&](std::size_t first, std::size_t last) {
          for (std::size_t i = first; i < last && broken.ok(); ++i) {
            const PolylineView& line = polylines[i];  // its count only: the points are in
            const std::uint32_t* lineIds = ids + offset;
            offset += line.count;
            const std::uint64_t firstPoint = store.polylinePoints;
            store.polylinePoints += line.count;
            const bool ring = line.count >= 3 && lineIds[0] == lineIds[line.count - 1];
            const std::uint32_t id = store.startPolyline(ring);
            ++d.stats.polylines;
            for (std::size_t k = 0; k + 1 < line.count; ++k) {
              if ((++segmentsTried & 255) == 0)
                progress(Phase::Constraints, offset - line.count + k, span);
              const std::uint32_t u = lineIds[k], v = lineIds[k + 1];
              if (u == v) continue;  // a repeated point: nothing to constrain
              EdgeSource src;
              src.segment = static_cast<std::uint32_t>(store.segments.size());
              src.winding = ring ? 1 : 0;
              src.polyline = id;
              store.segments.push_back({u, v});
              store.segmentStarts.push_back(
                  static_cast<std::uint32_t>(std::min<std::uint64_t>(firstPoint + k, kNoSegment)));
              if (!d.built()) {
                store.pending.push_back(
                    {u, v, src, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k)});
                continue;
              }
              if (snap) continue;  // stored: snap rounding inserts it with all the others
              if (twoRounds) {
                if (present.present(u, v)) {
                  store.mark(u, v, src);
                  ++d.stats.segments;
                } else {
                  later.push_back(
                      {u, v, src, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k)});
                }
                continue;
              }
              const Outcome outcome = inserter.insert(u, v, src);
              if (outcome == Outcome::Broken) {
                broken = located(inserter.error(), i, k);
                return;
              }
              snap = outcome == Outcome::GaveUp;
            }
          }
        },
        1);
    if (!broken.ok()) return broken;
    forChunks(0, later.size(), [&](std::size_t first, std::size_t last) {  // the second round
      for (std::size_t j = first; j < last && !snap && broken.ok(); ++j) {
        if ((j & 255) == 255) progress(Phase::Constraints, total + j * total / later.size(), span);
        const PendingSegment& p = later[j];
        const Outcome outcome = inserter.insert(p.u, p.v, p.src);
        if (outcome == Outcome::Broken) broken = located(inserter.error(), p.polyline, p.index);
        snap = outcome == Outcome::GaveUp;
      }
    });
    if (!broken.ok()) return broken;
    std::vector<PendingSegment>().swap(later);
    // Computed crossings stay where every chain that met one keeps the guarantee.
    if (!snap && d.built()) snap = !chainsKeepTheGuarantee(d, inserter.touchedSegments(), ends);
    if (snap) {
      const Status s = snapRoundConstraints(d, keep, state_->options);
      if (!s.ok()) return s;
    }
    progress(Phase::Constraints, total, total);
  } catch (const std::bad_alloc&) {
    d.clear();
    state_->values.clear();
    state_->changed();
    return {StatusCode::OutOfMemory,
            "out of memory: the input is too large for the available memory"};
  }
  return insertPendingSegments(d, state_->options);
}

}  // namespace geocdt
