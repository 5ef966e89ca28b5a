#pragma once
// Growing the wasm memory once for a whole call, before its input is written.

namespace geocdt::wasm {

// Grows the wasm memory, if it must, to exactly what is in use now plus `more` bytes, so that
// the call does not grow it again. Node's V8 counts each growth as memory outside its JS heap,
// and past a limit it collects the caller's whole heap: grown step by step during a call (20%
// at a time, the glue's default then), the memory had it do that three times in one first
// call on the Natural Earth 10m countries, 40-60 ms each with their GeoJSON alive
// (bench/EXPERIMENTS.md, GeoJSON 2; Chromium showed no such cost). Best effort: where the
// memory cannot grow that far, the call grows it as it goes. Growth nobody reserved for (the
// Steiner points of refinement) doubles the memory each time (heap_grow.js, GeoJSON 4).
void reserveHeap(double more);

// What a call needs at its peak, by input. The allocator's peak is 78 bytes a point without
// constraints and 126-135 bytes an input point with them (bench/README.md); its blocks need
// some room beyond that. With these, one growth sufficed on 200,000 to 7.3M points, and left
// about as much memory as growing by 20% steps had (85 MB against 87 for 1M points, 941
// against 919 for 7.3M).
constexpr double kReservePerPoint = 84;
constexpr double kReservePerLinePoint = 136;

}  // namespace geocdt::wasm
