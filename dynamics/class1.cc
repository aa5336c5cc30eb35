#include "dynamics/class1.h"

#include <cmath>
#include <cstring>
#include <string>

#include "core/error.h"

namespace tbridge {

namespace {

std::string NodeName(int node) { return std::to_string(node + 1); }

}  // namespace

Class1System::Class1System(const DynamicModel& model, const Class1Options& options,
                           std::vector<TimedLoad> timed_loads)
    : EngineFrame(model, options, timed_loads, "class-1 dynamics"),
      n_model_bars_(static_cast<int>(model.bars.size())) {
  std::vector<int> bars_at(n_n_, 0);
  for (const DynamicBar& b : model.bars) {
    ++bars_at[b.i];
    ++bars_at[b.j];
  }
  for (int a = 0; a < n_n_; ++a) {
    if (bars_at[a] > 1) {
      throw ModelError(Where() + ": node " + NodeName(a) + " carries " +
                       std::to_string(bars_at[a]) + " bars; this is a class-k structure");
    }
  }

  for (size_t k = 0; k < model.bars.size(); ++k) {
    const DynamicBar& b = model.bars[k];
    const int index = static_cast<int>(k);
    const bool fi = model.fixed[b.i], fj = model.fixed[b.j];
    if (fi && fj) continue;
    if (fi || fj) {
      const int pinned = fi ? b.i : b.j, free = fi ? b.j : b.i;
      const double mass = b.mass / 3.0 + NodeMass(free);
      if (!(mass > 0))
        throw ModelError(Where() + ": bar at node " + NodeName(free) + " has no mass");
      pinned_bars_.push_back(
          {pinned * dim_, free * dim_, mass, 1.0 / mass, b.length * b.length, index});
      AddMassBlock(-1, free * dim_, 0.0, 0.0, mass);
      continue;
    }
    PackedBar p{};
    p.oi = b.i * dim_;
    p.oj = b.j * dim_;
    const double m00 = b.mass / 3.0 + NodeMass(b.i);
    const double m11 = b.mass / 3.0 + NodeMass(b.j);
    const double m01 = b.mass / 6.0;
    const double det = m00 * m11 - m01 * m01;
    if (!(det > 0)) {
      throw ModelError(Where() + ": bar " + NodeName(b.i) + "-" + NodeName(b.j) +
                       " has a singular mass matrix (no mass)");
    }
    p.a00 = m11 / det;
    p.a11 = m00 / det;
    p.a01 = -m01 / det;
    p.p = p.a01 - p.a00;
    p.q = p.a11 - p.a01;
    p.inv_w = 1.0 / (p.a00 + p.a11 - 2.0 * p.a01);
    p.rest_sq = b.length * b.length;
    p.model_index = index;
    bars_.push_back(p);
    AddMassBlock(p.oi, p.oj, m00, m01, m11);
  }
  std::vector<bool> has_bar(n_n_);
  for (int a = 0; a < n_n_; ++a) has_bar[a] = bars_at[a] > 0;
  AddNodes(model, has_bar);
}

void Class1System::BarForceDensities(const Class1Workspace& ws, Eigen::VectorXd& out) const {
  out = ws.lambda;
}

template <int D, bool Damped, bool Stabilised>
void Class1System::DerivativeImpl(double t, const double* y, double* dy,
                                  Class1Workspace& ws) const {
  // CAUTION: performance-sensitive. Plain loops over flat arrays; no allocation, no matrices.
  const int c = coordinates();
  const double* x = y;
  const double* v = y + c;
  double* f = ws.force.data();
  double* acc = dy + c;
  ws.damper_power = StartDerivative<D, Damped>(
      t, y, dy, f, ws.record_strings);  // x' = v; loads, strings (eqs 16-17)
  ws.record_strings = nullptr;
  double* lambdas = ws.lambda.data();

  // Bars with both ends free (eq 23 in closed form, see the header).
  [[maybe_unused]] const double two_zeta_omega = 2.0 * options_.zeta * options_.omega_rad_s;
  [[maybe_unused]] const double half_omega_sq = 0.5 * options_.omega_rad_s * options_.omega_rad_s;
  for (const PackedBar& bar : bars_) {
    double b[D], bd[D], fi[D], fj[D];
    double l2 = 0, bd2 = 0, bpq = 0;
    for (int d = 0; d < D; ++d) {
      b[d] = x[bar.oj + d] - x[bar.oi + d];
      bd[d] = v[bar.oj + d] - v[bar.oi + d];
      fi[d] = f[bar.oi + d];
      fj[d] = f[bar.oj + d];
      l2 += b[d] * b[d];
      bd2 += bd[d] * bd[d];
      bpq += b[d] * (bar.p * fi[d] + bar.q * fj[d]);
    }
    double numerator = bd2 + bpq;
    if constexpr (Stabilised) {
      double bbd = 0;
      for (int d = 0; d < D; ++d) bbd += b[d] * bd[d];
      numerator += two_zeta_omega * bbd + half_omega_sq * (l2 - bar.rest_sq);
    }
    const double lambda = -numerator * bar.inv_w / l2;
    lambdas[bar.model_index] = lambda;
    for (int d = 0; d < D; ++d) {
      const double gi = fi[d] - lambda * b[d];
      const double gj = fj[d] + lambda * b[d];
      acc[bar.oi + d] = bar.a00 * gi + bar.a01 * gj;
      acc[bar.oj + d] = bar.a01 * gi + bar.a11 * gj;
    }
  }

  // Bars pinned at one end.
  for (const PinnedBar& bar : pinned_bars_) {
    double b[D];
    double l2 = 0, bd2 = 0, bf = 0, bbd = 0;
    for (int d = 0; d < D; ++d) {
      b[d] = x[bar.oj + d] - x[bar.oi + d];
      l2 += b[d] * b[d];
      bd2 += v[bar.oj + d] * v[bar.oj + d];
      bf += b[d] * f[bar.oj + d];
      bbd += b[d] * v[bar.oj + d];
    }
    double numerator = bar.mass * bd2 + bf;
    if constexpr (Stabilised)
      numerator += bar.mass * (two_zeta_omega * bbd + half_omega_sq * (l2 - bar.rest_sq));
    const double lambda = -numerator / l2;
    lambdas[bar.model_index] = lambda;
    for (int d = 0; d < D; ++d) acc[bar.oj + d] = (f[bar.oj + d] + lambda * b[d]) * bar.inv_mass;
  }

  FinishDerivative<D>(f, dy);
  ws.damper_power += MassDamping<D>(y, dy);
}

void Class1System::Derivative(double t, const double* y, double* dy, Class1Workspace& ws) const {
  Evaluate(*this, t, y, dy, ws);
}

}  // namespace tbridge
