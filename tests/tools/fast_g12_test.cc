// FormatG12 against the C library's own "%.12g": byte for byte, over the magnitudes a history
// holds and over the cases where its shortcut gives way (rounding near a half, powers of ten,
// the ends of the double range).

#include "tools/fast_g12.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

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
    if (Fast(v) != Printf(v) && ++mismatches <= 5)
      FAIL_CHECK(Fast(v) << " against printf's " << Printf(v));
  }
  CHECK(mismatches == 0);
}

// One value against printf, both signs; the value's own %.17g in the message.
void CheckBothSigns(double v) {
  for (const double s : {v, -v}) {
    char exact[40];
    std::snprintf(exact, sizeof exact, "%.17g", s);
    INFO(exact << ": printf gives " << Printf(s));
    CHECK(Fast(s) == Printf(s));
  }
}

TEST_CASE("FormatG12 writes what printf's %.12g writes at the ends of the double range") {
  // Exact equality, as above. These reach the shortcut's table of powers at both ends (it
  // once read past it for values just above 1e-290) and the fallback beyond it.
  constexpr double kMax = std::numeric_limits<double>::max();
  constexpr double kMin = std::numeric_limits<double>::min();
  constexpr double kTiny = std::numeric_limits<double>::denorm_min();
  const double edge[] = {kMax,
                         std::nextafter(kMax, 0.0),
                         kMin,
                         std::nextafter(kMin, 0.0),  // the largest subnormal
                         std::nextafter(kMin, 1.0),
                         kTiny,
                         2 * kTiny,
                         1e-308,
                         1e-307,
                         1e308,
                         9.99999999999e307,
                         9.999999999995e307,  // rounds up to 1e+308 in the 12th digit
                         9.9999999999949e307,
                         9.999999999995e-309,  // subnormal, rounds up to 1e-308
                         9.999999999995e-291,  // below the shortcut, rounds up to its lower end
                         9.999999999995e-290,  // inside it, rounds up across 1e-289
                         9.999999999995e289,   // rounds up to the shortcut's upper end
                         9.999999999995e290,   // beyond it, rounds up to 1e291
                         1.00000000000049e-290,
                         1.0000000000005e290};
  for (const double v : edge) CheckBothSigns(v);
  // Every power of ten of the double range, its neighbours, and the values just below it that
  // round up across it in the 12th digit, or just do not.
  for (int k = -323; k <= 308; ++k) {
    const std::string power = "1e" + std::to_string(k);
    const double p = std::strtod(power.c_str(), nullptr);  // the double nearest 10^k
    INFO("10^" << k);
    CheckBothSigns(p);
    CheckBothSigns(std::nextafter(p, 0.0));
    CheckBothSigns(std::nextafter(p, kMax));
    for (const char* digits :
         {"9.999999999995e", "9.9999999999951e", "9.9999999999949e", "9.99999999999e"}) {
      CheckBothSigns(std::strtod((digits + std::to_string(k - 1)).c_str(), nullptr));
    }
  }
}

}  // namespace
}  // namespace tbridge::cli
