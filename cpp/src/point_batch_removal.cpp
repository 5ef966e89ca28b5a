// Triangulation::removePoints: a batch of points, checked whole before anything changes, then
// removed one after the other along a Hilbert curve of their places.
#include <algorithm>
#include <string>
#include <vector>

#include "delaunay/insertion_order.h"
#include "edit_refusals.h"
#include "geocdt/triangulation.h"
#include "out_of_memory.h"
#include "triangulation_state.h"

namespace geocdt {

namespace {

// The first k < count whose id came before in ids (its index in repeat, the earlier one's in
// first), or false. count must stay below 2^32.
bool firstRepeat(const std::uint32_t* ids, std::size_t count, std::size_t& repeat,
                 std::size_t& first) {
  std::vector<std::uint64_t> byId(count);
  for (std::size_t k = 0; k < count; ++k) byId[k] = std::uint64_t{ids[k]} << 32 | k;
  std::sort(byId.begin(), byId.end());
  repeat = count;
  for (std::size_t i = 1; i < count; ++i) {
    const std::size_t k = static_cast<std::uint32_t>(byId[i]);
    if (byId[i] >> 32 != byId[i - 1] >> 32 || k >= repeat) continue;
    repeat = k;  // the group's second: its earliest repeat
    std::size_t j = i - 1;
    while (j > 0 && byId[j - 1] >> 32 == byId[i] >> 32) --j;
    first = static_cast<std::uint32_t>(byId[j]);
  }
  return repeat < count;
}

}  // namespace

Status Triangulation::removePoints(const std::uint32_t* ids, std::size_t count,
                                   std::size_t* removed) {
  const Delaunay& d = state_->delaunay;
  const EditState& edit = state_->edit;
  if (removed) *removed = 0;
  // Every id checked before anything changes; the first bad one in ids' order is named (with
  // its index), whether it names no point now or repeats an earlier one. Then the order.
  std::vector<std::uint32_t> order;
  const Status checked = catchOutOfMemory(
      [&] {
        std::size_t bad = 0;
        while (bad < count && ids[bad] < d.vertexCount() && !d.isRemoved(ids[bad]) &&
               (edit.kind(ids[bad]) & kPointVertex))
          ++bad;
        // Past vertexCount() valid ids, one must repeat: the search stops there.
        std::size_t repeat = 0, first = 0;
        if (firstRepeat(ids, std::min<std::size_t>(bad, d.vertexCount() + std::size_t{1}), repeat,
                        first))
          return invalidEdit("removePoints: ids[" + std::to_string(repeat) + "]: vertex " +
                                 std::to_string(ids[repeat]) + " is also ids[" +
                                 std::to_string(first) + "]",
                             repeat);
        if (bad < count) {
          const std::string call = "removePoints: ids[" + std::to_string(bad) + "]";
          Status s = checkId(d, ids[bad], call.c_str());
          if (s.ok())
            s = invalidEdit(call + ": vertex " + std::to_string(ids[bad]) +
                                " is not a point inserted with insertPoints (it is " +
                                describeVertex(edit, ids[bad]) + ")",
                            bad);
          s.index = bad;
          return s;
        }
        // Along a Hilbert curve of their places: consecutive removals touch nearby memory.
        order = insertionOrder(d.xy.data(), ids, static_cast<std::uint32_t>(count),
                               InsertionOrder::Hilbert);
        return Status::success();
      },
      [] {}, "out of memory while checking the ids of removePoints: nothing changed");
  if (!checked.ok()) return checked;
  for (const std::uint32_t id : order) {
    bool went = false;
    if (const Status s = removePoint(id, &went); !s.ok()) return s;
    if (removed && went) ++*removed;
  }
  return Status::success();
}

}  // namespace geocdt
