#pragma once
// ln, exp and x^p without branches or library calls, so that a loop over a batch that uses them
// compiles to vector code (the libm calls std::log and std::exp stop GCC's vectoriser). Only
// 64-bit integer shifts, and, or, add and double arithmetic: SSE2 has them all, so the default
// x86-64 target vectorises them too.
//
//   ln x:  x = m 2^e with m in [sqrt(1/2), sqrt(2)), ln x = e ln 2 + 2 atanh(s), s = (m-1)/(m+1),
//          |s| <= 0.1716, atanh's series to s^19 (truncation < 3e-17 relative).
//   exp y: y = n ln 2 + r, n = round(y / ln 2), |r| <= 0.347 (ln 2 split in two so that n ln 2_hi
//          is exact), exp r by its Taylor series to r^13 (truncation < 5e-18 relative), times 2^n
//          built in the exponent bits.
//
// Stated error (tests/core/branch_free_math_test.cpp checks it against std::log, std::exp and
// std::pow): ln to 2 ulps of max(1, |ln x|); exp to 4e-16 relative; x^p = exp(p ln x) to
// (4 + |p ln x|) 4.4e-16 relative of std::pow and of std::exp(p * std::log(x)), the second
// term being the rounding of ln x that each carries into the power (1.2e-14 for x^0.6567 at
// x = 1e-14, 3.5e-15 measured at x = 2e-8).
// Domain: ln and x^p for positive normal x (no zero, infinity, NaN or subnormal); exp for
// |y| < 708 (results normal).
#include <bit>
#include <cstdint>

namespace flotsam {

/// ln x for a positive normal x (header comment: method and error).
inline double branch_free_log(double x) {
  constexpr std::uint64_t mantissa_bits = 0x000FFFFFFFFFFFFFull;
  constexpr std::uint64_t one_bits = 0x3FF0000000000000ull;    // 1.0
  constexpr std::uint64_t two52_bits = 0x4330000000000000ull;  // 2^52
  constexpr double two52 = 4503599627370496.0;                 // 2^52
  constexpr double sqrt2 = 1.4142135623730951;
  constexpr double ln2_hi = 6.93147180369123816490e-01;  // ln 2, 32 leading bits
  constexpr double ln2_lo = 1.90821492927058770002e-10;  // ln 2 - ln2_hi
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  // The biased exponent as a double (2^52 + k - 2^52) and the mantissa in [1, 2).
  const double biased = std::bit_cast<double>((bits >> 52) | two52_bits) - two52;
  double m = std::bit_cast<double>((bits & mantissa_bits) | one_bits);
  const bool high = m > sqrt2;
  m = high ? 0.5 * m : m;
  const double e = biased - 1023.0 + (high ? 1.0 : 0.0);
  const double s = (m - 1.0) / (m + 1.0);
  const double s2 = s * s;
  // 2 atanh(s) = 2 s (1 + s^2/3 + s^4/5 + ... + s^18/19)
  double series = 1.0 / 19;
  series = 1.0 / 17 + s2 * series;
  series = 1.0 / 15 + s2 * series;
  series = 1.0 / 13 + s2 * series;
  series = 1.0 / 11 + s2 * series;
  series = 1.0 / 9 + s2 * series;
  series = 1.0 / 7 + s2 * series;
  series = 1.0 / 5 + s2 * series;
  series = 1.0 / 3 + s2 * series;
  const double ln_m = 2.0 * s + 2.0 * s * (s2 * series);
  return e * ln2_hi + (e * ln2_lo + ln_m);
}

/// exp y for |y| < 708 (header comment: method and error).
inline double branch_free_exp(double y) {
  constexpr double inv_ln2 = 1.4426950408889634;
  constexpr double ln2_hi = 6.93147180369123816490e-01;
  constexpr double ln2_lo = 1.90821492927058770002e-10;
  constexpr double round_shift = 6755399441055744.0;  // 1.5 2^52: adding it rounds to an integer
  const double shifted = y * inv_ln2 + round_shift;
  const double n = shifted - round_shift;  // round(y / ln 2)
  const double r = (y - n * ln2_hi) - n * ln2_lo;
  // exp r = 1 + r + r^2/2! + ... + r^13/13!
  double p = 1.0 / 6227020800.0;
  p = 1.0 / 479001600.0 + r * p;
  p = 1.0 / 39916800.0 + r * p;
  p = 1.0 / 3628800.0 + r * p;
  p = 1.0 / 362880.0 + r * p;
  p = 1.0 / 40320.0 + r * p;
  p = 1.0 / 5040.0 + r * p;
  p = 1.0 / 720.0 + r * p;
  p = 1.0 / 120.0 + r * p;
  p = 1.0 / 24.0 + r * p;
  p = 1.0 / 6.0 + r * p;
  p = 0.5 + r * p;
  const double exp_r = 1.0 + (r + r * (r * p));
  // 2^n: n sits in the low bits of `shifted`; moved into the exponent field with its bias.
  const std::uint64_t n_bits = std::bit_cast<std::uint64_t>(shifted) << 52;
  const double two_n = std::bit_cast<double>(n_bits + (1023ull << 52));
  return exp_r * two_n;
}

/// x^p = exp(p ln x) for a positive normal x (header comment: error).
inline double branch_free_pow(double x, double p) {
  return branch_free_exp(p * branch_free_log(x));
}

}  // namespace flotsam
