#pragma once
// The core reports bad input as Status values; only memory exhaustion arrives as an exception
// (std::bad_alloc from a vector that cannot grow past wasm32's 4 GB). The binding's own
// allocations run through the core's catchOutOfMemory too, so the module never aborts and
// stays usable.
#include <utility>

#include "out_of_memory.h"
#include "output.h"

namespace geocdt::wasm {

// Runs f(), which returns a Status, and stores that status in out; out of memory, out holds
// no arrays and the status carries outOfMemoryMessage.
template <typename F>
bool guarded(Output& out, F&& f, const char* outOfMemoryMessage) {
  out.status = catchOutOfMemory(
      std::forward<F>(f), [&] { out.clear(); }, outOfMemoryMessage);
  return out.status.ok();
}

}  // namespace geocdt::wasm
