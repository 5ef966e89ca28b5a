#pragma once
// A flat hash map from an undirected edge key to a value: open addressing with linear
// probing in one array of entries, no allocation per entry. The constraint store keeps one entry
// per constrained edge, hundreds of thousands on real data.
#include <cstdint>
#include <utility>
#include <vector>

#include "base/chunks.h"

namespace geocdt {

// Where a key's probe starts, in [0, capacity), capacity a multiple of 16. A 32-bit hash is
// scaled to the capacity by a multiplication, so that tables need not have power-of-two
// sizes.
inline std::size_t scaled(std::uint64_t hash32, std::size_t n) {
  return static_cast<std::size_t>((hash32 * n) >> 32);
}

// A multiplicative hash, for keys with no useful order.
struct HashedSlot {
  static constexpr bool kAdaptive = false;
  void fit(std::size_t, std::uint64_t) {}
  bool scatter() { return false; }
  std::size_t operator()(std::uint64_t key, std::size_t capacity) const {
    return scaled((key * 0x9E3779B97F4A7C15ull) >> 32, capacity);
  }
};

// For keys (u << 32 | v) of constrained edges, u < v: probes start in the order of u, scaled
// to the table. A polyline's vertices have consecutive ids and the triangles come in
// spatial order, so the edges marked along a polyline, and those looked up triangle by
// triangle at export, touch slots near the last ones, where hashed slots missed the cache
// on almost every edge (bench/EXPERIMENTS.md, C26). Ids crowding some slots (one vertex with
// thousands of edges, ids far past the bound) make long probe runs: when the inserts into a
// table have probed more than kMeanRun slots each on average, it turns to hashed slots for
// good, so a table never costs more than a few times what a hashed one would. Refinement,
// whose new vertices take ids far past the bound, turns it at its start (scatter()): those
// ids wrapped onto the full low slots, where probe runs grew long (bench/EXPERIMENTS.md,
// R11).
struct EdgeSlot {
  static constexpr bool kAdaptive = true;
  std::uint64_t scale = 1 << 16;  // slots per vertex id, 16.16 fixed point
  bool hashed = false;

  // The scale for ids below idBound (0: unknown, keep it) in a table of capacity slots.
  void fit(std::size_t capacity, std::uint64_t idBound) {
    if (idBound == 0) return;
    const std::uint64_t s = (static_cast<std::uint64_t>(capacity) << 16) / idBound;
    scale = s < 1 ? 1 : s > (1ull << 31) ? 1ull << 31 : s;
  }
  // Turns to hashed slots; false when already there.
  bool scatter() {
    const bool was = hashed;
    hashed = true;
    return !was;
  }
  std::size_t operator()(std::uint64_t key, std::size_t capacity) const {
    if (hashed) return HashedSlot()(key, capacity);
    const std::uint64_t u = key >> 32;
    const std::size_t s = static_cast<std::size_t>((u * scale) >> 16);
    return s < capacity ? s : s % capacity;
  }
};

template <typename Value, typename Slot = HashedSlot>
class EdgeMap {
 public:
  static constexpr std::uint64_t kEmpty = ~0ull;

  std::size_t size() const { return size_; }

  Value* find(std::uint64_t key) {
    if (entries_.empty()) return nullptr;
    for (std::size_t i = slot(key);; i = after(i)) {
      if (entries_[i].key == key) return &entries_[i].value;
      if (entries_[i].key == kEmpty) return nullptr;
    }
  }
  const Value* find(std::uint64_t key) const { return const_cast<EdgeMap*>(this)->find(key); }

  // Reads the first slot each key probes, so that finds of the same keys right after hit the
  // cache: the independent loads of this plain loop overlap their misses, where a find's
  // probe loop waits for each in turn (and WebAssembly has no prefetch instruction).
  std::uint64_t touch(const std::uint64_t* keys, std::size_t n) const {
    if (entries_.empty()) return 0;
    std::uint64_t any = 0;
    for (std::size_t k = 0; k < n; ++k) any |= entries_[slot(keys[k])].key;
    return any;  // for the caller to keep (in a volatile), so that the loads are
  }

  // The value at key, and whether it was inserted (with value) rather than found.
  std::pair<Value*, bool> insert(std::uint64_t key, const Value& value) {
    if (full(size_ + 1)) grow(2 * entries_.size());
    ++inserts_;
    for (std::size_t i = slot(key);; i = after(i), ++probes_) {
      Entry& at = entries_[i];
      if (at.key == key) return {&at.value, false};
      if (at.key == kEmpty) {
        at = {key, value};
        ++size_;
        if (Slot::kAdaptive && probes_ > kMeanRun * inserts_ + 4096 && slot_.scatter()) {
          grow(entries_.size());  // the same size, hashed
          return {find(key), true};
        }
        return {&at.value, true};
      }
    }
  }

  // Removes key, shifting later entries of its probe run back so no tombstone is needed.
  void erase(std::uint64_t key) {
    if (entries_.empty()) return;
    std::size_t i = slot(key);
    while (entries_[i].key != key) {
      if (entries_[i].key == kEmpty) return;
      i = after(i);
    }
    for (std::size_t j = after(i); entries_[j].key != kEmpty; j = after(j)) {
      const std::size_t home = slot(entries_[j].key);
      // Move j back to i when i lies on the way from j's home slot to j.
      if (distance(home, j) >= distance(i, j)) {
        entries_[i] = entries_[j];
        i = j;
      }
    }
    entries_[i].key = kEmpty;
    --size_;
  }

  // Room for n entries, n an upper bound (up to 3/4 full for it): one table at its final
  // size, where growing step by step holds two at the end (the old and the new).
  void reserve(std::size_t n) {
    const std::size_t capacity = (n + n / 3 + 16) / 16 * 16;
    if (capacity > entries_.size()) grow(capacity);
  }

  // The key order for slots that keep one (EdgeSlot): ids up to about idBound, from the
  // next time the table is sized.
  void orderIds(std::uint64_t idBound) { idBound_ = idBound; }
  // Turns the slots to hashed ones for good (EdgeSlot), laying the table out again.
  void scatter() {
    if constexpr (Slot::kAdaptive)
      if (slot_.scatter()) grow(entries_.size());
  }
  // Whether long probe runs turned the slots to hashed ones (EdgeSlot).
  bool scattered() const {
    if constexpr (Slot::kAdaptive) return slot_.hashed;
    return false;
  }

  // f(key, value) for every entry, in no useful order.
  template <typename F>
  void forEach(F&& f) const {
    for (const Entry& e : entries_)
      if (e.key != kEmpty) f(e.key, e.value);
  }

  void clear() {
    entries_.clear();
    size_ = inserts_ = probes_ = 0;
    slot_ = Slot();
  }

 private:
  static constexpr std::size_t kMeanRun = 16;

  std::size_t slot(std::uint64_t key) const { return slot_(key, entries_.size()); }
  std::size_t after(std::size_t i) const { return i + 1 == entries_.size() ? 0 : i + 1; }
  // Slots from i forward to j, wrapping around the end.
  std::size_t distance(std::size_t i, std::size_t j) const {
    return j >= i ? j - i : j + entries_.size() - i;
  }

  // Up to four fifths full. Reserved tables start at most three quarters full, where a
  // power-of-two size left real data's tables half empty (NE 10m rings: 473,772 edges in
  // 2^20 slots).
  bool full(std::size_t n) const { return 5 * n > 4 * entries_.size(); }

  void grow(std::size_t capacity) {
    std::vector<Entry> entries(capacity < 64 ? 64 : capacity, Entry{kEmpty, Value{}});
    entries.swap(entries_);
    slot_.fit(entries_.size(), idBound_);
    size_ = 0;
    forChunks(0, entries.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        if (entries[i].key != kEmpty) insert(entries[i].key, entries[i].value);
    });
    inserts_ = probes_ = 0;  // a new table
  }

  // Key and value side by side: a lookup on a table far larger than the caches (the
  // constraint store's, at export) misses once, not once in each of two arrays.
  struct Entry {
    std::uint64_t key;
    Value value;
  };
  std::vector<Entry> entries_;
  Slot slot_;
  std::uint64_t idBound_ = 0;
  std::size_t inserts_ = 0, probes_ = 0;  // since the table was sized
  std::size_t size_ = 0;
};

}  // namespace geocdt
