#include "dynamics/structure_model.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace tbridge {

namespace {

void RejectBridgeOnlyOptions(const ModelOptions& options) {
  if (!options.prestrain.empty()) {
    throw ConfigError(
        "dynamics.prestrain", std::string("\"") + NameOf(options.prestrain.front().group) + "\"",
        "not available with \"structure\" (its groups are a designed bridge's); give each string "
        "its rest_length_m or rest_ratio instead");
  }
  if (options.damping != 0) {
    throw ConfigError("dynamics.damping_c", std::to_string(options.damping),
                      "must be 0 with \"structure\": give each string its damping_n_s_m");
  }
}

// Every free node needs mass of its own or through a bar with mass, or its equations of
// motion have no inertia (the engines would stop with a singular mass matrix).
void RequireMassAtFreeNodes(const DynamicModel& m) {
  Eigen::VectorXd mass = m.node_mass;
  for (const DynamicBar& b : m.bars) {
    mass(b.i) += b.mass;
    mass(b.j) += b.mass;
  }
  for (int a = 0; a < m.num_nodes(); ++a) {
    if (m.fixed[a] || mass(a) > 0) continue;
    throw ConfigError(
        "structure.nodes[" + std::to_string(a) + "]", "(node " + std::to_string(a + 1) + ")",
        "a free node needs mass: it has no bar with mass_kg > 0 and no node mass; give it "
        "structure.node_masses, a string mass_kg shared by dynamics.string_mass \"nodes\" or "
        "\"bars\", or pin it");
  }
}

}  // namespace

DynamicModel BuildStructureModel(const StructureConfig& c, const ModelOptions& options) {
  if (c.Designable()) {
    throw ConfigError(
        "structure.members", "(a structure to design)",
        "a scene for simulate and modes gives bars and strings with their masses and "
        "stiffnesses; members in groups have neither until `tbridge design` sizes them");
  }
  RejectBridgeOnlyOptions(options);
  const int n_n = static_cast<int>(c.nodes.size());
  DynamicModel m;
  m.dim = c.dim;
  m.positions.resize(3, n_n);
  for (int a = 0; a < n_n; ++a) {
    for (int d = 0; d < 3; ++d) m.positions(d, a) = c.nodes[a][d];
  }
  m.fixed.assign(n_n, false);
  for (const int node : c.pinned) m.fixed[node - 1] = true;
  m.node_mass = Eigen::VectorXd::Zero(n_n);
  for (const StructureNodeMass& nm : c.node_masses) {
    if (!m.fixed[nm.node - 1]) m.node_mass(nm.node - 1) += nm.mass_kg;  // a support carries its own
  }
  m.loads = Eigen::Matrix3Xd::Zero(3, n_n);
  for (const StructureLoad& l : c.loads) {
    for (int d = 0; d < 3; ++d) m.loads(d, l.node - 1) += l.force_n[d];
  }
  m.allowed_stress = c.allowed_stress_pa.value_or(0.0);
  m.gravity = c.gravity_m_s2;
  for (const int node : c.deck_nodes) m.deck_nodes.push_back(node - 1);

  for (const StructureBarConfig& b : c.bars) {
    m.bars.push_back({b.nodes[0] - 1, b.nodes[1] - 1, b.mass_kg, c.Length(b.nodes)});
  }
  m.tensegrity_class = std::max(1, MaxBarsAtANode(m));
  for (size_t k = 0; k < c.strings.size(); ++k) {
    const StructureStringConfig& s = c.strings[k];
    DynamicString ds;
    ds.i = s.nodes[0] - 1;
    ds.j = s.nodes[1] - 1;
    ds.rest_length = c.RestLength(static_cast<int>(k));
    ds.stiffness = s.stiffness_n_m;
    ds.damping = s.damping_n_s_m;
    ds.mass = s.mass_kg;
    ds.area = s.area_m2.value_or(0.0);
    m.AddString(ds, std::to_string(s.nodes[0]) + "-" + std::to_string(s.nodes[1]),
                MemberGroup::kString);
  }
  ShareStringMass(m, options.string_mass);
  RequireMassAtFreeNodes(m);
  if (options.gravity_on_structure) AddStructureWeight(m);
  CheckModel(m, "structure");
  return m;
}

}  // namespace tbridge
