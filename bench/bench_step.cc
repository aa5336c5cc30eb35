// Cost of one class-1 RK4 step per member for the paper's planar bridges n = 1..12, with the
// scene's variants: plain, string damping on, stabilisation on; and the yardstick: a plain
// hand-written RK4 over the same members with the same physics as "stabilised" (the class-1
// right-hand side with string mass shared onto the bars, stabilisation on, no damping), in
// local arrays with no engine around it, timed in the same run.
//
//   build/bench/bench_step [max_n] [min_n]
//
// Each case is timed over enough steps to take ~0.2 s, after a warm-up; the state starts from
// the paper's design (configs/paper_n1.json at each n) with the central bar 1 mm down, so
// strings stay taut and nothing is skipped.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bridge/design_model.h"
#include "core/config.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "ns_per_call.h"

namespace {

using tbridge::Class1Options;
using tbridge::Class1System;

double NsPerMemberStep(const tbridge::DynamicModel& model, const Class1Options& options,
                       const Eigen::VectorXd& y0) {
  const Class1System system(model, options);
  tbridge::Class1Ode ode(system);
  tbridge::Rk4Workspace ws(system.state_size());
  Eigen::VectorXd y = y0;
  const double dt = 1e-8;  // tiny: the state barely changes, so every step costs the same
  return NsPerCall([&](long k) { tbridge::Rk4Step(ode, k * dt, dt, y, ws); }) /
         system.num_members();
}

// The yardstick's members: flat arrays of end coordinates and constants, planar.
struct PlainString {
  int i, j;
  double k, k_rest;
};
struct PlainBar {
  int i, j;
  double a00, a01, a11, p, q, inv_w, rest_sq;
};
struct PlainPinned {
  int j;  // the free end; the pinned end at pin
  double pin_x, pin_y, inv_mass, mass, rest_sq;
};

// dy = f(y) of the class-1 equations (dynamics/class1.h) for a planar bridge, stabilised.
void PlainDerivative(const std::vector<PlainString>& strings, const std::vector<PlainBar>& bars,
                     const std::vector<PlainPinned>& pinned, const std::vector<double>& loads,
                     const std::vector<int>& fixed, double omega, const double* y, double* dy,
                     double* f) {
  const int c = static_cast<int>(loads.size());
  const double* x = y;
  const double* v = y + c;
  for (int i = 0; i < c; ++i) {
    dy[i] = v[i];
    f[i] = loads[i];
  }
  for (const PlainString& s : strings) {
    const double dx = x[s.j] - x[s.i], dy_ = x[s.j + 1] - x[s.i + 1];
    const double g = std::max(s.k - s.k_rest / std::sqrt(dx * dx + dy_ * dy_), 0.0);
    f[s.i] += g * dx;
    f[s.i + 1] += g * dy_;
    f[s.j] -= g * dx;
    f[s.j + 1] -= g * dy_;
  }
  const double two_zeta_omega = 2.0 * omega, half_omega_sq = 0.5 * omega * omega;
  double* a = dy + c;
  for (const PlainBar& b : bars) {
    const double bx = x[b.j] - x[b.i], by = x[b.j + 1] - x[b.i + 1];
    const double vx = v[b.j] - v[b.i], vy = v[b.j + 1] - v[b.i + 1];
    const double l2 = bx * bx + by * by;
    const double num = vx * vx + vy * vy + bx * (b.p * f[b.i] + b.q * f[b.j]) +
                       by * (b.p * f[b.i + 1] + b.q * f[b.j + 1]) +
                       two_zeta_omega * (bx * vx + by * vy) + half_omega_sq * (l2 - b.rest_sq);
    const double lambda = -num * b.inv_w / l2;
    const double gix = f[b.i] - lambda * bx, giy = f[b.i + 1] - lambda * by;
    const double gjx = f[b.j] + lambda * bx, gjy = f[b.j + 1] + lambda * by;
    a[b.i] = b.a00 * gix + b.a01 * gjx;
    a[b.i + 1] = b.a00 * giy + b.a01 * gjy;
    a[b.j] = b.a01 * gix + b.a11 * gjx;
    a[b.j + 1] = b.a01 * giy + b.a11 * gjy;
  }
  for (const PlainPinned& b : pinned) {
    const double bx = x[b.j] - b.pin_x, by = x[b.j + 1] - b.pin_y;
    const double l2 = bx * bx + by * by;
    const double num =
        b.mass * (v[b.j] * v[b.j] + v[b.j + 1] * v[b.j + 1]) + bx * f[b.j] + by * f[b.j + 1] +
        b.mass *
            (two_zeta_omega * (bx * v[b.j] + by * v[b.j + 1]) + half_omega_sq * (l2 - b.rest_sq));
    const double lambda = -num / l2;
    a[b.j] = (f[b.j] + lambda * bx) * b.inv_mass;
    a[b.j + 1] = (f[b.j + 1] + lambda * by) * b.inv_mass;
  }
  for (const int o : fixed) {
    dy[o] = dy[o + 1] = a[o] = a[o + 1] = 0;
  }
}

// The yardstick: RK4 over PlainDerivative, ns per member per step.
double YardstickNsPerMemberStep(const tbridge::DynamicModel& m, const Eigen::VectorXd& y0) {
  std::vector<PlainString> strings;
  std::vector<PlainBar> bars;
  std::vector<PlainPinned> pinned;
  std::vector<int> fixed;
  for (const tbridge::DynamicString& s : m.strings) {
    if (m.fixed[s.i] && m.fixed[s.j]) continue;
    strings.push_back({2 * s.i, 2 * s.j, s.stiffness, s.stiffness * s.rest_length});
  }
  for (const tbridge::DynamicBar& b : m.bars) {
    if (m.fixed[b.i] && m.fixed[b.j]) continue;
    if (m.fixed[b.i] || m.fixed[b.j]) {
      const int pin = m.fixed[b.i] ? b.i : b.j, free = m.fixed[b.i] ? b.j : b.i;
      const double mass = b.mass / 3.0 + m.node_mass(free);
      pinned.push_back({2 * free, m.positions(0, pin), m.positions(1, pin), 1.0 / mass, mass,
                        b.length * b.length});
      continue;
    }
    const double m00 = b.mass / 3.0 + m.node_mass(b.i), m11 = b.mass / 3.0 + m.node_mass(b.j),
                 m01 = b.mass / 6.0;
    const double det = m00 * m11 - m01 * m01;
    const double a00 = m11 / det, a11 = m00 / det, a01 = -m01 / det;
    bars.push_back({2 * b.i, 2 * b.j, a00, a01, a11, a01 - a00, a11 - a01,
                    1.0 / (a00 + a11 - 2 * a01), b.length * b.length});
  }
  for (int a = 0; a < m.num_nodes(); ++a) {
    if (m.fixed[a]) fixed.push_back(2 * a);
  }
  const int c = 2 * m.num_nodes(), n = 2 * c;
  std::vector<double> loads(c);
  for (int a = 0; a < m.num_nodes(); ++a) {
    loads[2 * a] = m.loads(0, a);
    loads[2 * a + 1] = m.loads(1, a);
  }
  std::vector<double> y(y0.data(), y0.data() + n), k1(n), k2(n), k3(n), k4(n), stage(n), f(c);
  const double omega = tbridge::Class1Options{}.omega_rad_s;
  const double dt = 1e-8, half = 0.5 * dt;
  const long members = static_cast<long>(strings.size() + bars.size() + pinned.size());
  const double ns_per_step = NsPerCall([&](long) {
    PlainDerivative(strings, bars, pinned, loads, fixed, omega, y.data(), k1.data(), f.data());
    for (int i = 0; i < n; ++i) stage[i] = y[i] + half * k1[i];
    PlainDerivative(strings, bars, pinned, loads, fixed, omega, stage.data(), k2.data(), f.data());
    for (int i = 0; i < n; ++i) stage[i] = y[i] + half * k2[i];
    PlainDerivative(strings, bars, pinned, loads, fixed, omega, stage.data(), k3.data(), f.data());
    for (int i = 0; i < n; ++i) stage[i] = y[i] + dt * k3[i];
    PlainDerivative(strings, bars, pinned, loads, fixed, omega, stage.data(), k4.data(), f.data());
    for (int i = 0; i < n; ++i) y[i] += (dt / 6.0) * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
  });
  return ns_per_step / static_cast<double>(members);
}

}  // namespace

int main(int argc, char** argv) {
  const int max_n = argc > 1 ? std::atoi(argv[1]) : 12;
  const int min_n = argc > 2 ? std::atoi(argv[2]) : 1;
  std::printf("%3s %8s %8s %12s %12s %12s %12s %8s\n", "n", "members", "nodes", "plain", "damped",
              "stabilised", "yardstick", "ratio");
  std::printf("%3s %8s %8s %12s %12s %12s %12s %8s\n", "", "", "", "ns/mem/step", "ns/mem/step",
              "ns/mem/step", "ns/mem/step", "stab/yard");
  for (int n = min_n; n <= max_n; ++n) {
    // The paper's bridge with its switches (no self-weight, yield factor 10): its design loads
    // are the run's, so the model starts from the design's own state at every n.
    tbridge::Config config = tbridge::LoadConfig(TBRIDGE_SOURCE_DIR "/configs/paper_n1.json");
    config.bridge.n = n;
    const tbridge::Design design = tbridge::RunDesign(config);
    tbridge::DynamicsConfig scene;
    scene.perturbation = {1, 1e-3};
    const tbridge::DynamicModel plain = tbridge::BuildDynamicModel(design);
    tbridge::ModelOptions damping;
    damping.damping = 100;
    const tbridge::DynamicModel damped = tbridge::BuildDynamicModel(design, damping);
    const Eigen::VectorXd y0 = tbridge::InitialState(plain, scene);
    Class1Options stab;
    stab.stabilisation = true;
    const double a = NsPerMemberStep(plain, {}, y0);
    const double b = NsPerMemberStep(damped, {}, y0);
    const double c = NsPerMemberStep(plain, stab, y0);
    const double yard = YardstickNsPerMemberStep(plain, y0);
    std::printf("%3d %8zu %8d %12.1f %12.1f %12.1f %12.1f %8.2f\n", n,
                plain.bars.size() + plain.strings.size(), plain.num_nodes(), a, b, c, yard,
                c / yard);
    std::fflush(stdout);
  }
  return 0;
}
