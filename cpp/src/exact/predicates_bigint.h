#pragma once
// Big-integer evaluation of the predicates: exact for any finite inputs, whatever their
// exponent span, but slower than expansions; used only when scaling cannot help.
#include "geocdt/predicates.h"

namespace geocdt::detail {

// v = {ax, ay, bx, by, cx, cy}, all finite.
Sign orient2d_bigint(const double* v);

// v = {ax, ay, bx, by, cx, cy, dx, dy}, all finite.
Sign incircle_bigint(const double* v);

}  // namespace geocdt::detail
