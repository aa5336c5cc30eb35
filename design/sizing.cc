#include "design/sizing.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace tbridge {

const char* KindName(MemberKind kind) {
  switch (kind) {
    case MemberKind::kBar: return "bar";
    case MemberKind::kDeckString: return "deck_string";
    default: return "string";
  }
}

namespace {

// Areas and masses are finite for any config that passed CheckComputable (design/deck.h), short
// of a material at the edge of its range; the check keeps a NaN from reaching the output.
void CheckFinite(const MemberSizing& s, const Material& m) {
  if (!std::isfinite(s.area) || !std::isfinite(s.radius)) {
    throw ConfigError("material.yield_stress", std::to_string(m.yield_stress),
                      "with material.youngs_modulus = " + std::to_string(m.youngs_modulus) +
                          " gives a member area of " + std::to_string(s.area) + " m^2 (force " +
                          std::to_string(s.force) + " N), outside what can be computed");
  }
  if (!std::isfinite(s.stiffness)) {
    throw ConfigError("material.youngs_modulus", std::to_string(m.youngs_modulus),
                      "gives a string stiffness of " + std::to_string(s.stiffness) + " N/m, outside what can be computed");
  }
  if (!std::isfinite(s.mass)) {
    throw ConfigError("material.density", std::to_string(m.density),
                      "gives a member mass of " + std::to_string(s.mass) + " kg (area " + std::to_string(s.area) +
                          " m^2), outside what can be computed");
  }
}

}  // namespace

double EulerArea(double length, double compression, double E) {
  // C = pi^2 E A^2 / (4 pi l^2)  =>  A = 2 l sqrt(C / (pi E)).
  return 2.0 * length * std::sqrt(std::max(compression, 0.0) / (std::numbers::pi * E));
}

MemberSizing SizeString(double length, double tension, double min_area, double sigma_w,
                        const Material& m) {
  MemberSizing s;
  s.length = length;
  s.force = std::max(tension, 0.0);
  s.force_density = s.force / length;
  const double yield_area = s.force / sigma_w;
  // A prestressed minimum string sits at its floor; a relative slack of 1e-9 absorbs the
  // solver's tolerance on that bound.
  if (min_area > 0 && yield_area <= min_area * (1 + 1e-9)) {
    s.area = min_area;
    s.governed_by = "min_radius";
  } else {
    s.area = yield_area;
    s.governed_by = "yield";
  }
  s.radius = std::sqrt(s.area / std::numbers::pi);
  s.stress = s.area > 0 ? s.force / s.area : 0.0;
  s.rest_length = length / (1.0 + s.stress / m.youngs_modulus);
  s.stiffness = s.area > 0 ? m.youngs_modulus * s.area / s.rest_length : 0.0;
  s.mass = m.density * s.area * length;
  CheckFinite(s, m);
  return s;
}

MemberSizing SizeBar(double length, double compression, double min_area, double sigma_w,
                     double buckling_sf, const Material& m) {
  MemberSizing b;
  b.length = length;
  b.rest_length = length;
  b.force = std::max(compression, 0.0);
  b.force_density = b.force / length;
  const double yield_area = b.force / sigma_w;
  const double buckling_area = EulerArea(length, buckling_sf * b.force, m.youngs_modulus);
  b.area = yield_area;
  b.governed_by = "yield";
  if (buckling_area > b.area) {
    b.area = buckling_area;
    b.governed_by = "buckling";
  }
  if (min_area > b.area) {
    b.area = min_area;
    b.governed_by = "min_radius";
  }
  b.radius = std::sqrt(b.area / std::numbers::pi);
  b.stress = b.area > 0 ? b.force / b.area : 0.0;
  b.mass = m.density * b.area * length;
  CheckFinite(b, m);
  return b;
}

}  // namespace tbridge
