#pragma once
// Passes the core's progress checkpoints on to a JS function as (phase, fraction): each
// phase's first report at once (a bar can name every phase that ran, however short), then at
// most one per 100 ms, then the last one. Phases only move forward and a phase's fraction
// never goes back, even when one call runs several batches (the points, then the polylines'
// points).
#include <emscripten/val.h>

#include <cstddef>

#include "geocdt/triangulation.h"

namespace geocdt::wasm {

class ProgressRelay {
 public:
  // The Progress to put in the core's Options: it reports to this relay, which stays silent
  // between calls and in calls made without a JS function.
  Progress hook() { return {&ProgressRelay::report, this}; }
  bool active() const { return active_; }

  // A call begins; callback is a JS function or undefined. points: how many points the call
  // inserts in all, so that the points phase spans its batches.
  void start(emscripten::val callback, std::size_t points);
  // The next batch's points come after the first `inserted` of the call.
  void batch(std::size_t inserted) { batchStart_ = inserted; }
  // The call ends: the last state is sent if it was not, and the relay falls silent.
  void finish();

 private:
  static void report(void* relay, Phase phase, std::size_t done, std::size_t total);
  void update(Phase phase, double fraction);
  void send();

  emscripten::val callback_ = emscripten::val::undefined();
  bool active_ = false;
  std::size_t points_ = 0;
  std::size_t batchStart_ = 0;
  int phase_ = -1;
  double fraction_ = 0;
  bool unsent_ = false;
  double sentAt_ = 0;
};

}  // namespace geocdt::wasm
