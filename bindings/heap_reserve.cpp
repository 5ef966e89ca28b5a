#include "heap_reserve.h"

#include <emscripten/heap.h>
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

// heap_grow.js: grows the memory to `bytes` exactly (1), or leaves it as it is (0).
extern "C" int geocdt_grow_heap_to(std::size_t bytes);

namespace geocdt::wasm {

void reserveHeap(double more) {
  // wasm32's largest memory, 4 GB less one page. mallinfo's counts are ints: read as unsigned
  // (allocatedBytes() in module.cpp).
  constexpr double kLargest = 4294967296.0 - 65536.0;
  // The end of the allocator's region less what is free in it: the bytes in use, the static
  // data and the stack below the region included.
  const struct mallinfo m = mallinfo();
  const double used = static_cast<double>(reinterpret_cast<std::uintptr_t>(sbrk(0))) -
                      static_cast<unsigned>(m.fordblks);
  const double want = std::min(used + more, kLargest);
  // Not emscripten_resize_heap(): it would double the memory for a call that needs less.
  if (want > static_cast<double>(emscripten_get_heap_size()))
    geocdt_grow_heap_to(static_cast<std::size_t>(want));
}

}  // namespace geocdt::wasm
