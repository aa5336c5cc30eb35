#include "dynamics/sdirk.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "core/klu_factor.h"

namespace tbridge {

namespace {

// Alexander's L-stable SDIRK3 (stiffly accurate: the last stage is the solution).
constexpr double kGamma = 0.43586652150845899942;
constexpr double kA21 = 0.5 * (1.0 - kGamma);
constexpr double kB1 = -(6.0 * kGamma * kGamma - 16.0 * kGamma + 1.0) / 4.0;
constexpr double kB2 = (6.0 * kGamma * kGamma - 20.0 * kGamma + 5.0) / 4.0;
constexpr double kC[3] = {kGamma, 0.5 * (1.0 + kGamma), 1.0};

[[noreturn]] void Fail(double t, double h, const std::string& what) {
  std::ostringstream msg;
  msg << "sdirk3: " << what << " in the step from t = " << t << " s (dt = " << h
      << " s). Try a smaller dt (e.g. dt = " << h / 4 << " s)";
  throw ModelError(msg.str());
}

}  // namespace

Sdirk3::~Sdirk3() = default;

Sdirk3::Sdirk3(const AccelerationCoupling& coupling, int size, const SdirkOptions& options)
    : options_(options) {
  const int dim = coupling.dim;
  const int n_n = static_cast<int>(coupling.depends_on.size());
  c_ = dim * n_n;
  if (size != 2 * c_) {
    throw std::invalid_argument("sdirk3: state size " + std::to_string(size) + " != 2 x " +
                                std::to_string(c_) + " coordinates of the coupling");
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<size_t>(coupling.entries()) * dim * dim);
  for (int a = 0; a < n_n; ++a) {
    for (const int q : coupling.depends_on[a]) {
      for (int d = 0; d < dim; ++d) {
        for (int e = 0; e < dim; ++e)
          triplets.emplace_back(a * dim + d, q * dim + e, d == e && a == q ? 1.0 : 0.0);
      }
    }
  }
  matrix_.resize(c_, c_);
  matrix_.setFromTriplets(triplets.begin(), triplets.end());
  matrix_.makeCompressed();

  const std::vector<int> colour = ColourColumns(coupling);
  const int colours = n_n > 0 ? *std::max_element(colour.begin(), colour.end()) + 1 : 0;
  stats_.colours = colours;
  group_columns_.assign(static_cast<size_t>(colours) * dim, {});
  group_slots_.assign(static_cast<size_t>(colours) * dim, {});
  diagonal_.assign(c_, -1);
  const int* outer = matrix_.outerIndexPtr();
  const int* inner = matrix_.innerIndexPtr();
  for (int q = 0; q < n_n; ++q) {
    for (int e = 0; e < dim; ++e) {
      const int col = q * dim + e;
      const size_t g = static_cast<size_t>(colour[q]) * dim + e;
      group_columns_[g].push_back(col);
      for (int k = outer[col]; k < outer[col + 1]; ++k) {
        group_slots_[g].push_back({k, inner[k], col});
        if (inner[k] == col) diagonal_[col] = k;
      }
    }
  }
  if (!lu_.Analyse(matrix_))
    throw std::invalid_argument("sdirk3: KLU could not analyse the Newton matrix's pattern");
  counts_ = {static_cast<long>(matrix_.nonZeros()), lu_.FactorEntries(), lu_.EstimatedFlops(),
             colours * dim + 1};

  for (Eigen::VectorXd* v : {&y0_, &dy_, &dy_pert_, &y_pert_, &stage_})
    *v = Eigen::VectorXd::Zero(2 * c_);
  for (Eigen::VectorXd* v : {&sx_, &sv_, &vel_, &vel_old_, &residual_, &delta_, &eps_})
    *v = Eigen::VectorXd::Zero(c_);
  for (int i = 0; i < 3; ++i) {
    kx_[i] = Eigen::VectorXd::Zero(c_);
    kv_[i] = Eigen::VectorXd::Zero(c_);
  }
}

void Sdirk3::Refresh(OdeSystem& system, double t, double h, const Eigen::VectorXd& y) {
  const double hg = h * kGamma;
  system.Derivative(t, y.data(), dy_.data());
  ++stats_.evaluations;
  // One increment per column: large enough that the position part stands above rounding.
  for (int col = 0; col < c_; ++col) {
    const double ev = options_.fd_eps * std::max(1.0, std::abs(y[c_ + col]));
    const double ex = options_.fd_eps * std::max(1.0, std::abs(y[col]));
    eps_[col] = std::max(ev, ex / hg);
  }
  y_pert_ = y;
  double* values = matrix_.valuePtr();
  for (size_t g = 0; g < group_columns_.size(); ++g) {
    if (group_columns_[g].empty()) continue;
    for (const int col : group_columns_[g]) {
      y_pert_[col] += hg * eps_[col];
      y_pert_[c_ + col] += eps_[col];
    }
    system.Derivative(t, y_pert_.data(), dy_pert_.data());
    ++stats_.evaluations;
    for (const Slot& s : group_slots_[g]) {
      const double d = (dy_pert_[c_ + s.row] - dy_[c_ + s.row]) / eps_[s.col];
      values[s.value] = (s.row == s.col ? 1.0 : 0.0) - hg * d;
    }
    for (const int col : group_columns_[g]) {
      y_pert_[col] = y[col];
      y_pert_[c_ + col] = y[c_ + col];
    }
  }
  if (!lu_.Factorise(matrix_)) Fail(t, h, "the Newton matrix is singular");
  factor_h_ = h;
  ++stats_.jacobians;
}

bool Sdirk3::SolveStage(OdeSystem& system, int stage, double t_stage, double h, bool fresh) {
  // Newton with backtracking on the residual: across slack kinks a full step can overshoot
  // into the other branch and cycle, so a step that does not reduce |G| is halved.
  const double hg = h * kGamma;
  double previous_step = 0, previous_residual = 0, alpha = 1;
  int refreshes = 0, since_refresh = 0;
  for (int k = 0; k < options_.max_iterations; ++k) {
    stage_.head(c_) = sx_ + hg * vel_;
    stage_.tail(c_) = vel_;
    system.Derivative(t_stage, stage_.data(), dy_pert_.data());
    ++stats_.evaluations;
    ++stats_.newton_iterations;
    // The stage's damper power, at the iterate whose correction ends Newton: within its
    // tolerance of the converged stage.
    stage_power_[stage] = system.DissipatedPower();
    residual_ = sv_ - vel_ + hg * dy_pert_.tail(c_);  // -G(V)
    const double residual_norm = residual_.cwiseAbs().maxCoeff();
    if (!std::isfinite(residual_norm)) return false;
    if (k > 0 && residual_norm > previous_residual && alpha > 1.0 / 16) {
      alpha *= 0.5;  // back up along the last Newton direction
      vel_ = vel_old_ + alpha * delta_;
      continue;
    }
    previous_residual = residual_norm;
    vel_old_ = vel_;
    delta_ = residual_;
    lu_.Solve(delta_);
    alpha = 1;
    vel_ += delta_;
    double norm = 0;
    for (int i = 0; i < c_; ++i) {
      norm = std::max(
          norm, std::abs(delta_[i]) / (options_.abs_tol + options_.rel_tol * std::abs(vel_[i])));
    }
    if (!std::isfinite(norm)) return false;
    if (norm <= 1.0) return true;
    const bool slow = (since_refresh > 0 && norm > options_.max_contraction * previous_step) ||
                      since_refresh >= options_.fast_iterations;
    previous_step = norm;
    ++since_refresh;
    if (!slow) continue;
    // An old Jacobian: start the step again with one at its start. A fresh one that still
    // converges slowly sits across a slack kink (the right-hand side is only piecewise
    // smooth): re-linearise at the current iterate, which makes this a semismooth Newton.
    if (!fresh) return false;
    if (++refreshes > options_.max_refreshes) return false;
    y_pert_.head(c_) = sx_ + hg * vel_;
    y_pert_.tail(c_) = vel_;
    stage_ = y_pert_;
    Refresh(system, t_stage, h, stage_);
    since_refresh = 0;
  }
  return false;
}

void Sdirk3::Step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) {
  last_dissipated_ = 0;
  Split(system, t, h, y, options_.max_halvings);
}

void Sdirk3::Split(OdeSystem& system, double t, double h, Eigen::VectorXd& y, int halvings_left) {
  if (Attempt(system, t, h, y)) return;
  if (halvings_left == 0) {
    Fail(t, h,
         "Newton did not converge with a fresh Jacobian, even after halving the step " +
             std::to_string(options_.max_halvings) + " times,");
  }
  ++stats_.halvings;
  Split(system, t, 0.5 * h, y, halvings_left - 1);
  Split(system, t + 0.5 * h, 0.5 * h, y, halvings_left - 1);
}

bool Sdirk3::Attempt(OdeSystem& system, double t, double h, Eigen::VectorXd& y) {
  // CAUTION: performance-sensitive. Lazy Eigen expressions into the workspace.
  const double hg = h * kGamma;
  y0_ = y;
  const auto x0 = y0_.head(c_);
  const auto v0 = y0_.tail(c_);
  bool fresh = false;
  if (factor_h_ != h) {
    Refresh(system, t, h, y0_);
    fresh = true;
  }
  for (;;) {
    bool ok = true;
    for (int i = 0; i < 3 && ok; ++i) {
      if (i == 0) {
        sx_ = x0;
        sv_ = v0;
        vel_ = v0;
      } else if (i == 1) {
        sx_ = x0 + (h * kA21) * kx_[0];
        sv_ = v0 + (h * kA21) * kv_[0];
      } else {
        sx_ = x0 + h * (kB1 * kx_[0] + kB2 * kx_[1]);
        sv_ = v0 + h * (kB1 * kv_[0] + kB2 * kv_[1]);
      }
      ok = SolveStage(system, i, t + kC[i] * h, h, fresh);
      if (ok) {
        kx_[i] = vel_;
        kv_[i] = (vel_ - sv_) / hg;
      }
    }
    if (ok) break;
    if (fresh) return false;  // y untouched: the caller splits the step
    Refresh(system, t, h, y0_);
    fresh = true;
  }
  y.head(c_) = sx_ + hg * vel_;
  y.tail(c_) = vel_;
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    if (!std::isfinite(y[i])) Fail(t, h, "the state is not finite");
  }
  last_dissipated_ +=
      h * (kB1 * stage_power_[0] + kB2 * stage_power_[1] + kGamma * stage_power_[2]);
  ++stats_.steps;
  return true;
}

}  // namespace tbridge
