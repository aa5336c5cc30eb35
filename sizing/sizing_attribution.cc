#include "sizing/sizing_attribution.h"

#include <algorithm>
#include <cmath>

#include "optim/nnls.h"

namespace tbridge {
namespace {

// The row's kind; a strength row's share that the dynamic runs add (`dynamic` of its member)
// goes to "dynamics" (DynamicShare).
ConstraintKind KindOf(const SizingRow& row) {
  // Whatever its kind, a row of another state of the prestress: what the loss and the rest-length
  // tolerance cost.
  if (row.state != 0) return kRobustnessKind;
  switch (row.kind) {
    case SizingRow::kStrength:
      return kStrengthKind;
    case SizingRow::kBuckling:
      return kBucklingKind;
    case SizingRow::kYield:
      return kYieldKind;
    case SizingRow::kDeflectionDown:
    case SizingRow::kDeflectionUp:
      return kDeflectionKind;
    case SizingRow::kComfort:
      return kComfortKind;
    case SizingRow::kSupportHorizontal:
    case SizingRow::kSupportVertical:
      return kSupportsKind;
    case SizingRow::kServiceStress:
      return kServiceStressKind;
    case SizingRow::kTaut:
    case SizingRow::kReferenceTaut:
      break;
  }
  return kTautKind;
}

double DynamicShare(const SizingRow& row, const std::vector<double>& dynamic) {
  const ConstraintKind kind = KindOf(row);
  const bool strength = kind == kStrengthKind || kind == kBucklingKind || kind == kYieldKind;
  return strength && row.member >= 0 && row.member < static_cast<int>(dynamic.size())
             ? dynamic[row.member]
             : 0.0;
}

// The multiplier of a row in physical units: the rows are scaled (problem.h), utilisation and
// deflection rows as fractions of their limits, tension rows by the force scale, areas by
// the group's area scale.
double Physical(ConstraintKind kind, double lambda, const SizingProblem& p, int group) {
  if (kind == kTautKind) return lambda * p.mass_scale_kg() / p.force_scale_n();
  if (kind == kMinimumKind) return lambda * p.mass_scale_kg() / p.area_scale_m2(group);
  return lambda * p.mass_scale_kg();
}

const char* UnitOf(ConstraintKind kind) {
  return kind == kTautKind         ? "kg/N"
         : kind == kDeflectionKind ? "kg per unit deflection / limit"
         : kind == kMinimumKind    ? "kg/m^2"
         : kind == kComfortKind    ? "kg per unit of omega^2 / its bound"
         : kind == kSupportsKind   ? "kg per unit of reaction / capacity"
                                   : "kg per unit utilisation";
}

}  // namespace

MassAttribution AttributeMass(const SizingProblem& p, const Eigen::VectorXd& x,
                              const std::vector<double>& dynamic,
                              const Eigen::VectorXd& reference_x) {
  const int nv = p.num_variables(), nr = p.num_constraints();
  Eigen::VectorXd grad(nv), lo, hi;
  p.ObjectiveGradient(x, grad);
  p.VariableBounds(lo, hi);
  Eigen::VectorXd jac_values(static_cast<Eigen::Index>(p.JacobianPattern().size()));
  p.JacobianValues(x, jac_values.data());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nr, nv);
  for (size_t k = 0; k < p.JacobianPattern().size(); ++k) {
    J(p.JacobianPattern()[k].first, p.JacobianPattern()[k].second) =
        jac_values[static_cast<Eigen::Index>(k)];
  }
  // Unknowns: lambda per posed row, then mu per variable at its lower bound (a minimum size).
  std::vector<int> at_floor;
  for (int v = 0; v < nv; ++v) {
    if (std::isfinite(lo[v]) && x[v] <= lo[v] * (1 + 1e-6) + 1e-12) at_floor.push_back(v);
  }
  Eigen::MatrixXd A(nv, nr + static_cast<int>(at_floor.size()));
  A.leftCols(nr) = J.transpose();
  A.rightCols(static_cast<Eigen::Index>(at_floor.size())).setZero();
  for (size_t k = 0; k < at_floor.size(); ++k)
    A(at_floor[k], nr + static_cast<Eigen::Index>(k)) = 1.0;
  double residual = 0;
  const Eigen::VectorXd z = NonNegativeLeastSquares(A, grad, &residual);

  MassAttribution out;
  out.active_rows = nr;
  out.multipliers = z;
  out.stationarity_residual = residual / std::max(grad.norm(), 1e-300);
  out.structure_kg = p.Objective(x) * p.mass_scale_kg();
  // The split along x itself and along the change from the reference: the mass is linear in
  // the variables (zero at zero), so grad f . x = f and grad f . dx = df, and with grad f =
  // J^T lambda + mu each row's term lambda_r J_r . x (and mu . x) is its kind's share.
  const bool premium = reference_x.size() == x.size();
  const Eigen::VectorXd along_x = J * x, along_dx = premium ? Eigen::VectorXd(J * (x - reference_x))
                                                            : Eigen::VectorXd();
  for (int r = 0; r < nr; ++r) {
    const double f = DynamicShare(p.rows()[r], dynamic);
    const ConstraintKind kind = KindOf(p.rows()[r]);
    const double scale = z[r] * p.mass_scale_kg();
    out.mass_by_kind_kg[kind] += (1 - f) * scale * along_x[r];
    out.mass_by_kind_kg[kDynamicsKind] += f * scale * along_x[r];
    if (premium) {
      out.premium_by_kind_kg[kind] += (1 - f) * scale * along_dx[r];
      out.premium_by_kind_kg[kDynamicsKind] += f * scale * along_dx[r];
    }
  }
  for (size_t k = 0; k < at_floor.size(); ++k) {
    const int v = at_floor[k];
    const double scale = z[nr + static_cast<Eigen::Index>(k)] * p.mass_scale_kg();
    out.mass_by_kind_kg[kMinimumKind] += scale * x[v];
    if (premium) out.premium_by_kind_kg[kMinimumKind] += scale * (x[v] - reference_x[v]);
  }
  // Per group of members: the row whose term lambda_r dg_r/dx_v is largest binds it.
  const std::vector<int>& group_of = p.group_of();
  const int members = static_cast<int>(group_of.size());
  const int groups = *std::max_element(group_of.begin(), group_of.end()) + 1;
  std::vector<int> best_row(groups, -1);
  std::vector<double> best_term(groups, 0.0);
  for (int v = 0; v < groups; ++v) {
    for (int r = 0; r < nr; ++r) {
      const double term = z[r] * J(r, v);
      if (term > best_term[v]) best_term[v] = term, best_row[v] = r;
    }
  }
  for (size_t k = 0; k < at_floor.size(); ++k) {
    const int v = at_floor[k];
    if (v >= groups) continue;  // a prestress variable's bound costs no mass
    const double term = z[nr + static_cast<Eigen::Index>(k)];
    if (term > best_term[v]) best_term[v] = term, best_row[v] = -2 - static_cast<int>(k);
  }
  out.members.resize(members);
  for (int j = 0; j < members; ++j) {
    const int v = group_of[j], r = best_row[v];
    MemberBinding& b = out.members[j];
    if (r >= 0) {
      const ConstraintKind kind =
          DynamicShare(p.rows()[r], dynamic) > 0.5 ? kDynamicsKind : KindOf(p.rows()[r]);
      b.kind = kind;
      b.case_label = p.RowLabel(r);
      b.multiplier = Physical(kind, z[r], p, v);
      b.unit = UnitOf(kind);
    } else if (r <= -2) {
      b.kind = kMinimumKind;
      b.multiplier = Physical(kMinimumKind, z[nr - 2 - r], p, v);
      b.unit = UnitOf(kMinimumKind);
    }
  }
  return out;
}

}  // namespace tbridge
