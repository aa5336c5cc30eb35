#include "design/sizing.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"
#include "core/member_area.h"

namespace tbridge {

const char* KindName(MemberKind kind) {
  switch (kind) {
    case MemberKind::kBar:
      return "bar";
    case MemberKind::kDeckString:
      return "deck_string";
    default:
      return "string";
  }
}

namespace {

// Areas and masses are finite for any config that passed CheckComputable (design/deck.h), short
// of a material at the edge of its range; the check keeps a NaN from reaching the output.
void CheckFinite(const MemberSizing& s, const MemberMaterial& m) {
  if (!std::isfinite(s.area) || !std::isfinite(s.radius)) {
    throw ConfigError("material.yield_stress", NumberText(m.yield_stress),
                      "with material.youngs_modulus = " + NumberText(m.youngs_modulus) +
                          " gives a member area of " + NumberText(s.area) + " m^2 (force " +
                          NumberText(s.force) + " N), outside what can be computed");
  }
  if (!std::isfinite(s.stiffness)) {
    throw ConfigError("material.youngs_modulus", NumberText(m.youngs_modulus),
                      "gives a string stiffness of " + NumberText(s.stiffness) +
                          " N/m, outside what can be computed");
  }
  if (!std::isfinite(s.mass)) {
    throw ConfigError("material.density", NumberText(m.density),
                      "gives a member mass of " + NumberText(s.mass) + " kg (area " +
                          NumberText(s.area) + " m^2), outside what can be computed");
  }
}

}  // namespace

double EulerArea(double length, double compression, double E) {
  // C = pi^2 E A^2 / (4 pi l^2)  =>  A = 2 l sqrt(C / (pi E)).
  return 2.0 * length * std::sqrt(std::max(compression, 0.0) / (std::numbers::pi * E));
}

MemberSizing SizeString(double length, double tension, double reference_tension, double min_area,
                        const MemberMaterial& m) {
  const double sigma_w = m.DesignStress();
  MemberSizing s;
  s.length = length;
  s.force = std::max(tension, 0.0);
  s.force_density = s.force / length;
  const double yield_area = s.force / sigma_w;
  // A prestressed minimum string sits at its floor; a relative slack of 1e-9 absorbs the
  // solver's tolerance on that bound.
  if (min_area > 0 && yield_area <= min_area * (1 + 1e-9)) {
    s.area = min_area;
    s.governed_by = LimitMode::kMinRadius;
  } else {
    s.area = yield_area;
    s.governed_by = LimitMode::kYield;
  }
  s.radius = RadiusOfArea(s.area);
  s.stress = s.area > 0 ? s.force / s.area : 0.0;
  s.reference_force = std::max(reference_tension, 0.0);
  s.rest_length = RestLengthOfArea(m.youngs_modulus, s.area, s.reference_force, length);
  s.stiffness = s.area > 0 ? AxialStiffness(m.youngs_modulus, s.area, s.rest_length) : 0.0;
  s.mass = MassOfArea(m.density, s.area, length);
  CheckFinite(s, m);
  return s;
}

void Govern(MemberSizing& m, double demand, double resistance, LimitMode mode) {
  m.demand = demand;
  m.resistance = resistance;
  m.utilisation = resistance > 0 ? demand / resistance : 0.0;
  m.mode = mode;
}

void RaiseUtilisation(MemberSizing& m, double demand, double resistance,
                      const std::string& governing_case, LimitMode mode) {
  if (!(resistance > 0) || demand / resistance <= m.utilisation) return;
  Govern(m, demand, resistance, mode);
  m.governing_case = governing_case;
}

double ColumnCurveChi(double lambda, double alpha) {
  const double phi = 0.5 * (1.0 + alpha * (lambda - 0.2) + lambda * lambda);
  return std::min(1.0, 1.0 / (phi + std::sqrt(std::max(phi * phi - lambda * lambda, 0.0))));
}

BarCapacity BarResistance(double area, double length, const BarRule& rule, double E) {
  BarCapacity c;
  c.yield = area * rule.yield_stress / rule.yield_factor;
  c.d_yield = rule.yield_stress / rule.yield_factor;
  // N_cr = pi^2 E I / l^2 with I = A^2 / (4 pi).
  const double n_cr = std::numbers::pi * E * area * area / (4.0 * length * length);
  if (!rule.column_curve) {
    c.buckling = n_cr / rule.buckling_factor;
    c.d_buckling =
        2.0 * std::numbers::pi * E * area / (4.0 * length * length) / rule.buckling_factor;
  } else {
    const double lambda = n_cr > 0 ? std::sqrt(area * rule.yield_stress / n_cr) : 0.0;
    const double chi = ColumnCurveChi(lambda, rule.imperfection);
    const double fy = rule.yield_stress / rule.buckling_factor;
    c.buckling = chi * area * fy;
    // lambda ~ A^(-1/2), so d lambda / dA = -lambda / (2 A); chi = 1 / D with
    // D = Phi + sqrt(Phi^2 - lambda^2) below its cap at 1.
    double d_chi_d_area = 0;
    if (chi < 1.0 && area > 0) {
      const double phi = 0.5 * (1.0 + rule.imperfection * (lambda - 0.2) + lambda * lambda);
      const double root = std::sqrt(std::max(phi * phi - lambda * lambda, 0.0));
      const double d_phi = 0.5 * rule.imperfection + lambda;
      const double d_D = d_phi + (root > 0 ? (phi * d_phi - lambda) / root : 0.0);
      d_chi_d_area = -chi * chi * d_D * (-lambda / (2.0 * area));
    }
    c.d_buckling = fy * (chi + area * d_chi_d_area);
  }
  return c;
}

namespace {

// Least area whose column-curve resistance reaches `compression`: the resistance grows
// monotonically with the area, so bisection in log(area) from the squat bound (chi = 1).
double ColumnCurveArea(double length, double compression, const BarRule& rule, double E) {
  double lo = compression * rule.buckling_factor / rule.yield_stress;  // chi = 1: a lower bound
  if (!(lo > 0)) return 0.0;
  auto carries = [&](double a) {
    return BarResistance(a, length, rule, E).buckling >= compression;
  };
  double hi = lo;
  for (int k = 0; k < 2100 && !carries(hi); ++k) hi *= 2.0;  // bounded: a non-finite area ends it
  if (hi == lo) return lo;
  lo = hi / 2.0;
  // 60 halvings of a factor-2 bracket leave it 1e-18 wide relative: below rounding.
  for (int k = 0; k < 60 && hi > lo * (1 + 1e-15); ++k) {
    const double mid = std::sqrt(lo * hi);
    (carries(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

MemberSizing SizeBar(double length, double compression, double min_area, const BarRule& rule,
                     const MemberMaterial& m) {
  MemberSizing b;
  b.length = length;
  b.rest_length = length;
  b.force = std::max(compression, 0.0);
  b.force_density = b.force / length;
  const double yield_area = b.force * rule.yield_factor / rule.yield_stress;
  const double buckling_area =
      rule.column_curve ? ColumnCurveArea(length, b.force, rule, m.youngs_modulus)
                        : EulerArea(length, rule.buckling_factor * b.force, m.youngs_modulus);
  b.area = yield_area;
  b.governed_by = LimitMode::kYield;
  if (buckling_area > b.area) {
    b.area = buckling_area;
    b.governed_by = LimitMode::kBuckling;
  }
  if (min_area > b.area) {
    b.area = min_area;
    b.governed_by = LimitMode::kMinRadius;
  }
  b.radius = RadiusOfArea(b.area);
  b.stress = b.area > 0 ? b.force / b.area : 0.0;
  b.mass = MassOfArea(m.density, b.area, length);
  CheckFinite(b, m);
  return b;
}

}  // namespace tbridge
