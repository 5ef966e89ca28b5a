// The embind surface. Only numbers, byte addresses and two small classes cross it: bulk data
// moves through the heap in one copy each way (web/heap.js), never element by element.
#include <emscripten/bind.h>
#include <malloc.h>

#include "incremental.h"
#include "one_shot.h"
#include "output.h"

namespace geocdt::wasm {
namespace {

// Bytes handed out by malloc and not yet freed: lets tests prove that calls leak nothing.
// mallinfo's fields are int: read them as unsigned, since the heap may pass 2 GB.
double allocatedBytes() { return static_cast<unsigned>(mallinfo().uordblks); }

// The allocator's high-water mark of memory taken from the system.
double peakBytes() { return static_cast<unsigned>(mallinfo().usmblks); }

}  // namespace
}  // namespace geocdt::wasm

EMSCRIPTEN_BINDINGS(geocdt) {
  using namespace emscripten;
  using namespace geocdt::wasm;

  class_<Output>("Output")
      .constructor<>()
      .function("data", &Output::data)
      .function("size", &Output::size)
      .function("code", &Output::code)
      .function("message", &Output::message)
      .function("index", &Output::index)
      .function("segment", &Output::segment)
      .function("stat", &Output::stat)
      .function("clear", &Output::clear);

  class_<Incremental>("Incremental")
      .constructor<>()
      .function("insertPoints", &Incremental::insertPoints)
      .function("insertPolyline", &Incremental::insertPolyline)
      .function("mesh", &Incremental::mesh)
      .function("stats", &Incremental::stats)
      .function("locate", &Incremental::locate)
      .function("vertexCount", &Incremental::vertexCount)
      .function("triangleCount", &Incremental::triangleCount)
      .function("polylineCount", &Incremental::polylineCount);

  function("triangulateInto", &triangulateInto);
  function("allocatedBytes", &allocatedBytes);
  function("peakBytes", &peakBytes);
}
