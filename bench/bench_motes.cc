// The two MOTES example scenes, built as dynamic models directly, run with MOTES's published
// method (RK4, dt = 1e-3 s, 5000 steps): time per step and total error against a converged
// reference (RK4 at dt = 1e-5 s).
//
//   build/bench/bench_motes
//
// Class-1 prism: bottom triangle on the unit circle at z = 0, top triangle at z = 1 turned by
// 150 deg; bars b_k-t_k; strings: bottom b_k-b_k+1, top t_k-t_k+1, vertical b_k-t_k+1, each
// split into 3 segments (24 nodes, 27 segments). Bar mass 1 kg; each segment k = 100 N/m,
// c = 10 N s/m, mass 0.05 kg lumped half at each end; rest length 0.95 x its length; no load.
// D-bar (class 2): nodes 1 (1,0), 2 (0,1), 3 (-1,0), 4 (0,-1); bars 4-1, 1-2, 2-3, 3-4 (1 kg
// each: MOTES gives no mass); strings 2-4 (L0 = 1 m) and 1-3 (L0 = 0.5 m), k = 100 N/m, c = 0;
// node 1 pinned. Runs on the class-k engine.
// Error: max over 0.01-s samples and nodes of |x - x_ref| [m].

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "dynamics/class1.h"
#include "dynamics/classk.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"

namespace {

using namespace tbridge;

void AddString(DynamicModel& m, int i, int j, double k, double c, double mass, double ratio) {
  DynamicString s;
  s.i = i;
  s.j = j;
  s.rest_length = ratio * (m.positions.col(i) - m.positions.col(j)).norm();
  s.stiffness = k;
  s.damping = c;
  s.mass = mass;
  s.name = std::to_string(i + 1) + "-" + std::to_string(j + 1);
  m.strings.push_back(s);
  m.node_mass(i) += 0.5 * mass;
  m.node_mass(j) += 0.5 * mass;
}

DynamicModel Prism() {
  DynamicModel m;
  m.dim = 3;
  m.positions.resize(3, 24);
  const double alpha = 150.0 * std::numbers::pi / 180.0;
  for (int k = 0; k < 3; ++k) {
    const double th = 2.0 * std::numbers::pi * k / 3.0;
    m.positions.col(k) = Eigen::Vector3d(std::cos(th), std::sin(th), 0.0);
    m.positions.col(3 + k) = Eigen::Vector3d(std::cos(th + alpha), std::sin(th + alpha), 1.0);
  }
  m.node_mass = Eigen::VectorXd::Zero(24);
  m.loads = Eigen::Matrix3Xd::Zero(3, 24);
  for (int k = 0; k < 3; ++k) m.bars.push_back({k, 3 + k, 1.0, (m.positions.col(k) - m.positions.col(3 + k)).norm()});
  int next = 6;
  auto split = [&](int a, int b) {  // 3 segments through 2 new nodes
    const int p = next++, q = next++;
    m.positions.col(p) = m.positions.col(a) + (m.positions.col(b) - m.positions.col(a)) / 3.0;
    m.positions.col(q) = m.positions.col(a) + 2.0 * (m.positions.col(b) - m.positions.col(a)) / 3.0;
    for (auto [i, j] : {std::pair{a, p}, std::pair{p, q}, std::pair{q, b}}) AddString(m, i, j, 100, 10, 0.05, 0.95);
  };
  for (int k = 0; k < 3; ++k) {
    split(k, (k + 1) % 3);
    split(3 + k, 3 + (k + 1) % 3);
    split(k, 3 + (k + 1) % 3);
  }
  m.fixed.assign(24, false);
  return m;
}

DynamicModel DBar() {
  DynamicModel m;
  m.dim = 2;
  m.positions = Eigen::Matrix3Xd::Zero(3, 4);
  m.positions.col(0) << 1, 0, 0;
  m.positions.col(1) << 0, 1, 0;
  m.positions.col(2) << -1, 0, 0;
  m.positions.col(3) << 0, -1, 0;
  m.node_mass = Eigen::VectorXd::Zero(4);
  m.loads = Eigen::Matrix3Xd::Zero(3, 4);
  for (auto [i, j] : {std::pair{3, 0}, std::pair{0, 1}, std::pair{1, 2}, std::pair{2, 3}}) {
    m.bars.push_back({i, j, 1.0, (m.positions.col(i) - m.positions.col(j)).norm()});
  }
  for (auto [i, j, l0] : {std::tuple{1, 3, 1.0}, std::tuple{0, 2, 0.5}}) {
    DynamicString s;
    s.i = i;
    s.j = j;
    s.rest_length = l0;
    s.stiffness = 100;
    s.name = std::to_string(i + 1) + "-" + std::to_string(j + 1);
    m.strings.push_back(s);
  }
  m.fixed = {true, false, false, false};
  m.tensegrity_class = 2;
  return m;
}

// RK4 from y0 for `steps` of dt; positions sampled every `every` steps into the returned rows.
Eigen::MatrixXd Run(OdeSystem& ode, Eigen::VectorXd y, double dt, long steps, long every, double* seconds) {
  Rk4Workspace ws(ode.size());
  const int c = ode.size() / 2;
  Eigen::MatrixXd out(steps / every + 1, c);
  out.row(0) = y.head(c).transpose();
  const auto start = std::chrono::steady_clock::now();
  for (long k = 1; k <= steps; ++k) {
    Rk4Step(ode, (k - 1) * dt, dt, y, ws);
    if (k % every == 0) out.row(k / every) = y.head(c).transpose();
  }
  *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

template <class System, class Ode>
void Scene(const char* name, const DynamicModel& m) {
  const System system(m);
  Ode ode(system);
  const Eigen::VectorXd y0 = system.RestState();
  double ref_s = 0, s = 0, best = 1e300;
  const Eigen::MatrixXd ref = Run(ode, y0, 1e-5, 500000, 1000, &ref_s);
  Eigen::MatrixXd run;
  for (int r = 0; r < 5; ++r) {  // best of five
    run = Run(ode, y0, 1e-3, 5000, 10, &s);
    best = std::min(best, s);
  }
  const double err = (run - ref).cwiseAbs().maxCoeff();
  const double moved = (ref.rowwise() - ref.row(0)).cwiseAbs().maxCoeff();
  std::printf("%-8s nodes %2d bars %d strings %2d | RK4 dt 1e-3 x 5000: %.3g us/step, %.3g ms total | "
              "max position error %.2e m (motion %.3g m) | reference dt 1e-5: %.2f s\n",
              name, m.num_nodes(), static_cast<int>(m.bars.size()), static_cast<int>(m.strings.size()), 1e6 * best / 5000,
              1e3 * best, err, moved, ref_s);
}

}  // namespace

int main() {
  Scene<Class1System, Class1Ode>("prism", Prism());
  Scene<ClassKSystem, ClassKOde>("d-bar", DBar());
  return 0;
}
