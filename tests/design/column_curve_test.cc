// The bar's column curve against EN 1993-1-1 eq. 6.49 worked by hand and the printed values
// of its Table 6.2 curve c, and the column-curve sizing against that resistance.

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "core/material.h"
#include "design/sizing.h"

namespace tbridge {
namespace {

// Eq. 6.49, written out here rather than taken from the product.
double HandChi(double lambda, double alpha) {
  const double phi = 0.5 * (1.0 + alpha * (lambda - 0.2) + lambda * lambda);
  return 1.0 / (phi + std::sqrt(phi * phi - lambda * lambda));
}

constexpr double kCurveC = 0.49;  // alpha of curve c (solid sections)

TEST_CASE("column curve c matches eq. 6.49 and the printed table") {
  // lambda = 0.2 is the plateau's end: Phi = 0.52, sqrt(0.2704 - 0.04) = 0.48, chi = 1. The
  // sum 0.52 + 0.48 rounds, so allow a few ulps.
  CHECK(ColumnCurveChi(0.2, kCurveC) == Approx(1.0).epsilon(1e-15));
  CHECK(ColumnCurveChi(0.1, kCurveC) == 1.0);  // below 0.2 the formula exceeds 1 and is capped
  // Same formula, same operations up to order: agreement to a few rounding steps.
  CHECK(ColumnCurveChi(1.0, kCurveC) == Approx(HandChi(1.0, kCurveC)).epsilon(1e-14));
  CHECK(ColumnCurveChi(2.0, kCurveC) == Approx(HandChi(2.0, kCurveC)).epsilon(1e-14));
  // Printed 4-digit values of curve c (0.5970 and 0.2095 are curve b's, alpha = 0.34): the
  // hand values are 0.539939 and 0.196184, so half a unit of the last printed digit.
  CHECK(std::abs(ColumnCurveChi(1.0, kCurveC) - 0.5399) <= 0.5e-4);
  CHECK(std::abs(ColumnCurveChi(2.0, kCurveC) - 0.1962) <= 0.5e-4);
  // The curve b values, to show the table rows are told apart by alpha.
  CHECK(std::abs(ColumnCurveChi(1.0, 0.34) - 0.5970) <= 0.5e-4);
  CHECK(std::abs(ColumnCurveChi(2.0, 0.34) - 0.2095) <= 0.5e-4);
}

TEST_CASE("column-curve sizing gives the least area that carries the force") {
  const Material steel;  // E 2.06e11, f_y 6.9e8
  BarRule rule;
  rule.column_curve = true;
  rule.yield_stress = steel.yield_stress;
  rule.yield_factor = 1.1;
  rule.buckling_factor = 1.1;
  rule.imperfection = kCurveC;
  // A slender bar (3 m, 100 kN: lambda 3.8) so buckling governs.
  const double length = 3.0, force = 1e5;
  const MemberSizing b = SizeBar(length, force, 0.0, rule, BarMaterial(steel, 1.1));
  CHECK(b.governed_by == LimitMode::kBuckling);
  const double carried = BarResistance(b.area, length, rule, steel.youngs_modulus).buckling;
  // The bisection stops at a 1e-15 relative bracket in area; the resistance grows like A^2
  // at most, so it lands within a few 1e-15 of the force, above it.
  CHECK(carried >= force);
  CHECK(carried / force - 1.0 <= 1e-12);
  // 0.1 % less area loses at least 0.1 % of resistance (it grows at least like A): not enough.
  CHECK(BarResistance(0.999 * b.area, length, rule, steel.youngs_modulus).buckling < force);
  // Independently of the bisection: chi of that area's slenderness by hand, times A f_y / gamma.
  const double n_cr =
      std::numbers::pi * steel.youngs_modulus * b.area * b.area / (4.0 * length * length);
  const double lambda = std::sqrt(b.area * steel.yield_stress / n_cr);
  CHECK(lambda > 1.0);  // really on the slender branch
  CHECK(HandChi(lambda, kCurveC) * b.area * steel.yield_stress / 1.1 ==
        Approx(force).epsilon(1e-12));
}

}  // namespace
}  // namespace tbridge
