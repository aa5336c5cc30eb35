#include "design/as_built.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/json_reader.h"
#include "core/member_area.h"
#include "core/string_law.h"
#include "design/equilibrium.h"
#include "design/load_cases.h"
#include "statics/static_solve.h"

namespace tbridge {

namespace {

// The members' masses (rho A s, at the geometry of `s`) and, from them, the reference loads.
void WeighMembers(Design& d, std::vector<double>& masses) {
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars();
  const double bar_density = BarMaterial(d.config).density,
               string_density = StringMaterial(d.config).density;
  for (int k = 0; k < nb + s.num_strings(); ++k) {
    const bool bar = k < nb;
    MemberSizing& m = d.MemberAt(k);
    m.length = s.Length(s.MemberAt(k));
    m.mass = MassOfArea(bar ? bar_density : string_density, m.area, m.length);
    masses[k] = m.mass;
  }
  d.mass = MassesOf(d.bars, d.strings, d.mass.deck_beams);
  d.actions.base[kSelfWeight] = SelfWeightLoads(s, masses, d.config.design.gravity);
  d.loads = d.actions.Loads(d.reference);
}

}  // namespace

// `drawn` by value: the callers pass the design's own nodes, which the solve moves.
void SolveAsBuilt(Design& d, std::vector<std::string> edited, Eigen::Matrix3Xd drawn,
                  double bar_scale) {
  Structure& s = d.topology.structure;
  const int nb = s.num_bars(), ns = s.num_strings();
  std::vector<double> masses(static_cast<size_t>(nb + ns));
  StaticModel model;
  model.structure = s;
  model.structure.nodes *= bar_scale;
  for (const MemberSizing& m : d.strings) {
    model.string_stiffness.push_back(m.stiffness);
    model.string_rest_length.push_back(m.rest_length);
  }
  // The start: the file's geometry and bar forces, the strings' tensions there as read, in
  // equilibrium under the loads those forces balance.
  Eigen::VectorXd forces = d.reference_forces;
  for (int k = 0; k < ns; ++k) {
    forces[nb + k] =
        StringTension(d.strings[k].stiffness, d.strings[k].rest_length, d.strings[k].length);
  }
  const EquilibriumSystem eq = BuildEquilibrium(s);
  const Eigen::VectorXd residual = EquilibriumResidual(eq, forces, d.loads);
  Eigen::Matrix3Xd from_loads = d.loads;
  for (Eigen::Index r = 0; r < residual.size(); ++r)
    from_loads(eq.row_axis[r], eq.row_node[r]) -= residual[r];
  StaticState state = StateAt(model, s.nodes, forces.head(nb), from_loads);
  const Eigen::VectorXd file_forces = d.reference_forces;
  auto names = [&edited] {
    std::string out;
    for (size_t k = 0; k < edited.size() && k < 5; ++k) out += (k ? ", " : "") + edited[k];
    return out + (edited.size() > 5 ? ", ..." : "");
  };
  for (int pass = 0;; ++pass) {
    const StaticResult result = SolveStatic(model, state, from_loads, d.loads);
    if (!result.converged) {
      throw ConfigError(
          "members[].area", edited.empty() ? "(the members' weight)" : names(),
          "the structure as edited has no reference state under its permanent load (" +
              result.message + "): it does not stand as built");
    }
    state = result.state;
    from_loads = d.loads;
    s.nodes = model.structure.nodes = state.nodes;
    WeighMembers(d, masses);
    const double change = (d.loads - from_loads).cwiseAbs().maxCoeff();
    if (change <= 1e-12 * std::max(d.loads.cwiseAbs().maxCoeff(), 1.0)) break;
    if (pass == 4) {
      throw ConfigError("members[].area", names(),
                        "the strings' weight at the solved geometry did not settle in five solves");
    }
  }
  d.reference_forces.resize(nb + ns);
  d.reference_forces << state.bar_compression, state.string_tension;
  AsBuilt& a = d.as_built;
  a = AsBuilt{};
  a.re_derived = true;
  a.edited = std::move(edited);
  for (int v = 0; v < s.num_nodes(); ++v) {
    const double move = (s.nodes.col(v) - drawn.col(v)).norm();
    if (move > a.node_move_m) a.node_move_m = move, a.node = v;
  }
  for (int k = 0; k < nb + ns; ++k) {
    MemberSizing& m = d.MemberAt(k);
    const double change = std::abs(d.reference_forces[k] - file_forces[k]);
    if (change > a.force_change_n) a.force_change_n = change, a.force_member = m.name;
    m.reference_force = m.force = d.reference_forces[k];
    m.force_density = m.force / m.length;
    m.stress = m.area > 0 ? m.force / m.area : 0.0;
  }
  for (int k = 0; k < ns; ++k) a.slack_strings += state.string_tension[k] <= 0 ? 1 : 0;
}

Design WithRestLengths(const Design& design, const std::vector<double>& shortenings) {
  const size_t nb = design.bars.size(), ns = design.strings.size();
  if (shortenings.size() != ns) {
    throw ConfigError("shortenings", std::to_string(shortenings.size()) + " values",
                      "one per string: " + std::to_string(ns));
  }
  Design d = design;
  const double modulus = StringMaterial(d.config).youngs_modulus;
  std::vector<std::string> edited;
  for (size_t k = 0; k < ns; ++k) {
    if (shortenings[k] == 0) continue;
    MemberSizing& m = d.strings[k];
    const double rest = m.rest_length - shortenings[k];
    if (!(rest > 0) || !std::isfinite(rest)) {
      throw ConfigError("members[" + std::to_string(nb + k) + "].rest_length", NumberText(rest),
                        "a rest length > 0 [m]");
    }
    m.rest_length = rest;
    m.stiffness = AxialStiffness(modulus, m.area, rest);
    edited.push_back(m.name);
  }
  if (edited.empty()) return d;
  SolveAsBuilt(d, std::move(edited), d.topology.structure.nodes);
  AssessReferenceState(d);
  return d;
}

Design WithTemperature(const Design& design, double delta_k) {
  Design d = design;
  const MemberMaterial string_material = StringMaterial(d.config),
                       bar_material = BarMaterial(d.config);
  for (MemberSizing& m : d.strings) {
    m.rest_length *= 1.0 + string_material.thermal_expansion * delta_k;
    m.stiffness = AxialStiffness(string_material.youngs_modulus, m.area, m.rest_length);
  }
  try {
    SolveAsBuilt(d, {}, d.topology.structure.nodes, 1.0 + bar_material.thermal_expansion * delta_k);
  } catch (const ConfigError& e) {
    throw ConfigError("loads.temperature_delta_k", NumberText(delta_k) + " K",
                      std::string("the bridge so warmed has no reference state: ") + e.what());
  }
  AssessReferenceState(d);
  return d;
}

}  // namespace tbridge
