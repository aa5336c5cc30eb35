// What the tests of the prestress's other states share (tests/verify/rest_length_tolerance_test.cc,
// temperature_test.cc): the first-order change of a one-self-stress bridge's prestress that
// members' shortenings make, and the sizing's rows in the two other states against its rows as
// designed at the prestress shifted either way.
#pragma once

#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <vector>

#include "design/design.h"
#include "sizing/sizing_problem.h"

namespace tbridge::test {

// The first-order change of the prestress on a bridge of one self-stress P that the shortenings
// delta ([bars; strings] [m]) of the members' stress-free lengths make: the compatibility
// sum_j P_j (f_j dt_j - delta_j) = 0 with dt = c P, f_j = l_j / (E A_j + T_j) a string's
// flexibility and 0 a bar's (rigid), so c = sum P delta / sum_strings P^2 f.
inline Eigen::VectorXd FirstOrderChange(const Design& d, const std::vector<double>& shortenings) {
  const Eigen::VectorXd p = PrestressForces(d);
  const int nb = static_cast<int>(d.bars.size());
  const double modulus = StringMaterial(d.config).youngs_modulus;
  double num = 0, den = 0;
  for (Eigen::Index j = 0; j < p.size(); ++j) num += p[j] * shortenings[static_cast<size_t>(j)];
  for (size_t k = 0; k < d.strings.size(); ++k) {
    const MemberSizing& m = d.strings[k];
    const double pk = p[nb + static_cast<Eigen::Index>(k)];
    den += pk * pk * m.length / (modulus * m.area + m.reference_force);
  }
  return (num / den) * p;
}

// The rows of `with` (the design `d`'s, posed in three states) in its second and third states
// against `without`'s (the same bridge as designed only) at d's prestress plus and minus
// `change`: the same code at two points, so equal to rounding (1e-10 of a row's scale).
inline void CheckShiftedRows(const Design& d, const SizingProblem& with,
                             const SizingProblem& without, const Eigen::VectorXd& change) {
  const int n = without.num_constraints();
  REQUIRE(with.num_constraints() == 3 * n);
  const std::vector<double> areas = MemberAreas(d);
  const Eigen::VectorXd x = with.VariablesOf(areas, with.AlphaOf(d.reference_forces));
  const Eigen::VectorXd up =
      without.VariablesOf(areas, without.AlphaOf(d.reference_forces + change));
  const Eigen::VectorXd down =
      without.VariablesOf(areas, without.AlphaOf(d.reference_forces - change));
  Eigen::VectorXd g(with.num_constraints()), g_up(n), g_down(n);
  with.Constraints(x, g);
  without.Constraints(up, g_up);
  without.Constraints(down, g_down);
  CHECK((g.segment(n, n) - g_up).cwiseAbs().maxCoeff() <= 1e-10);
  CHECK((g.tail(n) - g_down).cwiseAbs().maxCoeff() <= 1e-10);
}

}  // namespace tbridge::test
