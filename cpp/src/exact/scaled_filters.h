#pragma once
// The filters again, for calls whose exponents span too wide for the expansions: on the
// coordinate differences scaled by one power of two, so that nothing overflows. Such calls
// otherwise all go to the big integers (microseconds each), though most of them only
// overflowed the filter and are far from degenerate: columns 1e131 apart with points 1e2
// apart along them made every in-circle test of 33,000 points such a call (fuzz_strips).
#include "geocdt/predicates.h"

namespace geocdt::detail {

// v = {ax, ay, bx, by, cx, cy}, all finite. Positive or Negative when decided, else Zero.
Sign orient2d_scaled_filter(const double* v);

// v = {ax, ay, bx, by, cx, cy, dx, dy}, all finite. Positive or Negative when decided, else
// Zero.
Sign incircle_scaled_filter(const double* v);

}  // namespace geocdt::detail
