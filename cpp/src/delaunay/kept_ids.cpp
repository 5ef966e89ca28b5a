// Triangulating vertices that keep their ids, some of them removed: what snap rounding and the
// rebuild of snap-rounded constraints after an edit start from.
#include <cmath>
#include <vector>

#include "delaunay/delaunay.h"
#include "delaunay/insertion_order.h"

namespace geocdt {

Status Delaunay::insertKeepingIds(const double* from, std::uint32_t count) {
  std::vector<std::uint32_t> live;
  live.reserve(count);
  for (std::uint32_t v = 0; v < count; ++v)
    if (!std::isnan(from[2 * static_cast<std::size_t>(v)])) live.push_back(v);
  if (live.size() == count) {  // no gaps: a batch, numbered in input order
    std::vector<std::uint32_t> ids(count);
    const Status s = insertBatch(from, count, ids.data());
    if (!s.ok()) return s;
    for (std::uint32_t i = 0; i < count; ++i)
      if (ids[i] != i) return {StatusCode::InternalError, "a rebuild renumbered a vertex"};
    return s;
  }
  xy.assign(from, from + 2 * static_cast<std::size_t>(count));
  stats.removed = count - live.size();
  if (live.empty()) return Status::success();
  // The live vertices wait in spatial order; the first three not on one line make the first
  // triangle, and the rest go in from the last triangle, as a batch's run does.
  std::vector<double> compact(2 * live.size());
  for (std::size_t k = 0; k < live.size(); ++k) {
    compact[2 * k] = xy[2 * static_cast<std::size_t>(live[k])];
    compact[2 * k + 1] = xy[2 * static_cast<std::size_t>(live[k]) + 1];
  }
  const std::vector<std::uint32_t> order =
      insertionOrder(compact.data(), static_cast<std::uint32_t>(live.size()), options_.order);
  pending_.clear();
  for (const std::uint32_t k : order) pending_.push_back(live[k]);
  batch_ = {vertexCount(), nullptr, nullptr};  // no batch: nothing is a duplicate
  std::array<std::uint32_t, 3> built{kGhost, kGhost, kGhost};
  return insertPending({}, built);
}

}  // namespace geocdt
