// The nonlinear static solve against the linear stiffness of the bar-constrained structure,
// assembled here independently: a small extra load must move the nodes as the linear
// (saddle-point) system predicts.

#include "statics/static_solve.h"

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <vector>

#include "checks/static_check.h"
#include "core/config.h"
#include "design/static_model.h"
#include "test_support.h"

namespace tbridge {
namespace {

// Linear response of the structure at `nodes` with bar compressions `P` to the out-of-balance
// force `rhs` (3 x n_n): unknowns the free coordinates dx and the bar force changes dP.
// Equilibrium of each free node: strings' tangent stiffness k u u^T + (T/s)(I - u u^T), bars'
// geometric term (P/l)(I - u u^T) with their force P u on the far end (compression pushes the
// ends apart) and dP u; each bar keeps its length, u . (dx_j - dx_i) = 0.
Eigen::Matrix3Xd LinearResponse(const StaticModel& m, const Eigen::Matrix3Xd& nodes,
                                const Eigen::VectorXd& P, const Eigen::Matrix3Xd& rhs) {
  const Structure& s = m.structure;
  const int dim = s.dim(), nb = s.num_bars();
  std::vector<int> first(s.num_nodes(), -1);
  int n = 0;
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (!s.fixed[v]) first[v] = n, n += dim;
  }
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + nb, n + nb);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n + nb);
  // Stiffness block `B` of a member between i and j: +B on the diagonal blocks, -B off them.
  auto add_pair = [&](int i, int j, const Eigen::Matrix3d& B) {
    const int ends[2] = {i, j};
    for (int p = 0; p < 2; ++p) {
      for (int q = 0; q < 2; ++q) {
        if (first[ends[p]] < 0 || first[ends[q]] < 0) continue;
        K.block(first[ends[p]], first[ends[q]], dim, dim) +=
            (p == q ? 1.0 : -1.0) * B.topLeftCorner(dim, dim);
      }
    }
  };
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (int k = 0; k < s.num_strings(); ++k) {
    const Member& e = s.strings[k];
    const Eigen::Vector3d d = nodes.col(e.j) - nodes.col(e.i);
    const double len = d.norm(), t = m.string_stiffness[k] * (len - m.string_rest_length[k]);
    REQUIRE(t > 0);  // every string taut: no slack switch within a small load
    const Eigen::Vector3d u = d / len;
    add_pair(e.i, e.j,
             m.string_stiffness[k] * u * u.transpose() + t / len * (I - u * u.transpose()));
  }
  const double k_ref = K.diagonal().cwiseAbs().maxCoeff();
  for (int a = 0; a < nb; ++a) {
    const Member& e = s.bars[a];
    const Eigen::Vector3d d = nodes.col(e.j) - nodes.col(e.i);
    const double l = d.norm();
    const Eigen::Vector3d u = d / l;
    add_pair(e.i, e.j, -P[a] / l * (I - u * u.transpose()));  // compression softens
    // Force change -dP u on i and +dP u on j moves to the left side with a minus sign. The
    // unknown is dP / k_ref and the constraint row is scaled by k_ref, so that the matrix has
    // one scale (unscaled, its constraint part is 1e-8 of the stiffness, below the rank
    // threshold of a pivoting LU).
    const Eigen::VectorXd w = k_ref * u.head(dim);
    if (first[e.j] >= 0)
      K.block(first[e.j], n + a, dim, 1) -= w, K.block(n + a, first[e.j], 1, dim) += w.transpose();
    if (first[e.i] >= 0)
      K.block(first[e.i], n + a, dim, 1) += w, K.block(n + a, first[e.i], 1, dim) -= w.transpose();
  }
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (first[v] >= 0) b.segment(first[v], dim) = rhs.col(v).head(dim);
  }
  const Eigen::VectorXd x = K.fullPivLu().solve(b);
  REQUIRE((K * x - b).norm() <= 1e-9 * b.norm());  // the saddle-point system is regular
  Eigen::Matrix3Xd dx = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (first[v] >= 0) dx.col(v).head(dim) = x.segment(first[v], dim);
  }
  return dx;
}

// Net force of loads and members on every node (the out-of-balance of a state).
Eigen::Matrix3Xd NetForce(const StaticModel& m, const Eigen::Matrix3Xd& nodes,
                          const Eigen::VectorXd& P, const Eigen::Matrix3Xd& loads) {
  const Structure& s = m.structure;
  Eigen::Matrix3Xd net = loads;
  for (int k = 0; k < s.num_strings(); ++k) {
    const Member& e = s.strings[k];
    const Eigen::Vector3d d = nodes.col(e.j) - nodes.col(e.i);
    const double t = m.string_stiffness[k] * (d.norm() - m.string_rest_length[k]);
    net.col(e.i) += t * d.normalized();
    net.col(e.j) -= t * d.normalized();
  }
  for (int a = 0; a < s.num_bars(); ++a) {
    const Member& e = s.bars[a];
    const Eigen::Vector3d u = (nodes.col(e.j) - nodes.col(e.i)).normalized();
    net.col(e.i) -= P[a] * u;
    net.col(e.j) += P[a] * u;
  }
  return net;
}

// SolveStatic under 1e-6 of a deck node's load along `direction` at the first deck node (off
// the symmetry axis) against the linear prediction.
void CheckSmallLoad(const Design& d, const Eigen::Vector3d& direction) {
  const StaticModel model = StaticModelOf(d);
  const Structure& s = model.structure;
  const Eigen::VectorXd P = d.reference_forces.head(s.num_bars());
  const StaticState start = StateAt(model, s.nodes, P, d.loads);
  Eigen::Matrix3Xd extra = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  extra.col(d.topology.deck_nodes[0]) = 1e-6 * d.deck.node_load * direction;
  const StaticResult r = SolveStatic(model, start, d.loads, d.loads + extra);
  REQUIRE(r.converged);
  // The linear prediction from the start state, its own small imbalance included.
  const Eigen::Matrix3Xd dx_lin =
      LinearResponse(model, s.nodes, P, NetForce(model, s.nodes, P, d.loads) + extra);
  const Eigen::Matrix3Xd dx = r.state.nodes - s.nodes;
  INFO("|dx| " << dx.norm() << " m, |dx - dx_lin| " << (dx - dx_lin).norm() << " m");
  CHECK(dx.norm() > 0);
  // At 1e-6 of the deck load the second-order terms (the change of the geometric stiffness
  // and of the string directions with the motion) are at most about 1e-6 of the first-order
  // ones; rounding of the 6 m coordinates (1e-15 m) is 1e-7 of motions of 1e-8 m. Measured
  // 1.5e-8 (n = 2), 9.7e-8 (n = 3) and 1.3e-7 (3D, n = 2); leaving out the bars' geometric
  // term gives 6.5e-4 on the planar bridges.
  CHECK((dx - dx_lin).norm() <= 1e-6 * dx_lin.norm());
}

TEST_CASE("a small load deflects the planar bridge as its linear stiffness predicts") {
  for (int n : {2, 3}) {
    INFO("n = " << n);
    CheckSmallLoad(test::PaperDesign(n), Eigen::Vector3d(0, -1, 0));
  }
}

TEST_CASE("a small load deflects the 3D bridge as its linear stiffness predicts", "[ipopt]") {
  REQUIRE(
      test::HaveSolvers({SolverKind::kIpopt}));  // the 3D bridge's design needs it (tagged [ipopt])
  const Design d = RunDesign(LoadConfig(TBRIDGE_SOURCE_DIR "/configs/paper_3d.json"));
  // Down and sideways: the transverse strings and the out-of-plane motion take part.
  CheckSmallLoad(d, Eigen::Vector3d(0, -1, 0.5));
}

TEST_CASE("the static tangent is the first-order change of the nonlinear solve") {
  const Design d = test::PaperDesign(3);
  const StaticModel model = StaticModelOf(d);
  const Structure& s = model.structure;
  const StaticState start = ReferenceState(model, d);
  StaticTangent tangent(model, start);
  REQUIRE(tangent.ok());
  // A deck node's load, off the symmetry axis, down and along the deck.
  Eigen::Matrix3Xd extra = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  extra.col(d.topology.deck_nodes[0]) = d.deck.node_load * Eigen::Vector3d(0.3, -1, 0);
  Eigen::Matrix3Xd du;
  Eigen::VectorXd dx;
  tangent.Solve(extra, du, dx);
  REQUIRE(du.norm() > 0);

  // Displacements: the saddle-point system assembled independently above, dense and by full
  // pivoting. 1e-8: two factorisations of a system whose bar rows are scaled to the
  // stiffness (condition about 1e6 here), against motions of 1e-3 m.
  const Eigen::Matrix3Xd du_dense = LinearResponse(model, s.nodes, start.bar_compression, extra);
  CHECK((du - du_dense).norm() <= 1e-8 * du.norm());

  // Member forces: central differences of the nonlinear solve at +-h of the load. Their
  // error is h^2 times the third derivative: at h = 1e-3 the bridge's nonlinearity (the
  // force changes move by about 0.4 of themselves over the whole load, so h^2 of that, 1e-7)
  // and the solves' tolerance (1e-10 of the largest force over 2h, 5e-8 of it) both stay
  // below 1e-6 of the change. Measured 3.8e-9.
  const double h = 1e-3;
  const StaticResult up = SolveStatic(model, start, d.loads, d.loads + h * extra);
  const StaticResult down = SolveStatic(model, start, d.loads, d.loads - h * extra);
  REQUIRE(up.converged);
  REQUIRE(down.converged);
  Eigen::VectorXd fd(dx.size());
  fd << up.state.bar_compression - down.state.bar_compression,
      up.state.string_tension - down.state.string_tension;
  fd /= 2 * h;
  INFO("|dx| " << dx.norm() << " N, |fd - dx| " << (fd - dx).norm() << " N");
  CHECK((fd - dx).norm() <= 1e-6 * dx.norm());

  // And the solve that takes the tangent's factorisation for its steps from the start is the
  // solve that factorises the same matrix itself, to rounding: its later Newton steps
  // factorise afresh where the plain solve refactorises with its first pivots (KLU), so the two
  // take the same steps up to rounding. 1e-12 relative: measured 3e-15 (forces) and 1e-15 m
  // (nodes, over a span of 12 m), a few roundings; a different step would show as the Newton
  // tolerance, 1e-10.
  const StaticResult plain = SolveStatic(model, start, d.loads, d.loads + extra);
  const StaticResult reused = SolveStatic(model, start, d.loads, d.loads + extra, &tangent);
  REQUIRE(plain.converged);
  CHECK(reused.newton_iterations == plain.newton_iterations);
  CHECK((reused.state.nodes - plain.state.nodes).cwiseAbs().maxCoeff() <=
        1e-12 * d.config.bridge.span);
  CHECK((reused.state.bar_compression - plain.state.bar_compression).cwiseAbs().maxCoeff() <=
        1e-12 * plain.state.bar_compression.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace tbridge
