// Numbers as printf's "%.12g" writes them, byte for byte, about six times faster than
// std::to_chars(general, 12) (tests/tools/fast_g12_test.cc holds it to snprintf;
// docs/benchmarks-history.md has the timing): a history row of the MOTES prism is 73 numbers every
// 10 steps, and formatting them cost more than the steps.
//
// How: the 12 significant digits are the value scaled by a power of ten and rounded to an
// integer. The scaling's rounding error is below 2e-4 of the last digit; a value whose
// scaled fraction lies within 1e-3 of a half (where that error could flip the rounding), or
// that is not finite, zero, subnormal or beyond 1e±290, goes to std::to_chars instead. The
// integer becomes characters four digits at a time from a table of all 10^4 groups (40 kB,
// built at compile time): 100 instructions a value where two digits at a time took 200.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace tbridge::cli {

namespace fast_g12_detail {

// The shortcut takes |v| in [10^-kShortcut, 10^kShortcut]: its decimal exponent e then lies
// in [-kShortcut - 1, kShortcut] (the first guess may be one low), and it asks for 10^(e + 1)
// and 10^(11 - e), so for powers from 10^-kShortcut to 10^(12 + kShortcut).
inline constexpr int kShortcut = 290;
inline constexpr int kLowestPower = -300, kHighestPower = 308;  // 10^308 < DBL_MAX
static_assert(kLowestPower <= -kShortcut && kHighestPower >= 12 + kShortcut,
              "the table must hold every power asked for");

// 10^k for k in [kLowestPower, kHighestPower], filled before main (no guard on each call);
// std::pow's powers are within an ulp, which the 1e-3 margin covers.
struct Powers {
  double p[kHighestPower - kLowestPower + 1];
  Powers() {
    for (int k = kLowestPower; k <= kHighestPower; ++k) p[k - kLowestPower] = std::pow(10.0, k);
  }
};
inline const Powers kPowersOfTen;
inline double Pow10(int k) { return kPowersOfTen.p[k - kLowestPower]; }

inline char* Fallback(char* p, char* end, double v) {
  return std::to_chars(p, end, v, std::chars_format::general, 12).ptr;
}

// The four characters of every n < 10^4, as one 32-bit word each (first character lowest).
constexpr std::array<std::uint32_t, 10000> MakeFourDigits() {
  std::array<std::uint32_t, 10000> t{};
  for (std::uint32_t n = 0; n < 10000; ++n) {
    t[n] = (0x30u + n / 1000) | ((0x30u + n / 100 % 10) << 8) | ((0x30u + n / 10 % 10) << 16) |
           ((0x30u + n % 10) << 24);
  }
  return t;
}
inline constexpr std::array<std::uint32_t, 10000> kFourDigits = MakeFourDigits();

}  // namespace fast_g12_detail

// Writes v at p and returns the end of what it wrote; [p, end) must hold 24 characters, and
// the buffer 32 from p: the digits are stored in fixed-size pieces (compiled to a few moves;
// variable ones are a library call), so a number may write past its own end.
inline char* FormatG12(char* p, char* end, double v) {
  namespace d = fast_g12_detail;
  const double a = std::fabs(v);
  if (!(a >= 1e-290 && a <= 1e290)) return d::Fallback(p, end, v);  // 10^±d::kShortcut
  std::uint64_t bits = 0;
  std::memcpy(&bits, &a, sizeof bits);
  const int e2 = static_cast<int>(bits >> 52) - 1023;  // a in [2^e2, 2^(e2 + 1)): a is normal here
  // floor(e2 log10 2) is floor(log10 a) or one less (the product's floor, rounded down).
  int e = e2 >= 0 ? (e2 * 78913) >> 18 : -((-e2 * 78913 + (1 << 18) - 1) >> 18);
  if (a >= d::Pow10(e + 1)) ++e;
  // m = a 10^(11 - e) in [1e11, 1e12): division by an exact power where there is one.
  const double m = 11 - e >= 0 ? a * d::Pow10(11 - e)
                               : (e - 11 <= 22 ? a / d::Pow10(e - 11) : a * d::Pow10(11 - e));
  // m < 2^63: the signed conversion (one instruction; the unsigned one branches) is floor.
  const std::uint64_t whole_m = static_cast<std::uint64_t>(static_cast<std::int64_t>(m));
  const double frac = m - static_cast<double>(whole_m);
  if (std::fabs(frac - 0.5) < 1e-3) return d::Fallback(p, end, v);
  std::uint64_t digits = whole_m + (frac > 0.5 ? 1 : 0);
  if (digits >= 1000000000000ULL) {  // rounded up to 10^12
    digits /= 10;
    ++e;
  }
  if (digits < 100000000000ULL)
    return d::Fallback(p, end, v);  // e one too high: leave it to to_chars
  // Three groups of four digits.
  const std::uint32_t low8 = static_cast<std::uint32_t>(digits % 100000000);
  const std::uint32_t g0 = d::kFourDigits[digits / 100000000];
  const std::uint32_t g1 = d::kFourDigits[low8 / 10000];
  const std::uint32_t g2 = d::kFourDigits[low8 % 10000];
  // n: the significant digits left once %g drops the trailing zeros.
  int n = 12;
  if (low8 % 10 == 0) {
    std::uint64_t x = digits / 10;
    --n;
    while (x % 10 == 0) {
      x /= 10;
      --n;
    }
  }
  *p = '-';
  p += v < 0 ? 1 : 0;
  // The layouts of positions and times near 1 are put together in registers and stored whole:
  // small stores read back as one wide load stall the load.
  if (e == 0) {  // d.ddddddddddd
    const std::uint64_t head =
        (g0 & 0xFF) | (std::uint64_t{'.'} << 8) | (static_cast<std::uint64_t>(g0 >> 8) << 16);
    std::memcpy(p, &head, 8);
    std::memcpy(p + 5, &g1, 4);
    std::memcpy(p + 9, &g2, 4);
    return p + (n > 1 ? n + 1 : 1);
  }
  if (e < 0 && e >= -4) {  // 0.000ddd: the prefix, then the digits over its tail
    std::memcpy(p, "0.000000", 8);
    p += 1 - e;
    std::memcpy(p, &g0, 4);
    std::memcpy(p + 4, &g1, 4);
    std::memcpy(p + 8, &g2, 4);
    return p + n;
  }
  char digit[24];  // the 12 digits, then zeros for the fixed-size copies
  std::memcpy(digit, &g0, 4);
  std::memcpy(digit + 4, &g1, 4);
  std::memcpy(digit + 8, &g2, 4);
  std::memcpy(digit + 12, "000000000000", 12);
  if (e > 0 && e < 12) {  // ddd[.ddd]
    const int whole = e + 1;
    std::memcpy(p, digit, 16);
    if (n <= whole) return p + whole;
    p[whole] = '.';
    std::memcpy(p + whole + 1, digit + whole, 12);
    return p + n + 1;
  }
  *p++ = digit[0];  // scientific: d[.ddd]e±XX
  if (n > 1) {
    *p++ = '.';
    std::memcpy(p, digit + 1, 12);
    p += n - 1;
  }
  *p++ = 'e';
  *p++ = e < 0 ? '-' : '+';
  int x = e < 0 ? -e : e;
  if (x >= 100) {
    *p++ = static_cast<char>('0' + x / 100);
    x %= 100;
  }
  p[0] = static_cast<char>('0' + x / 10);
  p[1] = static_cast<char>('0' + x % 10);
  return p + 2;
}

}  // namespace tbridge::cli
