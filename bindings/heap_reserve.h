#pragma once
// Growing the wasm memory once for a whole call, before its input is written.
#include <cstddef>

namespace geocdt::wasm {

// Grows the wasm memory, if it must, so that the bytes allocated now and `more` fit without
// growing it again. Engines count each growth as memory outside their JS heap, and past a
// limit they collect the caller's whole heap: grown step by step during a call (20% at a
// time), the memory had V8 do that three times in one first call on the Natural Earth 10m
// countries, 40-60 ms each with their GeoJSON alive (bench/EXPERIMENTS.md, GeoJSON 2). Best
// effort: where the memory cannot grow that far, the call grows it as it goes, as before.
void reserveHeap(double more);

// What a call needs at its peak, by input. The allocator's peak is 78 bytes a point without
// constraints and 126-135 bytes an input point with them (bench/README.md); its blocks need
// some room beyond that. Growing by 20% steps ended above these: 87 MB for 1M points, 75 MB
// for the Natural Earth 10m rings (544,898 points), 277 MB for a 2M-point GSHHG region.
constexpr double kReservePerPoint = 84;
constexpr double kReservePerLinePoint = 136;

}  // namespace geocdt::wasm
