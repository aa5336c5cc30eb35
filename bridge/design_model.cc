#include "bridge/design_model.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/member_area.h"
#include "design/abutments.h"
#include "design/static_model.h"
#include "dynamics/simulation.h"

namespace tbridge {

DynamicModel BuildDynamicModel(const Design& design, const ModelOptions& options) {
  const Structure& st = design.topology.structure;
  const MemberMaterial strings = StringMaterial(design.config);
  if (!(options.damping >= 0) || !std::isfinite(options.damping)) {
    throw ConfigError("dynamics.damping_c", std::to_string(options.damping), "must be >= 0");
  }
  for (const StringPrestrain& p : options.prestrain) {
    bool found = false;
    for (const Member& m : st.strings) found = found || m.group == p.group;
    if (!found) {
      throw ConfigError("dynamics.prestrain.group", std::string("\"") + NameOf(p.group) + "\"",
                        "this bridge has no string of that group");
    }
    if (!(p.ratio > 0 && p.ratio <= 1.5)) {
      throw ConfigError("dynamics.prestrain.ratio", std::to_string(p.ratio), "must be in (0, 1.5]");
    }
  }

  DynamicModel m;
  m.dim = st.dim();
  m.positions = st.nodes;
  m.fixed = st.fixed;
  m.loads = design.loads;
  m.node_mass = Eigen::VectorXd::Zero(st.num_nodes());
  m.allowed_stress = strings.DesignStress();
  m.youngs_modulus = strings.youngs_modulus;
  m.tensegrity_class = st.TensegrityClass();
  m.deck_nodes = design.topology.deck_nodes;
  m.gravity = design.config.design.gravity;
  for (const Abutment& a : AbutmentsOf(st, design.config.bridge.span))
    m.reaction_groups.push_back(a.nodes);

  for (const MemberSizing& b : design.bars) m.bars.push_back({b.i, b.j, b.mass, b.length});

  for (size_t k = 0; k < design.strings.size(); ++k) {
    const MemberSizing& s = design.strings[k];
    DynamicString ds;
    ds.i = s.i;
    ds.j = s.j;
    ds.rest_length = s.rest_length;
    ds.stiffness = s.stiffness;
    ds.damping = options.damping;
    ds.mass = MassOfArea(strings.density, s.area, s.rest_length);
    ds.area = s.area;
    const MemberGroup group = st.strings[k].group;
    for (const StringPrestrain& p : options.prestrain) {
      if (p.group != group) continue;
      ds.rest_length = p.ratio * s.length;
      ds.stiffness = AxialStiffness(strings.youngs_modulus, s.area, ds.rest_length);
    }
    m.AddString(ds, s.name, group);
  }
  ShareStringMass(m, options.string_mass);
  // A run carries the design loads: the permanent load and the payload (the paper's design
  // load). An engineering design's reference state is the permanent load alone, so the
  // payload is added, and the run starts from the equilibrium under it.
  const double payload = options.payload_share - PayloadShare(design.reference);
  if (payload != 0 && design.actions.base[kPayloadFull].size() == m.loads.size()) {
    m.loads += payload * design.actions.base[kPayloadFull];
  }
  // Each weight once. The design's loads carry the deck's, the superimposed dead load's and
  // the payload's weight, and the members' own when the design counts it (design.self_weight):
  // then the run keeps that weight, lumped as the design lumps it, so that a run with nothing
  // added starts in the design's own equilibrium. Otherwise the members' weight is added here,
  // before the deck's masses join the node masses (their weight is in the loads already).
  if (options.gravity_on_structure && design.reference.factor[kSelfWeight] == 0)
    AddStructureWeight(m);
  if (options.deck_inertia) AddDeckInertia(m, design, options.payload_share);
  SettleAtEquilibrium(m, design);
  CheckModel(m, "design model");
  return m;
}

ModelOptions ModalModelOptions(const Config& config) {
  ModelOptions options = config.dynamics ? ModelOptionsOf(*config.dynamics) : ModelOptions{};
  if (!config.dynamics && !config.structure) options.deck_inertia = !KeepsPaperSwitches(config);
  return options;
}

void AddDeckInertia(DynamicModel& m, const Design& d, double payload_factor) {
  const BridgeConfig& b = d.config.bridge;
  const double g = d.config.design.gravity;
  const double planes = b.planes;
  // Per deck node: one beam of each plane's share, and the load per metre over one section.
  double per_node = d.deck.section_mass / planes;
  if (g > 0) {
    per_node += d.config.loads.superimposed_dead_n_per_m * d.deck.section_length / g / planes;
    per_node += payload_factor * b.payload / b.span * d.deck.section_length / g / planes;
  }
  for (int v : d.topology.deck_nodes) m.node_mass(v) += per_node;
}

void SettleAtEquilibrium(DynamicModel& m, const Design& d) {
  if ((m.loads - d.loads).cwiseAbs().maxCoeff() == 0.0) return;
  const StaticModel statics = StaticModelOf(d);
  const StaticState start = ReferenceState(statics, d);
  const StaticResult r = SolveStatic(statics, start, d.loads, m.loads);
  if (!r.converged) throw ModelError("the run's initial static equilibrium: " + r.message);
  m.positions = r.state.nodes;
}

std::vector<PrestrainReport> ReportPrestrain(const DynamicModel& model, const Design& design,
                                             const ModelOptions& options) {
  std::vector<PrestrainReport> out;
  for (const StringPrestrain& p : options.prestrain) {
    PrestrainReport r;
    r.group = p.group;
    r.ratio = p.ratio;
    r.allowed_stress = model.allowed_stress;
    r.yield_stress = StringMaterial(design.config).yield_stress;
    for (size_t k = 0; k < model.strings.size(); ++k) {
      const DynamicString& s = model.strings[k];
      if (model.names.string_group[k] != p.group) continue;
      ++r.strings;
      const double length = (model.positions.col(s.j) - model.positions.col(s.i)).norm();
      const double stress = model.youngs_modulus * (length - s.rest_length) / s.rest_length;
      r.max_stress = std::max(r.max_stress, stress);
    }
    r.exceeds_allowed = r.max_stress > r.allowed_stress;
    out.push_back(r);
  }
  return out;
}

}  // namespace tbridge
