#pragma once
// Growing the wasm memory once for a whole call, before its input is written.

namespace geocdt::wasm {

// Grows the wasm memory, if it must, to exactly what is in use now plus `more` bytes, so that
// the call does not grow it again. Node's V8 counts each growth as memory outside its JS heap,
// and past a limit it collects the caller's whole heap, GeoJSON included: grown step by step
// during a call, the memory had it do that several times a call (bench/EXPERIMENTS.md, G2).
// Best effort: where the memory cannot grow that far, the call grows it as it goes. Growth
// nobody reserved for (the Steiner points of refinement) doubles the memory each time
// (heap_grow.js, G4).
void reserveHeap(double more);

// What a call needs at its peak, by input: the allocator's peaks without and with constraints
// (bench/README.md) and some room for its blocks, so that one growth suffices for inputs
// small and large (bench/EXPERIMENTS.md, G2).
constexpr double kReservePerPoint = 84;
constexpr double kReservePerLinePoint = 136;

}  // namespace geocdt::wasm
