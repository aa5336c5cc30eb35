#include "design/min_mass.h"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"

namespace tbridge {

MinMassProblem::MinMassProblem(const Structure& s, const Eigen::Matrix3Xd& loads,
                               MinMassSettings settings)
    : nb_(s.num_bars()),
      ns_(s.num_strings()),
      settings_(std::move(settings)),
      eq_(BuildEquilibrium(s)) {
  if (loads.cols() != s.num_nodes()) throw ModelError("min-mass: load matrix has the wrong size");
  if (static_cast<int>(settings_.string_min_tension.size()) != ns_ ||
      static_cast<int>(settings_.bar_min_area.size()) != nb_) {
    throw ModelError("min-mass: per-member minima have the wrong size");
  }
  if (!(settings_.strings.DesignStress() > 0) || !(settings_.bars.DesignStress() > 0)) {
    throw ModelError("min-mass: working stress must be > 0");
  }

  force_ref_ = 0.0;
  for (int v = 0; v < s.num_nodes(); ++v) force_ref_ = std::max(force_ref_, loads.col(v).norm());
  for (double t : settings_.string_min_tension) force_ref_ = std::max(force_ref_, t);
  if (!(force_ref_ > 0)) force_ref_ = 1.0;
  const Eigen::Vector3d extent = s.nodes.rowwise().maxCoeff() - s.nodes.rowwise().minCoeff();
  const double length_ref = std::max(extent.norm(), 1e-300);
  // The bars' design stress and modulus: their areas are in units of force_ref_ / sigma_w.
  const double sigma_w = settings_.bars.DesignStress();
  const double E = settings_.bars.youngs_modulus;
  const double bar_mass_ratio = settings_.BarMassRatio();
  mass_ref_ =
      settings_.strings.density * length_ref * force_ref_ / settings_.strings.DesignStress();

  rhs_ = -FreeLoads(eq_, loads) / force_ref_;
  cost_.setZero(num_variables());
  kappa_.resize(nb_);
  a_min_.resize(nb_);
  t_min_.resize(ns_);
  for (int b = 0; b < nb_; ++b) {
    const double l = s.Length(s.bars[b]);
    cost_[bar_area_index(b)] = bar_mass_ratio * l / length_ref;
    // A >= 2 l sqrt(SF C / (pi E)) in scaled units.
    kappa_[b] = 2.0 * l * sigma_w *
                std::sqrt(settings_.buckling_safety_factor / (std::numbers::pi * E * force_ref_));
    a_min_[b] = settings_.bar_min_area[b] * sigma_w / force_ref_;
  }
  for (int k = 0; k < ns_; ++k) {
    cost_[string_force_index(k)] = s.Length(s.strings[k]) / length_ref;
    t_min_[k] = settings_.string_min_tension[k] / force_ref_;
  }

  // Jacobian pattern: equality rows (the equilibrium matrix), then yield, then buckling rows.
  for (int col = 0; col < eq_.A.outerSize(); ++col) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(eq_.A, col); it; ++it) {
      jac_pattern_.emplace_back(static_cast<int>(it.row()), col);
      eq_values_.push_back(it.value());
    }
  }
  const int m = num_equalities();
  for (int b = 0; b < nb_; ++b) {
    jac_pattern_.emplace_back(m + b, bar_area_index(b));
    jac_pattern_.emplace_back(m + b, bar_force_index(b));
  }
  for (int b = 0; b < nb_; ++b) {
    jac_pattern_.emplace_back(m + nb_ + b, bar_area_index(b));
    jac_pattern_.emplace_back(m + nb_ + b, bar_force_index(b));
  }
  for (int b = 0; b < nb_; ++b) hess_pattern_.emplace_back(bar_area_index(b), bar_area_index(b));
}

void MinMassProblem::VariableBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const {
  const double inf = std::numeric_limits<double>::infinity();
  lo.setZero(num_variables());
  hi.setConstant(num_variables(), inf);
  for (int k = 0; k < ns_; ++k) lo[string_force_index(k)] = t_min_[k];
  for (int b = 0; b < nb_; ++b) lo[bar_area_index(b)] = a_min_[b];
}

void MinMassProblem::ConstraintBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const {
  const double inf = std::numeric_limits<double>::infinity();
  lo.setZero(num_constraints());
  hi.setConstant(num_constraints(), inf);
  lo.head(num_equalities()) = rhs_;
  hi.head(num_equalities()) = rhs_;
}

Eigen::VectorXd MinMassProblem::StartingPoint() const {
  // Least-norm equilibrium forces: x = A^T (A A^T)^-1 rhs. A tiny shift keeps A A^T
  // factorable when the structure has infinitesimal mechanisms.
  Eigen::SparseMatrix<double> AAt = eq_.A * eq_.A.transpose();
  Eigen::SparseMatrix<double> I(AAt.rows(), AAt.cols());
  I.setIdentity();
  AAt += 1e-12 * I;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(AAt);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(nb_ + ns_);
  if (ldlt.info() == Eigen::Success) forces = eq_.A.transpose() * ldlt.solve(rhs_);
  Eigen::VectorXd x(num_variables());
  for (int b = 0; b < nb_; ++b) {
    const double c = std::max(forces[b], 1e-3);
    x[bar_force_index(b)] = c;
    x[bar_area_index(b)] = 1.1 * std::max({c, kappa_[b] * std::sqrt(c), a_min_[b]}) + 1e-3;
  }
  for (int k = 0; k < ns_; ++k) {
    x[string_force_index(k)] = std::max(forces[nb_ + k], t_min_[k]) + 1e-3;
  }
  return x;
}

double MinMassProblem::Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return cost_.dot(x);
}

void MinMassProblem::Constraints(const Eigen::Ref<const Eigen::VectorXd>& x,
                                 Eigen::Ref<Eigen::VectorXd> g) const {
  const int m = num_equalities();
  g.head(m) = eq_.A * x.head(nb_ + ns_);
  for (int b = 0; b < nb_; ++b) {
    const double a = x[bar_area_index(b)], c = x[bar_force_index(b)];
    g[m + b] = a - c;
    g[m + nb_ + b] = a * a - kappa_[b] * kappa_[b] * c;
  }
}

void MinMassProblem::JacobianValues(const Eigen::Ref<const Eigen::VectorXd>& x,
                                    double* values) const {
  size_t v = 0;
  for (double e : eq_values_) values[v++] = e;
  for (int b = 0; b < nb_; ++b) {
    values[v++] = 1.0;
    values[v++] = -1.0;
  }
  for (int b = 0; b < nb_; ++b) {
    values[v++] = 2.0 * x[bar_area_index(b)];
    values[v++] = -kappa_[b] * kappa_[b];
  }
}

void MinMassProblem::HessianValues(const Eigen::Ref<const Eigen::VectorXd>&, double,
                                   const double* lambda, double* values) const {
  const int first_buckling = num_equalities() + nb_;
  for (int b = 0; b < nb_; ++b) values[b] = 2.0 * lambda[first_buckling + b];
}

Eigen::VectorXd MinMassProblem::MemberForces(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return x.head(nb_ + ns_) * force_ref_;
}

}  // namespace tbridge
