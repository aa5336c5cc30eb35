// Numbers as printf's "%.12g" writes them, byte for byte, about four times faster than
// std::to_chars(general, 12) (tests/tools/fast_g12_test.cc holds it to snprintf;
// BENCHMARKS.md has the timing): a history row of the MOTES prism is 73 numbers every 10 steps,
// and formatting them cost more than the steps.
//
// How: the 12 significant digits are the value scaled by a power of ten and rounded to an
// integer. The scaling's rounding error is below 2e-4 of the last digit; a value whose
// scaled fraction lies within 1e-3 of a half (where that error could flip the rounding), or
// that is not finite, zero, subnormal or beyond 1e±290, goes to std::to_chars instead.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace tbridge::cli {

namespace fast_g12_detail {

// 10^(k - 300), filled before main (no guard on each call); std::pow's powers are within an
// ulp, which the 1e-3 margin covers.
struct Powers {
  double p[600];
  Powers() {
    for (int k = 0; k < 600; ++k) p[k] = std::pow(10.0, k - 300);
  }
};
inline const Powers kPowersOfTen;
inline double Pow10(int k) { return kPowersOfTen.p[k + 300]; }

inline char* Fallback(char* p, char* end, double v) {
  return std::to_chars(p, end, v, std::chars_format::general, 12).ptr;
}

inline const char* TwoDigits() {
  return "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
         "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
         "8081828384858687888990919293949596979899";
}

}  // namespace fast_g12_detail

// Writes v at p and returns the end of what it wrote; [p, end) must hold 24 characters, and
// the buffer 26 from p: the digits are copied 12 at a time (fixed-size copies compile to a
// few moves, variable ones to a library call), so a number may write past its own end.
inline char* FormatG12(char* p, char* end, double v) {
  namespace d = fast_g12_detail;
  const double a = std::fabs(v);
  if (!(a >= 1e-290 && a <= 1e290)) return d::Fallback(p, end, v);
  std::uint64_t bits = 0;
  std::memcpy(&bits, &a, sizeof bits);
  const int e2 = static_cast<int>(bits >> 52) - 1023;  // a in [2^e2, 2^(e2 + 1)): a is normal here
  // floor(e2 log10 2) is floor(log10 a) or one less (the product's floor, rounded down).
  int e = e2 >= 0 ? (e2 * 78913) >> 18 : -((-e2 * 78913 + (1 << 18) - 1) >> 18);
  if (a >= d::Pow10(e + 1)) ++e;
  // m = a 10^(11 - e) in [1e11, 1e12): division by an exact power where there is one.
  const double m = 11 - e >= 0 ? a * d::Pow10(11 - e) : (e - 11 <= 22 ? a / d::Pow10(e - 11) : a * d::Pow10(11 - e));
  const std::uint64_t whole_m = static_cast<std::uint64_t>(m);  // m < 2^63: truncation is floor
  const double frac = m - static_cast<double>(whole_m);
  if (std::fabs(frac - 0.5) < 1e-3) return d::Fallback(p, end, v);
  std::uint64_t digits = whole_m + (frac > 0.5 ? 1 : 0);
  if (digits >= 1000000000000ULL) {  // rounded up to 10^12
    digits /= 10;
    ++e;
  }
  if (digits < 100000000000ULL) return d::Fallback(p, end, v);  // e one too high: leave it to to_chars
  // The 12 digits, most significant first.
  char buf[24] = {};  // 12 digits, then room for the fixed-size copies below
  const char* two = d::TwoDigits();
  // Two halves of six digits in 32-bit arithmetic.
  std::uint32_t halves[2] = {static_cast<std::uint32_t>(digits / 1000000), static_cast<std::uint32_t>(digits % 1000000)};
  for (int h = 0; h < 2; ++h) {
    std::uint32_t x = halves[h];
    for (int k = 6 * h + 4; k >= 6 * h; k -= 2) {
      const std::uint32_t r = x % 100;
      x /= 100;
      buf[k] = two[2 * r];
      buf[k + 1] = two[2 * r + 1];
    }
  }
  int n = 12;
  while (n > 1 && buf[n - 1] == '0') --n;  // %g drops trailing zeros
  if (v < 0) *p++ = '-';
  if (e < -4 || e >= 12) {  // scientific: d[.ddd]e±XX
    *p++ = buf[0];
    if (n > 1) {
      *p++ = '.';
      std::memcpy(p, buf + 1, static_cast<std::size_t>(n - 1));
      p += n - 1;
    }
    *p++ = 'e';
    *p++ = e < 0 ? '-' : '+';
    int x = e < 0 ? -e : e;
    if (x >= 100) {
      *p++ = static_cast<char>('0' + x / 100);
      x %= 100;
    }
    *p++ = two[2 * x];
    *p++ = two[2 * x + 1];
  } else if (e >= 0) {  // ddd[.ddd]; whole copies of 12 bytes, then the end moved back
    const int whole = e + 1;
    if (n <= whole) {
      std::memcpy(p, buf, 12);
      p += whole;
    } else {
      std::memcpy(p, buf, 12);
      p[whole] = '.';
      std::memcpy(p + whole + 1, buf + whole, 12);  // reads into buf's zeroed tail
      p += n + 1;
    }
  } else {  // 0.000ddd
    std::memcpy(p, "0.0000", 6);
    p += 1 - e;
    std::memcpy(p, buf, 12);
    p += n;
  }
  return p;
}

}  // namespace tbridge::cli
