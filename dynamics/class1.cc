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
    : dim_(model.dim), n_n_(model.num_nodes()), options_(options) {
  if (dim_ != 2 && dim_ != 3) throw ModelError("class-1 dynamics: dim must be 2 or 3");
  if (static_cast<int>(model.fixed.size()) != n_n_) {
    throw ModelError("class-1 dynamics: fixed has " + std::to_string(model.fixed.size()) +
                     " entries for " + std::to_string(n_n_) + " nodes");
  }
  const bool has_node_mass = model.node_mass.size() != 0;
  if (has_node_mass && model.node_mass.size() != n_n_) {
    throw ModelError("class-1 dynamics: node_mass has the wrong size");
  }
  if (options.stabilisation && !(options.omega_rad_s > 0 && options.zeta >= 0)) {
    throw ModelError("class-1 dynamics: stabilisation needs omega > 0 and zeta >= 0");
  }
  auto node_mass = [&](int a) { return has_node_mass ? model.node_mass(a) : 0.0; };
  auto check_node = [&](int a, const std::string& what) {
    if (a < 0 || a >= n_n_) throw ModelError("class-1 dynamics: " + what + " names node " + NodeName(a) + " out of range");
  };

  loads_ = NodeLoads(model, timed_loads, "class-1 dynamics");
  strings_ = PackStrings(model, "class-1 dynamics", damped_);
  rest_positions_.resize(coordinates());
  for (int a = 0; a < n_n_; ++a) {
    for (int d = 0; d < dim_; ++d) rest_positions_(a * dim_ + d) = model.positions(d, a);
  }

  std::vector<int> bars_at(n_n_, 0);
  for (const DynamicBar& b : model.bars) {
    check_node(b.i, "a bar");
    check_node(b.j, "a bar");
    ++bars_at[b.i];
    ++bars_at[b.j];
  }
  for (int a = 0; a < n_n_; ++a) {
    if (bars_at[a] > 1) {
      throw ModelError("class-1 dynamics: node " + NodeName(a) + " carries " +
                       std::to_string(bars_at[a]) + " bars; this is a class-k structure");
    }
  }

  for (const DynamicBar& b : model.bars) {
    const bool fi = model.fixed[b.i], fj = model.fixed[b.j];
    if (fi && fj) continue;
    if (!(b.mass >= 0 && b.length > 0)) throw ModelError("class-1 dynamics: a bar needs mass >= 0 and length > 0");
    if (fi || fj) {
      const int pinned = fi ? b.i : b.j, free = fi ? b.j : b.i;
      const double mass = b.mass / 3.0 + node_mass(free);
      if (!(mass > 0)) throw ModelError("class-1 dynamics: bar at node " + NodeName(free) + " has no mass");
      pinned_bars_.push_back({pinned * dim_, free * dim_, mass, 1.0 / mass, b.length * b.length});
      continue;
    }
    PackedBar p{};
    p.oi = b.i * dim_;
    p.oj = b.j * dim_;
    p.m00 = b.mass / 3.0 + node_mass(b.i);
    p.m11 = b.mass / 3.0 + node_mass(b.j);
    p.m01 = b.mass / 6.0;
    const double det = p.m00 * p.m11 - p.m01 * p.m01;
    if (!(det > 0)) {
      throw ModelError("class-1 dynamics: bar " + NodeName(b.i) + "-" + NodeName(b.j) +
                       " has a singular mass matrix (no mass)");
    }
    p.a00 = p.m11 / det;
    p.a11 = p.m00 / det;
    p.a01 = -p.m01 / det;
    p.p = p.a01 - p.a00;
    p.q = p.a11 - p.a01;
    p.inv_w = 1.0 / (p.a00 + p.a11 - 2.0 * p.a01);
    p.rest_sq = b.length * b.length;
    bars_.push_back(p);
  }

  for (int a = 0; a < n_n_; ++a) {
    if (model.fixed[a]) {
      fixed_offsets_.push_back(a * dim_);
    } else if (bars_at[a] == 0) {
      const double m = node_mass(a);
      if (!(m > 0)) {
        throw ModelError("class-1 dynamics: free node " + NodeName(a) +
                         " has neither a bar nor a mass (use string_mass \"nodes\" or give it mass)");
      }
      lone_.push_back({a * dim_, m, 1.0 / m});
    }
  }
}

Eigen::VectorXd Class1System::RestState() const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(state_size());
  y.head(coordinates()) = rest_positions_;
  return y;
}

void Class1System::Derivative(double t, const double* y, double* dy, Class1Workspace& ws) const {
  Specialise(dim_, damped_, options_.stabilisation,
             [&]<int D, bool Damped, bool Stabilised>() { DerivativeImpl<D, Damped, Stabilised>(t, y, dy, ws); });
}

template <int D, bool Damped, bool Stabilised>
void Class1System::DerivativeImpl(double t, const double* y, double* dy, Class1Workspace& ws) const {
  // CAUTION: performance-sensitive. Plain loops over flat arrays; no allocation, no matrices.
  const int c = coordinates();
  const double* x = y;
  const double* v = y + c;
  double* f = ws.force.data();
  double* acc = dy + c;
  std::memcpy(dy, v, sizeof(double) * static_cast<size_t>(c));  // x' = v
  LoadsAt(t, f);

  // Strings (eqs 16-17).
  AccumulateStringForces<D, Damped>(strings_, x, v, f);

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
    if constexpr (Stabilised) numerator += bar.mass * (two_zeta_omega * bbd + half_omega_sq * (l2 - bar.rest_sq));
    const double lambda = -numerator / l2;
    for (int d = 0; d < D; ++d) acc[bar.oj + d] = (f[bar.oj + d] + lambda * b[d]) * bar.inv_mass;
  }

  for (const LoneNode& n : lone_) {
    for (int d = 0; d < D; ++d) acc[n.o + d] = f[n.o + d] * n.inv_mass;
  }
  for (const int o : fixed_offsets_) {
    for (int d = 0; d < D; ++d) {
      acc[o + d] = 0;
      dy[o + d] = 0;
    }
  }
}

double Class1System::KineticEnergy(const double* y) const {
  const int c = coordinates();
  const double* v = y + c;
  auto dot = [&](int a, int b) {
    double s = 0;
    for (int d = 0; d < dim_; ++d) s += v[a + d] * v[b + d];
    return s;
  };
  double e = 0;
  for (const PackedBar& b : bars_) {
    e += b.m00 * dot(b.oi, b.oi) + 2.0 * b.m01 * dot(b.oi, b.oj) + b.m11 * dot(b.oj, b.oj);
  }
  for (const PinnedBar& b : pinned_bars_) e += b.mass * dot(b.oj, b.oj);
  for (const LoneNode& n : lone_) e += n.mass * dot(n.o, n.o);
  return 0.5 * e;
}

}  // namespace tbridge
