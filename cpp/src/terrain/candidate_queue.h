#pragma once
// The items waiting to be split (triangles by slot, border segments by index), largest error
// first: a binary max-heap that knows where each item sits, so that an item whose error
// changes moves in place instead of leaving a stale entry behind. Only items whose error
// exceeds the bound are in it: the others would never be split.
#include <cstdint>
#include <vector>

namespace geocdt::terrain {

class CandidateQueue {
 public:
  bool empty() const { return heap_.empty(); }
  std::size_t size() const { return heap_.size(); }
  std::uint32_t top() const { return heap_[0].item; }
  double topError() const { return heap_[0].error; }

  // Puts item in the queue with this error, or moves it there if it is in already.
  void set(std::uint32_t item, double error) {
    if (item >= position_.size()) position_.resize(item + item / 2 + 16, kAbsent);
    std::uint32_t at = position_[item];
    if (at == kAbsent) {
      at = static_cast<std::uint32_t>(heap_.size());
      heap_.push_back({error, item});
      position_[item] = at;
      up(at);
      return;
    }
    const double before = heap_[at].error;
    heap_[at].error = error;
    if (error > before) {
      up(at);
    } else {
      down(at);
    }
  }

  void remove(std::uint32_t item) {
    if (item >= position_.size() || position_[item] == kAbsent) return;
    const std::uint32_t at = position_[item];
    position_[item] = kAbsent;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (at == heap_.size()) return;
    heap_[at] = last;
    position_[last.item] = at;
    if (at > 0 && heap_[(at - 1) / 2].error < last.error) {
      up(at);
    } else {
      down(at);
    }
  }

  void clear() {
    heap_.clear();
    position_.clear();
  }

 private:
  static constexpr std::uint32_t kAbsent = 0xFFFFFFFFu;
  struct Entry {
    double error;
    std::uint32_t item;
  };

  void up(std::uint32_t at) {
    const Entry e = heap_[at];
    while (at > 0) {
      const std::uint32_t parent = (at - 1) / 2;
      if (!(heap_[parent].error < e.error)) break;
      heap_[at] = heap_[parent];
      position_[heap_[at].item] = at;
      at = parent;
    }
    heap_[at] = e;
    position_[e.item] = at;
  }

  void down(std::uint32_t at) {
    const Entry e = heap_[at];
    const auto n = static_cast<std::uint32_t>(heap_.size());
    for (;;) {
      std::uint32_t child = 2 * at + 1;
      if (child >= n) break;
      if (child + 1 < n && heap_[child].error < heap_[child + 1].error) ++child;
      if (!(e.error < heap_[child].error)) break;
      heap_[at] = heap_[child];
      position_[heap_[at].item] = at;
      at = child;
    }
    heap_[at] = e;
    position_[e.item] = at;
  }

  std::vector<Entry> heap_;
  std::vector<std::uint32_t> position_;  // per item: its index in heap_, or kAbsent
};

}  // namespace geocdt::terrain
