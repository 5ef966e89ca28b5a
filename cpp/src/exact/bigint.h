#pragma once
// Fixed-capacity signed integers for the rare predicate calls whose coordinates span too
// many binades for expansions: each double becomes an exact integer multiple of the
// smallest unit among the inputs. Limbs live on the stack; 32-bit limbs keep every
// product in a uint64_t, which is plain C++ everywhere (wasm included).
#include <cassert>
#include <cstdint>
#include <cstring>

namespace geocdt::detail {

template <int Capacity>
struct BigInt {
  std::uint32_t limb[Capacity];  // magnitude, least significant limb first
  int size = 0;                  // limbs in use; limb[size - 1] is nonzero
  bool negative = false;
};

// A finite nonzero double is mantissa * 2^unit_exponent with an integer mantissa.
inline void decompose(double v, std::uint64_t& mantissa, int& unit_exponent) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  mantissa = bits & ((std::uint64_t{1} << 52) - 1);
  if (biased == 0) {
    unit_exponent = -1074;  // subnormal
  } else {
    mantissa |= std::uint64_t{1} << 52;
    unit_exponent = biased - 1075;
  }
}

template <int C>
void trim(BigInt<C>& r) {
  while (r.size > 0 && r.limb[r.size - 1] == 0) --r.size;
  if (r.size == 0) r.negative = false;
}

// r = v / 2^base_exponent, which must be an integer (base_exponent <= v's unit exponent).
template <int C>
void set_double(BigInt<C>& r, double v, int base_exponent) {
  r.size = 0;
  r.negative = v < 0.0;
  if (v == 0.0) return trim(r);
  std::uint64_t mantissa;
  int unit_exponent;
  decompose(v, mantissa, unit_exponent);
  const int shift = unit_exponent - base_exponent;
  assert(shift >= 0);
  const int word = shift / 32, bit = shift % 32;
  assert(word + 3 <= C);
  for (int i = 0; i < word; ++i) r.limb[i] = 0;
  const std::uint64_t low = mantissa << bit;
  const std::uint64_t high = bit == 0 ? 0 : mantissa >> (64 - bit);
  r.limb[word] = static_cast<std::uint32_t>(low);
  r.limb[word + 1] = static_cast<std::uint32_t>(low >> 32);
  r.limb[word + 2] = static_cast<std::uint32_t>(high);
  r.size = word + 3;
  trim(r);
}

template <int A, int B>
int compare_magnitude(const BigInt<A>& a, const BigInt<B>& b) {
  if (a.size != b.size) return a.size < b.size ? -1 : 1;
  for (int i = a.size - 1; i >= 0; --i) {
    if (a.limb[i] != b.limb[i]) return a.limb[i] < b.limb[i] ? -1 : 1;
  }
  return 0;
}

// |r| = |a| + |b|.
template <int C, int A, int B>
void add_magnitude(BigInt<C>& r, const BigInt<A>& a, const BigInt<B>& b) {
  const int n = a.size > b.size ? a.size : b.size;
  assert(n + 1 <= C);
  std::uint64_t carry = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t sum = carry + (i < a.size ? a.limb[i] : 0u) + (i < b.size ? b.limb[i] : 0u);
    r.limb[i] = static_cast<std::uint32_t>(sum);
    carry = sum >> 32;
  }
  r.limb[n] = static_cast<std::uint32_t>(carry);
  r.size = n + 1;
}

// |r| = |a| - |b|, given |a| >= |b|.
template <int C, int A, int B>
void subtract_magnitude(BigInt<C>& r, const BigInt<A>& a, const BigInt<B>& b) {
  assert(a.size <= C);
  std::uint32_t borrow = 0;
  for (int i = 0; i < a.size; ++i) {
    const std::uint64_t subtrahend = std::uint64_t{i < b.size ? b.limb[i] : 0u} + borrow;
    const std::uint64_t minuend = a.limb[i];
    borrow = minuend < subtrahend ? 1u : 0u;
    r.limb[i] = static_cast<std::uint32_t>(minuend + (std::uint64_t{borrow} << 32) - subtrahend);
  }
  r.size = a.size;
}

// r = a + b, or a - b when negate_b. r must be a different object from a and b.
template <int C, int A, int B>
void add(BigInt<C>& r, const BigInt<A>& a, const BigInt<B>& b, bool negate_b = false) {
  const bool b_negative = b.negative != negate_b;
  if (a.negative == b_negative) {
    add_magnitude(r, a, b);
    r.negative = a.negative;
  } else if (compare_magnitude(a, b) >= 0) {
    subtract_magnitude(r, a, b);
    r.negative = a.negative;
  } else {
    subtract_magnitude(r, b, a);
    r.negative = b_negative;
  }
  trim(r);
}

// r = a * b, schoolbook. r must be a different object from a and b.
template <int C, int A, int B>
void multiply(BigInt<C>& r, const BigInt<A>& a, const BigInt<B>& b) {
  r.size = a.size + b.size;
  assert(r.size <= C);
  for (int i = 0; i < r.size; ++i) r.limb[i] = 0;
  // Inputs far apart in magnitude leave many zero limbs (a huge coordinate in units of a tiny
  // one ends in zeros): skipping them makes such calls several times cheaper.
  int low = 0;
  while (low < b.size && b.limb[low] == 0) ++low;
  for (int i = 0; i < a.size; ++i) {
    if (a.limb[i] == 0) continue;
    std::uint64_t carry = 0;
    for (int j = low; j < b.size; ++j) {
      // (2^32 - 1)^2 + 2 * (2^32 - 1) < 2^64: never overflows.
      const std::uint64_t t = std::uint64_t{a.limb[i]} * b.limb[j] + r.limb[i + j] + carry;
      r.limb[i + j] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    r.limb[i + b.size] = static_cast<std::uint32_t>(carry);
  }
  r.negative = a.negative != b.negative;
  trim(r);
}

template <int C>
int sign(const BigInt<C>& a) {
  return a.size == 0 ? 0 : (a.negative ? -1 : 1);
}

}  // namespace geocdt::detail
