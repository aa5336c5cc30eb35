#include "design/reduced_min_mass.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/error.h"

namespace tbridge {

namespace {

// An entry of the orthonormal self-stress basis below this magnitude is rounding: a member
// outside every self-stress gets entries of about eps * (condition of A), far below it, while
// a real self-stress spread over 2^16 deck strings has entries of 2^-8.
constexpr double kActiveThreshold = 1e-10;
// A fixed member's scaled force may sit this far beyond its floor (rounding of the particular
// solution, ~1e-15 relative) and still count as on it.
constexpr double kFloorTolerance = 1e-9;

}  // namespace

double SelfStressForceScale(const EquilibriumBasis& basis, const MinMassSettings& settings) {
  double scale = basis.particular.size() ? basis.particular.cwiseAbs().maxCoeff() : 0.0;
  for (const double t : settings.string_min_tension) scale = std::max(scale, t);
  return scale > 0 ? scale : 1.0;
}

ReducedMinMassProblem::ReducedMinMassProblem(const Structure& s, const EquilibriumBasis& basis,
                                             MinMassSettings settings)
    : nb_(s.num_bars()),
      ns_(s.num_strings()),
      s_(static_cast<int>(basis.self_stress.cols())),
      settings_(std::move(settings)) {
  const int members = nb_ + ns_;
  if (!basis.basis_formed)
    throw ModelError("min-mass: the self-stress basis was not formed (too large)");
  if (basis.particular.rows() != members || basis.self_stress.rows() != members ||
      basis.particular.cols() < 1) {
    throw ModelError("min-mass: the equilibrium basis does not match the structure");
  }
  if (static_cast<int>(settings_.string_min_tension.size()) != ns_ ||
      static_cast<int>(settings_.bar_min_area.size()) != nb_) {
    throw ModelError("min-mass: per-member minima have the wrong size");
  }
  if (!(settings_.strings.DesignStress() > 0) || !(settings_.bars.DesignStress() > 0)) {
    throw ModelError("min-mass: working stress must be > 0");
  }
  // The bars' design stress and modulus: their areas are in units of force_ref_ / sigma_w.
  const double sigma_w = settings_.bars.DesignStress();
  const double E = settings_.bars.youngs_modulus;
  const double bar_mass_ratio = settings_.BarMassRatio();

  force_ref_ = SelfStressForceScale(basis, settings_);
  const Eigen::Vector3d extent = s.nodes.rowwise().maxCoeff() - s.nodes.rowwise().minCoeff();
  const double length_ref = std::max(extent.norm(), 1e-300);
  mass_ref_ =
      settings_.strings.density * length_ref * force_ref_ / settings_.strings.DesignStress();
  p_ = basis.particular / force_ref_;
  n_ = basis.self_stress;
  const int cases = num_cases();
  const bool string_envelopes = cases > 1;

  cost_.setZero(s_);
  std::vector<double> envelope_cost;
  for (int j = 0; j < members; ++j) {
    const bool bar = j < nb_;
    const Member& m = s.MemberAt(j);
    const double weight = (bar ? bar_mass_ratio : 1.0) * s.Length(m) / length_ref;
    const double lo = bar ? 0.0 : settings_.string_min_tension[j - nb_] / force_ref_;
    const double kappa =
        bar ? 2.0 * s.Length(m) * sigma_w *
                  std::sqrt(settings_.buckling_safety_factor / (std::numbers::pi * E * force_ref_))
            : 0.0;
    const double area_min = bar ? settings_.bar_min_area[j] * sigma_w / force_ref_ : lo;
    Active a{j, -1, bar, weight, lo, kappa, {}};
    for (int k = 0; k < s_; ++k) {
      if (std::abs(n_(j, k)) > kActiveThreshold) a.row.emplace_back(k, n_(j, k));
    }
    if (a.row.empty()) {  // fixed: its area is known
      double area = area_min;
      for (int c = 0; c < cases; ++c) {
        const double f = p_(j, c);
        if (f < lo - kFloorTolerance) {
          std::ostringstream os;
          os << "min-mass: " << (bar ? "bar " : "string ") << Structure::Name(m) << " carries "
             << f * force_ref_ << " N in load case " << c + 1 << " ("
             << (bar ? "compression" : "tension") << " must be at least " << lo * force_ref_
             << " N) and no self-stress can change it";
          throw ModelError(os.str());
        }
        area = std::max({area, f, kappa * std::sqrt(std::max(f, 0.0))});
      }
      constant_ += weight * area;
      continue;
    }
    if (bar || string_envelopes) {
      a.envelope = s_ + num_envelopes_++;
      envelope_cost.push_back(weight);
      var_lo_.conservativeResize(num_envelopes_);
      var_lo_[num_envelopes_ - 1] = area_min;
    } else {  // one case: the string's area is its tension, priced directly
      constant_ += weight * p_(j, 0);
      for (const auto& [k, v] : a.row) cost_[k] += weight * v;
    }
    active_bars_ += bar ? 1 : 0;
    active_.push_back(std::move(a));
  }
  cost_.conservativeResize(s_ + num_envelopes_);
  for (int e = 0; e < num_envelopes_; ++e) cost_[s_ + e] = envelope_cost[e];

  FormRows();
}

// Rows: per case, per active member: floor, then envelope, then buckling.
void ReducedMinMassProblem::FormRows() {
  const int cases = num_cases();
  std::vector<double> lo_rows;
  hess_of_active_.assign(active_.size(), -1);
  for (int c = 0; c < cases; ++c) {
    for (int i = 0; i < num_active(); ++i) {
      const Active& a = active_[i];
      const double p = p_(a.member, c);
      const int kinds = a.bar ? 3 : (a.envelope >= 0 ? 2 : 1);
      for (int kind = 0; kind < kinds; ++kind) {
        const int r = static_cast<int>(rows_.size());
        rows_.push_back({kind, i, c});
        lo_rows.push_back(kind == 0 ? a.lo - p : kind == 1 ? p : a.kappa * a.kappa * p);
        if (kind > 0) jac_pattern_.emplace_back(r, a.envelope);
        for (const auto& [k, v] : a.row) jac_pattern_.emplace_back(r, k);
      }
      if (a.bar && hess_of_active_[i] < 0) {
        hess_of_active_[i] = static_cast<int>(hess_pattern_.size());
        hess_pattern_.emplace_back(a.envelope, a.envelope);
      }
    }
  }
  row_lo_ = Eigen::Map<Eigen::VectorXd>(lo_rows.data(), static_cast<Eigen::Index>(lo_rows.size()));
}

void ReducedMinMassProblem::VariableBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const {
  const double inf = std::numeric_limits<double>::infinity();
  lo.setConstant(num_variables(), -inf);
  hi.setConstant(num_variables(), inf);
  lo.tail(num_envelopes_) = var_lo_;
}

void ReducedMinMassProblem::ConstraintBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const {
  lo = row_lo_;
  hi.setConstant(num_constraints(), std::numeric_limits<double>::infinity());
}

double ReducedMinMassProblem::ScaledForce(const Active& a, int c,
                                          const Eigen::Ref<const Eigen::VectorXd>& x) const {
  double f = p_(a.member, c);
  for (const auto& [k, v] : a.row) f += v * x[k];
  return f;
}

Eigen::VectorXd ReducedMinMassProblem::StartingPoint() const {
  // Project the forces pushed onto their floors back into the self-stress space (N is
  // orthonormal), then give every envelope 10 % room over its case forces.
  Eigen::VectorXd x = Eigen::VectorXd::Zero(num_variables());
  for (const Active& a : active_) {
    const double push = std::max(a.lo + 1e-3 - p_(a.member, 0), 0.0);
    for (const auto& [k, v] : a.row) x[k] += v * push;
  }
  for (const Active& a : active_) {
    if (a.envelope < 0) continue;
    double need = var_lo_[a.envelope - s_];
    for (int c = 0; c < num_cases(); ++c) {
      const double f = std::max(ScaledForce(a, c, x), 0.0);
      need = std::max({need, f, a.kappa * std::sqrt(f)});
    }
    x[a.envelope] = 1.1 * need + 1e-3;
  }
  return x;
}

double ReducedMinMassProblem::Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return constant_ + cost_.dot(x);
}

void ReducedMinMassProblem::Constraints(const Eigen::Ref<const Eigen::VectorXd>& x,
                                        Eigen::Ref<Eigen::VectorXd> g) const {
  for (size_t r = 0; r < rows_.size(); ++r) {
    const Active& a = active_[rows_[r].active];
    double nalpha = 0;
    for (const auto& [k, v] : a.row) nalpha += v * x[k];
    switch (rows_[r].kind) {
      case 0:
        g[r] = nalpha;
        break;
      case 1:
        g[r] = x[a.envelope] - nalpha;
        break;
      default:
        g[r] = x[a.envelope] * x[a.envelope] - a.kappa * a.kappa * nalpha;
        break;
    }
  }
}

void ReducedMinMassProblem::JacobianValues(const Eigen::Ref<const Eigen::VectorXd>& x,
                                           double* values) const {
  size_t v = 0;
  for (const Row& row : rows_) {
    const Active& a = active_[row.active];
    const double scale = row.kind == 0 ? 1.0 : row.kind == 1 ? -1.0 : -a.kappa * a.kappa;
    if (row.kind > 0) values[v++] = row.kind == 1 ? 1.0 : 2.0 * x[a.envelope];
    for (const auto& entry : a.row) values[v++] = scale * entry.second;
  }
}

void ReducedMinMassProblem::HessianValues(const Eigen::Ref<const Eigen::VectorXd>&, double,
                                          const double* lambda, double* values) const {
  // Only the buckling rows are nonlinear: d^2(e^2)/de^2 = 2 on the bar's envelope variable.
  std::fill(values, values + hess_pattern_.size(), 0.0);
  for (size_t r = 0; r < rows_.size(); ++r) {
    if (rows_[r].kind == 2) values[hess_of_active_[rows_[r].active]] += 2.0 * lambda[r];
  }
}

Eigen::VectorXd ReducedMinMassProblem::MemberForces(const Eigen::Ref<const Eigen::VectorXd>& x,
                                                    int c) const {
  return (p_.col(c) + n_ * x.head(s_)) * force_ref_;
}

SolverOutcome ReducedMinMassProblem::SolveDirect(Eigen::VectorXd& x) const {
  if (!DirectApplies())
    throw ModelError("min-mass: the direct solve needs at most one self-stress, loading no bar");
  SolverOutcome out;
  out.solver = SolverKind::kDirect;
  x = Eigen::VectorXd::Zero(num_variables());
  if (s_ == 1) {
    // The objective is linear in alpha (strings only: each area is its largest case tension,
    // shifted by N_j alpha), so the optimum is the cheaper end of the feasible interval.
    const double inf = std::numeric_limits<double>::infinity();
    double lo = -inf, hi = inf, slope = 0, scale = 0;
    for (const Active& a : active_) {
      const double v = a.row.front().second;
      slope += a.weight * v;
      scale += a.weight * std::abs(v);
      for (int c = 0; c < num_cases(); ++c) {
        const double bound = (a.lo - p_(a.member, c)) / v;  // N_j alpha >= lo - p
        if (v > 0)
          lo = std::max(lo, bound);
        else
          hi = std::min(hi, bound);
      }
    }
    if (lo > hi)
      throw ModelError("min-mass: the self-stress cannot bring every string to its floor at once");
    // A slope within rounding of zero leaves alpha free: take the feasible value nearest zero.
    const bool flat = std::abs(slope) <= 1e-12 * scale;
    const double alpha = flat ? std::clamp(0.0, lo, hi) : (slope > 0 ? lo : hi);
    if (!std::isfinite(alpha)) {
      throw ModelError(
          "min-mass: the self-stress lowers the mass without bound (no string floors it)");
    }
    x[0] = alpha;
    out.message = "self-stress coefficient at the cheaper end of its feasible interval";
  } else {
    out.message = "no self-stress: the forces are the unique equilibrium solution";
  }
  for (const Active& a : active_) {
    if (a.envelope < 0) continue;
    double need = var_lo_[a.envelope - s_];
    for (int c = 0; c < num_cases(); ++c) need = std::max(need, ScaledForce(a, c, x));
    x[a.envelope] = need;
  }
  out.status = "Solve_Succeeded";
  out.success = true;
  out.objective = Objective(x);
  return out;
}

}  // namespace tbridge
