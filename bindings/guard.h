#pragma once
// The core reports bad input as Status values; only memory exhaustion arrives as an
// exception (std::bad_alloc from a vector that cannot grow past wasm32's 4 GB). It is
// caught here, at the boundary, so the module never aborts and stays usable.
#include <new>
#include <stdexcept>

#include "output.h"

namespace geocdt::wasm {

inline void setOutOfMemory(Output& out, const char* what) {
  out.clear();
  out.status.code = StatusCode::OutOfMemory;
  out.status.message = what;
}

// Runs f(), which returns a Status, and stores that status in out.
template <typename F>
bool guarded(Output& out, F&& f, const char* outOfMemoryMessage) {
  try {
    out.status = f();
  } catch (const std::bad_alloc&) {
    setOutOfMemory(out, outOfMemoryMessage);
  } catch (const std::length_error&) {
    setOutOfMemory(out, outOfMemoryMessage);
  }
  return out.status.ok();
}

}  // namespace geocdt::wasm
