// Cost of one class-1 RK4 step per member for the paper's planar bridges n = 1..12, with the
// scene's variants: plain, string damping on, stabilisation on; and the yardstick: a plain
// hand-written RK4 over the same members with the same physics as "stabilised" (the class-1
// right-hand side with string mass shared onto the bars, stabilisation on, no damping), in
// local arrays with no engine around it, and a second, the same over structure-of-arrays members
// (SoaDerivative), both timed in the same run.
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

// The second yardstick: the same physics as PlainDerivative over structure-of-arrays members
// (each constant of every member in its own array, unit stride), the node state interleaved as
// the plain one's. The strings run in three passes: their vectors gathered, their force
// densities computed over unit-stride arrays with no store to a shared node (a loop the
// compiler vectorises; the slack test a max, with no branch), and their pulls scattered. With
// the state split by coordinate ([x | y | vx | vy]) instead it measured 1.0-1.3x slower still
// here (a string's two gathers then touch two cache lines per node).
struct SoaMembers {
  std::vector<int> si, sj;  // strings' nodes
  std::vector<double> sk, skr, gx, gy;
  std::vector<int> bi, bj;  // free bars' nodes
  std::vector<double> a00, a01, a11, p, q, inv_w, rest_sq;
  std::vector<int> pj;  // pinned bars' free nodes
  std::vector<double> pin_x, pin_y, pinv, pmass, prest_sq;
  std::vector<double> load_x, load_y;
  std::vector<int> fixed;
};

SoaMembers Soa(const std::vector<PlainString>& strings, const std::vector<PlainBar>& bars,
               const std::vector<PlainPinned>& pinned, const std::vector<double>& loads,
               const std::vector<int>& fixed) {
  SoaMembers s;
  for (const PlainString& t : strings) {
    s.si.push_back(t.i / 2);
    s.sj.push_back(t.j / 2);
    s.sk.push_back(t.k);
    s.skr.push_back(t.k_rest);
  }
  s.gx.resize(strings.size());
  s.gy.resize(strings.size());
  for (const PlainBar& b : bars) {
    s.bi.push_back(b.i / 2);
    s.bj.push_back(b.j / 2);
    s.a00.push_back(b.a00);
    s.a01.push_back(b.a01);
    s.a11.push_back(b.a11);
    s.p.push_back(b.p);
    s.q.push_back(b.q);
    s.inv_w.push_back(b.inv_w);
    s.rest_sq.push_back(b.rest_sq);
  }
  for (const PlainPinned& b : pinned) {
    s.pj.push_back(b.j / 2);
    s.pin_x.push_back(b.pin_x);
    s.pin_y.push_back(b.pin_y);
    s.pinv.push_back(b.inv_mass);
    s.pmass.push_back(b.mass);
    s.prest_sq.push_back(b.rest_sq);
  }
  for (size_t a = 0; 2 * a < loads.size(); ++a) {
    s.load_x.push_back(loads[2 * a]);
    s.load_y.push_back(loads[2 * a + 1]);
  }
  for (const int o : fixed) s.fixed.push_back(o / 2);
  return s;
}

void SoaDerivative(SoaMembers& m, double omega, const double* state, double* rate, double* f) {
  const int nn = static_cast<int>(m.load_x.size()), ns = static_cast<int>(m.si.size());
  const int c = 2 * nn;
  const double *x = state, *v = state + c;
  double* a = rate + c;
  std::copy(v, v + c, rate);
  for (int k = 0; k < nn; ++k) {
    f[2 * k] = m.load_x[k];
    f[2 * k + 1] = m.load_y[k];
  }
  const int *si = m.si.data(), *sj = m.sj.data();
  const double *sk = m.sk.data(), *skr = m.skr.data();
  double *gx = m.gx.data(), *gy = m.gy.data();
  for (int s = 0; s < ns; ++s) {
    const int i = 2 * si[s], j = 2 * sj[s];
    gx[s] = x[j] - x[i];
    gy[s] = x[j + 1] - x[i + 1];
  }
  for (int s = 0; s < ns; ++s) {
    const double g = std::max(sk[s] - skr[s] / std::sqrt(gx[s] * gx[s] + gy[s] * gy[s]), 0.0);
    gx[s] *= g;
    gy[s] *= g;
  }
  for (int s = 0; s < ns; ++s) {
    const int i = 2 * si[s], j = 2 * sj[s];
    f[i] += gx[s];
    f[i + 1] += gy[s];
    f[j] -= gx[s];
    f[j + 1] -= gy[s];
  }
  const double two_zeta_omega = 2.0 * omega, half_omega_sq = 0.5 * omega * omega;
  const int nb = static_cast<int>(m.bi.size());
  for (int b = 0; b < nb; ++b) {
    const int i = 2 * m.bi[b], j = 2 * m.bj[b];
    const double bx = x[j] - x[i], by = x[j + 1] - x[i + 1];
    const double ux = v[j] - v[i], uy = v[j + 1] - v[i + 1];
    const double l2 = bx * bx + by * by;
    const double num = ux * ux + uy * uy + bx * (m.p[b] * f[i] + m.q[b] * f[j]) +
                       by * (m.p[b] * f[i + 1] + m.q[b] * f[j + 1]) +
                       two_zeta_omega * (bx * ux + by * uy) + half_omega_sq * (l2 - m.rest_sq[b]);
    const double lambda = -num * m.inv_w[b] / l2;
    const double gix = f[i] - lambda * bx, giy = f[i + 1] - lambda * by;
    const double gjx = f[j] + lambda * bx, gjy = f[j + 1] + lambda * by;
    a[i] = m.a00[b] * gix + m.a01[b] * gjx;
    a[i + 1] = m.a00[b] * giy + m.a01[b] * gjy;
    a[j] = m.a01[b] * gix + m.a11[b] * gjx;
    a[j + 1] = m.a01[b] * giy + m.a11[b] * gjy;
  }
  const int np = static_cast<int>(m.pj.size());
  for (int b = 0; b < np; ++b) {
    const int j = 2 * m.pj[b];
    const double bx = x[j] - m.pin_x[b], by = x[j + 1] - m.pin_y[b];
    const double l2 = bx * bx + by * by;
    const double num =
        m.pmass[b] * (v[j] * v[j] + v[j + 1] * v[j + 1]) + bx * f[j] + by * f[j + 1] +
        m.pmass[b] *
            (two_zeta_omega * (bx * v[j] + by * v[j + 1]) + half_omega_sq * (l2 - m.prest_sq[b]));
    const double lambda = -num / l2;
    a[j] = (f[j] + lambda * bx) * m.pinv[b];
    a[j + 1] = (f[j + 1] + lambda * by) * m.pinv[b];
  }
  for (const int o : m.fixed) rate[2 * o] = rate[2 * o + 1] = a[2 * o] = a[2 * o + 1] = 0;
}

// RK4 over SoaDerivative, ns per member per step.
double SoaYardstickNsPerMemberStep(SoaMembers m, double omega, const Eigen::VectorXd& y0) {
  const int nn = static_cast<int>(m.load_x.size()), n = 4 * nn;
  std::vector<double> y(y0.data(), y0.data() + n), k1(n), k2(n), k3(n), k4(n), stage(n), f(2 * nn);
  const double dt = 1e-8, half = 0.5 * dt;
  const long members = static_cast<long>(m.si.size() + m.bi.size() + m.pj.size());
  const double ns_per_step = NsPerCall([&](long) {
    SoaDerivative(m, omega, y.data(), k1.data(), f.data());
    for (int i = 0; i < n; ++i) stage[i] = y[i] + half * k1[i];
    SoaDerivative(m, omega, stage.data(), k2.data(), f.data());
    for (int i = 0; i < n; ++i) stage[i] = y[i] + half * k2[i];
    SoaDerivative(m, omega, stage.data(), k3.data(), f.data());
    for (int i = 0; i < n; ++i) stage[i] = y[i] + dt * k3[i];
    SoaDerivative(m, omega, stage.data(), k4.data(), f.data());
    for (int i = 0; i < n; ++i) y[i] += (dt / 6.0) * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
  });
  return ns_per_step / static_cast<double>(members);
}

// The two yardsticks compute the same right-hand side: checked at y0 before either is timed,
// to 1e-12 of the largest rate (the sums differ only in order).
void SameDerivativeOrExit(const std::vector<PlainString>& strings,
                          const std::vector<PlainBar>& bars, const std::vector<PlainPinned>& pinned,
                          const std::vector<double>& loads, const std::vector<int>& fixed,
                          SoaMembers& soa, double omega, const Eigen::VectorXd& y0) {
  const size_t n = static_cast<size_t>(y0.size());
  std::vector<double> plain(n), split(n), f(n / 2);
  PlainDerivative(strings, bars, pinned, loads, fixed, omega, y0.data(), plain.data(), f.data());
  SoaDerivative(soa, omega, y0.data(), split.data(), f.data());
  double largest = 0, difference = 0;
  for (size_t i = 0; i < n; ++i) {
    largest = std::max(largest, std::abs(plain[i]));
    difference = std::max(difference, std::abs(plain[i] - split[i]));
  }
  if (difference > 1e-12 * largest) {
    std::fprintf(stderr, "bench_step: the yardsticks differ by %g of %g\n", difference, largest);
    std::exit(1);
  }
}

struct Yardsticks {
  double plain, soa;  // ns per member per step
};

// The yardsticks: RK4 over PlainDerivative and over SoaDerivative, ns per member per step.
Yardsticks YardstickNsPerMemberStep(const tbridge::DynamicModel& m, const Eigen::VectorXd& y0) {
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
  SoaMembers soa = Soa(strings, bars, pinned, loads, fixed);
  SameDerivativeOrExit(strings, bars, pinned, loads, fixed, soa, omega, y0);
  return {ns_per_step / static_cast<double>(members), SoaYardstickNsPerMemberStep(soa, omega, y0)};
}

}  // namespace

int main(int argc, char** argv) {
  const int max_n = argc > 1 ? std::atoi(argv[1]) : 12;
  const int min_n = argc > 2 ? std::atoi(argv[2]) : 1;
  std::printf("%3s %8s %8s %12s %12s %12s %12s %12s %8s %8s\n", "n", "members", "nodes", "plain",
              "damped", "stabilised", "yardstick", "soa", "ratio", "ratio");
  std::printf("%3s %8s %8s %12s %12s %12s %12s %12s %8s %8s\n", "", "", "", "ns/mem/step",
              "ns/mem/step", "ns/mem/step", "ns/mem/step", "ns/mem/step", "stab/yard", "stab/soa");
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
    const Yardsticks yard = YardstickNsPerMemberStep(plain, y0);
    std::printf("%3d %8zu %8d %12.1f %12.1f %12.1f %12.1f %12.1f %8.2f %8.2f\n", n,
                plain.bars.size() + plain.strings.size(), plain.num_nodes(), a, b, c, yard.plain,
                yard.soa, c / yard.plain, c / yard.soa);
    std::fflush(stdout);
  }
  return 0;
}
