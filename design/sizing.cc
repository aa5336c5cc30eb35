#include "design/sizing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tbridge {

const char* KindName(MemberKind kind) {
  switch (kind) {
    case MemberKind::kBar: return "bar";
    case MemberKind::kDeckString: return "deck_string";
    default: return "string";
  }
}

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
  return b;
}

}  // namespace tbridge
