// The verified minimum-mass sizing as one nonlinear program (docs/verified_sizing.md): the
// member areas and the prestress are the variables, and every load case's member forces
// and deflections come from the linear stiffness analysis about the reference state
// (design/linear_response.h), so the constraints see the forces the bridge carries.
//
//   min  sum_j rho l_j A_j
//   over A_g (one per group of mirror-image members) and alpha (self-stress coefficients)
//   s.t. for every ultimate combination c (each travelling station one combination):
//          kappa_j C_cj <= R_j(A_j) (bars: buckling and yield), kappa_j T_cj <= sigma_w A_j,
//        for every combination c: T_cs >= tau_s for the strings that must stay taut,
//        for every serviceability combination c:
//          kappa_d |v_cn| <= span / deflection_limit at each deck node,
//          kappa_j T_cs <= sigma_ser A_s for every string (the characteristic stress limit of a
//          tension component, MemberMaterial::ServiceStress),
//        T_s >= 0 in the reference state, A_j >= the member's minimum area,
//        for each comfort row: omega_k^2(A, alpha) >= (or <=) its target (ComfortRow),
//        for every ultimate combination c and abutment a, where supports.* gives a capacity:
//          kappa_h |H_ca| <= H_cap, kappa_v |V_ca| <= V_cap (the reactions at the drawn
//          directions: minus the member forces on the abutment's nodes and their loads),
//   x_c = x_G + N alpha + dx_c(A, alpha),  dx_c the linear response to f_c - f_G;
// every row but the comfort rows again in each other state of the prestress
// (design/prestress_states.h: alpha -> (1 - loss) alpha -/+ the rest-length tolerance's change).
//
// kappa (per member), kappa_d and kappa_h, kappa_v correct the linear demand by what the nonlinear
// static check and the dynamic runs found, either way (sizing/verified_design.h); tau_s the taut
// margin they ask. The members' weight in G is held at the design the problem was built from (the
// outer iterations update it). Gradients are exact (adjoint sensitivities); the Hessian is the
// reciprocal diagonal of optim/reciprocal_curvature.h, the SQP's own curvature (NLopt's SLSQP
// approximates it instead).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "design/design.h"
#include "design/limit_mode.h"
#include "design/prestress_states.h"
#include "optim/nlp.h"

namespace tbridge {

// One comfort row (sizing/comfort_sizing.h builds them from a design's deck modes): a mode's
// eigenvalue held above (or below) the frequency at which its Sétra acceleration meets its
// limit or it leaves the risk ranges. The eigenvalue is the Rayleigh quotient of the mode's
// shape at the design the problem is built from (x0),
//
//   omega^2(x) = (omega0^2 + sum_j by_area_j dA_j + sum_j by_force_j dF_j) / (1 + sum_j
//   mass_by_area_j dA_j)
//
// with dA, dF each member's area and reference force less x0's: K and M are affine in both at
// the shape and state held, so the row's value and gradient are the eigenvalue's at x0
// (d omega^2 = phi^T (dK - omega^2 dM) phi, dynamics/modal_sensitivity.h), and the outer
// iterations rebuild it from the next design's modes, as the corrections of the other rows.
struct ComfortRow {
  std::string label;  // the mode and what its bound is, for the report
  std::string
      key;  // the mode and the bound's side ("vertical 2 crowded"), the same from sizing to sizing
  bool lower = true;         // omega^2 >= target (stay above, or climb out of a range); else <=
  bool below = false;        // the mode held on the passing piece below (ComfortRowsOf's `below`)
  double target_omega2 = 0;  // [rad^2/s^2]
  double omega2 = 0;         // at x0 [rad^2/s^2]
  // Per member [bars; strings]:
  std::vector<double> by_area;  // d omega^2 / dA through its stiffness [rad^2/s^2 per m^2]
  std::vector<double>
      by_force;  // d omega^2 / d(its reference force, bars in compression) [rad^2/s^2 per N]
  std::vector<double> mass_by_area;  // d(phi^T M phi) / dA [1/m^2]
  // Where set, the row follows its mode: the mode's own eigenvalue and coefficients at the areas
  // and reference forces given (per member [bars; strings]), its shape found again there with the
  // static state held (sizing/comfort_sizing.h). The row is then the eigenvalue itself, not the
  // quotient of a shape held: that quotient overestimates the eigenvalue after a move, and a
  // sizing left free with it concentrated stiffness where it overestimated most (the default at
  // n = 3: strings grown seven times, others to a tenth, its frequency foretold 4.0 Hz and found
  // 2.7 Hz).
  std::function<ComfortRow(const std::vector<double>& areas, const Eigen::VectorXd& forces)> follow;
};

// What the outer iterations tell the problem (all sized by [bars; strings]).
struct SizingCorrections {
  std::vector<double> demand_factor;  // kappa_j on each member's linear demand (1: none)
  std::vector<double> taut_margin_n;  // tau_s [N] per member (strings that must stay taut)
  double deflection_factor = 1.0;     // kappa_d on the linear deflections
  // kappa_h, kappa_v on the linear abutment reactions: the static check's reactions at the
  // deformed geometry over the linear ones at the drawn directions.
  double horizontal_reaction_factor = 1.0;
  double vertical_reaction_factor = 1.0;
  std::vector<ComfortRow> comfort;  // the comfort rows, about the design the problem is built from
};

// One constraint row's meaning, for the report: which member (or deck node), combination and
// kind.
struct SizingRow {
  enum Kind {
    kStrength,
    kBuckling,
    kYield,
    kTaut,
    kDeflectionDown,
    kDeflectionUp,
    kReferenceTaut,
    kServiceStress,  // a string's stress in a characteristic combination, at most sigma_ser
    kSupportHorizontal,
    kSupportVertical,
    kComfort  // the last: kComfort + 1 kinds
  };
  Kind kind = kStrength;
  // [bars; strings] index, the deck node for a deflection row, the abutment (0: x = 0, 1: the
  // far end) for a support row, the SizingCorrections::comfort entry for a comfort row
  int member = -1;
  int combination = -1;
  // The state of the prestress it is posed in (PrestressState, design/prestress_states.h: 0 as
  // designed); `combination` is that state's.
  int state = 0;
};
// The mode a row of `kind` limits (yield for both strength rows, deflection for both
// directions, supports for both components), and its text.
LimitMode ModeOfRow(SizingRow::Kind kind);
const char* SizingRowKindName(SizingRow::Kind kind);

// One combination of a case and (for a travelling family) a station.
struct SizingCombination {
  int case_index = 0;
  int station = -1;
  bool ultimate = true;
  std::string label;
};

// Each member's mirror image across the bridge's planes of symmetry (x = span / 2; between the
// planes of a 3D bridge), joined into groups: per member [bars; strings], its group (0-based).
// A member and its images share one area, and the prestress gives them one force.
std::vector<int> MirrorGroups(const Structure& s, double span);

class SizingProblem final : public NlpProblem {
 public:
  // Most self-stress states the problem takes as variables: only the symmetric ones count (the
  // prestress gives mirror-image members equal forces, as they share an area). The dense basis
  // and one sensitivity solve per state stay affordable up to here.
  static constexpr int kMaxStates = 64;
  // Most self-stress states among which the symmetric ones are sought: their dense basis and
  // its SVD grow as states^2 x members (the 3D bridge at n = 8: 2 042 states, 5 000 members),
  // and on these bridges about a third of the states are symmetric (79 of 250 at n = 5), so
  // beyond four times the limit they are over it.
  static constexpr int kMaxSoughtStates = 4 * kMaxStates;
  // The number of symmetric self-stress states of a design's structure (the problem's), or -1
  // where it has more than kMaxSoughtStates states and they are not sought.
  static int SymmetricStates(const Design& design);
  // `design`: a design whose topology, actions, cases and reference loads the problem takes
  // (its members' weight held). Throws ModelError when the bridge has more symmetric
  // self-stress states than kMaxStates (or more states than kMaxSoughtStates) or the reference
  // state has no stiffness.
  // `keep` (optional, one flag per row of the whole problem, in rows() order of the whole
  // problem): the rows this problem poses; the others are left out (an active set).
  SizingProblem(const Design& design, SizingCorrections corrections,
                const std::vector<char>* keep = nullptr);
  ~SizingProblem() override;

  int num_variables() const override;
  int num_constraints() const override;
  void VariableBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const override;
  void ConstraintBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const override;
  double Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const override;
  void ObjectiveGradient(const Eigen::Ref<const Eigen::VectorXd>& x,
                         Eigen::Ref<Eigen::VectorXd> grad) const override;
  void Constraints(const Eigen::Ref<const Eigen::VectorXd>& x,
                   Eigen::Ref<Eigen::VectorXd> g) const override;
  const Pattern& JacobianPattern() const override;
  void JacobianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double* values) const override;
  bool DenseJacobian(const Eigen::Ref<const Eigen::VectorXd>& x,
                     Eigen::MatrixXd& jac) const override;
  const Pattern& HessianPattern() const override;  // the diagonal
  void HessianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double sigma, const double* lambda,
                     double* values) const override;

  // The variables of a design's own areas and prestress (its start), and back.
  Eigen::VectorXd VariablesOf(const std::vector<double>& areas, const Eigen::VectorXd& alpha) const;
  std::vector<double> Areas(const Eigen::VectorXd& x) const;  // per member [bars; strings] [m^2]
  Eigen::VectorXd Alpha(const Eigen::VectorXd& x) const;      // self-stress coefficients [N]
  // The coefficients of the prestress in reference forces [N] carrying this problem's G.
  Eigen::VectorXd AlphaOf(const Eigen::VectorXd& reference_forces) const;
  // Each member's largest linear utilisation (with its correction) over the combinations,
  // and the row that gives it.
  struct MemberDemand {
    double utilisation = 0;
    double demand = 0;      // [N], corrected
    double resistance = 0;  // [N]
    int row = -1;
  };
  std::vector<MemberDemand> Demands(const Eigen::VectorXd& x) const;
  // Each row's margin, where Constraints gives it as posed: a strength row's 1 - kappa F / R(A)
  // (its utilisation's complement) where it is posed as (R(A) - kappa F) / R_ref; the other
  // rows as posed. Both hold (>= 0) together.
  void Margins(const Eigen::VectorXd& x, Eigen::VectorXd& margin) const;
  // The largest vertical deck deflection over the serviceability combinations [m], as the
  // linear analysis gives it (without kappa_d).
  double LargestDeflection(const Eigen::VectorXd& x) const;
  // The largest horizontal and vertical abutment reactions over the ultimate combinations [N],
  // as the linear analysis gives them (without kappa_h, kappa_v); zero where no capacity is
  // given (the problem has no support rows of that kind).
  struct Reactions {
    double horizontal = 0, vertical = 0;
  };
  Reactions LargestReactions(const Eigen::VectorXd& x) const;
  const std::vector<SizingRow>& rows() const;
  // The scales of the program: objective = mass / mass_scale_kg; a tension row = force /
  // force_scale_n; an area variable = area / area_scale_m2(its group), the group's area in the
  // design the problem is built from: each variable starts near 1, and SLSQP's first Hessian,
  // the identity, weighs them alike (one scale of 1e-4 m^2 for all took 1 700 evaluations
  // against 1 375 at n = 5).
  double mass_scale_kg() const;
  double force_scale_n() const;
  double area_scale_m2(int group) const;
  // Row r's scale as posed: a strength row is (R(A) - kappa F) / row_scale(r), its member's
  // resistance at the problem's own area [N]; 1 for the other rows.
  double row_scale(int r) const;
  const std::vector<SizingCombination>& combinations() const;  // the intact state's
  // What row r is about, for the report: its combination's label, or a comfort row's.
  const std::string& RowLabel(int r) const;
  const std::vector<ComfortRow>& comfort_rows() const;  // SizingCorrections::comfort
  // The eigenvalue comfort row r's Rayleigh quotient gives at x [rad^2/s^2].
  double ComfortOmega2(int r, const Eigen::VectorXd& x) const;
  const std::vector<int>& group_of() const;  // per member
  // The problem's symmetries are the mirrors that keep the structure and its reference loads
  // and take every case onto a case (itself, or another: the payload on the left onto the
  // right's) and every station onto a station. Under them
  // a row and its images are one function of the variables once each member's corrections are
  // the largest of its images' (ImageCorrections). Per row of the whole problem: the first row
  // of its orbit (in a posed problem, each row itself).
  const std::vector<int>& representatives() const;
  // `c` with each member's demand factor and taut margin raised to the largest of its images'.
  // The feasible set stays the same: a member and its images share one area and carry each
  // other's forces in mirrored combinations, so each row of one holds where the row of the
  // other with the larger factor does.
  SizingCorrections ImageCorrections(const SizingCorrections& c) const;

 private:
  struct Impl;
  static size_t Build(Impl& p, const Design& d, SizingCorrections corrections,
                      const std::vector<char>* keep, size_t offset,
                      const PrestressStateSpec& state);
  std::vector<const Impl*> Parts() const;  // impl_, then extra_'s
  // Row r's part and its index there.
  std::pair<const Impl*, int> Part(int r) const;
  const Eigen::MatrixXd& JacobianAt(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  std::unique_ptr<Impl> impl_;  // the prestress as designed
  // The other states of the prestress the design must pass in (PrestressStatesOf), in order.
  std::vector<std::unique_ptr<Impl>> extra_;
  std::vector<SizingRow> rows_;  // the parts' rows, in order
  std::vector<int> representatives_;
  mutable Eigen::MatrixXd jacobian_;  // the parts' Jacobians stacked, at jacobian_x_
  mutable Eigen::VectorXd jacobian_x_;
};

}  // namespace tbridge
