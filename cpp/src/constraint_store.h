#pragma once
// Which input polylines each constrained edge came from. Keyed by the undirected vertex
// pair, so it survives the flips and re-triangulations that move half-edges around.
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace geocdt {

class ConstraintStore {
 public:
  static std::uint64_t key(std::uint32_t u, std::uint32_t v) {
    if (u > v) std::swap(u, v);
    return static_cast<std::uint64_t>(u) << 32 | v;
  }

  // Records that edge u-v carries polyline p (once per polyline).
  void add(std::uint32_t u, std::uint32_t v, std::uint32_t p) {
    std::vector<std::uint32_t>& list = sources_[key(u, v)];
    for (const std::uint32_t q : list)
      if (q == p) return;
    list.push_back(p);
  }

  // An edge u-v split at w: both halves carry what u-v carried.
  void split(std::uint32_t u, std::uint32_t v, std::uint32_t w) {
    const auto it = sources_.find(key(u, v));
    if (it == sources_.end()) return;
    std::vector<std::uint32_t> list = std::move(it->second);
    sources_.erase(it);
    for (const std::uint32_t p : list) {
      add(u, w, p);
      add(w, v, p);
    }
  }

  const std::vector<std::uint32_t>* find(std::uint32_t u, std::uint32_t v) const {
    const auto it = sources_.find(key(u, v));
    return it == sources_.end() ? nullptr : &it->second;
  }

  std::uint32_t polylineCount = 0;
  std::vector<std::uint8_t> isRing;  // per polyline: closed (last point equals first)

  void clear() {
    sources_.clear();
    polylineCount = 0;
    isRing.clear();
  }
  std::size_t edgeCount() const { return sources_.size(); }

 private:
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> sources_;
};

}  // namespace geocdt
