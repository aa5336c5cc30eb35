#include <cmath>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/member_area.h"
#include "design/design.h"
#include "design/equilibrium.h"
#include "design/equilibrium_basis.h"

namespace tbridge {

Design SizedDesign(const Config& config, const std::vector<double>& areas,
                   const Eigen::VectorXd& alpha) {
  DesignInputs in = PrepareDesign(config);
  Design d;
  d.config = config;
  d.topology = std::move(in.topology);
  d.deck = in.deck;
  d.actions = std::move(in.actions);
  d.cases = MakeLoadCases(config, d.deck, d.notes);
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars(), ns = s.num_strings();
  if (static_cast<int>(areas.size()) != nb + ns)
    throw ModelError("SizedDesign: one area per member expected");

  const MemberMaterial bar_material = BarMaterial(config), string_material = StringMaterial(config);
  std::vector<double> masses(nb + ns);
  for (int j = 0; j < nb + ns; ++j) {
    masses[j] = MassOfArea((j < nb ? bar_material : string_material).density, areas[j],
                           s.Length(s.MemberAt(j)));
  }
  if (config.design.self_weight)
    d.actions.base[kSelfWeight] = SelfWeightLoads(s, masses, config.design.gravity);
  d.reference = ReferenceCase(config, d.cases);
  d.loads = d.actions.Loads(d.reference);

  const EquilibriumSystem eq = BuildEquilibrium(s);
  const EquilibriumSolver solver(eq);
  d.self_stress_states = solver.states();
  d.reference_forces = solver.Particular(FreeLoads(eq, d.loads)).col(0);
  if (alpha.size()) d.reference_forces += solver.SelfStresses() * alpha;
  d.alpha = alpha;

  const BarRule rule = BarRuleOf(config);
  for (int j = 0; j < nb + ns; ++j) {
    const bool bar = j < nb;
    const Member& e = s.MemberAt(j);
    const double force = d.reference_forces[j];
    // The sizers at zero force with the area as the floor give that area and what follows
    // from it (radius, mass, rest length from the reference force, stiffness).
    MemberSizing m = bar ? SizeBar(s.Length(e), 0.0, areas[j], rule, bar_material)
                         : SizeString(s.Length(e), 0.0, force, areas[j], string_material);
    m.kind = bar ? MemberKind::kBar : StringKind(e);
    m.i = e.i;
    m.j = e.j;
    m.name = Structure::Name(e);
    m.reference_force = force;
    m.force = force;
    m.force_density = force / m.length;
    m.stress = m.area > 0 ? force / m.area : 0.0;
    (bar ? d.bars : d.strings).push_back(m);
  }
  const Eigen::VectorXd residual = EquilibriumResidual(eq, d.reference_forces, d.loads);
  d.equilibrium_residual = residual.size() ? residual.cwiseAbs().maxCoeff() : 0.0;
  AssessReferenceState(d);
  d.mass = MassesOf(d.bars, d.strings, d.deck.beams_mass);
  return d;
}

Design WithPrestressLoss(const Design& design, double loss) {
  Design d = design;
  d.reference_forces -= loss * PrestressForces(design);
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars();
  const MemberMaterial string_material = StringMaterial(d.config);
  for (int j = 0; j < static_cast<int>(d.reference_forces.size()); ++j) {
    const double force = d.reference_forces[j];
    MemberSizing& m = d.MemberAt(j);
    if (j >= nb) {
      // The sizer at zero demand with the area as its floor: that area, and the rest length that
      // carries `force` at the string's length.
      const MemberSizing at = SizeString(m.length, 0.0, force, m.area, string_material);
      m.rest_length = at.rest_length;
      m.stiffness = at.stiffness;
    }
    m.reference_force = force;
  }
  if (d.alpha.size()) d.alpha *= 1.0 - loss;
  AssessReferenceState(d);  // the prestress leans on the supports: their reactions change
  return d;
}

void AssessReferenceState(Design& d) {
  const Structure& s = d.topology.structure;
  std::vector<double> string_stiffness(static_cast<size_t>(s.num_strings()));
  for (int k = 0; k < s.num_strings(); ++k)
    string_stiffness[static_cast<size_t>(k)] = d.strings[k].stiffness;
  d.stability = AssessStability(s, d.reference_forces, string_stiffness, d.config.bridge.n <= 6);
  d.reactions = SupportReactions(s, d.reference_forces, d.loads);
  d.reactions.array() += 0.0;  // -0 reads as 0 in the outputs
}

}  // namespace tbridge
