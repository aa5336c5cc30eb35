#include "design/design.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.h"
#include "design/equilibrium.h"

namespace tbridge {

namespace {

MemberKind StringKind(const Member& m) {
  return m.group == "deck" ? MemberKind::kDeckString : MemberKind::kString;
}

}  // namespace

Eigen::VectorXd MemberForces(const Design& d) {
  Eigen::VectorXd x(d.bars.size() + d.strings.size());
  for (size_t b = 0; b < d.bars.size(); ++b) x[b] = d.bars[b].force;
  for (size_t k = 0; k < d.strings.size(); ++k) x[d.bars.size() + k] = d.strings[k].force;
  return x;
}

const MemberSizing* FindMember(const Design& d, const std::string& name) {
  const auto dash = name.find('-');
  if (dash == std::string::npos) return nullptr;
  const std::string flipped = name.substr(dash + 1) + "-" + name.substr(0, dash);
  for (const auto* list : {&d.bars, &d.strings}) {
    for (const MemberSizing& m : *list) {
      if (m.name == name || m.name == flipped) return &m;
    }
  }
  return nullptr;
}

Design RunDesign(const Config& config) {
  if (config.structure) {
    throw ConfigError("structure", "(custom scene)",
                      "designing needs a \"bridge\" section; a \"structure\" config runs with tbridge simulate "
                      "or tbridge modes");
  }
  Design d;
  d.config = config;
  d.topology = MakeBridge(config.bridge);
  const Structure& s = d.topology.structure;
  d.deck = ComputeDeck(config.bridge, config.material, config.design);

  d.loads = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  for (int v : d.topology.deck_nodes) d.loads(1, v) = -d.deck.node_load;

  const double sigma_w = config.material.yield_stress / config.design.yield_safety_factor;
  const double deck_min_area =
      std::numbers::pi * config.design.deck_string_min_radius * config.design.deck_string_min_radius;
  const double transverse_min_area = std::numbers::pi *
                                     config.design.transverse_string_min_radius *
                                     config.design.transverse_string_min_radius;
  const double bar_min_area =
      std::numbers::pi * config.design.bar_min_radius * config.design.bar_min_radius;

  MinMassSettings settings;
  settings.working_stress = sigma_w;
  settings.buckling_safety_factor = config.design.buckling_safety_factor;
  settings.material = config.material;
  settings.bar_min_area.assign(s.num_bars(), bar_min_area);
  settings.string_min_tension.resize(s.num_strings());
  std::vector<double> string_min_area(s.num_strings(), 0.0);
  for (int k = 0; k < s.num_strings(); ++k) {
    // Deck strings have a minimum radius and are prestressed at the working stress.
    if (StringKind(s.strings[k]) == MemberKind::kDeckString) string_min_area[k] = deck_min_area;
    // Transverse strings (3D bridge) likewise: unloaded by symmetric vertical loads, they
    // stiffen the coupling only through this prestress.
    if (s.strings[k].group == "transverse") string_min_area[k] = transverse_min_area;
    settings.string_min_tension[k] = sigma_w * string_min_area[k];
  }

  MinMassProblem problem(s, d.loads, settings);
  Eigen::VectorXd x = problem.StartingPoint();
  SolverOptions options{config.design.tolerance, config.design.max_iterations, false};
  d.solver = config.design.solver == "nlopt" ? SolveWithNlopt(problem, options, x)
                                             : SolveWithIpopt(problem, options, x);
  const Eigen::VectorXd forces = problem.MemberForces(x);
  const Eigen::VectorXd residual = EquilibriumResidual(problem.equilibrium(), forces, d.loads);
  d.equilibrium_residual = residual.size() ? residual.cwiseAbs().maxCoeff() : 0.0;
  const double load_scale = problem.ForceScale();
  if (!d.solver.success || !std::isfinite(d.equilibrium_residual) ||
      d.equilibrium_residual > 1e-6 * load_scale || forces.minCoeff() < -1e-6 * load_scale) {
    std::ostringstream os;
    os << "no minimum-mass design found for n = " << config.bridge.n << ", p = " << config.bridge.p
       << ", beta = " << config.bridge.beta_deg << " deg: solver " << d.solver.solver
       << " returned status " << d.solver.status << " after " << d.solver.iterations
       << " iterations (equilibrium residual " << d.equilibrium_residual << " N)";
    throw ModelError(os.str());
  }

  for (int b = 0; b < s.num_bars(); ++b) {
    MemberSizing m = SizeBar(s.Length(s.bars[b]), forces[b], bar_min_area, sigma_w,
                             config.design.buckling_safety_factor, config.material);
    m.kind = MemberKind::kBar;
    m.i = s.bars[b].i;
    m.j = s.bars[b].j;
    m.name = Structure::Name(s.bars[b]);
    d.mass.bars += m.mass;
    d.bars.push_back(m);
  }
  for (int k = 0; k < s.num_strings(); ++k) {
    MemberSizing m = SizeString(s.Length(s.strings[k]), forces[s.num_bars() + k],
                                string_min_area[k], sigma_w, config.material);
    m.kind = StringKind(s.strings[k]);
    m.i = s.strings[k].i;
    m.j = s.strings[k].j;
    m.name = Structure::Name(s.strings[k]);
    (m.kind == MemberKind::kDeckString ? d.mass.deck_strings : d.mass.strings) += m.mass;
    d.strings.push_back(m);
  }
  d.mass.deck_beams = d.deck.beams_mass;
  d.mass.structure = d.mass.bars + d.mass.strings + d.mass.deck_strings;
  d.mass.total = d.mass.structure + d.mass.deck_beams;
  if (s.num_bars() + s.num_strings() <= 400) {
    d.self_stress_states = CountSelfStresses(problem.equilibrium());
  }
  return d;
}

}  // namespace tbridge
