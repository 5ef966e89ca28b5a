// The editing calls a user makes by the hundred thousand (a dragged vertex, a selection
// deleted point by point), exported as plain functions: embind's method calls marshal their
// arguments through generated JS that cost as much as a removal's own work in the core
// (bench/EXPERIMENTS.md, E18). JS passes the addresses that Incremental::objectAddress() and
// Output::objectAddress() gave it once.
#include <emscripten/emscripten.h>

#include <cstdint>

#include "incremental.h"
#include "output.h"

namespace {

geocdt::wasm::Incremental& incrementalAt(std::uintptr_t address) {
  return *reinterpret_cast<geocdt::wasm::Incremental*>(address);
}
geocdt::wasm::Output& outputAt(std::uintptr_t address) {
  return *reinterpret_cast<geocdt::wasm::Output*>(address);
}

}  // namespace

extern "C" {

// As Incremental::removePoint: 1 removed, 0 kept (a polyline's vertex), -1 failed.
EMSCRIPTEN_KEEPALIVE int geocdt_remove_point(std::uintptr_t incremental, std::uintptr_t out,
                                             double id) {
  return incrementalAt(incremental).removePoint(outputAt(out), id);
}

// As Incremental::movePoint: 1 moved, 0 failed.
EMSCRIPTEN_KEEPALIVE int geocdt_move_point(std::uintptr_t incremental, std::uintptr_t out,
                                           double id, double x, double y) {
  return incrementalAt(incremental).movePoint(outputAt(out), id, x, y) ? 1 : 0;
}

}  // extern "C"
