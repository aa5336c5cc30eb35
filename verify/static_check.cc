#include "verify/static_check.h"

#include <algorithm>
#include <cmath>

#include "design/case_envelope.h"
#include "design/static_model.h"

namespace tbridge {

namespace {

// Up to `max` stations evenly spread over `count`, both ends included.
std::vector<int> SpreadStations(int count, int max) {
  std::vector<int> out;
  if (count <= max) {
    for (int k = 0; k < count; ++k) out.push_back(k);
    return out;
  }
  for (int k = 0; k < max; ++k) {
    const int s = static_cast<int>(std::lround(static_cast<double>(k) * (count - 1) / (max - 1)));
    if (out.empty() || out.back() != s) out.push_back(s);
  }
  return out;
}

}  // namespace

StaticCheck CheckStatics(const Design& d, int max_stations) {
  const Structure& s = d.topology.structure;
  const StaticModel model = StaticModelOf(d);
  const int nb = s.num_bars();
  const StaticState start = ReferenceState(model, d);
  const BarRule rule = BarRuleOf(d.config);
  const double E = d.config.material.youngs_modulus;
  const double sigma_w = d.config.material.yield_stress / d.config.design.yield_safety_factor;

  StaticCheck out;
  out.done = true;
  out.members.resize(d.bars.size() + d.strings.size());
  out.deflection_limit_m = d.config.bridge.span / d.config.loads.deflection_limit;
  const std::vector<int> stations = SpreadStations(static_cast<int>(d.actions.station_nodes.size()), max_stations);
  out.stations_per_family = static_cast<int>(stations.size());
  for (size_t c = 0; c < d.cases.size(); ++c) {
    const LoadCase& lc = d.cases[c];
    const std::vector<int> at = lc.station_load != 0 ? stations : std::vector<int>{-1};
    for (int station : at) {
      CaseResponse r;
      r.case_index = static_cast<int>(c);
      r.station = station;
      r.label = CaseLabel(d.cases, d.actions, MemberExtreme{0, static_cast<int>(c), station});
      const Eigen::Matrix3Xd loads = d.actions.Loads(lc, station);
      const StaticResult result = SolveStatic(model, start, d.loads, loads);
      r.converged = result.converged;
      r.message = result.message;
      r.slack_strings = result.slack_strings;
      r.reactions = result.state.reactions;
      const Eigen::Vector3d total = loads.rowwise().sum();
      r.balance = (r.reactions.rowwise().sum() + total).norm() / std::max(loads.cwiseAbs().sum(), 1e-300);
      for (int v : d.topology.deck_nodes) {
        const double dy = std::abs(result.state.nodes(1, v) - s.nodes(1, v));
        if (dy > r.deflection_m) r.deflection_m = dy, r.deflection_node = v;
      }
      out.all_converged = out.all_converged && r.converged;
      if (r.converged && lc.state == LimitState::kUltimate) {
        for (int b = 0; b < nb; ++b) {
          const MemberSizing& m = d.bars[b];
          const double force = result.state.bar_compression[b];
          const BarCapacity cap = BarResistance(m.area, m.length, rule, E);
          RaiseFinding(out.members[b], std::abs(force), cap.yield, r.label, "yield");
          if (force > 0) RaiseFinding(out.members[b], force, cap.buckling, r.label, "buckling");
        }
        for (size_t k = 0; k < d.strings.size(); ++k) {
          const MemberSizing& m = d.strings[k];
          if (m.area > 0) RaiseFinding(out.members[nb + k], result.state.string_tension[k], m.area * sigma_w, r.label, "yield");
        }
      }
      if (r.converged && lc.state == LimitState::kServiceability) {
        for (size_t k = 0; k < d.strings.size(); ++k) {
          const Member& e = s.strings[k];
          const double length = (result.state.nodes.col(e.j) - result.state.nodes.col(e.i)).norm();
          const MemberSizing& m = d.strings[k];
          if (length >= m.rest_length || !MustStayTaut(d, static_cast<int>(k))) continue;
          RaiseSlackFinding(out.members[nb + k], (length - m.rest_length) / m.rest_length, sigma_w, E, r.label);
        }
        if (r.deflection_m > out.deflection_max_m) {
          out.deflection_max_m = r.deflection_m;
          out.deflection_case = r.label;
        }
      }
      out.cases.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace tbridge
