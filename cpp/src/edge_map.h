#pragma once
// A flat hash map from an undirected edge key to a value: open addressing with linear
// probing in two arrays, no allocation per entry. The constraint store keeps one entry per
// constrained edge, hundreds of thousands on real data.
#include <cstdint>
#include <utility>
#include <vector>

#include "chunks.h"

namespace geocdt {

// Where a key's probe starts: a multiplicative hash, for keys with no useful order.
struct HashedSlot {
  std::size_t operator()(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32);
  }
};

// For keys (u << 32 | v) of edges with u < v: edges between nearby vertex ids start their
// probes in nearby slots, so that a run of edges along a polyline (whose vertices are
// numbered in input order) touches a few cache lines instead of one each. The ids are hashed
// in blocks of 8 (u's block and v's), which spreads the edges of one vertex to many others
// (a hub) and ids far apart; within a block, u picks a pair of slots.
struct EdgeSlot {
  std::size_t operator()(std::uint64_t key) const {
    const std::uint64_t u = key >> 32, v = key & 0xFFFFFFFFu;
    const std::uint64_t block =
        ((u >> 3) * 0x9E3779B97F4A7C15ull) ^ ((v >> 3) * 0xC2B2AE3D27D4EB4Full);
    return static_cast<std::size_t>((block >> 32) << 4 | (u & 7) << 1);
  }
};

template <typename Value, typename Slot = HashedSlot>
class EdgeMap {
 public:
  static constexpr std::uint64_t kEmpty = ~0ull;

  std::size_t size() const { return size_; }

  Value* find(std::uint64_t key) {
    if (keys_.empty()) return nullptr;
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return &values_[i];
      if (keys_[i] == kEmpty) return nullptr;
    }
  }
  const Value* find(std::uint64_t key) const { return const_cast<EdgeMap*>(this)->find(key); }

  // The value at key, and whether it was inserted (with value) rather than found.
  std::pair<Value*, bool> insert(std::uint64_t key, const Value& value) {
    if (full(size_ + 1)) grow(2 * keys_.size());
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return {&values_[i], false};
      if (keys_[i] == kEmpty) {
        keys_[i] = key;
        values_[i] = value;
        ++size_;
        return {&values_[i], true};
      }
    }
  }

  // Removes key, shifting later entries of its probe run back so no tombstone is needed.
  void erase(std::uint64_t key) {
    if (keys_.empty()) return;
    std::size_t i = slot(key);
    while (keys_[i] != key) {
      if (keys_[i] == kEmpty) return;
      i = (i + 1) & mask_;
    }
    for (std::size_t j = (i + 1) & mask_; keys_[j] != kEmpty; j = (j + 1) & mask_) {
      const std::size_t home = slot(keys_[j]);
      // Move j back to i when i lies on the way from j's home slot to j.
      if (((j - home) & mask_) >= ((j - i) & mask_)) {
        keys_[i] = keys_[j];
        values_[i] = values_[j];
        i = j;
      }
    }
    keys_[i] = kEmpty;
    --size_;
  }

  // Room for about n entries, n an upper bound (up to 7/8 full for it): one table at its final
  // size, where growing step by step holds two at the end (the old and the new).
  void reserve(std::size_t n) {
    std::size_t capacity = keys_.empty() ? 64 : keys_.size();
    while (8 * n > 7 * capacity) capacity *= 2;
    if (capacity > keys_.size()) grow(capacity);
  }

  void clear() {
    keys_.clear();
    values_.clear();
    size_ = 0;
    mask_ = 0;
  }

 private:
  std::size_t slot(std::uint64_t key) const { return Slot()(key) & mask_; }

  // Up to three quarters full: half the memory of a half-full table for the same
  // entries at the sizes of real data (NE 10m: 2^20 slots instead of 2^21), for probes a
  // little longer.
  bool full(std::size_t n) const { return 4 * n > 3 * keys_.size(); }

  void grow(std::size_t capacity) {
    std::vector<std::uint64_t> keys(capacity < 64 ? 64 : capacity, kEmpty);
    std::vector<Value> values(keys.size());
    keys.swap(keys_);
    values.swap(values_);
    mask_ = keys_.size() - 1;
    size_ = 0;
    forChunks(0, keys.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        if (keys[i] != kEmpty) insert(keys[i], values[i]);
    });
  }

  std::vector<std::uint64_t> keys_;
  std::vector<Value> values_;
  std::size_t size_ = 0, mask_ = 0;
};

}  // namespace geocdt
