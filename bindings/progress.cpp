#include "progress.h"

#include <emscripten/emscripten.h>

#include <algorithm>
#include <string>
#include <utility>

namespace geocdt::wasm {

namespace {
constexpr double kIntervalMs = 100;  // within a phase, at most ten reports a second
}

void ProgressRelay::start(emscripten::val callback, std::size_t points) {
  active_ = callback.typeOf().as<std::string>() == "function";
  callback_ = active_ ? std::move(callback) : emscripten::val::undefined();
  points_ = points;
  batchStart_ = 0;
  phase_ = -1;
  fraction_ = 0;
  unsent_ = false;
}

void ProgressRelay::finish() {
  if (active_ && unsent_) send();
  active_ = false;
  callback_ = emscripten::val::undefined();
}

void ProgressRelay::report(void* relay, Phase phase, std::size_t done, std::size_t total) {
  auto& self = *static_cast<ProgressRelay*>(relay);
  if (!self.active_) return;
  double fraction = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
  // The sort and the insertion of points run once per batch: their fractions count the points
  // of the whole call.
  if ((phase == Phase::Sort || phase == Phase::Points) && self.points_ > 0)
    fraction = static_cast<double>(self.batchStart_ + done) / static_cast<double>(self.points_);
  self.update(phase, std::min(fraction, 1.0));
}

void ProgressRelay::update(Phase phase, double fraction) {
  const int p = static_cast<int>(phase);
  if (p < phase_ || (p == phase_ && fraction <= fraction_)) return;
  const bool begins = p != phase_;
  phase_ = p;
  fraction_ = fraction;
  unsent_ = true;
  if (begins || emscripten_get_now() - sentAt_ >= kIntervalMs) send();
}

void ProgressRelay::send() {
  unsent_ = false;
  callback_(phase_, fraction_);
  // Timed from the callback's return, so that two reports are 100 ms apart wherever inside the
  // callback the caller looks at the clock (a slow callback or a pause in it would otherwise
  // bring the next report closer).
  sentAt_ = emscripten_get_now();
}

}  // namespace geocdt::wasm
