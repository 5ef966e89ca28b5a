#pragma once
// Memory exhaustion is the one failure that arrives as an exception: std::bad_alloc, or
// std::length_error from a vector asked for more than it can hold (in wasm32, past 4 GB).
// Everything that allocates for a caller (the Triangulation's entry points, the WebAssembly
// bindings) runs through catchOutOfMemory: the exception stops there, `undo` leaves the state
// valid (cleared, or as it was), and the caller gets a Status. The module never aborts.
#include <new>
#include <stdexcept>

#include "geocdt/status.h"

namespace geocdt {

inline constexpr const char* kOutOfMemoryMessage =
    "out of memory: the input is too large for the available memory";

// work() returns a Status; undo() runs only when work() ran out of memory.
template <typename Work, typename Undo>
Status catchOutOfMemory(Work&& work, Undo&& undo, const char* message = kOutOfMemoryMessage) {
  try {
    return work();
  } catch (const std::bad_alloc&) {
  } catch (const std::length_error&) {
  }
  undo();
  return {StatusCode::OutOfMemory, message};
}

}  // namespace geocdt
