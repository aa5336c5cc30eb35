#include "design/case_envelope.h"

#include <algorithm>
#include <limits>

namespace tbridge {

StationInfluence InfluenceOfStations(const EquilibriumSolver& solver, const EquilibriumSystem& eq,
                                     const Actions& actions, int block) {
  const int stations = static_cast<int>(actions.station_nodes.size());
  const Eigen::Index members = eq.A.cols();
  StationInfluence out;
  out.max = Eigen::VectorXd::Constant(members, -std::numeric_limits<double>::infinity());
  out.min = Eigen::VectorXd::Constant(members, std::numeric_limits<double>::infinity());
  out.argmax.assign(members, -1);
  out.argmin.assign(members, -1);
  // At most 2^24 doubles (128 MB) of solutions at once, whatever the size.
  block = static_cast<int>(std::clamp<Eigen::Index>(
      (Eigen::Index{1} << 24) / std::max<Eigen::Index>(members, 1), 1, block));
  for (int first = 0; first < stations; first += block) {
    const int count = std::min(block, stations - first);
    Eigen::MatrixXd w(eq.A.rows(), count);
    for (int k = 0; k < count; ++k) w.col(k) = FreeLoads(eq, actions.StationLoad(first + k, 1.0));
    const Eigen::MatrixXd x = solver.Particular(w);
    const Eigen::MatrixXd residual = eq.A * x + w;
    if (residual.size())
      out.load_residual = std::max(out.load_residual, residual.cwiseAbs().maxCoeff());
    for (int k = 0; k < count; ++k) {
      for (Eigen::Index j = 0; j < members; ++j) {
        const double v = x(j, k);
        if (v > out.max[j]) out.max[j] = v, out.argmax[j] = first + k;
        if (v < out.min[j]) out.min[j] = v, out.argmin[j] = first + k;
      }
    }
  }
  if (stations == 0) out.max.setZero(), out.min.setZero();
  return out;
}

CaseEnvelope EnvelopeOf(const std::vector<LoadCase>& cases, const Eigen::MatrixXd& base,
                        const StationInfluence* influence) {
  const Eigen::Index members = base.rows();
  CaseEnvelope env;
  const double inf = std::numeric_limits<double>::infinity();
  env.uls_max.assign(members, MemberExtreme{-inf, -1, -1});
  env.min.assign(members, MemberExtreme{inf, -1, -1});
  for (size_t c = 0; c < cases.size(); ++c) {
    const LoadCase& lc = cases[c];
    const Eigen::VectorXd x = base * lc.Factors();
    const bool travels = lc.station_load != 0 && influence != nullptr;
    for (Eigen::Index j = 0; j < members; ++j) {
      // A travelling load s >= 0: its extremes are s times the extreme influences.
      MemberExtreme hi{x[j], static_cast<int>(c), -1}, lo = hi;
      if (travels) {
        hi.force += lc.station_load * influence->max[j];
        hi.station = influence->argmax[j];
        lo.force += lc.station_load * influence->min[j];
        lo.station = influence->argmin[j];
      }
      if (lc.state == LimitState::kUltimate && hi.force > env.uls_max[j].force) env.uls_max[j] = hi;
      if (lo.force < env.min[j].force) env.min[j] = lo;
    }
  }
  return env;
}

std::string CaseLabel(const std::vector<LoadCase>& cases, const Actions& actions,
                      const MemberExtreme& e) {
  if (e.case_index < 0) return "";
  std::string label = cases[e.case_index].name;
  if (e.station >= 0)
    label += " at node " + std::to_string(actions.station_nodes[e.station].front() + 1);
  return label;
}

}  // namespace tbridge
