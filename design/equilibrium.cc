#include "design/equilibrium.h"

#include <Eigen/QR>

namespace tbridge {

EquilibriumSystem BuildEquilibrium(const Structure& s) {
  EquilibriumSystem eq;
  const int dim = s.dim();
  eq.node_row.assign(s.num_nodes(), -1);
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (s.fixed[v]) continue;
    eq.node_row[v] = static_cast<int>(eq.row_node.size());
    for (int a = 0; a < dim; ++a) {
      eq.row_node.push_back(v);
      eq.row_axis.push_back(a);
    }
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(2 * dim * (s.num_bars() + s.num_strings()));
  // A member pulls node i toward j with its tension; a bar's compression pushes it away.
  auto add = [&](const Member& m, int column, double sign) {
    const Eigen::Vector3d u = (s.nodes.col(m.j) - s.nodes.col(m.i)).normalized();
    for (int a = 0; a < dim; ++a) {
      if (eq.node_row[m.i] >= 0) triplets.emplace_back(eq.node_row[m.i] + a, column, sign * u[a]);
      if (eq.node_row[m.j] >= 0) triplets.emplace_back(eq.node_row[m.j] + a, column, -sign * u[a]);
    }
  };
  for (int b = 0; b < s.num_bars(); ++b) add(s.bars[b], b, -1.0);
  for (int k = 0; k < s.num_strings(); ++k) add(s.strings[k], s.num_bars() + k, +1.0);
  eq.A.resize(static_cast<int>(eq.row_node.size()), s.num_bars() + s.num_strings());
  eq.A.setFromTriplets(triplets.begin(), triplets.end());
  eq.A.makeCompressed();
  return eq;
}

Eigen::VectorXd FreeLoads(const EquilibriumSystem& eq, const Eigen::Matrix3Xd& loads) {
  Eigen::VectorXd w(eq.row_node.size());
  for (size_t r = 0; r < eq.row_node.size(); ++r) w[r] = loads(eq.row_axis[r], eq.row_node[r]);
  return w;
}

Eigen::VectorXd EquilibriumResidual(const EquilibriumSystem& eq, const Eigen::VectorXd& forces,
                                    const Eigen::Matrix3Xd& loads) {
  return eq.A * forces + FreeLoads(eq, loads);
}

Eigen::Matrix3Xd SupportReactions(const Structure& s, const Eigen::VectorXd& forces,
                                  const Eigen::Matrix3Xd& loads) {
  Eigen::Matrix3Xd member_force = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  auto add = [&](const Member& m, double tension) {
    const Eigen::Vector3d u = (s.nodes.col(m.j) - s.nodes.col(m.i)).normalized();
    member_force.col(m.i) += tension * u;
    member_force.col(m.j) -= tension * u;
  };
  for (int b = 0; b < s.num_bars(); ++b) add(s.bars[b], -forces[b]);
  for (int k = 0; k < s.num_strings(); ++k) add(s.strings[k], forces[s.num_bars() + k]);
  Eigen::Matrix3Xd reactions = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (s.fixed[v]) reactions.col(v) = -(member_force.col(v) + loads.col(v));
  }
  return reactions;
}

int CountSelfStresses(const EquilibriumSystem& eq) {
  const Eigen::MatrixXd dense(eq.A);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(dense);
  qr.setThreshold(1e-10);
  return static_cast<int>(dense.cols() - qr.rank());
}

}  // namespace tbridge
