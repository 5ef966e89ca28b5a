#pragma once
// The pool the constraint store keeps the extra sources of its edges in (see
// ConstraintStore): lists linked through fixed blocks.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace geocdt {

// One of the extra (polyline, segment) pairs an edge carries (see ConstraintStore).
struct ExtraMember {
  std::uint32_t polyline, segment;
  std::int32_t winding;  // this pair's share of the edge's winding
  std::int32_t next;     // the list's next member, or -1
};

// Members in fixed blocks: growing never moves or copies what is there (a vector would
// double at the heap's peak), so indices and references stay valid.
class ExtraMembers {
 public:
  std::int32_t append(const ExtraMember& m) {
    if ((size_ & kBlockMask) == 0) {
      blocks_.emplace_back();
      blocks_.back().reserve(kBlock);
    }
    blocks_.back().push_back(m);
    return static_cast<std::int32_t>(size_++);
  }
  ExtraMember& operator[](std::int32_t i) { return blocks_[i >> kBlockBits][i & kBlockMask]; }
  const ExtraMember& operator[](std::int32_t i) const {
    return blocks_[i >> kBlockBits][i & kBlockMask];
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear() {
    blocks_.clear();
    size_ = 0;
  }

 private:
  static constexpr int kBlockBits = 12;
  static constexpr std::size_t kBlock = std::size_t{1} << kBlockBits;
  static constexpr std::size_t kBlockMask = kBlock - 1;
  std::vector<std::vector<ExtraMember>> blocks_;
  std::size_t size_ = 0;
};

}  // namespace geocdt
