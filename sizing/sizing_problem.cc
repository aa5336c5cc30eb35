#include "sizing/sizing_problem.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "core/error.h"
#include "core/member_area.h"
#include "core/tangent_blocks.h"
#include "core/two_lanes.h"
#include "design/abutments.h"
#include "design/case_envelope.h"
#include "design/equilibrium.h"
#include "design/equilibrium_basis.h"
#include "design/linear_response.h"
#include "design/mirror.h"
#include "design/stability.h"
#include "optim/reciprocal_curvature.h"

namespace tbridge {

namespace {

// The smallest area any member may take [m^2] (a radius of 56 um): keeps T / (sigma_w A)
// finite for a string the loads do not use.
constexpr double kAreaFloor = 1e-8;

// The self-stresses that give mirror-image members equal forces: the columns of N (orthonormal,
// members x states) whose combinations are constant over every symmetry group, as an
// orthonormal basis again. The bridge and every load family on it are symmetric, so a
// symmetric prestress loses nothing the areas (shared by the same groups) could use, and the 3D
// bridge's 122 states at n = 4 become 39 variables.
Eigen::MatrixXd SymmetricSelfStresses(const Eigen::MatrixXd& N, const std::vector<int>& group_of,
                                      int groups) {
  if (N.cols() == 0) return N;
  // Each row minus its group's mean: zero exactly on the symmetric combinations.
  Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(groups, N.cols());
  Eigen::VectorXd count = Eigen::VectorXd::Zero(groups);
  for (int j = 0; j < N.rows(); ++j) {
    mean.row(group_of[j]) += N.row(j);
    count[group_of[j]] += 1;
  }
  Eigen::MatrixXd spread = N;
  for (int j = 0; j < N.rows(); ++j) spread.row(j) -= mean.row(group_of[j]) / count[group_of[j]];
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(spread, Eigen::ComputeFullV);
  // N's columns have unit norm, so a combination that is symmetric reads a singular value at
  // rounding (1e-15); an antisymmetric part reads one of order one.
  constexpr double kSymmetric = 1e-9;
  const Eigen::VectorXd& sv = svd.singularValues();
  std::vector<int> keep;
  for (int k = 0; k < N.cols(); ++k) {
    if (k >= sv.size() || sv[k] <= kSymmetric) keep.push_back(k);
  }
  Eigen::MatrixXd out(N.rows(), static_cast<Eigen::Index>(keep.size()));
  for (size_t k = 0; k < keep.size(); ++k)
    out.col(static_cast<Eigen::Index>(k)) = N * svd.matrixV().col(keep[k]);
  return out;
}

// A member's resistance [N] and its derivative by the area [N/m^2].
struct Resistance {
  double value = 0, derivative = 0;
};

}  // namespace

std::vector<int> MirrorGroups(const Structure& s, double span) {
  const int nm = s.num_bars() + s.num_strings();
  std::vector<int> root(nm);
  for (int j = 0; j < nm; ++j) root[j] = j;
  auto find = [&root](int j) {
    while (root[j] != j) j = root[j] = root[root[j]];
    return j;
  };
  for (const Mirror& mirror : Mirrors(s, span)) {
    for (int j = 0; j < nm; ++j) {
      if (mirror.member[static_cast<size_t>(j)] >= 0)
        root[find(mirror.member[static_cast<size_t>(j)])] = find(j);
    }
  }
  std::vector<int> group(nm, -1), index(nm, -1);
  int groups = 0;
  for (int j = 0; j < nm; ++j) {
    const int r = find(j);
    if (index[r] < 0) index[r] = groups++;
    group[j] = index[r];
  }
  return group;
}

LimitMode ModeOfRow(SizingRow::Kind kind) {
  switch (kind) {
    case SizingRow::kStrength:
    case SizingRow::kYield:
      return LimitMode::kYield;
    case SizingRow::kBuckling:
      return LimitMode::kBuckling;
    case SizingRow::kTaut:
      return LimitMode::kTaut;
    case SizingRow::kDeflectionDown:
    case SizingRow::kDeflectionUp:
      return LimitMode::kDeflection;
    case SizingRow::kReferenceTaut:
      return LimitMode::kReferenceTaut;
    case SizingRow::kServiceStress:
      return LimitMode::kServiceability;
    case SizingRow::kSupportHorizontal:
    case SizingRow::kSupportVertical:
      return LimitMode::kSupports;
    case SizingRow::kComfort:
      break;
  }
  return LimitMode::kComfort;
}

const char* SizingRowKindName(SizingRow::Kind kind) { return NameOf(ModeOfRow(kind)); }

struct SizingProblem::Impl {
  // The model: constant once built.
  Structure s;
  SizingCorrections corrections;
  int nb = 0, ns = 0, nm = 0, states = 0, groups = 0;
  // E_bar: the bars' modulus (their buckling); E, sigma_w: the strings' modulus and design stress.
  // sigma_ser: the strings' serviceability stress limit (the characteristic combinations).
  double E = 0, E_bar = 0, sigma_w = 0, sigma_ser = 0, deflection_limit_m = 0, force_scale = 1,
         mass_scale = 1;
  std::vector<double> rho;  // per member [kg/m^3]
  BarRule rule;
  std::vector<double> length, min_area;
  std::vector<int> group_of;
  std::vector<double>
      area_scale;  // per group [m^2]: its area in the design the problem is built from
  std::vector<std::vector<int>> members_of;
  std::vector<bool> must_taut;
  std::vector<int> deck_nodes;
  // The abutments and their capacities [N] (0: none given, no rows of that kind). An abutment's
  // reaction in combination c is, to first order about the reference state (as the linear
  // response is),
  //   R_c = sum_j w_j F_cj - sum_j t_j (I - e_j e_j^T) / l_j u_c(far end of j) + reaction_load[c]
  // over the members j on its nodes: w_j the reaction to a unit force along the drawn direction
  // (SupportReactions), t_j the member's reference tension (a bar's: minus its compression) turned
  // by its far end's displacement, and the reaction to the loads on its nodes. The turning term
  // is what the prestress adds as the deck deflects: on the default at n = 3, 6.7 kN of a 24 kN
  // vertical reaction under a 440 kN thrust.
  std::array<Abutment, 2> abutments;
  std::vector<int> abutment_of_node;  // per node: its abutment, -1 at a free node
  double horizontal_capacity = 0, vertical_capacity = 0;
  struct ReactionTerm {
    int member;
    Eigen::Vector3d w;
    int far = -1;     // the member's other end where it is free, else -1 (it does not turn)
    double sign = 1;  // its tension per unit force: +1 a string, -1 a bar
    Eigen::Matrix3d turn = Eigen::Matrix3d::Zero();  // (I - e e^T) / l [1/m]
  };
  // The reaction rows' adjoint columns come after the members' and nodes': per abutment a, the
  // turning term's components 3 a + x, y, z.
  int TurnColumn(int a, int axis) const {
    return static_cast<int>(adjoint_members.size() + adjoint_nodes.size()) + 3 * a + axis;
  }
  std::array<std::vector<ReactionTerm>, 2> reaction_terms;
  std::vector<std::array<Eigen::Vector3d, 2>> reaction_load;  // per combination [N]
  // The vertical reaction is statically determinate (moment equilibrium about the other
  // abutment): no stiffness moves it, only the loads, and of those the sizing moves the
  // members' own weight. Per abutment, per member: the weight it puts on the abutment per unit
  // area, rho g l_j (1 - |x_a - x_mid,j| / L) [N/m^2] (half of it at each end node); per
  // combination, its self-weight factor. G holds the weight at area0, so the row adds the change.
  std::array<std::vector<double>, 2> weight_share;
  std::vector<double> self_weight_factor;
  Eigen::MatrixXd N;         // members x states, orthonormal symmetric self-stresses
  Eigen::MatrixXd to_basis;  // the equilibrium solver's states x states: N's coefficients there
  Eigen::VectorXd x_g;       // the reference loads' particular forces [N]
  // The areas and reference forces of the design the problem is built from: the comfort rows'
  // Rayleigh quotients are taken about them.
  std::vector<double> area0;
  Eigen::VectorXd xr0;
  // Free-DOF columns: each case's change from G, then a unit load per station; in a posed
  // problem only those its rows read (a symmetric bridge's posed rows read half the stations).
  Eigen::MatrixXd loads;
  std::vector<SizingCombination> combos;
  std::vector<double> station_factor;  // per combination: its station load [N] (0: none)
  std::vector<int> base_column;        // per combination: its case's column of `loads`
  std::vector<int> station_column;     // per combination: its station's column (-1: none)
  std::vector<char> combo_read;        // per combination: some row reads it
  std::vector<SizingRow> rows;
  // Per row: its member's resistance at the problem's own area [N] (strength rows; 1 for the
  // others), the scale of its posed form (Posed).
  std::vector<double> reference_resistance;
  // The dense pattern (every row reads every variable), formed on first use: the whole
  // problem, whose rows are only evaluated, never needs it (n = 7: 64 M entries, 512 MB).
  mutable Pattern jacobian;
  mutable std::once_flag jacobian_formed;
  mutable Pattern hessian;  // the diagonal, formed on first use
  mutable std::once_flag hessian_formed;
  // What each row reads, for the adjoint Jacobian: the members whose force change and the deck
  // nodes whose vertical displacement some row reads (LinearResponse::Adjoint's columns, the
  // members first), and per row its column (-1: the reference-taut rows, which read none).
  std::vector<int> adjoint_members, adjoint_nodes, row_functional;
  std::vector<int> member_functional;  // per member: its column among the adjoints, -1: none
  // Under the problem's symmetries (SizingProblem::representatives): per row of the whole
  // problem, the first row of its orbit (itself in a posed problem), and per member the first
  // member of its.
  std::vector<int> row_representative, member_representative;

  // The workspace: the last point evaluated, its values and (on demand) its Jacobian.
  struct State {
    Eigen::VectorXd x;
    bool valid = false;
    Eigen::VectorXd g;       // the rows as posed (Posed)
    Eigen::VectorXd margin;  // the rows as margins (Value)
    Eigen::MatrixXd jac;     // rows x variables, of g
    bool have_jac = false;
    std::unique_ptr<LinearResponse> lin;
    Eigen::MatrixXd u, dx;  // solutions and force changes per column
    Eigen::VectorXd xr;
    std::vector<double> a;
    std::vector<BarCapacity> bar_capacity;  // per bar, at its area a
    std::vector<Eigen::VectorXd> forces;    // per combination [N]
    // Per comfort entry that follows its mode: its row about this point, found on first use.
    std::vector<std::optional<ComfortRow>> followed;
    // Per combination read (with support rows), per abutment: the turning term of its reaction [N].
    std::vector<std::array<Eigen::Vector3d, 2>> turned;
    // Per abutment: the change of the members' weight on it from G's [N] (weight_share).
    std::array<double, 2> weight_change{};
    // The state's change of the self-stress by the variables (states x variables), where the
    // part has one (StateShift).
    Eigen::MatrixXd shift_jac;
  };
  mutable State st;

  // The state of the prestress this part's rows are in (design/prestress_states.h): the share of
  // the self-stress coefficients its reference state carries (1, or 1 - design.prestress_loss),
  // and the change of them the state's shortenings make (the rest-length tolerance, the
  // temperature): StateShift at the point's areas and prestress as designed. Its rows are
  // functions of the same variables.
  double alpha_factor = 1.0;
  bool shifted = false;            // any shortening nonzero
  std::vector<double> shortening;  // per member [m], [bars; strings]: held (StateShortenings)
  int state = 0;

  int num_variables() const { return groups + states; }

  // The change of the self-stress coefficients [N] the members' `shortening` makes at the areas
  // `a` and the prestress as designed of x: N^T F N d = N^T delta, F each string's flexibility
  // l / (E A + T) (its tangent: E A / L0), bars rigid, so a bar's shortening enters delta alone
  // (design/prestress_states.h). With `jac`, its derivatives by the variables (states x
  // variables): dd = -(N^T F N)^-1 N^T dF N d.
  Eigen::VectorXd StateShift(const std::vector<double>& a, const Eigen::VectorXd& x,
                             Eigen::MatrixXd* jac) const {
    const Eigen::VectorXd designed = x_g + N * (force_scale * x.tail(states));
    Eigen::VectorXd f(ns), df_dt(ns);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(states);
    for (int q = 0; q < ns; ++q) {
      const int j = nb + q;
      const double k = E * a[static_cast<size_t>(j)] + designed[j];
      f[q] = length[j] / k;
      df_dt[q] = -length[j] / (k * k);
    }
    for (int j = 0; j < nm; ++j) rhs += N.row(j).transpose() * shortening[static_cast<size_t>(j)];
    const Eigen::MatrixXd ns_rows = N.bottomRows(ns);
    const Eigen::LDLT<Eigen::MatrixXd> g((ns_rows.transpose() * f.asDiagonal() * ns_rows).eval());
    const Eigen::VectorXd d = g.solve(rhs);
    if (jac != nullptr) {
      // Per string, N_q^T (N_q d): what its flexibility's change does to N^T F N d.
      const Eigen::VectorXd along = ns_rows * d;
      Eigen::MatrixXd dg_d = Eigen::MatrixXd::Zero(states, num_variables());
      for (int q = 0; q < ns; ++q) {
        const int j = nb + q, v = group_of[static_cast<size_t>(j)];
        const Eigen::VectorXd row = ns_rows.row(q).transpose() * (along[q] * df_dt[q]);
        dg_d.col(v) += row * E * area_scale[static_cast<size_t>(v)];  // dk/dx_v = E area_scale
        for (int m = 0; m < states; ++m) dg_d.col(groups + m) += row * N(j, m) * force_scale;
      }
      *jac = -g.solve(dg_d);
    }
    return d;
  }
  std::vector<double> Areas(const Eigen::VectorXd& x) const {
    std::vector<double> a(nm);
    for (int j = 0; j < nm; ++j) a[j] = area_scale[group_of[j]] * x[group_of[j]];
    return a;
  }
  // The reference forces at x; with the tolerance, its change of the self-stress then in `shift`
  // (and its derivatives in `shift_jac`, where asked).
  Eigen::VectorXd Reference(const Eigen::VectorXd& x, Eigen::MatrixXd* shift_jac = nullptr) const {
    if (!states) return x_g;
    Eigen::VectorXd alpha = force_scale * alpha_factor * x.tail(states);
    if (shifted) alpha += StateShift(Areas(x), x, shift_jac);
    return x_g + N * alpha;
  }
  // The member forces of combination c for force changes dx (members x columns) and the
  // reference forces xr.
  Eigen::VectorXd Forces(int c, const Eigen::VectorXd& xr, const Eigen::MatrixXd& dx) const {
    Eigen::VectorXd f = xr + dx.col(base_column[c]);
    if (station_factor[c] != 0) f += station_factor[c] * dx.col(station_column[c]);
    return f;
  }
  double Vertical(int c, int node, const Eigen::MatrixXd& u) const {
    const int row = st.lin->VerticalRow(node);
    if (row < 0) return 0.0;
    double out = u(row, base_column[c]);
    if (station_factor[c] != 0) out += station_factor[c] * u(row, station_column[c]);
    return out;
  }

  void Evaluate(const Eigen::VectorXd& x) const {
    if (st.valid && st.x.size() == x.size() && st.x == x) return;
    st.x = x;
    st.valid = true;
    st.have_jac = false;
    st.followed.assign(corrections.comfort.size(), std::nullopt);
    st.a = Areas(x);
    // Each bar's resistances, once per point: a member's rows are many (n = 8: 777
    // combinations), its resistance one.
    st.bar_capacity.resize(static_cast<size_t>(nb));
    for (int j = 0; j < nb; ++j)
      st.bar_capacity[static_cast<size_t>(j)] = BarResistance(st.a[j], length[j], rule, E_bar);
    st.xr = Reference(x, &st.shift_jac);
    Eigen::VectorXd k(ns);
    for (int q = 0; q < ns; ++q)
      k[q] = TautStringStiffness(E, st.a[nb + q], st.xr[nb + q], length[nb + q]);
    st.g.resize(static_cast<Eigen::Index>(rows.size()));
    // A reference state that is not stable (a negative stiffness on the motions that keep the
    // bar lengths) has no meaningful linear response: the point is an evaluation error, and
    // the solvers step back from it.
    const std::vector<double> k_list(k.data(), k.data() + k.size());
    const bool stable = AssessStability(s, st.xr, k_list, false).stable;
    try {
      if (!stable) throw ModelError("unstable");
      st.lin = std::make_unique<LinearResponse>(s, st.xr, k);
    } catch (const ModelError&) {
      st.lin.reset();
      st.g.setConstant(std::numeric_limits<double>::quiet_NaN());
      st.margin = st.g;
      return;
    }
    st.u = st.lin->Solve(loads);
    st.dx = st.lin->ForceChanges(st.u);
    st.forces.resize(combos.size());
    for (size_t c = 0; c < combos.size(); ++c) {
      if (combo_read[c]) st.forces[c] = Forces(static_cast<int>(c), st.xr, st.dx);
    }
    for (int a = 0; a < 2; ++a) {
      const std::vector<double>& share = weight_share[static_cast<size_t>(a)];
      double& change = st.weight_change[static_cast<size_t>(a)];
      change = 0;
      for (size_t j = 0; j < share.size(); ++j) change += share[j] * (st.a[j] - area0[j]);
    }
    st.turned.resize(reaction_load.empty() ? 0 : combos.size());
    for (size_t c = 0; c < st.turned.size(); ++c) {
      if (!combo_read[c]) continue;
      for (int a = 0; a < 2; ++a) {
        st.turned[c][static_cast<size_t>(a)] =
            Turned(a, static_cast<int>(c), [this](int m) { return st.xr[m]; });
      }
    }
    st.margin.resize(st.g.size());
    for (size_t r = 0; r < rows.size(); ++r) {
      st.margin[r] = Value(rows[r]);
      st.g[r] = Posed(static_cast<int>(r));
    }
  }

  static bool IsSupport(const SizingRow& row) {
    return row.kind == SizingRow::kSupportHorizontal || row.kind == SizingRow::kSupportVertical;
  }
  // The displacement of term t's far end in combination c at the evaluated state [m].
  Eigen::Vector3d FarDisplacement(const ReactionTerm& t, int c) const {
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    for (int axis = 0; axis < 3; ++axis) {
      const int row = st.lin->DisplacementRow(t.far, axis);
      if (row >= 0) u[axis] = Combined(st.u, row, c);
    }
    return u;
  }
  // The turning term of abutment a's reaction in combination c with reference forces
  // reference(member) [N] (or their change along a direction).
  template <class Reference>
  Eigen::Vector3d Turned(int a, int c, Reference reference) const {
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for (const ReactionTerm& t : reaction_terms[static_cast<size_t>(a)]) {
      if (t.far >= 0) r -= t.sign * reference(t.member) * (t.turn * FarDisplacement(t, c));
    }
    return r;
  }
  // The functionals whose values are the turning terms (each column TurnColumn(a, axis) less the
  // first): over the solutions' rows, -t_j (I - e e^T) / l at the far ends' displacements.
  Eigen::MatrixXd TurnFunctionals() const {
    Eigen::MatrixXd l = Eigen::MatrixXd::Zero(st.u.rows(), 6);
    for (int a = 0; a < 2; ++a) {
      for (const ReactionTerm& t : reaction_terms[static_cast<size_t>(a)]) {
        if (t.far < 0) continue;
        for (int axis = 0; axis < 3; ++axis) {
          const int row = st.lin->DisplacementRow(t.far, axis);
          if (row < 0) continue;
          for (int k = 0; k < 3; ++k)
            l(row, 3 * a + k) -= t.sign * st.xr[t.member] * t.turn(k, axis);
        }
      }
    }
    return l;
  }
  // Abutment a's reaction in combination c at the evaluated state [N].
  Eigen::Vector3d Reaction(int c, int a) const {
    Eigen::Vector3d r = reaction_load[static_cast<size_t>(c)][static_cast<size_t>(a)] +
                        st.turned[static_cast<size_t>(c)][static_cast<size_t>(a)];
    for (const ReactionTerm& t : reaction_terms[static_cast<size_t>(a)])
      r += t.w * st.forces[c][t.member];
    if (!self_weight_factor.empty()) {
      r.y() +=
          self_weight_factor[static_cast<size_t>(c)] * st.weight_change[static_cast<size_t>(a)];
    }
    return r;
  }
  // d R_y / d x_v of abutment a in combination c through the members' weight [N per unit x_v].
  double WeightChange(int a, int c, int v) const {
    const std::vector<double>& share = weight_share[static_cast<size_t>(a)];
    if (share.empty()) return 0.0;
    double d = 0;
    for (const int j : members_of[static_cast<size_t>(v)]) d += share[static_cast<size_t>(j)];
    return self_weight_factor[static_cast<size_t>(c)] * d * area_scale[static_cast<size_t>(v)];
  }
  // A support row's derivative along a direction that moves each member's force in the row's
  // combination by force_change(member) [N] and its abutment's turning term by turn_change(axis):
  // the reaction's change dR = sum_j w_j dF_j + d turned, then the row's,
  // d(1 - kappa_h |(R_x, R_z)| / cap) or d(1 - kappa_v |R_y| / cap).
  template <class ForceChange, class TurnChange>
  double SupportDerivative(const SizingRow& row, ForceChange force_change,
                           TurnChange turn_change) const {
    Eigen::Vector3d dr(turn_change(0), turn_change(1), turn_change(2));
    for (const ReactionTerm& t : reaction_terms[static_cast<size_t>(row.member)])
      dr += t.w * force_change(t.member);
    const Eigen::Vector3d r = Reaction(row.combination, row.member);
    if (row.kind == SizingRow::kSupportVertical) {
      return -corrections.vertical_reaction_factor * (r.y() < 0 ? -dr.y() : dr.y()) /
             vertical_capacity;
    }
    const double h = std::hypot(r.x(), r.z());
    if (h == 0) return 0.0;  // |H| has no gradient at 0, where its row is far from binding
    return -corrections.horizontal_reaction_factor * (r.x() * dr.x() + r.z() * dr.z()) /
           (h * horizontal_capacity);
  }

  // The rows of a demand against a resistance: a string's strength and serviceability stress,
  // a bar's buckling and yield.
  static bool IsStrength(const SizingRow& row) {
    return row.kind == SizingRow::kStrength || row.kind == SizingRow::kBuckling ||
           row.kind == SizingRow::kYield || row.kind == SizingRow::kServiceStress;
  }
  static bool IsStringStress(const SizingRow& row) {
    return row.kind == SizingRow::kStrength || row.kind == SizingRow::kServiceStress;
  }
  // The resistance of row's member [N] and its derivative by the area [N/m^2] (strength
  // rows): a string's at `area`, a bar's of its capacity `cap` (unread for a string).
  Resistance ResistanceOf(const SizingRow& row, double area, const BarCapacity& cap) const {
    if (row.kind == SizingRow::kStrength) return {sigma_w * area, sigma_w};
    if (row.kind == SizingRow::kServiceStress) return {sigma_ser * area, sigma_ser};
    return row.kind == SizingRow::kBuckling ? Resistance{cap.buckling, cap.d_buckling}
                                            : Resistance{cap.yield, cap.d_yield};
  }
  // At `area`.
  Resistance ResistanceAt(const SizingRow& row, double area) const {
    return ResistanceOf(
        row, area,
        IsStringStress(row) ? BarCapacity{} : BarResistance(area, length[row.member], rule, E_bar));
  }
  // At the evaluated state.
  Resistance ResistanceOf(const SizingRow& row) const {
    const size_t j = static_cast<size_t>(row.member);
    return ResistanceOf(row, st.a[j], IsStringStress(row) ? BarCapacity{} : st.bar_capacity[j]);
  }

  // Row r as the solvers see it. A strength row is posed as (R(A) - kappa F) / R_ref, R_ref its
  // resistance at the problem's own area: it holds where its margin 1 - kappa F / R(A) does,
  // but is near linear in the member's own area (R is linear in A, or convex for buckling, and
  // F moves with A only through the stiffness), where the margin is reciprocal in it. The
  // margin's linearisation promised a shrinking member (to a fifth of its area, as the move
  // limits allow) the strength it lost, and its full steps failed: at n = 7 the sizing took
  // half steps, each halving the violation, over 170 evaluations.
  double Posed(int r) const {
    const SizingRow& row = rows[r];
    if (!IsStrength(row)) return st.margin[r];
    const int j = row.member;
    return (ResistanceOf(row).value -
            corrections.demand_factor[j] * st.forces[row.combination][j]) /
           reference_resistance[r];
  }

  // A row's value at the evaluated state.
  double Value(const SizingRow& row) const {
    const int j = row.member, c = row.combination;
    switch (row.kind) {
      case SizingRow::kStrength:
      case SizingRow::kBuckling:
      case SizingRow::kYield:
      case SizingRow::kServiceStress:
        return 1.0 - corrections.demand_factor[j] * st.forces[c][j] / ResistanceOf(row).value;
      case SizingRow::kTaut:
        return (st.forces[c][j] - corrections.taut_margin_n[j]) / force_scale;
      case SizingRow::kDeflectionDown:
        return 1.0 + corrections.deflection_factor * Vertical(c, j, st.u) / deflection_limit_m;
      case SizingRow::kDeflectionUp:
        return 1.0 - corrections.deflection_factor * Vertical(c, j, st.u) / deflection_limit_m;
      case SizingRow::kReferenceTaut:
        return st.xr[j] / force_scale;
      case SizingRow::kSupportHorizontal: {
        const Eigen::Vector3d r = Reaction(c, j);
        return 1.0 - corrections.horizontal_reaction_factor * std::hypot(r.x(), r.z()) /
                         horizontal_capacity;
      }
      case SizingRow::kSupportVertical:
        return 1.0 - corrections.vertical_reaction_factor * std::abs(Reaction(c, j).y()) /
                         vertical_capacity;
      case SizingRow::kComfort:
        break;
    }
    const ComfortRow& k = corrections.comfort[static_cast<size_t>(j)];
    const double ratio = ComfortQuotient(j).value() / k.target_omega2;
    return k.lower ? ratio - 1.0 : 1.0 - ratio;
  }

  // Comfort entry k's row about the evaluated point: a row that follows its mode is the mode's own
  // there (found once per point), a held one the quotient about the design the problem is built
  // from.
  const ComfortRow& ComfortAbout(int k, const std::vector<double>*& a0,
                                 const Eigen::VectorXd*& f0) const {
    const ComfortRow& held = corrections.comfort[static_cast<size_t>(k)];
    a0 = &area0;
    f0 = &xr0;
    if (!held.follow) return held;
    std::optional<ComfortRow>& here = st.followed[static_cast<size_t>(k)];
    if (!here) here = held.follow(st.a, st.xr);
    a0 = &st.a;
    f0 = &st.xr;
    return *here;
  }

  // Comfort entry k's eigenvalue at the evaluated point: its row's Rayleigh quotient (ComfortRow),
  // numerator and denominator affine in the areas and reference forces.
  struct Quotient {
    double stiffness = 0, mass = 1;
    double value() const { return stiffness / mass; }
  };
  Quotient ComfortQuotient(int index) const {
    const std::vector<double>* a0 = nullptr;
    const Eigen::VectorXd* f0 = nullptr;
    const ComfortRow& k = ComfortAbout(index, a0, f0);
    Quotient q{k.omega2, 1.0};
    for (int j = 0; j < nm; ++j) {
      const double da = st.a[static_cast<size_t>(j)] - (*a0)[static_cast<size_t>(j)];
      q.stiffness += k.by_area[static_cast<size_t>(j)] * da +
                     k.by_force[static_cast<size_t>(j)] * (st.xr[j] - (*f0)[j]);
      q.mass += k.mass_by_area[static_cast<size_t>(j)] * da;
    }
    return q;
  }

  // The comfort rows' gradients at the evaluated state, by the quotient rule on
  // ComfortQuotient: d omega^2 = (d stiffness - omega^2 d mass) / mass.
  void ComfortGradients() const {
    for (size_t r = 0; r < rows.size(); ++r) {
      if (rows[r].kind != SizingRow::kComfort) continue;
      const int index = rows[r].member;
      const ComfortRow& held = corrections.comfort[static_cast<size_t>(index)];
      const std::vector<double>* a0 = nullptr;
      const Eigen::VectorXd* f0 = nullptr;
      const ComfortRow& k = ComfortAbout(index, a0, f0);
      const Quotient q = ComfortQuotient(index);
      const double w2 = q.value(), sign = (held.lower ? 1.0 : -1.0) / (held.target_omega2 * q.mass);
      for (int v = 0; v < groups; ++v) {
        double d = 0;
        for (const int j : members_of[static_cast<size_t>(v)]) {
          d += (k.by_area[static_cast<size_t>(j)] - w2 * k.mass_by_area[static_cast<size_t>(j)]) *
               area_scale[static_cast<size_t>(v)];
        }
        st.jac(static_cast<Eigen::Index>(r), v) = sign * d;
      }
      for (int m = 0; m < states; ++m) {
        double d = 0;
        for (int j = 0; j < nm; ++j)
          d += k.by_force[static_cast<size_t>(j)] * N(j, m) * force_scale;
        st.jac(static_cast<Eigen::Index>(r), groups + m) = sign * d;
      }
    }
  }

  // A row's derivative along a direction that moves its member's force in its combination by
  // `d_force` [N] (member rows), its node's vertical displacement there by `d_vertical` [m]
  // (deflection rows), the member's reference force by `d_reference` [N] and its area by
  // `d_area`.
  double Derivative(int r, double d_force, double d_vertical, double d_reference,
                    double d_area) const {
    const SizingRow& row = rows[r];
    const int j = row.member;
    switch (row.kind) {
      case SizingRow::kStrength:
      case SizingRow::kBuckling:
      case SizingRow::kYield:
      case SizingRow::kServiceStress:
        // As posed: g = (R(A) - kappa F) / R_ref, dg = (R'(A) dA - kappa dF) / R_ref.
        return (ResistanceOf(row).derivative * d_area - corrections.demand_factor[j] * d_force) /
               reference_resistance[r];
      case SizingRow::kTaut:
        return d_force / force_scale;
      case SizingRow::kDeflectionDown:
        return corrections.deflection_factor * d_vertical / deflection_limit_m;
      case SizingRow::kDeflectionUp:
        return -corrections.deflection_factor * d_vertical / deflection_limit_m;
      case SizingRow::kReferenceTaut:
        return d_reference / force_scale;
      case SizingRow::kSupportHorizontal:
      case SizingRow::kSupportVertical:
      case SizingRow::kComfort:
        break;  // read several forces (SupportDerivative), or none (ComfortGradients)
    }
    return 0.0;
  }

  // Indexes what each row reads (adjoint_members, adjoint_nodes, row_functional): once, as
  // the rows are fixed.
  void IndexFunctionals() {
    member_functional.assign(static_cast<size_t>(nm), -1);
    std::vector<int>& member_col = member_functional;
    std::vector<int> node_col(s.num_nodes(), -1);
    std::vector<std::pair<bool, int>> read(rows.size(), {false, -1});
    for (size_t r = 0; r < rows.size(); ++r) {
      const SizingRow& row = rows[r];
      if (IsSupport(row)) {  // reads the forces of its abutment's members
        for (const ReactionTerm& t : reaction_terms[static_cast<size_t>(row.member)]) {
          if (member_col[t.member] < 0) {
            member_col[t.member] = static_cast<int>(adjoint_members.size());
            adjoint_members.push_back(t.member);
          }
        }
        continue;
      }
      if (row.kind == SizingRow::kReferenceTaut || row.kind == SizingRow::kComfort) continue;
      const bool deflection =
          row.kind == SizingRow::kDeflectionDown || row.kind == SizingRow::kDeflectionUp;
      std::vector<int>& col = deflection ? node_col : member_col;
      std::vector<int>& list = deflection ? adjoint_nodes : adjoint_members;
      if (col[row.member] < 0) {
        col[row.member] = static_cast<int>(list.size());
        list.push_back(row.member);
      }
      read[r] = {deflection, col[row.member]};
    }
    row_functional.assign(rows.size(), -1);
    const int n_members = static_cast<int>(adjoint_members.size());
    for (size_t r = 0; r < rows.size(); ++r) {
      if (read[r].second >= 0) row_functional[r] = read[r].second + (read[r].first ? n_members : 0);
    }
  }

  // The abutments, their members' coefficients and each combination's reaction to the loads on
  // their nodes (reaction_terms, reaction_load), where a capacity is given.
  void IndexReactions(const Design& d) {
    abutments = AbutmentsOf(s, d.config.bridge.span);
    abutment_of_node.assign(static_cast<size_t>(s.num_nodes()), -1);
    for (int a = 0; a < 2; ++a) {
      for (const int v : abutments[static_cast<size_t>(a)].nodes)
        abutment_of_node[static_cast<size_t>(v)] = a;
    }
    const auto vector = [](const AbutmentReaction& r) { return Eigen::Vector3d(r.x, r.y, r.z); };
    const Eigen::Matrix3Xd no_loads = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(nm);
    for (int j = 0; j < nm; ++j) {
      const Member& m = s.MemberAt(j);
      const int ends[] = {abutment_of_node[static_cast<size_t>(m.i)],
                          abutment_of_node[static_cast<size_t>(m.j)]};
      if (ends[0] < 0 && ends[1] < 0) continue;
      unit[j] = 1;
      const Eigen::Matrix3Xd r = SupportReactions(s, unit, no_loads);
      unit[j] = 0;
      for (int a = 0; a < 2; ++a) {
        if (ends[0] != a && ends[1] != a) continue;
        const Eigen::Vector3d w = vector(ReactionOf(abutments[static_cast<size_t>(a)], r));
        if (w.norm() == 0) continue;  // both ends on this abutment
        ReactionTerm t{j, w};
        const int far = ends[0] == a ? m.j : m.i;
        t.far = s.fixed[static_cast<size_t>(far)] ? -1 : far;
        t.sign = j < nb ? -1.0 : 1.0;
        const Eigen::Vector3d e = (s.nodes.col(m.j) - s.nodes.col(m.i)).normalized();
        t.turn = NormalProjector(e) / s.Length(m);
        reaction_terms[static_cast<size_t>(a)].push_back(t);
      }
    }
    if (d.config.design.self_weight) {
      const double span = d.config.bridge.span;
      for (int a = 0; a < 2; ++a) {
        std::vector<double>& share = weight_share[static_cast<size_t>(a)];
        for (int j = 0; j < nm; ++j) {
          const Member& m = s.MemberAt(j);
          const double x_mid = 0.5 * (s.nodes(0, m.i) + s.nodes(0, m.j));
          share.push_back(rho[static_cast<size_t>(j)] * d.config.design.gravity *
                          length[static_cast<size_t>(j)] *
                          (1 - std::abs(abutments[static_cast<size_t>(a)].x_m - x_mid) / span));
        }
      }
      for (const SizingCombination& combo : combos) {
        self_weight_factor.push_back(
            d.cases[static_cast<size_t>(combo.case_index)].factor[kSelfWeight]);
      }
    }
    reaction_load.resize(combos.size());
    for (size_t c = 0; c < combos.size(); ++c) {
      const Eigen::Matrix3Xd r =
          SupportReactions(s, Eigen::VectorXd::Zero(nm),
                           d.actions.Loads(d.cases[combos[c].case_index], combos[c].station));
      for (int a = 0; a < 2; ++a)
        reaction_load[c][static_cast<size_t>(a)] =
            vector(ReactionOf(abutments[static_cast<size_t>(a)], r));
    }
  }

  // The combinations the rows read, and the load columns: only those read, renumbered.
  void ReadColumns() {
    combo_read.assign(combos.size(), 0);
    for (const SizingRow& row : rows) {
      if (row.combination >= 0) combo_read[static_cast<size_t>(row.combination)] = 1;
    }
    std::vector<int> column(static_cast<size_t>(loads.cols()), -1);
    int used = 0;
    for (size_t c = 0; c < combos.size(); ++c) {
      if (!combo_read[c]) continue;
      for (const int k : {base_column[c], station_column[c]}) {
        if (k >= 0 && column[static_cast<size_t>(k)] < 0) column[static_cast<size_t>(k)] = used++;
      }
    }
    if (used == loads.cols()) return;
    Eigen::MatrixXd read(loads.rows(), used);
    for (Eigen::Index k = 0; k < loads.cols(); ++k) {
      if (column[static_cast<size_t>(k)] >= 0)
        read.col(column[static_cast<size_t>(k)]) = loads.col(k);
    }
    loads = std::move(read);
    for (size_t c = 0; c < combos.size(); ++c) {
      base_column[c] = column[static_cast<size_t>(base_column[c])];
      if (station_column[c] >= 0)
        station_column[c] = column[static_cast<size_t>(station_column[c])];
    }
  }

  // The mirrors that map the problem onto itself (symmetries, pointers into `mirrors`) and, per
  // symmetry, each combination's image.
  std::vector<std::vector<int>> CombinationImages(const Design& d,
                                                  const std::vector<Mirror>& mirrors,
                                                  std::vector<const Mirror*>& symmetries) const {
    const int stations = static_cast<int>(d.actions.station_nodes.size());
    const double span = d.config.bridge.span;
    std::vector<std::vector<int>> combo_image;
    std::vector<std::vector<int>> combo_at(d.cases.size(),
                                           std::vector<int>(static_cast<size_t>(stations) + 1, -1));
    for (size_t c = 0; c < combos.size(); ++c) {
      combo_at[static_cast<size_t>(combos[c].case_index)]
              [static_cast<size_t>(combos[c].station + 1)] = static_cast<int>(c);
    }
    for (const Mirror& m : mirrors) {
      if (!m.Complete(s) || !m.Keeps(d.loads)) continue;
      const std::vector<int> case_image = CaseImages(m, d.actions, d.cases);
      const std::vector<int> station_image = StationImages(m, d.actions, span);
      if (case_image.empty() || (stations > 0 && station_image.empty())) continue;
      std::vector<int> image(combos.size());
      for (size_t c = 0; c < combos.size(); ++c) {
        const int k = combos[c].station;
        image[c] =
            combo_at[static_cast<size_t>(case_image[static_cast<size_t>(combos[c].case_index)])]
                    [static_cast<size_t>(k < 0 ? 0 : station_image[static_cast<size_t>(k)] + 1)];
      }
      symmetries.push_back(&m);
      combo_image.push_back(std::move(image));
    }
    return combo_image;
  }

  // Each row's place within its combination by kind and member (or node), per layout of the
  // combinations' rows; the reference-taut rows by member.
  struct RowSlots {
    int width = 0;
    std::vector<std::vector<int>> slot;  // per combination layout: kind x width -> offset
    std::vector<int> layout;             // per combination, its layout in `slot`
    std::vector<int> reference_taut;     // per member, its reference-taut row (-1: none)
  };
  RowSlots SlotRows(const std::vector<int>& first_row) const {
    const int n_rows = static_cast<int>(rows.size());
    RowSlots out;
    const int kinds = SizingRow::kComfort + 1;
    const int width = std::max({nm, s.num_nodes(), static_cast<int>(corrections.comfort.size())});
    out.width = width;
    std::vector<std::vector<int>>& slot = out.slot;
    std::vector<int>& layout = out.layout;
    layout.resize(combos.size());
    std::map<std::vector<char>, int> layouts;
    out.reference_taut.assign(static_cast<size_t>(nm), -1);
    // The comfort and reference-taut rows come last, after every combination's.
    int combos_end = n_rows;
    for (int r = n_rows - 1; r >= 0 && rows[static_cast<size_t>(r)].combination < 0; --r) {
      combos_end = r;
      const SizingRow& row = rows[static_cast<size_t>(r)];
      if (row.kind == SizingRow::kReferenceTaut)
        out.reference_taut[static_cast<size_t>(row.member)] = r;
    }
    for (size_t c = 0; c < combos.size(); ++c) {
      const int begin = first_row[c], end = c + 1 < combos.size() ? first_row[c + 1] : combos_end;
      std::vector<char> key;  // the kinds in order: the layout
      for (int r = begin; r < end; ++r)
        key.push_back(static_cast<char>(rows[static_cast<size_t>(r)].kind));
      const auto [it, added] = layouts.try_emplace(key, static_cast<int>(slot.size()));
      layout[c] = it->second;
      if (!added) continue;
      std::vector<int> offsets(static_cast<size_t>(kinds) * width, -1);
      for (int r = begin; r < end; ++r) {
        const SizingRow& row = rows[static_cast<size_t>(r)];
        offsets[static_cast<size_t>(row.kind) * width + row.member] = r - begin;
      }
      slot.push_back(std::move(offsets));
    }
    return out;
  }

  // Each member's representative: the least of its images under the symmetries and their
  // pairs.
  void MemberRepresentatives(const std::vector<const Mirror*>& symmetries) {
    for (int j = 0; j < nm; ++j) {
      int first = j;
      for (const Mirror* m : symmetries) first = std::min(first, m->member[static_cast<size_t>(j)]);
      for (const Mirror* m1 : symmetries) {
        for (const Mirror* m2 : symmetries)
          first =
              std::min(first, m2->member[static_cast<size_t>(m1->member[static_cast<size_t>(j)])]);
      }
      member_representative[static_cast<size_t>(j)] = first;
    }
  }

  // The problem's symmetries and, for the whole problem (`first_row`: per combination, its
  // first row), each row's orbit under them (row_representative, member_representative).
  void IndexImages(const Design& d, const std::vector<int>* first_row) {
    const int n_rows = static_cast<int>(rows.size());
    row_representative.resize(static_cast<size_t>(n_rows));
    member_representative.resize(static_cast<size_t>(nm));
    for (int r = 0; r < n_rows; ++r) row_representative[static_cast<size_t>(r)] = r;
    for (int j = 0; j < nm; ++j) member_representative[static_cast<size_t>(j)] = j;
    if (first_row == nullptr) return;
    const double span = d.config.bridge.span;
    // Per symmetry, each combination's image.
    std::vector<const Mirror*> symmetries;
    const std::vector<Mirror> mirrors = Mirrors(s, span);
    const std::vector<std::vector<int>> combo_image = CombinationImages(d, mirrors, symmetries);
    if (symmetries.empty()) return;
    // Each row's place within its combination by kind and member (or node): the same in a
    // combination and its image, which share a case. The reference-taut rows by member.
    const RowSlots slots = SlotRows(*first_row);
    const int width = slots.width;
    const std::vector<std::vector<int>>& slot = slots.slot;
    const std::vector<int>& layout = slots.layout;
    const std::vector<int>& reference_taut = slots.reference_taut;
    const auto image_of = [&](size_t m, int r) {
      const SizingRow& row = rows[static_cast<size_t>(r)];
      // A mode's eigenvalue reads the group variables only, which the mirrors keep.
      if (row.kind == SizingRow::kComfort) return r;
      const Mirror& mirror = *symmetries[m];
      const bool deflection =
          row.kind == SizingRow::kDeflectionDown || row.kind == SizingRow::kDeflectionUp;
      const int member = IsSupport(row)
                             ? abutment_of_node[static_cast<size_t>(mirror.node[static_cast<size_t>(
                                   abutments[static_cast<size_t>(row.member)].nodes.front())])]
                         : deflection ? mirror.node[static_cast<size_t>(row.member)]
                                      : mirror.member[static_cast<size_t>(row.member)];
      if (row.combination < 0) return reference_taut[static_cast<size_t>(member)];
      const int c = combo_image[m][static_cast<size_t>(row.combination)];
      if (c < 0) return -1;
      const int offset = slot[static_cast<size_t>(layout[static_cast<size_t>(c)])]
                             [static_cast<size_t>(row.kind) * width + member];
      return offset < 0 ? -1 : (*first_row)[static_cast<size_t>(c)] + offset;
    };
    std::vector<int> orbit;
    for (int r = 0; r < n_rows; ++r) {
      orbit.assign(1, r);
      for (size_t m = 0; m < symmetries.size(); ++m) {
        const size_t size = orbit.size();
        for (size_t i = 0; i < size; ++i) {
          const int image = image_of(m, orbit[i]);
          if (image < 0) throw std::logic_error("SizingProblem: a row without its mirror image");
          orbit.push_back(image);
        }
      }
      row_representative[static_cast<size_t>(r)] = *std::min_element(orbit.begin(), orbit.end());
    }
    MemberRepresentatives(symmetries);
  }

  // Combination c's value of row `row` of per-column values `m` (its case's column plus its
  // station's times the station load), as Forces and Vertical combine them.
  double Combined(const Eigen::MatrixXd& m, int row, int c) const {
    double out = m(row, base_column[c]);
    if (station_factor[c] != 0) out += station_factor[c] * m(row, station_column[c]);
    return out;
  }

  // The Jacobian at the evaluated state, by adjoints: one solve per member and deck node that
  // a row reads (design/linear_response.h), then per variable a product over the DOFs its
  // members touch. The direct form (a solve per variable and load column) took 40 % of a
  // sizing at n = 5, where the variables (64) times the columns (37) outnumber the
  // functionals (141) by 17.
  //
  // An area moves only its group's strings' stiffness, dK = dk e e^T on each: a functional's
  // change is then -dk (e^T (a_j - a_i)) (e^T (u_j - u_i)), the string's stretch in the adjoint
  // solution times its stretch in the load's, so an area's column costs a few products per row
  // (a bar's area moves no stiffness, only its resistance). Forming dK u and its product with
  // the adjoints for every area, as a self-stress needs, took half the Jacobian's time at n = 6.
  void Jacobian() const {
    const int nv = num_variables(), nr = static_cast<int>(rows.size());
    Eigen::MatrixXd adjoint = st.lin->Adjoint(adjoint_members, adjoint_nodes);
    if (!reaction_load.empty()) {  // the turning terms' columns (TurnColumn)
      const Eigen::Index first = adjoint.cols();
      adjoint.conservativeResize(Eigen::NoChange, first + 6);
      adjoint.rightCols(6) = st.lin->AdjointOf(TurnFunctionals());
    }
    const Eigen::MatrixXd stretch = st.lin->StringStretches(st.u);
    const Eigen::MatrixXd adjoint_stretch =
        st.lin->StringStretches(adjoint);  // strings x functionals
    st.jac.resize(nr, nv);
    std::vector<Coefficients> k(nr);
    for (int r = 0; r < nr; ++r) {
      k[r] = {Derivative(r, 1, 0, 0, 0), Derivative(r, 0, 1, 0, 0), Derivative(r, 0, 0, 1, 0),
              Derivative(r, 0, 0, 0, 1)};
    }
    // The columns in two lanes (core/two_lanes.h), each column written by one of them: the
    // first half of the variables and the second (half of each kind in each lane took longer
    // at n = 7: 4.5 s of sizing against 4.2 s).
    const auto columns = [&](int v_first, int v_last) {
      AreaColumns(v_first, std::min(v_last, groups), k, adjoint_stretch, stretch);
      StateColumns(std::max(v_first, groups), v_last, k, adjoint, stretch);
    };
    const int half = (nv + 1) / 2;
    InTwoLanes([&] { columns(half, nv); }, [&] { columns(0, half); });
    ComfortGradients();
    if (shifted && states > 0) {
      // The chain through the state's change of the self-stress: the rows by the self-stress
      // coefficients per newton (the state columns over their scale) times its derivatives.
      const Eigen::MatrixXd by_alpha = st.jac.rightCols(states) / (force_scale * alpha_factor);
      st.jac += by_alpha * st.shift_jac;
    }
    st.have_jac = true;
  }

  // The Jacobian at x (rows x variables), formed once per point; NaN throughout at an unstable
  // point, where the rows are NaN too.
  const Eigen::MatrixXd& JacobianAt(const Eigen::Ref<const Eigen::VectorXd>& x) const {
    Evaluate(x);
    if (!st.lin) {
      st.jac.setConstant(static_cast<Eigen::Index>(rows.size()), num_variables(),
                         std::numeric_limits<double>::quiet_NaN());
    } else if (!st.have_jac) {
      Jacobian();
    }
    return st.jac;
  }

  // Each row's derivative is linear in what moves it (Derivative): its coefficients.
  struct Coefficients {
    double force, vertical, reference, area;
  };

  // The Jacobian's columns of the areas v_first .. v_last - 1.
  void AreaColumns(int v_first, int v_last, const std::vector<Coefficients>& k,
                   const Eigen::MatrixXd& adjoint_stretch, const Eigen::MatrixXd& stretch) const {
    const int nr = static_cast<int>(rows.size());
    const int n_members = static_cast<int>(adjoint_members.size());
    for (int v = v_first; v < v_last; ++v) {
      std::vector<std::pair<int, double>> strings;  // (string, dk/dx_v [N/m])
      for (int j : members_of[v]) {
        if (j >= nb)
          strings.emplace_back(j - nb, TautStringStiffness(E, area_scale[v], 0.0, length[j]));
      }
      // A member's force change in combination c: through the strings' stiffness on the load's
      // stretches (the adjoint's), and a string's own on its stretch.
      const auto force_change = [&](int m, int c) {
        const int f = member_functional[static_cast<size_t>(m)];
        double d = 0;
        for (const auto& [q, dk] : strings) {
          d -= dk * adjoint_stretch(q, f) * Combined(stretch, q, c);
          if (q == m - nb) d += dk * Combined(stretch, q, c);
        }
        return d;
      };
      for (int r = 0; r < nr; ++r) {
        const SizingRow& row = rows[r];
        const int j = row.member, c = row.combination, f = row_functional[r];
        if (IsSupport(row)) {
          // The turning term moves with the far ends' displacements only: d(l^T u) through the
          // strings' stiffness, as a force change less the string's own.
          const auto turn_change = [&](int axis) {
            const int col = TurnColumn(j, axis);
            double d = axis == 1 ? WeightChange(j, c, v) : 0.0;
            for (const auto& [q, dk] : strings)
              d -= dk * adjoint_stretch(q, col) * Combined(stretch, q, c);
            return d;
          };
          st.jac(r, v) = SupportDerivative(
              row, [&](int m) { return force_change(m, c); }, turn_change);
          continue;
        }
        double d_value = 0;
        for (const auto& [q, dk] : strings) {
          if (f >= 0) d_value -= dk * adjoint_stretch(q, f) * Combined(stretch, q, c);
        }
        double d_force = 0, d_vertical = 0;
        if (f >= n_members) {
          d_vertical = d_value;
        } else if (f >= 0) {
          d_force = d_value;
          // The string's own stiffness change on its stretch: dk e^T (u_j - u_i).
          for (const auto& [q, dk] : strings) {
            if (q == j - nb) d_force += dk * Combined(stretch, q, c);
          }
        }
        const double d_area = group_of[j] == v ? area_scale[v] : 0.0;
        st.jac(r, v) = k[r].force * d_force + k[r].vertical * d_vertical + k[r].area * d_area;
      }
    }
  }

  // The Jacobian's columns of the self-stresses v_first .. v_last - 1 (numbered after the areas).
  void StateColumns(int v_first, int v_last, const std::vector<Coefficients>& k,
                    const Eigen::MatrixXd& adjoint, const Eigen::MatrixXd& stretch) const {
    const int nr = static_cast<int>(rows.size());
    const int n_members = static_cast<int>(adjoint_members.size());
    std::vector<int> touched;
    for (int v = v_first; v < v_last; ++v) {
      LinearResponse::Direction dp;
      dp.forces = N.col(v - groups) * (force_scale * alpha_factor);
      dp.stiffness = Eigen::VectorXd(ns);
      for (int q = 0; q < ns; ++q)
        dp.stiffness[q] = TautStringStiffness(E, 0.0, dp.forces[nb + q], length[nb + q]);
      const Eigen::MatrixXd action = st.lin->StiffnessAction(st.u, dp);
      touched.clear();
      for (Eigen::Index i = 0; i < action.rows(); ++i) {
        if (!action.row(i).isZero(0.0)) touched.push_back(static_cast<int>(i));
      }
      // d(functional f in column q)/dp = -adjoint(:, f)^T action(:, q), over the touched DOFs
      // (every DOF, for a self-stress): gathered, then one product per entry a row reads. The
      // whole product (functionals x columns) was 15 times the entries the rows read at n = 7.
      const int nt = static_cast<int>(touched.size());
      Eigen::MatrixXd adjoint_t(nt, adjoint.cols()), action_t(nt, action.cols());
      for (int t = 0; t < nt; ++t) {
        adjoint_t.row(t) = adjoint.row(touched[t]);
        action_t.row(t) = action.row(touched[t]);
      }
      // As Combined, on -adjoint_t^T action_t.
      const auto d_value = [&](int f, int c) {
        double out = -adjoint_t.col(f).dot(action_t.col(base_column[c]));
        if (station_factor[c] != 0) {
          out -= station_factor[c] * adjoint_t.col(f).dot(action_t.col(station_column[c]));
        }
        return out;
      };
      const auto force_change = [&](int m, int c) {
        double d = dp.forces[m] + d_value(member_functional[static_cast<size_t>(m)], c);
        if (m >= nb) d += dp.stiffness[m - nb] * Combined(stretch, m - nb, c);
        return d;
      };
      for (int r = 0; r < nr; ++r) {
        const SizingRow& row = rows[r];
        const int j = row.member, c = row.combination, f = row_functional[r];
        if (IsSupport(row)) {
          // The turning term moves with the displacements and with the members' own tension.
          const Eigen::Vector3d turned = Turned(j, c, [&dp](int m) { return dp.forces[m]; });
          const auto turn_change = [&](int axis) {
            return d_value(TurnColumn(j, axis), c) + turned[axis];
          };
          st.jac(r, v) = SupportDerivative(
              row, [&](int m) { return force_change(m, c); }, turn_change);
          continue;
        }
        double d_force = 0, d_vertical = 0;
        if (f >= n_members) {
          d_vertical = d_value(f, c);
        } else if (f >= 0) {
          d_force = dp.forces[j] + d_value(f, c);
          if (j >= nb) d_force += dp.stiffness[j - nb] * Combined(stretch, j - nb, c);
        }
        const double d_reference = row.kind == SizingRow::kReferenceTaut ? dp.forces[j] : 0.0;
        st.jac(r, v) =
            k[r].force * d_force + k[r].vertical * d_vertical + k[r].reference * d_reference;
      }
    }
  }

  // Building (SizingProblem::Build): the members, their materials, floors, groups and scales.
  static void ReadMembers(Impl& p, const Design& d, SizingCorrections corrections) {
    p.s = d.topology.structure;
    const Structure& s = p.s;
    p.nb = s.num_bars();
    p.ns = s.num_strings();
    p.nm = p.nb + p.ns;
    const Config& config = d.config;
    const MemberMaterial strings = StringMaterial(config), bars = BarMaterial(config);
    p.E = strings.youngs_modulus;
    p.E_bar = bars.youngs_modulus;
    p.sigma_w = strings.DesignStress();
    p.sigma_ser = StringServiceStress(config);
    for (int j = 0; j < p.nm; ++j) p.rho.push_back(j < p.nb ? bars.density : strings.density);
    p.rule = BarRuleOf(config);
    p.deflection_limit_m = config.bridge.span / config.loads.deflection_limit;
    corrections.demand_factor.resize(p.nm, 1.0);
    corrections.taut_margin_n.resize(p.nm, 0.0);
    p.corrections = std::move(corrections);
    const DesignInputs in = PrepareDesign(config);
    for (int j = 0; j < p.nm; ++j) {
      const Member& m = s.MemberAt(j);
      p.length.push_back(s.Length(m));
      const double floor = j < p.nb ? in.settings.bar_min_area[j] : in.string_min_area[j - p.nb];
      p.min_area.push_back(std::max(floor, kAreaFloor));
      p.must_taut.push_back(j >= p.nb && MustStayTaut(d, j - p.nb));
    }
    p.group_of = MirrorGroups(s, config.bridge.span);
    p.groups = *std::max_element(p.group_of.begin(), p.group_of.end()) + 1;
    p.members_of.resize(p.groups);
    for (int j = 0; j < p.nm; ++j) p.members_of[p.group_of[j]].push_back(j);
    p.area_scale.assign(p.groups, 0.0);
    for (int j = 0; j < p.nm; ++j) {
      const double area = d.MemberAt(j).area;
      double& scale = p.area_scale[p.group_of[j]];
      scale = std::max({scale, area, p.min_area[j]});
    }
    p.deck_nodes = d.topology.deck_nodes;
  }

  // Building: the reference state, the particular forces of G and the self-stresses, and the
  // design's reference forces as the problem reads them.
  static void ReadReferenceState(Impl& p, const Design& d) {
    const Structure& s = p.s;
    // The reference state: the particular forces of G and the self-stresses.
    const EquilibriumSystem eq = BuildEquilibrium(s);
    const EquilibriumSolver solver(eq);
    if (solver.states() > kMaxSoughtStates) {
      throw ModelError("the verified sizing seeks its symmetric self-stress states among at most " +
                       std::to_string(kMaxSoughtStates) + " states; this bridge has " +
                       std::to_string(solver.states()));
    }
    if (solver.states()) {
      const Eigen::MatrixXd all = solver.SelfStresses();
      p.N = SymmetricSelfStresses(all, p.group_of, p.groups);
      p.to_basis = all.transpose() * p.N;
    }
    p.states = static_cast<int>(p.N.cols());
    if (p.states > kMaxStates) {
      throw ModelError("the verified sizing takes at most " + std::to_string(kMaxStates) +
                       " symmetric self-stress states; this bridge has " +
                       std::to_string(p.states));
    }
    // The minimum-norm particular forces of symmetric loads are symmetric themselves.
    p.x_g = solver.Particular(FreeLoads(eq, d.loads)).col(0);
    p.force_scale = std::max(d.reference_forces.cwiseAbs().maxCoeff(), 1.0);
    for (int j = 0; j < p.nm; ++j) p.area0.push_back(d.MemberAt(j).area);
    // The design's reference forces as the problem reads them: G's particular forces and the
    // symmetric part of its prestress.
    p.xr0 = p.states
                ? Eigen::VectorXd(p.x_g + p.N * (p.N.transpose() * (d.reference_forces - p.x_g)))
                : p.x_g;
    p.mass_scale = std::max(d.mass.structure, 1e-3);
  }

  // Building: the load columns and the combinations, named as the static check names them.
  static void FormCombinations(Impl& p, const Design& d) {
    const Structure& s = p.s;
    // The load columns: each case's change from the reference loads, then a unit station load.
    const int stations = static_cast<int>(d.actions.station_nodes.size());
    auto free = [&s](const Eigen::Matrix3Xd& node_loads) {
      return LinearResponse::FreeVector(s, node_loads);
    };
    const Eigen::VectorXd reference_free = free(d.loads);
    p.loads.resize(reference_free.size(), static_cast<Eigen::Index>(d.cases.size()) + stations);
    for (size_t c = 0; c < d.cases.size(); ++c)
      p.loads.col(c) = free(d.actions.Loads(d.cases[c])) - reference_free;
    const int station_column0 = static_cast<int>(d.cases.size());
    for (int k = 0; k < stations; ++k)
      p.loads.col(station_column0 + k) = free(d.actions.StationLoad(k, 1.0));
    for (size_t c = 0; c < d.cases.size(); ++c) {
      const LoadCase& lc = d.cases[c];
      for (int k = lc.station_load != 0 ? 0 : -1; k < (lc.station_load != 0 ? stations : 0); ++k) {
        SizingCombination combo;
        combo.case_index = static_cast<int>(c);
        combo.station = k;
        combo.ultimate = lc.state == LimitState::kUltimate;
        // Named as the static check names its solves: the station by its first deck node.
        combo.label = CaseLabel(d.cases, d.actions, MemberExtreme{0, static_cast<int>(c), k});
        p.combos.push_back(combo);
        p.station_factor.push_back(k >= 0 ? lc.station_load : 0.0);
        p.base_column.push_back(static_cast<int>(c));
        p.station_column.push_back(k >= 0 ? station_column0 + k : -1);
      }
    }
  }

  // Building: the rows of every combination, then the comfort and reference-taut rows; returns
  // per combination its first row.
  static std::vector<int> FormRows(Impl& p, const Design& d) {
    const Structure& s = p.s;
    const Config& config = d.config;
    // The rows.
    std::vector<int> first_row;  // per combination
    for (int c = 0; c < static_cast<int>(p.combos.size()); ++c) {
      first_row.push_back(static_cast<int>(p.rows.size()));
      if (p.combos[c].ultimate) {
        for (int j = 0; j < p.nm; ++j) {
          if (j < p.nb) {
            p.rows.push_back({SizingRow::kBuckling, j, c});
            p.rows.push_back({SizingRow::kYield, j, c});
          } else {
            p.rows.push_back({SizingRow::kStrength, j, c});
          }
        }
        for (int a = 0; a < 2; ++a) {
          if (p.horizontal_capacity > 0) p.rows.push_back({SizingRow::kSupportHorizontal, a, c});
          // Without the members' weight no variable moves a vertical reaction (weight_share):
          // the check holds it, as a row it would be a constant.
          if (p.vertical_capacity > 0 && config.design.self_weight)
            p.rows.push_back({SizingRow::kSupportVertical, a, c});
        }
      }
      // The strings that must stay taut (the prestressed ones) do so in every combination. The
      // others may go slack, as the checks allow: the linear analysis then reads them in
      // compression, and the checks' corrections (kappa, kappa_d) carry the difference.
      for (int j = p.nb; j < p.nm; ++j) {
        if (p.must_taut[j]) p.rows.push_back({SizingRow::kTaut, j, c});
      }
      // Each string's stress under the characteristic combinations, the reference loads alone
      // included (the permanent case: the prestress is there at its highest against the load).
      if (!p.combos[c].ultimate) {
        for (int j = p.nb; j < p.nm; ++j) p.rows.push_back({SizingRow::kServiceStress, j, c});
      }
      // The deflections are those from the reference state: none in a combination of the
      // reference loads alone (the permanent serviceability case), nor at a support.
      const bool deflects = p.station_factor[c] != 0 || !p.loads.col(p.base_column[c]).isZero(0.0);
      if (!p.combos[c].ultimate && deflects) {
        for (int v : p.deck_nodes) {
          if (s.fixed[v]) continue;
          p.rows.push_back({SizingRow::kDeflectionDown, v, c});
          p.rows.push_back({SizingRow::kDeflectionUp, v, c});
        }
      }
    }
    // The comfort rows: each a function of the variables alone, posed once.
    for (size_t k = 0; k < p.corrections.comfort.size(); ++k)
      p.rows.push_back({SizingRow::kComfort, static_cast<int>(k), -1});
    // A string that no self-stress reaches (its row of the orthonormal N is rounding) has the
    // reference force G alone gives it, whatever the variables: its row would be a constant,
    // violated (n = 8: 126 strings at 0.95 of the row's margin once the weight had grown) or not,
    // which no sizing can mend. The checks find such a string slack or taut.
    for (int j = p.nb; j < p.nm; ++j) {
      if (p.states > 0 && !p.N.row(j).isZero(1e-12))
        p.rows.push_back({SizingRow::kReferenceTaut, j, -1});
    }
    return first_row;
  }
};

// Builds `p`, the rows of the reference state carrying alpha_factor of the prestress; the rows
// posed are those `keep` flags from `offset` on (all without `keep`). Returns the number of
// rows of the whole problem of that state.
size_t SizingProblem::Build(Impl& p, const Design& d, SizingCorrections corrections,
                            const std::vector<char>* keep, size_t offset,
                            const PrestressStateSpec& state) {
  p.alpha_factor = state.alpha_factor;
  p.state = static_cast<int>(state.state);
  Impl::ReadMembers(p, d, std::move(corrections));
  Impl::ReadReferenceState(p, d);
  Impl::FormCombinations(p, d);

  const Config& config = d.config;
  p.horizontal_capacity = config.supports.horizontal_capacity_n.value_or(0.0);
  p.vertical_capacity = config.supports.vertical_capacity_n.value_or(0.0);
  if (p.horizontal_capacity > 0 || p.vertical_capacity > 0) p.IndexReactions(d);

  const std::vector<int> first_row = Impl::FormRows(p, d);  // per combination
  const size_t whole = p.rows.size();
  for (SizingRow& row : p.rows) row.state = p.state;
  for (SizingCombination& combo : p.combos) combo.label += state.suffix;
  if (keep) {
    if (keep->size() < offset + whole) throw ModelError("SizingProblem: one flag per row expected");
    std::vector<SizingRow> kept;
    for (size_t r = 0; r < whole; ++r) {
      if ((*keep)[offset + r]) kept.push_back(p.rows[r]);
    }
    p.rows = std::move(kept);
  }
  p.ReadColumns();
  p.reference_resistance.assign(p.rows.size(), 1.0);
  for (size_t r = 0; r < p.rows.size(); ++r) {
    const SizingRow& row = p.rows[r];
    if (Impl::IsStrength(row)) {
      p.reference_resistance[r] = p.ResistanceAt(row, p.area_scale[p.group_of[row.member]]).value;
    }
  }
  p.IndexFunctionals();
  p.IndexImages(d, keep == nullptr ? &first_row : nullptr);
  return whole;
}

SizingProblem::SizingProblem(const Design& d, SizingCorrections corrections,
                             const std::vector<char>* keep)
    : impl_(std::make_unique<Impl>()) {
  // The other states of the prestress have the rows of every combination again; the comfort rows
  // are the design's state's alone (the modes the comfort check reads).
  SizingCorrections other_corrections = corrections;
  other_corrections.comfort.clear();
  const std::vector<PrestressStateSpec> states = PrestressStatesOf(d.config);
  size_t whole = Build(*impl_, d, std::move(corrections), keep, 0, states.front());
  if (impl_->states > 0) {
    // Each state's shortenings (the rest-length tolerance's pattern, the design's, and the
    // temperature's), held (design/prestress_states.h); their change of the self-stress follows
    // the variables.
    for (size_t k = 1; k < states.size(); ++k) {
      extra_.push_back(std::make_unique<Impl>());
      whole += Build(*extra_.back(), d, other_corrections, keep, whole, states[k]);
      Impl& part = *extra_.back();
      part.shortening = StateShortenings(d, states[k]);
      part.shifted = std::any_of(part.shortening.begin(), part.shortening.end(),
                                 [](double v) { return v != 0; });
    }
  }
  if (keep && keep->size() != whole) throw ModelError("SizingProblem: one flag per row expected");
  rows_ = impl_->rows;
  representatives_ = impl_->row_representative;
  for (const std::unique_ptr<Impl>& part : extra_) {
    const int offset = static_cast<int>(rows_.size());
    rows_.insert(rows_.end(), part->rows.begin(), part->rows.end());
    for (const int r : part->row_representative) representatives_.push_back(r + offset);
  }
}

SizingProblem::~SizingProblem() = default;

std::vector<const SizingProblem::Impl*> SizingProblem::Parts() const {
  std::vector<const Impl*> out{impl_.get()};
  for (const std::unique_ptr<Impl>& part : extra_) out.push_back(part.get());
  return out;
}

std::pair<const SizingProblem::Impl*, int> SizingProblem::Part(int r) const {
  for (const Impl* p : Parts()) {
    const int n = static_cast<int>(p->rows.size());
    if (r < n) return {p, r};
    r -= n;
  }
  throw std::out_of_range("SizingProblem: no row " + std::to_string(r));
}

const Eigen::MatrixXd& SizingProblem::JacobianAt(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  if (extra_.empty()) return impl_->JacobianAt(x);
  if (jacobian_x_.size() != x.size() || jacobian_x_ != x) {
    jacobian_.resize(num_constraints(), num_variables());
    Eigen::Index row = 0;
    for (const Impl* p : Parts()) {
      const Eigen::MatrixXd& part = p->JacobianAt(x);
      jacobian_.middleRows(row, part.rows()) = part;
      row += part.rows();
    }
    jacobian_x_ = x;
  }
  return jacobian_;
}

int SizingProblem::SymmetricStates(const Design& d) {
  const Structure& s = d.topology.structure;
  const EquilibriumSolver solver(BuildEquilibrium(s));
  if (!solver.states()) return 0;
  if (solver.states() > kMaxSoughtStates) return -1;
  const std::vector<int> group_of = MirrorGroups(s, d.config.bridge.span);
  const int groups = *std::max_element(group_of.begin(), group_of.end()) + 1;
  return static_cast<int>(SymmetricSelfStresses(solver.SelfStresses(), group_of, groups).cols());
}

int SizingProblem::num_variables() const { return impl_->num_variables(); }
int SizingProblem::num_constraints() const { return static_cast<int>(rows_.size()); }

void SizingProblem::VariableBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const {
  const Impl& p = *impl_;
  lo.resize(p.num_variables());
  hi.resize(p.num_variables());
  for (int g = 0; g < p.groups; ++g) {
    double floor = 0;
    for (int j : p.members_of[g]) floor = std::max(floor, p.min_area[j]);
    lo[g] = floor / p.area_scale[g];
    hi[g] = std::numeric_limits<double>::infinity();
  }
  for (int m = 0; m < p.states; ++m) {
    lo[p.groups + m] = -std::numeric_limits<double>::infinity();
    hi[p.groups + m] = std::numeric_limits<double>::infinity();
  }
}

void SizingProblem::ConstraintBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const {
  // A margin of 1e-4 on every row (a utilisation at most 0.9999): the outer iterations'
  // corrections make the linear demand the checks' only up to the change of the last step,
  // and a solver's feasibility tolerance (1e-8) must not leave a utilisation above 1.
  lo = Eigen::VectorXd::Constant(num_constraints(), 1e-4);
  hi = Eigen::VectorXd::Constant(num_constraints(), std::numeric_limits<double>::infinity());
}

double SizingProblem::Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const Impl& p = *impl_;
  double mass = 0;
  for (int j = 0; j < p.nm; ++j)
    mass += p.rho[j] * p.length[j] * p.area_scale[p.group_of[j]] * x[p.group_of[j]];
  return mass / p.mass_scale;
}

void SizingProblem::ObjectiveGradient(const Eigen::Ref<const Eigen::VectorXd>& x,
                                      Eigen::Ref<Eigen::VectorXd> grad) const {
  const Impl& p = *impl_;
  (void)x;
  grad.setZero();
  for (int j = 0; j < p.nm; ++j)
    grad[p.group_of[j]] += p.rho[j] * p.length[j] * p.area_scale[p.group_of[j]] / p.mass_scale;
}

void SizingProblem::Constraints(const Eigen::Ref<const Eigen::VectorXd>& x,
                                Eigen::Ref<Eigen::VectorXd> g) const {
  Eigen::Index row = 0;
  for (const Impl* p : Parts()) {
    p->Evaluate(x);
    g.segment(row, p->st.g.size()) = p->st.g;
    row += p->st.g.size();
  }
}

void SizingProblem::Margins(const Eigen::VectorXd& x, Eigen::VectorXd& margin) const {
  margin.resize(num_constraints());
  Eigen::Index row = 0;
  for (const Impl* p : Parts()) {
    p->Evaluate(x);
    margin.segment(row, p->st.margin.size()) = p->st.margin;
    row += p->st.margin.size();
  }
}

const NlpProblem::Pattern& SizingProblem::JacobianPattern() const {
  const Impl& p = *impl_;
  const int nr = num_constraints();
  std::call_once(p.jacobian_formed, [&p, nr]() {
    p.jacobian.reserve(static_cast<size_t>(nr) * static_cast<size_t>(p.num_variables()));
    for (int r = 0; r < nr; ++r) {
      for (int v = 0; v < p.num_variables(); ++v) p.jacobian.emplace_back(r, v);
    }
  });
  return p.jacobian;
}

void SizingProblem::JacobianValues(const Eigen::Ref<const Eigen::VectorXd>& x,
                                   double* values) const {
  const Eigen::MatrixXd& jac = JacobianAt(x);
  // Row-major, as the pattern lists (r, v) pairs.
  for (Eigen::Index r = 0; r < jac.rows(); ++r) {
    for (Eigen::Index v = 0; v < jac.cols(); ++v) values[r * jac.cols() + v] = jac(r, v);
  }
}

bool SizingProblem::DenseJacobian(const Eigen::Ref<const Eigen::VectorXd>& x,
                                  Eigen::MatrixXd& jac) const {
  jac = JacobianAt(x);
  return true;
}

const NlpProblem::Pattern& SizingProblem::HessianPattern() const {
  const Impl& p = *impl_;
  std::call_once(p.hessian_formed, [&p]() {
    for (int v = 0; v < p.num_variables(); ++v) p.hessian.emplace_back(v, v);
  });
  return p.hessian;
}

// The reciprocal diagonal the SQP takes (optim/reciprocal_curvature.h), in NlpProblem's sign:
// its Lagrangian is sigma f + sum lambda_r g_r, where a binding row g_r >= lo_r has lambda_r <= 0
// (Ipopt's), so the curvature's multipliers are -lambda. The prestress variables get none: the
// SQP's secant there is learnt along its own path, which another solver does not walk, and the
// rows are nearly linear in the prestress (a strength row exactly, at given areas); Ipopt's
// inertia correction adds what its step needs there.
void SizingProblem::HessianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double sigma,
                                  const double* lambda, double* values) const {
  const Impl& p = *impl_;
  const Eigen::MatrixXd& jac = JacobianAt(x);
  const Eigen::VectorXd binding = -Eigen::Map<const Eigen::VectorXd>(lambda, jac.rows());
  Eigen::VectorXd grad(p.num_variables());
  ObjectiveGradient(x, grad);
  for (int v = 0; v < p.num_variables(); ++v)
    values[v] =
        v < p.groups ? ReciprocalCurvature(x[v], jac.col(v), binding, sigma * grad[v]) : 0.0;
}

Eigen::VectorXd SizingProblem::VariablesOf(const std::vector<double>& areas,
                                           const Eigen::VectorXd& alpha) const {
  const Impl& p = *impl_;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(p.num_variables());
  for (int j = 0; j < p.nm; ++j)
    x[p.group_of[j]] = std::max(x[p.group_of[j]], areas[j] / p.area_scale[p.group_of[j]]);
  // alpha on the solver's basis: its symmetric part on N's.
  if (p.states && alpha.size() == p.to_basis.rows())
    x.tail(p.states) = p.to_basis.transpose() * alpha / p.force_scale;
  return x;
}

std::vector<double> SizingProblem::Areas(const Eigen::VectorXd& x) const { return impl_->Areas(x); }

Eigen::VectorXd SizingProblem::Alpha(const Eigen::VectorXd& x) const {
  const Impl& p = *impl_;
  if (!p.states) return Eigen::VectorXd::Zero(p.to_basis.rows());
  return p.to_basis * (p.force_scale * x.tail(p.states));
}

Eigen::VectorXd SizingProblem::AlphaOf(const Eigen::VectorXd& reference_forces) const {
  const Impl& p = *impl_;
  if (!p.states) return Eigen::VectorXd::Zero(p.to_basis.rows());
  return p.to_basis * (p.N.transpose() * (reference_forces - p.x_g));  // N is orthonormal
}

std::vector<SizingProblem::MemberDemand> SizingProblem::Demands(const Eigen::VectorXd& x) const {
  std::vector<MemberDemand> out(static_cast<size_t>(impl_->nm));
  int offset = 0;
  for (const Impl* p : Parts()) {
    p->Evaluate(x);
    if (!p->st.lin) return std::vector<MemberDemand>(static_cast<size_t>(impl_->nm));
    for (size_t r = 0; r < p->rows.size(); ++r) {
      const SizingRow& row = p->rows[r];
      if (!Impl::IsStrength(row)) continue;
      const int j = row.member;
      const double resistance = p->ResistanceOf(row).value;
      const double demand = p->corrections.demand_factor[j] * p->st.forces[row.combination][j];
      if (demand / resistance > out[j].utilisation || out[j].row < 0) {
        out[j] = {demand / resistance, demand, resistance, offset + static_cast<int>(r)};
      }
    }
    offset += static_cast<int>(p->rows.size());
  }
  return out;
}

double SizingProblem::LargestDeflection(const Eigen::VectorXd& x) const {
  double largest = 0;
  for (const Impl* p : Parts()) {
    p->Evaluate(x);
    if (!p->st.lin) continue;
    for (size_t c = 0; c < p->combos.size(); ++c) {
      if (p->combos[c].ultimate || !p->combo_read[c])
        continue;  // a combination no row reads has no column
      for (int v : p->deck_nodes)
        largest = std::max(largest, std::abs(p->Vertical(static_cast<int>(c), v, p->st.u)));
    }
  }
  return largest;
}

SizingProblem::Reactions SizingProblem::LargestReactions(const Eigen::VectorXd& x) const {
  Reactions out;
  for (const Impl* p : Parts()) {
    p->Evaluate(x);
    if (!p->st.lin) continue;
    for (const SizingRow& row : p->rows) {
      if (!Impl::IsSupport(row)) continue;
      const Eigen::Vector3d r = p->Reaction(row.combination, row.member);
      out.horizontal = std::max(out.horizontal, std::hypot(r.x(), r.z()));
      out.vertical = std::max(out.vertical, std::abs(r.y()));
    }
  }
  return out;
}

double SizingProblem::mass_scale_kg() const { return impl_->mass_scale; }
double SizingProblem::force_scale_n() const { return impl_->force_scale; }
double SizingProblem::area_scale_m2(int group) const { return impl_->area_scale[group]; }
double SizingProblem::row_scale(int r) const {
  const auto [p, local] = Part(r);
  return p->reference_resistance[static_cast<size_t>(local)];
}

const std::vector<SizingRow>& SizingProblem::rows() const { return rows_; }
const std::vector<SizingCombination>& SizingProblem::combinations() const { return impl_->combos; }
const std::vector<int>& SizingProblem::group_of() const { return impl_->group_of; }

const std::string& SizingProblem::RowLabel(int r) const {
  const auto [part, local] = Part(r);
  const Impl& p = *part;
  const SizingRow& row = p.rows[static_cast<size_t>(local)];
  if (row.kind == SizingRow::kComfort)
    return p.corrections.comfort[static_cast<size_t>(row.member)].label;
  static const std::string kNone;
  return row.combination >= 0 ? p.combos[static_cast<size_t>(row.combination)].label : kNone;
}

const std::vector<ComfortRow>& SizingProblem::comfort_rows() const {
  return impl_->corrections.comfort;
}

double SizingProblem::ComfortOmega2(int r, const Eigen::VectorXd& x) const {
  const auto [part, local] = Part(r);
  part->Evaluate(x);
  return part->ComfortQuotient(part->rows[static_cast<size_t>(local)].member).value();
}

const std::vector<int>& SizingProblem::representatives() const { return representatives_; }

SizingCorrections SizingProblem::ImageCorrections(const SizingCorrections& c) const {
  const Impl& p = *impl_;
  SizingCorrections out = c;
  out.demand_factor.resize(static_cast<size_t>(p.nm), 1.0);
  out.taut_margin_n.resize(static_cast<size_t>(p.nm), 0.0);
  std::vector<double> factor(static_cast<size_t>(p.nm), 0.0),
      margin(static_cast<size_t>(p.nm), -std::numeric_limits<double>::infinity());
  for (int j = 0; j < p.nm; ++j) {
    const size_t first = static_cast<size_t>(p.member_representative[static_cast<size_t>(j)]);
    factor[first] = std::max(factor[first], out.demand_factor[static_cast<size_t>(j)]);
    margin[first] = std::max(margin[first], out.taut_margin_n[static_cast<size_t>(j)]);
  }
  for (int j = 0; j < p.nm; ++j) {
    const size_t first = static_cast<size_t>(p.member_representative[static_cast<size_t>(j)]);
    out.demand_factor[static_cast<size_t>(j)] = factor[first];
    out.taut_margin_n[static_cast<size_t>(j)] = margin[first];
  }
  return out;
}

}  // namespace tbridge
