#pragma once
// The items waiting to be split (triangles by slot, border segments by index), the lowest rank
// first and the largest error first within a rank. Each rank (a tile, once the mesher orders
// by tiles; all 0 before) has a binary max-heap of its own, small and warm while its tile is
// meshed, and every item knows where it sits, so that an item whose error changes moves in
// place instead of leaving a stale entry behind. Only items whose error exceeds the bound are
// in it: the others would never be split.
#include <cstdint>
#include <vector>

namespace geocdt::terrain {

class CandidateQueue {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  std::uint32_t top() const { return heaps_[first_][0].item; }
  double topError() const { return heaps_[first_][0].error; }
  std::uint32_t topRank() const { return first_; }

  // Puts item in the queue with this error and rank, or moves it there if it is in already.
  void set(std::uint32_t item, double error, std::uint32_t rank = 0) {
    fit(item);
    if (position_[item] != kAbsent && rank_[item] != rank) remove(item);
    const std::uint32_t at = position_[item];
    if (at == kAbsent) {
      push(item, error, rank);
      return;
    }
    std::vector<Entry>& heap = heaps_[rank];
    const double before = heap[at].error;
    heap[at].error = error;
    if (error > before) {
      up(heap, at);
    } else {
      down(heap, at);
    }
  }

  void remove(std::uint32_t item) {
    if (item >= position_.size() || position_[item] == kAbsent) return;
    const std::uint32_t at = position_[item], rank = rank_[item];
    position_[item] = kAbsent;
    --size_;
    std::vector<Entry>& heap = heaps_[rank];
    const Entry last = heap.back();
    heap.pop_back();
    if (heap.empty()) {
      filled_[rank / 64] &= ~(std::uint64_t{1} << rank % 64);
      if (rank == first_ && size_ > 0) first_ = nextFilled(rank);
      return;
    }
    if (at == heap.size()) return;
    heap[at] = last;
    position_[last.item] = at;
    if (at > 0 && heap[(at - 1) / 2].error < last.error) {
      up(heap, at);
    } else {
      down(heap, at);
    }
  }

  // Every item's rank anew, from rankOf(item).
  template <class RankOf>
  void rerank(RankOf rankOf) {
    std::vector<Entry> all;
    for (const std::vector<Entry>& heap : heaps_) all.insert(all.end(), heap.begin(), heap.end());
    clear();
    for (const Entry& e : all) push(e.item, e.error, rankOf(e.item));
  }

  void clear() {
    for (std::vector<Entry>& heap : heaps_) heap.clear();
    position_.clear();
    rank_.clear();
    filled_.assign(filled_.size(), 0);
    first_ = 0;
    size_ = 0;
  }

 private:
  static constexpr std::uint32_t kAbsent = 0xFFFFFFFFu;
  struct Entry {
    double error;
    std::uint32_t item;
  };

  // Room for item in the per-item arrays, grown by half again.
  void fit(std::uint32_t item) {
    if (item < position_.size()) return;
    position_.resize(item + item / 2 + 16, kAbsent);
    rank_.resize(position_.size(), 0);
  }

  void push(std::uint32_t item, double error, std::uint32_t rank) {
    fit(item);
    if (rank >= heaps_.size()) {
      heaps_.resize(rank + 1);
      filled_.resize(rank / 64 + 1, 0);
    }
    std::vector<Entry>& heap = heaps_[rank];
    if (heap.empty()) filled_[rank / 64] |= std::uint64_t{1} << rank % 64;
    if (size_ == 0 || rank < first_) first_ = rank;
    ++size_;
    rank_[item] = rank;
    heap.push_back({error, item});
    up(heap, static_cast<std::uint32_t>(heap.size() - 1));
  }

  // The lowest rank above `after` whose heap holds an item; one must.
  std::uint32_t nextFilled(std::uint32_t after) const {
    std::uint32_t rank = after + 1;
    while (filled_[rank / 64] >> rank % 64 == 0) rank = (rank / 64 + 1) * 64;
    std::uint64_t bits = filled_[rank / 64] >> rank % 64;
    while ((bits & 1) == 0) {
      bits >>= 1;
      ++rank;
    }
    return rank;
  }

  void up(std::vector<Entry>& heap, std::uint32_t at) {
    const Entry e = heap[at];
    while (at > 0) {
      const std::uint32_t parent = (at - 1) / 2;
      if (!(heap[parent].error < e.error)) break;
      heap[at] = heap[parent];
      position_[heap[at].item] = at;
      at = parent;
    }
    heap[at] = e;
    position_[e.item] = at;
  }

  void down(std::vector<Entry>& heap, std::uint32_t at) {
    const Entry e = heap[at];
    const auto n = static_cast<std::uint32_t>(heap.size());
    for (;;) {
      std::uint32_t child = 2 * at + 1;
      if (child >= n) break;
      if (child + 1 < n && heap[child].error < heap[child + 1].error) ++child;
      if (!(e.error < heap[child].error)) break;
      heap[at] = heap[child];
      position_[heap[at].item] = at;
      at = child;
    }
    heap[at] = e;
    position_[e.item] = at;
  }

  std::vector<std::vector<Entry>> heaps_;  // per rank
  std::vector<std::uint32_t> position_;    // per item: its index in its rank's heap, or kAbsent
  std::vector<std::uint32_t> rank_;        // per item in the queue: its rank
  std::vector<std::uint64_t> filled_;      // a bit per rank whose heap holds an item
  std::uint32_t first_ = 0;                // the lowest rank whose heap holds an item
  std::size_t size_ = 0;
};

}  // namespace geocdt::terrain
