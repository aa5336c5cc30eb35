// FormatG12 against the C library's own "%.12g": byte for byte, over the magnitudes a history
// holds and over the cases where its shortcut gives way (rounding near a half, powers of ten,
// the ends of the double range).

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "tools/fast_g12.h"

namespace tbridge::cli {
namespace {

std::string Fast(double v) {
  char buffer[32];
  char* end = FormatG12(buffer, buffer + 24, v);
  return std::string(buffer, end);
}

std::string Printf(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.12g", v);
  return buffer;
}

TEST_CASE("FormatG12 writes what printf's %.12g writes") {
  // Exact equality: the output is a file format that must not depend on the formatter.
  const double edge[] = {0.0,
                         -0.0,
                         1.0,
                         10.0,
                         0.1,
                         1e-4,
                         1e-5,
                         9.9999999999995e-5,  // rounds up across the fixed/scientific switch
                         999999999999.5,      // rounds up to 1e12
                         123456789012.0,
                         1234567890123.0,
                         0.5,
                         2.5,
                         1.0000000000005,  // a half in the 13th digit: to_chars decides
                         1e-290,
                         1e290,
                         1e-300,
                         1e300,
                         std::numeric_limits<double>::denorm_min(),
                         std::numeric_limits<double>::max(),
                         std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN()};
  for (const double v : edge) {
    for (const double s : {v, -v}) {
      INFO(Printf(s));
      CHECK(Fast(s) == Printf(s));
    }
  }
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  long mismatches = 0;
  for (int k = 0; k < 300000; ++k) {
    // Positions and times (|v| < 1e3), any magnitude, and short decimals (exact thousandths).
    const double v = k % 3 == 0   ? unit(rng) * std::pow(10.0, exponent(rng))
                     : k % 3 == 1 ? unit(rng) * 1e3
                                  : std::round(unit(rng) * 1e6) / 1e3;
    if (Fast(v) != Printf(v) && ++mismatches <= 5) FAIL_CHECK(Fast(v) << " against printf's " << Printf(v));
  }
  CHECK(mismatches == 0);
}

}  // namespace
}  // namespace tbridge::cli
