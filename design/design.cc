#include "design/design.h"

#include <cmath>
#include <optional>
#include <numbers>
#include <sstream>

#include "core/error.h"
#include "design/equilibrium.h"
#include "design/equilibrium_basis.h"
#include "design/reduced_min_mass.h"
#include "design/solvers.h"

namespace tbridge {

namespace {

MemberKind StringKind(const Member& m) {
  return m.group == "deck" ? MemberKind::kDeckString : MemberKind::kString;
}

// The rank decision and the loads' reach: a sound basis leaves A N at rounding (entries of A
// are direction cosines, so ~1e-12 is far above rounding and far below any real stress state).
void CheckBasis(const EquilibriumBasis& basis) {
  if (basis.basis_residual > 1e-9) {
    throw ModelError("equilibrium factorisation: the self-stress basis misses equilibrium by " +
                     std::to_string(basis.basis_residual) + " (rank decision unreliable)");
  }
  // Rounding of A x_p grows with the largest member force it sums, not with the node load.
  const double force_scale = basis.particular.size() ? basis.particular.cwiseAbs().maxCoeff() : 0.0;
  if (basis.load_residual > 1e-9 * force_scale) {
    throw ModelError("no equilibrium: the loads excite a mechanism of the bridge (unbalanced force " +
                     std::to_string(basis.load_residual) + " N)");
  }
}

// design.solver: "auto" takes the direct solve wherever it applies, else Ipopt. An iterative
// solve takes the self-stress form while its Jacobian is no larger than the full problem's:
// with many self-stresses (the 3D bridge at n >= 5: 2042 of them at n = 8) the orthonormal
// basis fills every active row, and the full problem's sparse equilibrium rows are cheaper.
// Returns the member forces [C; T] in N; `form` says which problem was solved.
// `problem` is null when the self-stress basis was too large to form (the 3D bridge at n >= 10):
// then only the full problem is left.
Eigen::VectorXd SolveMinMass(const ReducedMinMassProblem* problem, int states, const Structure& s,
                             const Eigen::Matrix3Xd& loads, const MinMassSettings& settings, const DesignConfig& config,
                             SolverOutcome& outcome, std::string& form) {
  const bool applies = problem && problem->DirectApplies();
  const bool direct = config.solver == "direct" || (config.solver == "auto" && applies);
  form = "self-stress";
  Eigen::VectorXd x;
  if (direct) {
    if (!applies) {
      throw ConfigError("design.solver", "direct",
                        "\"direct\" needs at most one self-stress state loading no bar; this bridge has " +
                            std::to_string(states) + " states" +
                            (problem ? " with " + std::to_string(problem->num_active_bars()) + " bars in them" : "") +
                            ": use \"auto\", \"ipopt\" or \"nlopt\"");
    }
    outcome = problem->SolveDirect(x);
    return problem->MemberForces(x, 0);
  }
  // "auto" takes the first iterative solver built in (Ipopt before NLopt).
  std::string name = config.solver;
  if (name == "auto") {
    const std::vector<std::string> built = BuiltInIterativeSolvers();
    if (built.empty()) {
      throw ConfigError("design.solver", "\"auto\"",
                        "this bridge has " + std::to_string(states) +
                            " self-stress states and needs an iterative solver, but this build has neither "
                            "Ipopt nor NLopt (rebuild with -DTBRIDGE_WITH_IPOPT=ON or -DTBRIDGE_WITH_NLOPT=ON)");
    }
    name = built.front();
  }
  const SolverOptions options{config.tolerance, config.max_iterations, false};
  auto solve = [&](const NlpProblem& nlp) { return SolveNlp(name, nlp, options, x); };
  const MinMassProblem full(s, loads, settings);
  // NLopt's SLSQP holds the Jacobian dense (rows x variables): there the smaller dense size
  // decides, and Ipopt's sparse factorisation counts the non-zeros.
  auto dense = [](const NlpProblem& p) { return static_cast<double>(p.num_constraints()) * p.num_variables(); };
  const bool take_full = !problem || (config.solver == "nlopt" ? dense(*problem) > dense(full)
                                                              : problem->JacobianPattern().size() >
                                                                    full.JacobianPattern().size());
  if (take_full) {
    form = "full";
    x = full.StartingPoint();
    outcome = solve(full);
    return full.MemberForces(x);
  }
  x = problem->StartingPoint();
  outcome = solve(*problem);
  return problem->MemberForces(x, 0);
}

}  // namespace

void RequireStable(const Design& d) {
  const StabilityVerdict& v = d.stability;
  if (v.stable) return;
  std::ostringstream os;
  os << "the design is unstable: its tangent stiffness on the " << v.reduced_dofs
     << " motions that keep the bar lengths has " << v.negative_pivots << " negative and " << v.zero_pivots
     << " zero pivots (smallest " << v.min_pivot
     << " N/m), so the compressed bars can swing away from equilibrium under the design load; more string "
        "prestress holds them (design.deck_string_min_radius, design.transverse_string_min_radius)";
  throw ModelError(os.str());
}

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

DesignInputs PrepareDesign(const Config& config) {
  if (config.structure) {
    throw ConfigError("structure", "(custom scene)",
                      "designing needs a \"bridge\" section; a \"structure\" config runs with tbridge simulate "
                      "or tbridge modes");
  }
  Validate(config);                            // a config built in code gets the parse's checks
  RequireSolverBuiltIn(config.design.solver);  // before any work: the build decides what it accepts
  DesignInputs in;
  in.topology = MakeBridge(config.bridge);
  const Structure& s = in.topology.structure;
  in.deck = ComputeDeck(config.bridge, config.material, config.design);
  in.loads = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  for (int v : in.topology.deck_nodes) in.loads(1, v) = -in.deck.node_load;

  const double sigma_w = config.material.yield_stress / config.design.yield_safety_factor;
  auto circle = [](double r) { return std::numbers::pi * r * r; };
  MinMassSettings& settings = in.settings;
  settings.working_stress = sigma_w;
  settings.buckling_safety_factor = config.design.buckling_safety_factor;
  settings.material = config.material;
  settings.bar_min_area.assign(s.num_bars(), circle(config.design.bar_min_radius));
  settings.string_min_tension.resize(s.num_strings());
  in.string_min_area.assign(s.num_strings(), 0.0);
  for (int k = 0; k < s.num_strings(); ++k) {
    // Deck strings have a minimum radius and are prestressed at the working stress.
    if (StringKind(s.strings[k]) == MemberKind::kDeckString) {
      in.string_min_area[k] = circle(config.design.deck_string_min_radius);
    }
    // Transverse strings (3D bridge) likewise: unloaded by symmetric vertical loads, they
    // stiffen the coupling only through this prestress.
    if (s.strings[k].group == "transverse") in.string_min_area[k] = circle(config.design.transverse_string_min_radius);
    settings.string_min_tension[k] = sigma_w * in.string_min_area[k];
  }
  return in;
}

Design RunDesign(const Config& config, ProgressReporter* progress) {
  // Fractions of a whole design's time at n = 16: topology 0.2, factorisation 0.4, solve and
  // sizing the rest (the caller's output writing comes after).
  auto done = [progress](double fraction) {
    if (progress) progress->Update(fraction, 1.0);
  };
  if (progress) progress->Stage("design");
  DesignInputs in = PrepareDesign(config);
  done(0.2);
  Design d;
  d.config = config;
  d.topology = std::move(in.topology);
  d.deck = in.deck;
  d.loads = std::move(in.loads);
  const Structure& s = d.topology.structure;
  const MinMassSettings& settings = in.settings;
  const double sigma_w = settings.working_stress;
  const std::vector<double>& string_min_area = in.string_min_area;

  const EquilibriumSystem eq = BuildEquilibrium(s);
  const EquilibriumBasis basis = FactorEquilibrium(eq, FreeLoads(eq, d.loads));
  d.self_stress_states = basis.self_stress_states();
  CheckBasis(basis);
  done(0.6);
  std::optional<ReducedMinMassProblem> problem;
  if (basis.basis_formed) problem.emplace(s, basis, settings);
  const Eigen::VectorXd forces = SolveMinMass(problem ? &*problem : nullptr, basis.self_stress_states(), s, d.loads,
                                              settings, config.design, d.solver, d.solver_form);
  const Eigen::VectorXd residual = EquilibriumResidual(eq, forces, d.loads);
  d.equilibrium_residual = residual.size() ? residual.cwiseAbs().maxCoeff() : 0.0;
  const double load_scale = SelfStressForceScale(basis, settings);
  if (!d.solver.success || !std::isfinite(d.equilibrium_residual) ||
      d.equilibrium_residual > 1e-6 * load_scale || forces.minCoeff() < -1e-6 * load_scale) {
    std::ostringstream os;
    os << "no minimum-mass design found for n = " << config.bridge.n << ", p = " << config.bridge.p
       << ", beta = " << config.bridge.beta_deg << " deg: solver " << d.solver.solver
       << " returned status " << d.solver.status << " after " << d.solver.iterations
       << " iterations (equilibrium residual " << d.equilibrium_residual << " N)";
    throw ModelError(os.str());
  }
  done(0.8);

  for (int b = 0; b < s.num_bars(); ++b) {
    MemberSizing m = SizeBar(s.Length(s.bars[b]), forces[b], settings.bar_min_area[b], sigma_w,
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
  // Stability with the bars held: sparse and roughly linear, so it runs at every n; the dense
  // critical load factor only where it costs well under a second (n <= 6).
  std::vector<double> string_stiffness(d.strings.size());
  for (size_t k = 0; k < d.strings.size(); ++k) string_stiffness[k] = d.strings[k].stiffness;
  d.stability = AssessStability(s, forces, string_stiffness, config.bridge.n <= 6);
  d.reactions = SupportReactions(s, forces, d.loads);
  d.reactions.array() += 0.0;  // -0 (a fixed node's untouched axis) reads as 0 in the outputs
  d.mass.deck_beams = d.deck.beams_mass;
  d.mass.structure = d.mass.bars + d.mass.strings + d.mass.deck_strings;
  d.mass.total = d.mass.structure + d.mass.deck_beams;
  done(1.0);
  return d;
}

}  // namespace tbridge
