#include "delaunay/insertion_order.h"

#include <algorithm>

#include "base/chunks.h"

namespace geocdt {

namespace {

// The Hilbert curve's refinement as a state machine: the state is how the current quadrant
// is transformed (bit 0: x and y swapped, bit 1: both mirrored). One table step reads four
// levels (four bits of x and of y) and gives their eight bits of the index and the next
// state, without the data-dependent branch per level of the textbook loop, which
// mispredicts (bench/EXPERIMENTS.md, P4).
struct HilbertTable {
  std::uint16_t entry[4 << 8];  // index (state << 8 | x4 << 4 | y4): digits << 2 | state
};

constexpr HilbertTable makeHilbertTable() {
  HilbertTable t{};
  for (int state = 0; state < 4; ++state)
    for (int x4 = 0; x4 < 16; ++x4)
      for (int y4 = 0; y4 < 16; ++y4) {
        int swapped = state & 1, mirrored = state >> 1, digits = 0;
        for (int level = 3; level >= 0; --level) {
          const int bx = (x4 >> level) & 1, by = (y4 >> level) & 1;
          const int rx = (swapped ? by : bx) ^ mirrored, ry = (swapped ? bx : by) ^ mirrored;
          digits = digits << 2 | ((3 * rx) ^ ry);
          if (ry == 0) {  // the lower quadrants turn: swap, and mirror the right one
            swapped ^= 1;
            mirrored ^= rx;
          }
        }
        t.entry[state << 8 | x4 << 4 | y4] =
            static_cast<std::uint16_t>(digits << 2 | mirrored << 1 | swapped);
      }
  return t;
}

constexpr HilbertTable kHilbert = makeHilbertTable();

}  // namespace

std::uint32_t hilbertIndex(std::uint32_t x, std::uint32_t y, int bits) {
  // At 16 levels, then cut: the cells of a coarser curve are runs of the finer one.
  x <<= 16 - bits;
  y <<= 16 - bits;
  std::uint32_t d = 0, state = 0;
  for (int shift = 12; shift >= 0; shift -= 4) {
    const std::uint32_t e =
        kHilbert.entry[state << 8 | ((x >> shift) & 15) << 4 | ((y >> shift) & 15)];
    d = d << 8 | e >> 2;
    state = e & 3;
  }
  return d >> (2 * (16 - bits));
}

namespace {

// Sorts items (key << 32 | index) by their keys of keyBits bits: an LSD radix sort with
// digits of at most 12 bits, whose 4096 buckets' write positions stay in the cache.
void sortByKey(std::vector<std::uint64_t>& items, int keyBits) {
  const std::size_t n = items.size();
  if (n < 2048) {
    std::sort(items.begin(), items.end());
    return;
  }
  const int passes = (keyBits + 11) / 12;
  const int digit = (keyBits + passes - 1) / passes;
  const std::size_t buckets = std::size_t{1} << digit;
  const std::uint64_t mask = buckets - 1;
  std::vector<std::uint32_t> start(passes * buckets);
  std::uint32_t* counts = start.data();
  forChunks(0, n, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      for (int p = 0; p < passes; ++p)
        ++counts[p * buckets + ((items[i] >> (32 + p * digit)) & mask)];
  });
  for (int p = 0; p < passes; ++p) {
    std::uint32_t sum = 0;
    for (std::size_t b = 0; b < buckets; ++b) {
      const std::uint32_t c = start[p * buckets + b];
      start[p * buckets + b] = sum;
      sum += c;
    }
  }
  std::vector<std::uint64_t> scratch(n);
  for (int p = 0; p < passes; ++p) {
    std::uint32_t* next = start.data() + p * buckets;
    const std::uint64_t* from = items.data();
    std::uint64_t* to = scratch.data();
    const int shift = 32 + p * digit;
    forChunks(0, n, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) to[next[(from[i] >> shift) & mask]++] = from[i];
    });
    items.swap(scratch);
  }
}

std::uint32_t toCell(double v, double min, double scale, double top) {
  const double c = (v - min) * scale;
  if (!(c > 0)) return 0;
  return c >= top ? static_cast<std::uint32_t>(top) : static_cast<std::uint32_t>(c);
}

}  // namespace

Bounds boundsOf(const double* xy, std::uint32_t count) {
  Bounds b{xy[0], xy[1], xy[0], xy[1]};
  forChunks(1, count, [&](std::size_t begin, std::size_t end) {
    Bounds c = b;
    for (std::size_t i = begin; i < end; ++i) {
      c.minX = std::min(c.minX, xy[2 * i]);
      c.maxX = std::max(c.maxX, xy[2 * i]);
      c.minY = std::min(c.minY, xy[2 * i + 1]);
      c.maxY = std::max(c.maxY, xy[2 * i + 1]);
    }
    b = c;
  });
  return b;
}

std::vector<std::uint32_t> insertionOrder(const double* xy, std::uint32_t count,
                                          InsertionOrder order) {
  return insertionOrder(xy, nullptr, count, order);
}

std::vector<std::uint32_t> insertionOrder(const double* xy, const std::uint32_t* subset,
                                          std::uint32_t count, InsertionOrder order) {
  const auto at = [subset](std::size_t i) -> std::size_t { return subset ? subset[i] : i; };
  if (order == InsertionOrder::Input || count < 3) {
    std::vector<std::uint32_t> ids(count);
    for (std::uint32_t i = 0; i < count; ++i) ids[i] = static_cast<std::uint32_t>(at(i));
    return ids;
  }

  Bounds box{xy[2 * at(0)], xy[2 * at(0) + 1], xy[2 * at(0)], xy[2 * at(0) + 1]};
  if (subset) {
    forChunks(1, count, [&](std::size_t begin, std::size_t end) {
      Bounds c = box;
      for (std::size_t i = begin; i < end; ++i) {
        const double x = xy[2 * at(i)], y = xy[2 * at(i) + 1];
        c.minX = std::min(c.minX, x);
        c.maxX = std::max(c.maxX, x);
        c.minY = std::min(c.minY, y);
        c.maxY = std::max(c.maxY, y);
      }
      box = c;
    });
  } else {
    box = boundsOf(xy, count);
  }
  const double minX = box.minX, minY = box.minY, maxX = box.maxX, maxY = box.maxY;
  // The finest curve the key holds (BRIO keeps 4 bits for the round): clustered points
  // need cells much smaller than the average spacing, and uniform and real data lose
  // nothing (bench/EXPERIMENTS.md, P8). One scale for both axes keeps the cells square.
  const int bits = order == InsertionOrder::Brio ? 14 : 16;
  const double top = static_cast<double>((1u << bits) - 1);
  const double extent = std::max(maxX - minX, maxY - minY);
  const double scale = extent > 0 ? top / extent : 0.0;

  // Brio: rounds of 8 times the size, the last about 7/8 of the points, each point's
  // round drawn from a hash of its index (reproducible, and no shuffle's random memory
  // accesses). The round goes above the Hilbert key, so that one sort orders both.
  int lastRound = 0;
  if (order == InsertionOrder::Brio)
    while (lastRound < 15 && (std::uint64_t{count} >> (3 * (lastRound + 1))) >= 64) ++lastRound;
  std::vector<std::uint64_t> items(count);
  std::uint64_t* item = items.data();
  forChunks(0, count, [=](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t v = at(i);
      const std::uint64_t key = hilbertIndex(toCell(xy[2 * v], minX, scale, top),
                                             toCell(xy[2 * v + 1], minY, scale, top), bits);
      int round = lastRound;  // earlier with probability 1/8 per round
      if (round > 0) {
        std::uint64_t h = (i + 1) * 0x9E3779B97F4A7C15ull;  // splitmix64's finaliser
        h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
        h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
        h ^= h >> 31;
        for (; round > 0 && (h & 7) == 0; h >>= 3) --round;
      }
      item[i] = (static_cast<std::uint64_t>(round) << (2 * bits) | key) << 32 | i;
    }
  });
  int roundBits = 0;
  while ((1 << roundBits) <= lastRound) ++roundBits;
  sortByKey(items, 2 * bits + roundBits);
  std::vector<std::uint32_t> ids(count);
  forChunks(0, count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      ids[i] = static_cast<std::uint32_t>(at(static_cast<std::uint32_t>(items[i])));
  });
  return ids;
}

}  // namespace geocdt
