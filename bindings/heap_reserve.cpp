#include "heap_reserve.h"

#include <emscripten/heap.h>
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>

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
  if (want > static_cast<double>(emscripten_get_heap_size()))
    emscripten_resize_heap(static_cast<std::size_t>(want));
}

}  // namespace geocdt::wasm
