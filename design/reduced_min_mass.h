// The minimum-mass problem in the self-stress coordinates (SPEC.md §4, same optimum as the full
// problem of design/min_mass.h).
//
// Every equilibrium solution of load case c is x^c = x_p^c + N alpha (design/equilibrium_basis.h),
// with the self-stress coefficients alpha shared by every case. A member whose row of N is
// zero ("fixed" member) has the same forces for every alpha, so its area is known: strings
// max(T, T_min) / sigma_w, bars max(C / sigma_w, Euler, minimum) over the cases. Only the
// members in the self-stresses ("active" members) enter the program:
//
// Variables (scaled by F_ref, like the full problem):
//   alpha_k                  self-stress coefficients [F_ref],          k = 0..s-1
//   e_j = A_j sigma_w / F_ref  envelope area of each active bar, and of each active string when
//                            there is more than one load case (one case: a string's area is
//                            its tension, so the tension itself is priced)
// Constraints, for every case c and active member j, f_j^c = p_j^c + N_j alpha (scaled force):
//   floor     N_j alpha >= lo_j - p_j^c              (lo: 0 for bars, T_min for strings)
//   envelope  e_j - N_j alpha >= p_j^c               (members with an envelope variable)
//   buckling  e_j^2 - kappa_j^2 N_j alpha >= kappa_j^2 p_j^c   (active bars; Euler, solid circle)
//   bounds    e_j >= a_min_j (bars), T_min_j (strings)
// Objective: (structure mass) / M_ref, linear: the fixed members' mass is a constant.
//
// With no self-stress, or one that loads strings only (planar p >= 1: the deck chain), the
// objective is linear in alpha on an interval and SolveDirect() takes its cheaper end: no
// iteration. Otherwise (the 3D bridge) the small program above goes to Ipopt or NLopt.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/structure.h"
#include "design/equilibrium_basis.h"
#include "design/min_mass.h"
#include "optim/nlp.h"

namespace tbridge {

// The force scale F_ref of the problem [N]: its largest particular force or tension floor (1 N
// when both are zero). Scaled forces are O(1), and the design's equilibrium checks use it too.
double SelfStressForceScale(const EquilibriumBasis& basis, const MinMassSettings& settings);

class ReducedMinMassProblem final : public NlpProblem {
 public:
  // `basis` holds the particular solutions of every load case and the self-stresses of
  // `structure`; `settings` as for the full problem. Throws ModelError on size mismatches, and
  // when a fixed member is infeasible in some case (a bar in tension or a string below its
  // floor that no self-stress can reach).
  ReducedMinMassProblem(const Structure& structure, const EquilibriumBasis& basis,
                        MinMassSettings settings);

  int num_self_stresses() const { return s_; }
  int num_cases() const { return static_cast<int>(p_.cols()); }
  int num_active() const { return static_cast<int>(active_.size()); }
  int num_active_bars() const { return active_bars_; }
  // True when SolveDirect() applies: no self-stress, or one that loads no bar.
  bool DirectApplies() const { return s_ == 0 || (s_ == 1 && active_bars_ == 0); }
  // The optimum without iteration; throws ModelError when the interval of alpha is empty
  // (infeasible) or the cheaper end is unbounded. Requires DirectApplies().
  SolverOutcome SolveDirect(Eigen::VectorXd& x) const;

  int num_variables() const override { return s_ + num_envelopes_; }
  int num_constraints() const override { return static_cast<int>(row_lo_.size()); }
  void VariableBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const override;
  void ConstraintBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const override;
  Eigen::VectorXd StartingPoint() const;
  double Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const override;
  void ObjectiveGradient(const Eigen::Ref<const Eigen::VectorXd>&,
                         Eigen::Ref<Eigen::VectorXd> grad) const override {
    grad = cost_;  // constant
  }
  void Constraints(const Eigen::Ref<const Eigen::VectorXd>& x,
                   Eigen::Ref<Eigen::VectorXd> g) const override;
  const Pattern& JacobianPattern() const override { return jac_pattern_; }
  void JacobianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double* values) const override;
  const Pattern& HessianPattern() const override { return hess_pattern_; }
  void HessianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double sigma, const double* lambda,
                     double* values) const override;

  double MassScale() const { return mass_ref_; }    // kg per objective unit
  double ForceScale() const { return force_ref_; }  // N per scaled force unit
  // Member forces [C; T] in N of load case `c` at x: x_p^c + N alpha, with the whole basis
  // (also the entries below the activity threshold), so equilibrium holds to rounding.
  Eigen::VectorXd MemberForces(const Eigen::Ref<const Eigen::VectorXd>& x, int c) const;

 private:
  struct Active {
    int member;    // index into [bars; strings]
    int envelope;  // variable index of e_j, or -1
    bool bar;
    double weight;                            // l_j / L_ref: objective per unit of scaled area
    double lo;                                // floor of the scaled force (0 bars, T_min strings)
    double kappa;                             // buckling coefficient (bars)
    std::vector<std::pair<int, double>> row;  // nonzeros (k, N_jk) of N's row
  };
  // One constraint row: kind 0 floor, 1 envelope, 2 buckling; of active member a in case c.
  struct Row {
    int kind, active, c;
  };
  double ScaledForce(const Active& a, int c, const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // The constructor's constraint rows (rows_, row_lo_) and the sparsity patterns.
  void FormRows();

  int nb_ = 0, ns_ = 0, s_ = 0, num_envelopes_ = 0, active_bars_ = 0;
  MinMassSettings settings_;
  Eigen::MatrixXd p_;  // scaled particular forces, members x cases
  Eigen::MatrixXd n_;  // self-stress basis, members x s (orthonormal)
  std::vector<Active> active_;
  std::vector<Row> rows_;
  Eigen::VectorXd row_lo_, var_lo_, cost_;
  double constant_ = 0;  // objective of the fixed members (and of priced string tensions)
  double force_ref_ = 1, mass_ref_ = 1;
  Pattern jac_pattern_, hess_pattern_;
  std::vector<int>
      hess_of_active_;  // Hessian entry of each active member's envelope, -1 for strings
};

}  // namespace tbridge
