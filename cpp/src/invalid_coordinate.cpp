#include "invalid_coordinate.h"

#include <cmath>
#include <cstdint>
#include <vector>

#include "base/chunks.h"
#include "geocdt/status.h"

namespace geocdt {

std::size_t firstInvalidCoordinate(const double* xy, std::size_t first, std::size_t last) {
  std::size_t found = last;
  forChunks(first, last, [&](std::size_t begin, std::size_t end) {
    if (found != last) return;
    for (std::size_t i = begin; i < end; ++i)
      if (!(std::isfinite(xy[i]) && std::fabs(xy[i]) <= kMaxCoordinate)) {
        found = i;
        return;
      }
  });
  return found;
}

std::string integerToString(double v) {
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  // |v| = mantissa * 2^exponent with a 53-bit mantissa; an integer has no bits below 2^0.
  int exponent = 0;
  const double fraction = std::frexp(std::fabs(v), &exponent);
  auto mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
  exponent -= 53;
  if (exponent < 0) {
    mantissa = exponent > -64 ? mantissa >> -exponent : 0;
    exponent = 0;
  }
  // Base 10^9 digits, least significant first, doubled `exponent` times in steps of 2^29
  // (a digit times 2^29 plus a carry fits in 64 bits).
  constexpr std::uint32_t kBase = 1000000000;
  std::vector<std::uint32_t> digits;
  do {
    digits.push_back(static_cast<std::uint32_t>(mantissa % kBase));
    mantissa /= kBase;
  } while (mantissa > 0);
  while (exponent > 0) {
    const int shift = exponent < 29 ? exponent : 29;
    exponent -= shift;
    std::uint64_t carry = 0;
    for (std::uint32_t& d : digits) {
      const std::uint64_t x = (std::uint64_t{d} << shift) + carry;
      d = static_cast<std::uint32_t>(x % kBase);
      carry = x / kBase;
    }
    if (carry > 0) digits.push_back(static_cast<std::uint32_t>(carry));
  }
  std::string text = std::signbit(v) ? "-" : "";
  text += std::to_string(digits.back());
  for (std::size_t i = digits.size() - 1; i-- > 0;) {
    const std::string d = std::to_string(digits[i]);
    text.append(9 - d.size(), '0') += d;
  }
  return text + ".000000";
}

std::string describeInvalidCoordinate(double v, bool isY) {
  std::string text = isY ? "y = " : "x = ";
  text += std::isnan(v) ? "NaN" : integerToString(v);
  text += std::isfinite(v) ? ": coordinates must lie within +-1e150"
                           : ": coordinates must be finite numbers";
  return text;
}

}  // namespace geocdt
