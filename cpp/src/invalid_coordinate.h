#pragma once
// Finding an invalid coordinate, and the text that names it in a Status message.
#include <cstddef>
#include <string>

namespace geocdt {

// The index of the first value in xy[first, last) that is NaN, infinite or beyond
// kMaxCoordinate, or last. In chunks (chunks.h): a call checks every input value once.
std::size_t firstInvalidCoordinate(const double* xy, std::size_t first, std::size_t last);

// "x = <v>: coordinates must ..." (or "y = ..." when isY) for a coordinate that is NaN,
// infinite or beyond kMaxCoordinate. The value reads as std::to_string prints it ("%f":
// every digit of the integer it is, then ".000000"; "inf", "-inf"), without pulling C's
// printf and its long double arithmetic into the WebAssembly module.
std::string describeInvalidCoordinate(double v, bool isY);

// The digits std::to_string gives for v, for the values describeInvalidCoordinate names:
// infinities and integers (as every double of magnitude 2^53 or more is). Exposed for tests.
std::string integerToString(double v);

}  // namespace geocdt
