// What a member's area sets (core/member_area.h): the radius, the mass and the two forms of a
// string's stiffness, against closed forms and against each other.
#include "core/member_area.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "core/string_law.h"

namespace tbridge {
namespace {

TEST_CASE("a member's radius and mass from its area", "[member_area]") {
  const double r = 0.0125, area = std::numbers::pi * r * r;  // [m], [m^2]
  CHECK(RadiusOfArea(area) == Approx(r).epsilon(1e-15));     // a square root of a rounded product
  CHECK(RadiusOfArea(0.0) == 0.0);
  // 1 m^2 of steel 2 m long: 2 x 7862 kg, exact in binary.
  CHECK(MassOfArea(7862.0, 1.0, 2.0) == 15724.0);
  CHECK(MassOfArea(7862.0, area, 3.5) ==
        Approx(7862.0 * std::numbers::pi * r * r * 3.5).epsilon(1e-15));
}

TEST_CASE("a string's stiffness: E A / L0 at its rest length is (E A + T) / L at its length",
          "[member_area]") {
  const double E = 2.06e11, area = 4.9e-4, tension = 6.9e4, length = 3.7;  // SI
  const double rest = RestLengthOfArea(E, area, tension, length);
  // The closed form: L0 = L / (1 + sigma / E), sigma = T / A.
  CHECK(rest == Approx(length / (1 + tension / area / E)).epsilon(1e-15));
  const double k = AxialStiffness(E, area, rest);
  CHECK(k == Approx(E * area / rest).epsilon(1e-15));
  // The two forms differ by rounding only: a few ulps of k.
  CHECK(TautStringStiffness(E, area, tension, length) == Approx(k).epsilon(1e-14));
  // The string so made carries T at L: L - L0 is 7e-4 L, so the subtraction keeps ~12 digits.
  CHECK(StringTension(k, rest, length) == Approx(tension).epsilon(1e-10));
  // No area: the rest length is the length, and a taut string's force alone stiffens it.
  CHECK(RestLengthOfArea(E, 0.0, tension, length) == length);
  CHECK(TautStringStiffness(E, 0.0, tension, length) == tension / length);
}

}  // namespace
}  // namespace tbridge
