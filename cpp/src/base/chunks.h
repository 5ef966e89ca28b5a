#pragma once
// Long loops of functions that run once a call, cut into chunks that are each a call of their
// own. WebAssembly engines start every function in a baseline tier and swap in optimised code
// for its later calls once it has run enough; a loop that runs to its end inside one call
// never gets that code (engines have no on-stack replacement for wasm), so in the first call
// in a process such loops ran at baseline speed throughout. Worse, V8 charges a function's
// budget at each loop's back edge by the loop's size in bytes, so such a loop got the
// function that runs it once optimised during the call, for nothing, on a core the call
// could have used (bench/EXPERIMENTS.md, F16 and F21). A chunk is a few thousand
// iterations, whose call costs next to nothing natively.
// Binaryen would inline the chunk functions back (one caller each) without the link flag in
// bindings/CMakeLists.txt.
#include <algorithm>
#include <cstddef>

#if defined(__GNUC__)
#define GEOCDT_NOINLINE __attribute__((noinline))
#else
#define GEOCDT_NOINLINE
#endif

namespace geocdt {

inline constexpr std::size_t kChunk = 4096;

template <typename Body>
GEOCDT_NOINLINE void runChunk(Body& body, std::size_t begin, std::size_t end) {
  body(begin, end);
}

// Calls body(begin, end) on consecutive ranges of at most `chunk` indices covering
// [first, last). A chunk of 1 suits items of much work each (a polyline, a segment's checks).
template <typename Body>
void forChunks(std::size_t first, std::size_t last, Body body, std::size_t chunk = kChunk) {
  for (std::size_t begin = first; begin < last;) {
    const std::size_t end = begin + std::min(chunk, last - begin);
    runChunk(body, begin, end);
    begin = end;
  }
}

}  // namespace geocdt
