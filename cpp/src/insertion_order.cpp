#include "insertion_order.h"

#include <algorithm>
#include <numeric>

namespace geocdt {

std::uint32_t hilbertIndex(std::uint32_t x, std::uint32_t y, int bits) {
  std::uint32_t d = 0;
  const std::uint32_t mask = (1u << bits) - 1;
  for (std::uint32_t s = 1u << (bits - 1); s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0;
    const std::uint32_t ry = (y & s) ? 1 : 0;
    d += s * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant so that the curve stays continuous
      if (rx == 1) {
        x = mask - x;
        y = mask - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

namespace {

// Sorts ids[begin, end) by their Hilbert keys with a two-pass 16-bit radix sort.
void sortByKey(std::vector<std::uint64_t>& items, std::vector<std::uint64_t>& scratch,
               std::size_t begin, std::size_t end) {
  // Below a few thousand items the radix passes' 64k-entry tables cost more than they save.
  if (end - begin < 4096) {
    std::sort(items.begin() + static_cast<std::ptrdiff_t>(begin),
              items.begin() + static_cast<std::ptrdiff_t>(end));
    return;
  }
  std::vector<std::uint32_t> count(1u << 16);
  for (int pass = 0; pass < 2; ++pass) {
    const int shift = 32 + 16 * pass;
    std::fill(count.begin(), count.end(), 0);
    for (std::size_t i = begin; i < end; ++i) ++count[(items[i] >> shift) & 0xFFFF];
    std::uint32_t sum = static_cast<std::uint32_t>(begin);
    for (auto& c : count) {
      const std::uint32_t n = c;
      c = sum;
      sum += n;
    }
    for (std::size_t i = begin; i < end; ++i)
      scratch[count[(items[i] >> shift) & 0xFFFF]++] = items[i];
    std::copy(scratch.begin() + begin, scratch.begin() + end, items.begin() + begin);
  }
}

std::uint32_t toCell(double v, double min, double scale, double top) {
  const double c = (v - min) * scale;
  if (!(c > 0)) return 0;
  return c >= top ? static_cast<std::uint32_t>(top) : static_cast<std::uint32_t>(c);
}

}  // namespace

std::vector<std::uint32_t> insertionOrder(const double* xy, std::uint32_t count,
                                          InsertionOrder order) {
  std::vector<std::uint32_t> ids(count);
  std::iota(ids.begin(), ids.end(), 0u);
  if (order == InsertionOrder::Input || count < 3) return ids;

  double minX = xy[0], minY = xy[1], maxX = xy[0], maxY = xy[1];
  for (std::uint32_t i = 1; i < count; ++i) {
    minX = std::min(minX, xy[2 * i]);
    maxX = std::max(maxX, xy[2 * i]);
    minY = std::min(minY, xy[2 * i + 1]);
    maxY = std::max(maxY, xy[2 * i + 1]);
  }
  // About one point per cell is fine enough: a coarser curve is cheaper to compute and
  // sorts in the same two radix passes. One scale for both axes keeps the cells square.
  int bits = 4;
  while (bits < 16 && (1ull << (2 * bits)) < 4ull * count) ++bits;
  if (order == InsertionOrder::Brio) bits = std::min(bits, 14);  // 4 bits for the round
  const double top = static_cast<double>((1u << bits) - 1);
  const double extent = std::max(maxX - minX, maxY - minY);
  const double scale = extent > 0 ? top / extent : 0.0;

  // Brio: rounds of 8 times the size, the last about 7/8 of the points, each point's
  // round drawn from a hash of its index (reproducible, and no shuffle's random memory
  // accesses). The round goes above the Hilbert key, so that one sort orders both.
  int lastRound = 0;
  if (order == InsertionOrder::Brio)
    while (lastRound < 15 && (std::uint64_t{count} >> (3 * (lastRound + 1))) >= 64) ++lastRound;
  std::vector<std::uint64_t> items(count), scratch(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint64_t key = hilbertIndex(toCell(xy[2 * i], minX, scale, top),
                                           toCell(xy[2 * i + 1], minY, scale, top), bits);
    int round = lastRound;  // earlier with probability 1/8 per round
    if (round > 0) {
      std::uint64_t h = (i + 1) * 0x9E3779B97F4A7C15ull;  // splitmix64's finaliser
      h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
      h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
      h ^= h >> 31;
      for (; round > 0 && (h & 7) == 0; h >>= 3) --round;
    }
    items[i] = (static_cast<std::uint64_t>(round) << (2 * bits) | key) << 32 | i;
  }
  sortByKey(items, scratch, 0, count);
  for (std::uint32_t i = 0; i < count; ++i) ids[i] = static_cast<std::uint32_t>(items[i]);
  return ids;
}

}  // namespace geocdt
