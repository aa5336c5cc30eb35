// The full minimum-mass problem, independent of any solver (SPEC.md §4): every member force
// is a variable and node equilibrium is an equality. The design solves the same problem in the
// self-stress coordinates (design/reduced_min_mass.h); this form is its cross-check.
//
// Variables (all scaled to O(1)):
//   c_b = C_b / F_ref           bar compressions,            b = 0..n_b-1
//   t_k = T_k / F_ref           string tensions,             k = 0..n_s-1
//   a_b = A_b sigma_w / F_ref   bar areas as yield capacity, b = 0..n_b-1
// Constraints:
//   equilibrium  A [c; t] = -w / F_ref                  (one row per free DOF)
//   yield        a_b - c_b >= 0                         (bar area covers the force at sigma_w)
//   buckling     a_b^2 - kappa_b^2 c_b >= 0             (Euler, pinned-pinned, solid circle)
//   bounds       c, t >= 0; t_k >= t_min_k (prestressed minimum strings); a_b >= a_min_b
// Objective: (structure mass) / M_ref = sum_b (l_b / L_ref) a_b + sum_k (l_k / L_ref) t_k,
// with M_ref = rho L_ref F_ref / sigma_w: strings work at sigma_w, bars at their governing area.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "core/material.h"
#include "core/structure.h"
#include "design/equilibrium.h"
#include "optim/nlp.h"

namespace tbridge {

struct MinMassSettings {
  // What the members are made of. The problems count forces in units of the strings' design
  // stress: a bar's area variable is in units of its own, and its mass per unit carries the
  // ratio BarMassRatio().
  MemberMaterial strings, bars;
  double buckling_safety_factor = 1;  // on the bar force in the Euler check
  // A bar's mass per unit of force it carries over a string's: (rho_b / sigma_b) / (rho_s /
  // sigma_s).
  double BarMassRatio() const {
    return (bars.density / bars.DesignStress()) / (strings.density / strings.DesignStress());
  }
  std::vector<double> string_min_tension;  // per string [N] (prestress floor), may be 0
  std::vector<double> bar_min_area;        // per bar [m^2], may be 0
};

class MinMassProblem final : public NlpProblem {
 public:
  // `loads` is 3 x n_n [N]. Throws ModelError on inconsistent sizes.
  MinMassProblem(const Structure& structure, const Eigen::Matrix3Xd& loads,
                 MinMassSettings settings);

  int num_bars() const { return nb_; }
  int num_strings() const { return ns_; }
  int num_variables() const override { return 2 * nb_ + ns_; }
  int num_equalities() const override { return static_cast<int>(rhs_.size()); }
  int num_constraints() const override { return num_equalities() + 2 * nb_; }
  // Index helpers into x.
  int bar_force_index(int b) const { return b; }
  int string_force_index(int k) const { return nb_ + k; }
  int bar_area_index(int b) const { return nb_ + ns_ + b; }

  // Bounds on x and on g(x) (equalities have lo = hi); +inf as std::numeric_limits::infinity.
  void VariableBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const override;
  void ConstraintBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const override;
  // A feasible-ish start: least-norm equilibrium solution, pushed inside the bounds.
  Eigen::VectorXd StartingPoint() const;

  double Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const override;
  void ObjectiveGradient(const Eigen::Ref<const Eigen::VectorXd>&,
                         Eigen::Ref<Eigen::VectorXd> grad) const override {
    grad = cost_;  // constant
  }
  void Constraints(const Eigen::Ref<const Eigen::VectorXd>& x,
                   Eigen::Ref<Eigen::VectorXd> g) const override;

  // Jacobian of g: fixed sparsity (row, col) and values in that order.
  const Pattern& JacobianPattern() const override { return jac_pattern_; }
  void JacobianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double* values) const override;
  // Hessian of the Lagrangian sigma f + sum lambda_i g_i: only the buckling rows contribute,
  // 2 lambda on each a_b diagonal. Pattern is the n_b diagonal entries of the a block.
  const Pattern& HessianPattern() const override { return hess_pattern_; }
  void HessianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double sigma, const double* lambda,
                     double* values) const override;

  // Unscaled results.
  double MassScale() const { return mass_ref_; }    // kg per objective unit
  double ForceScale() const { return force_ref_; }  // N per force unit
  Eigen::VectorXd MemberForces(const Eigen::Ref<const Eigen::VectorXd>& x) const;  // [C; T] in N
  const EquilibriumSystem& equilibrium() const { return eq_; }
  const MinMassSettings& settings() const { return settings_; }
  // Buckling coefficient kappa_b (scaled): a_b >= kappa_b sqrt(c_b).
  double Kappa(int b) const { return kappa_[b]; }

 private:
  int nb_ = 0, ns_ = 0;
  MinMassSettings settings_;
  EquilibriumSystem eq_;
  Eigen::VectorXd rhs_;   // -w_free / F_ref
  Eigen::VectorXd cost_;  // objective gradient
  Eigen::VectorXd kappa_;
  Eigen::VectorXd t_min_, a_min_;
  double force_ref_ = 1, mass_ref_ = 1;
  Pattern jac_pattern_, hess_pattern_;
  std::vector<double> eq_values_;  // constant equality-row values, in pattern order
};

}  // namespace tbridge
