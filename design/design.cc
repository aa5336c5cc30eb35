#include "design/design.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "design/case_envelope.h"
#include "design/deck_beams.h"
#include "design/equilibrium.h"
#include "design/equilibrium_basis.h"
#include "design/reduced_min_mass.h"
#include "optim/solvers.h"

namespace tbridge {

MemberKind StringKind(const Member& m) {
  return m.group == MemberGroup::kDeck ? MemberKind::kDeckString : MemberKind::kString;
}

MassBreakdown MassesOf(const std::vector<MemberSizing>& bars,
                       const std::vector<MemberSizing>& strings, double deck_beams) {
  MassBreakdown mass;
  for (const MemberSizing& b : bars) mass.bars += b.mass;
  for (const MemberSizing& s : strings)
    (s.kind == MemberKind::kDeckString ? mass.deck_strings : mass.strings) += s.mass;
  mass.deck_beams = deck_beams;
  mass.structure = mass.bars + mass.strings + mass.deck_strings;
  mass.total = mass.structure + mass.deck_beams;
  return mass;
}

namespace {

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
    throw ModelError(
        "no equilibrium: the loads excite a mechanism of the bridge (unbalanced force " +
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
struct MinMassSolution {
  Eigen::MatrixXd forces;  // members x columns of the problem [N]: [C; T]
  Eigen::VectorXd alpha;   // self-stress coefficients [N]; empty when the full problem was solved
};

MinMassSolution SolveMinMass(const ReducedMinMassProblem* problem, int states, const Structure& s,
                             const Eigen::Matrix3Xd* single_loads, const MinMassSettings& settings,
                             const DesignConfig& config, SolverOutcome& outcome,
                             std::string& form) {
  const bool applies = problem && problem->DirectApplies();
  const bool direct =
      config.solver == SolverKind::kDirect || (config.solver == SolverKind::kAuto && applies);
  form = "self-stress";
  Eigen::VectorXd x;
  MinMassSolution out;
  auto reduced_forces = [&]() {
    out.forces.resize(s.num_bars() + s.num_strings(), problem->num_cases());
    for (int c = 0; c < problem->num_cases(); ++c) out.forces.col(c) = problem->MemberForces(x, c);
    out.alpha = x.head(problem->num_self_stresses()) * problem->ForceScale();
    return out;
  };
  if (direct) {
    if (!applies) {
      throw ConfigError(
          "design.solver", "direct",
          "\"direct\" needs at most one self-stress state loading no bar; this bridge has " +
              std::to_string(states) + " states" +
              (problem ? " with " + std::to_string(problem->num_active_bars()) + " bars in them"
                       : "") +
              ": use \"auto\", \"ipopt\" or \"nlopt\"");
    }
    outcome = problem->SolveDirect(x);
    return reduced_forces();
  }
  // "auto" takes the first iterative solver built in (Ipopt before NLopt).
  SolverKind solver = config.solver;
  if (solver == SolverKind::kAuto) {
    const std::vector<SolverKind> built = BuiltInIterativeSolvers();
    if (built.empty()) {
      throw ConfigError(
          "design.solver", "\"auto\"",
          "this bridge has " + std::to_string(states) +
              " self-stress states and needs an iterative solver, but this build has neither "
              "Ipopt nor NLopt (rebuild with -DTBRIDGE_WITH_IPOPT=ON or -DTBRIDGE_WITH_NLOPT=ON)");
    }
    solver = built.front();
  }
  SolverOptions options;
  options.tolerance = config.tolerance;
  options.max_iterations = config.max_iterations;
  auto solve = [&](const NlpProblem& nlp) { return SolveNlp(solver, nlp, options, x); };
  // The full problem holds one load case; several cases need the self-stress form.
  if (single_loads == nullptr && problem == nullptr) {
    throw ModelError(
        "this bridge has " + std::to_string(states) +
        " self-stress states, too many for the several load cases of loads.cases to share one "
        "self-stress form; design it for one case (loads.cases [\"paper\"]) or at a lower n");
  }
  if (single_loads) {
    const MinMassProblem full(s, *single_loads, settings);
    // NLopt's SLSQP holds the Jacobian dense (rows x variables): there the smaller dense size
    // decides, and Ipopt's sparse factorisation counts the non-zeros.
    auto dense = [](const NlpProblem& p) {
      return static_cast<double>(p.num_constraints()) * p.num_variables();
    };
    const bool take_full =
        !problem || (config.solver == SolverKind::kNlopt
                         ? dense(*problem) > dense(full)
                         : problem->JacobianPattern().size() > full.JacobianPattern().size());
    if (take_full) {
      form = "full";
      x = full.StartingPoint();
      outcome = solve(full);
      out.forces = full.MemberForces(x);
      return out;
    }
  }
  x = problem->StartingPoint();
  outcome = solve(*problem);
  return reduced_forces();
}

}  // namespace

Eigen::VectorXd PrestressForces(const Design& d) {
  const EquilibriumSystem eq = BuildEquilibrium(d.topology.structure);
  const EquilibriumSolver solver(eq);
  return d.reference_forces - solver.Particular(FreeLoads(eq, d.loads)).col(0);
}

LoadCase ReferenceCase(const Config& config, const std::vector<LoadCase>& cases) {
  return KeepsPaperSwitches(config) ? cases.at(0) : PermanentCase(config);
}

bool MustStayTaut(const Design& d, int k) {
  return d.strings[k].kind == MemberKind::kDeckString ||
         d.topology.structure.strings[k].group == MemberGroup::kTransverse;
}

void RequireStable(const Design& d) {
  const StabilityVerdict& v = d.stability;
  if (v.stable) return;
  std::ostringstream os;
  os << "the design is unstable: its tangent stiffness on the " << v.reduced_dofs
     << " motions that keep the bar lengths has " << v.negative_pivots << " negative and "
     << v.zero_pivots << " zero pivots (smallest " << v.min_pivot
     << " N/m), so the compressed bars can swing away from equilibrium under the design load; more "
        "string "
        "prestress holds them (design.deck_string_min_radius, design.transverse_string_min_radius)";
  throw ModelError(os.str());
}

std::vector<double> MemberAreas(const Design& d) {
  std::vector<double> areas;
  for (const auto* list : {&d.bars, &d.strings}) {
    for (const MemberSizing& m : *list) areas.push_back(m.area);
  }
  return areas;
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
    throw ConfigError(
        "structure", "(custom scene)",
        "designing needs a \"bridge\" section; a \"structure\" config runs with tbridge simulate "
        "or tbridge modes");
  }
  Validate(config);                            // a config built in code gets the parse's checks
  RequireSolverBuiltIn(config.design.solver);  // before any work: the build decides what it accepts
  DesignInputs in;
  in.topology = MakeBridge(config.bridge);
  const Structure& s = in.topology.structure;
  in.deck = SizeDeckBeams(config, ComputeDeck(config.bridge, config.material, config.design));
  in.actions = MakeActions(config, in.topology, in.deck);
  in.loads = in.actions.base[kPaperLoad];

  auto circle = [](double r) { return std::numbers::pi * r * r; };
  MinMassSettings& settings = in.settings;
  settings.strings = StringMaterial(config);
  settings.bars = BarMaterial(config);
  const double sigma_w = settings.strings.DesignStress();
  settings.buckling_safety_factor = config.design.buckling_safety_factor;
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
    if (s.strings[k].group == MemberGroup::kTransverse)
      in.string_min_area[k] = circle(config.design.transverse_string_min_radius);
    settings.string_min_tension[k] = sigma_w * in.string_min_area[k];
  }
  return in;
}

BarRule BarRuleOf(const Config& c) {
  BarRule r;
  r.column_curve = c.design.bar_resistance == BarResistanceRule::kColumnCurve;
  const MemberMaterial bars = BarMaterial(c);
  r.yield_stress = bars.yield_stress;
  r.yield_factor = bars.partial_factor;
  r.buckling_factor = c.design.buckling_safety_factor;
  r.imperfection = c.design.imperfection_factor;
  return r;
}

namespace {

// Utilisation of a sized member under its largest and smallest force, and the mode that
// governs it: strings yield (or go slack below zero), bars yield or buckle.
void Utilise(MemberSizing& m, double largest, double smallest, const BarRule& rule, double sigma_w,
             double E) {
  if (m.kind == MemberKind::kBar) {
    const BarCapacity cap = BarResistance(m.area, m.length, rule, E);
    const double u_yield = cap.yield > 0 ? largest / cap.yield : 0.0;
    const double u_buckling = cap.buckling > 0 ? largest / cap.buckling : 0.0;
    if (u_buckling > u_yield) {
      Govern(m, largest, cap.buckling, LimitMode::kBuckling);
    } else {
      Govern(m, largest, cap.yield, LimitMode::kYield);
    }
    // A bar pulled in some case (the paper's designs; the minimum-mass program keeps bars in
    // compression): at least 1, the tension over the largest compression above it.
    if (smallest < 0) {
      const double scale = std::max(largest, 1.0), tension = 1.0 + (-smallest) / scale;
      if (tension > m.utilisation) {
        Govern(m, scale - smallest, scale, LimitMode::kTension);
      } else {
        m.mode = LimitMode::kTension;
      }
    }
  } else {
    Govern(m, largest, m.area * sigma_w, smallest < 0 ? LimitMode::kSlack : LimitMode::kYield);
  }
}

// Drops the travelling families where their station solves would cost too much, and the design
// says so; returns whether a travelling load is left to check.
bool KeepAffordableTravellingLoads(Design& d, int members) {
  bool travels = false;
  for (const LoadCase& c : d.cases) travels = travels || c.station_load != 0;
  // A travelling family costs one equilibrium solve per deck station, each linear in the
  // members: 0.6 s at n = 10, 9.5 s at n = 12, 310 s at n = 14. Beyond 2^23 station-members
  // (n = 10 on a planar bridge) the families are left out, and the design says so.
  const double station_members = static_cast<double>(d.actions.station_nodes.size()) * members;
  if (travels && station_members > 8388608.0) {
    std::erase_if(d.cases, [](const LoadCase& c) { return c.station_load != 0; });
    d.notes.push_back(
        "loads.cases: the travelling loads are not checked: " +
        std::to_string(d.actions.station_nodes.size()) + " deck stations x " +
        std::to_string(members) +
        " members exceed the 2^23 station-members a design solves for them (n <= 10 on a planar "
        "bridge)");
    d.unchecked_cases = true;
    travels = false;
    if (d.cases.empty())
      throw ModelError(
          "loads.cases: only travelling loads were asked for, and they are too costly to check at "
          "this n");
  }
  return travels;
}

// The self-stress basis, formed where it is small enough (2^20 entries).
EquilibriumBasis BasisOf(const EquilibriumSolver& solver, const EquilibriumSystem& eq,
                         int members) {
  EquilibriumBasis basis;
  basis.rank = solver.rank();
  basis.states = solver.states();
  basis.basis_formed = static_cast<double>(members) * basis.states <= 1048576.0;
  basis.self_stress = basis.basis_formed ? solver.SelfStresses() : Eigen::MatrixXd(members, 0);
  if (basis.self_stress.size())
    basis.basis_residual = (eq.A * basis.self_stress).cwiseAbs().maxCoeff();
  return basis;
}

// Sizes every member for its largest force, rest lengths from the reference state; `mass`
// takes each member's mass. Returns the members' total mass.
template <typename Floor>
double SizeMembers(Design& d, const DesignInputs& in, const BarRule& rule, const Floor& floor,
                   const Eigen::VectorXd& largest, const Eigen::VectorXd& reference_forces,
                   std::vector<double>& mass) {
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars();
  const MinMassSettings& settings = in.settings;
  d.bars.clear();
  d.strings.clear();
  double total = 0;
  for (int b = 0; b < nb; ++b) {
    MemberSizing m =
        SizeBar(s.Length(s.bars[b]), largest[b], settings.bar_min_area[b], rule, settings.bars);
    if (floor(b) > 0 && m.area == floor(b)) m.governed_by = LimitMode::kResized;
    m.kind = MemberKind::kBar;
    m.i = s.bars[b].i;
    m.j = s.bars[b].j;
    m.name = Structure::Name(s.bars[b]);
    m.reference_force = reference_forces[b];
    mass[b] = m.mass;
    total += m.mass;
    d.bars.push_back(m);
  }
  for (int k = 0; k < s.num_strings(); ++k) {
    MemberSizing m = SizeString(s.Length(s.strings[k]), largest[nb + k], reference_forces[nb + k],
                                std::max(in.string_min_area[k], floor(nb + k)), settings.strings);
    if (floor(nb + k) > in.string_min_area[k] && m.area == floor(nb + k))
      m.governed_by = LimitMode::kResized;
    m.kind = StringKind(s.strings[k]);
    m.i = s.strings[k].i;
    m.j = s.strings[k].j;
    m.name = Structure::Name(s.strings[k]);
    mass[nb + k] = m.mass;
    total += m.mass;
    d.strings.push_back(m);
  }
  return total;
}

// The self-weight fixed point: each pass adds the weight of the last sizing. The weight
// is a fraction of the load well below 1 for any bridge that can stand, so the change of
// mass shrinks geometrically, to 1e-12 (a few hundred rounding steps of a sum of masses)
// where each pass's optimum is exact (the closed-form and direct solves). An iterative
// solver returns it only to about design.tolerance (relative): there the change stops
// shrinking at a few times that (the 3D bridge at n = 2: +-1.2e-9 at 1e-10), and a change
// below 100 times the tolerance that did not halve is as settled as the solver can tell.
// Where the problem has many optima (the 3D bridge's dozens of self-stress states), such
// a change of weight can move the solver between them and the passes cycle (at n = 3 with
// a period of 4 passes and a spread of 4e-6): after 8 passes a change of 1e-5 is settled.
// The weight is then right to 1e-5 of the structure's own weight, far below what any check
// resolves, and the verified sizing rebuilds the weight from its own design anyway. A
// change that grows after the first passes does not settle: the mass either diverges or
// jumps between optima (the 3D bridge at n = 4: 1232, 1233, 1172, 1197, 1171 kg).
// Returns whether the sizing of mass `total` settles it; throws where it does not settle.
bool SelfWeightSettled(const Config& config, const Design& d, double total, double previous_total,
                       double& previous_change) {
  const double change = std::abs(total - previous_total) / total;
  const bool settled =
      change <= 1e-12 ||
      (change <= 100 * config.design.tolerance && change > 0.5 * previous_change) ||
      (d.self_weight_iterations > 8 && change <= 1e-5);
  if (!config.design.self_weight || settled) return true;
  const bool unsettled = d.self_weight_iterations >= 3 && change > previous_change && change > 1e-5;
  previous_change = change;
  if (d.self_weight_iterations >= 200 || unsettled || !std::isfinite(total)) {
    // Still growing: the weight outruns what the members carry. Moving back and forth: the
    // minimum-mass problem has many optima (self-stresses), and a small change of weight
    // moves the solver from one to another.
    const bool growing = !std::isfinite(total) || total > 1.05 * previous_total;
    throw ModelError(
        "self-weight: the member mass did not settle in " +
        std::to_string(d.self_weight_iterations) + " sizings (" + NumberText(previous_total) +
        " kg, then " + NumberText(total) + " kg): " +
        (growing
             ? std::string("the members cannot carry their own weight at this span and material")
             : std::string("it moves between optima of the minimum-mass problem (" +
                           std::to_string(d.self_stress_states) +
                           " self-stress states); design.self_weight false designs without it")));
  }
  return false;
}

// No design where the solver failed, the reference state is out of equilibrium or a member is
// past its floor: the error says what was solved, and on a 3D bridge what may be at fault.
void RequireDesignFound(const Design& d, const Config& config, const EquilibriumBasis& basis,
                        const MinMassSettings& settings, const MinMassSolution& solution,
                        double sigma_w) {
  const double load_scale = SelfStressForceScale(basis, settings);
  const double smallest = solution.forces.col(solution.forces.cols() - 1).minCoeff();
  if (!d.solver.success || !std::isfinite(d.equilibrium_residual) ||
      d.equilibrium_residual > 1e-6 * load_scale || smallest < -1e-6 * load_scale) {
    std::ostringstream os;
    os << "no minimum-mass design found for n = " << config.bridge.n << ", p = " << config.bridge.p
       << ", beta = " << config.bridge.beta_deg << " deg: solver " << NameOf(d.solver.solver)
       << " returned status " << d.solver.status << " after " << d.solver.iterations
       << " iterations (equilibrium residual " << d.equilibrium_residual << " N)";
    if (d.topology.planes == 2) {
      // The transverse strings' prestress floor grows with sigma_w; where the loads cannot
      // balance it, no member forces are both in equilibrium and of the right sign.
      const double r = config.design.transverse_string_min_radius;
      os << "; the transverse strings are prestressed at sigma_w pi r^2 = "
         << sigma_w * std::numbers::pi * r * r
         << " N each (design.transverse_string_min_radius = " << r
         << " m), which these loads may not balance: a "
         << "smaller radius lowers it";
    }
    throw ModelError(os.str());
  }
}

// Utilisation of every member under its largest (ultimate) and smallest force of any case.
void UtiliseMembers(Design& d, const MinMassSolution& solution, const BarRule& rule, double sigma_w,
                    const MinMassSettings& settings, bool single, const CaseEnvelope& env) {
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars(), members = nb + s.num_strings();
  const Eigen::VectorXd& largest = solution.forces.col(0);
  const Eigen::VectorXd& least = solution.forces.col(solution.forces.cols() - 1);
  for (int j = 0; j < members; ++j) {
    MemberSizing& m = d.MemberAt(j);
    Utilise(m, largest[j], least[j], rule, sigma_w, settings.bars.youngs_modulus);
    m.force_min = least[j];
    m.governing_case = single ? d.cases[0].name : CaseLabel(d.cases, d.actions, env.uls_max[j]);
    if (m.mode == LimitMode::kSlack || m.mode == LimitMode::kTension)
      m.governing_case = CaseLabel(d.cases, d.actions, env.min[j]);
  }
}

// Keeps the reference state and assesses it: stability, support reactions, and the masses.
void CompleteDesign(Design& d, const Config& config, const MinMassSolution& solution,
                    const Eigen::VectorXd& reference_forces,
                    const Eigen::Matrix3Xd& reference_loads, const LoadCase& reference) {
  const Structure& s = d.topology.structure;
  d.alpha = solution.alpha;
  d.reference_forces = reference_forces;
  d.loads = reference_loads;
  d.reference = reference;
  // Stability with the bars held: sparse and roughly linear, so it runs at every n; the dense
  // critical load factor only where it costs well under a second (n <= 6).
  std::vector<double> string_stiffness(d.strings.size());
  for (size_t k = 0; k < d.strings.size(); ++k) string_stiffness[k] = d.strings[k].stiffness;
  d.stability = AssessStability(s, reference_forces, string_stiffness, config.bridge.n <= 6);
  d.reactions = SupportReactions(s, reference_forces, reference_loads);
  d.reactions.array() += 0.0;  // -0 (a fixed node's untouched axis) reads as 0 in the outputs
  d.mass = MassesOf(d.bars, d.strings, d.deck.beams_mass);
}

}  // namespace

// The permanent action's factors: deck dead load, and the members' weight when it is on.
LoadCase PermanentCase(const Config& c) {
  LoadCase g;
  g.name = "permanent";
  g.factor[kDeckDead] = 1.0;
  g.factor[kSelfWeight] = c.design.self_weight ? 1.0 : 0.0;
  return g;
}

Design RunDesign(const Config& config, ProgressReporter* progress,
                 const std::vector<double>* area_floor) {
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
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars(), members = nb + s.num_strings();
  if (area_floor && static_cast<int>(area_floor->size()) != members)
    throw ModelError("RunDesign: area floors do not match the members");
  auto floor = [area_floor](int j) { return area_floor ? (*area_floor)[j] : 0.0; };
  for (int b = 0; b < nb; ++b)
    in.settings.bar_min_area[b] = std::max(in.settings.bar_min_area[b], floor(b));
  const MinMassSettings& settings = in.settings;
  const double sigma_w = settings.strings.DesignStress();
  const BarRule rule = BarRuleOf(config);

  d.actions = std::move(in.actions);
  d.cases = MakeLoadCases(config, d.deck, d.notes);
  const bool travels = KeepAffordableTravellingLoads(d, members);
  const bool single = d.cases.size() == 1 && !travels;

  const EquilibriumSystem eq = BuildEquilibrium(s);
  const EquilibriumSolver solver(eq);
  d.self_stress_states = solver.states();
  StationInfluence influence;
  if (travels) influence = InfluenceOfStations(solver, eq, d.actions);
  EquilibriumBasis basis = BasisOf(solver, eq, members);
  done(0.6);

  // The reference state: the drawn geometry is in equilibrium under it (the paper's design
  // load; else the permanent load G with the prestress).
  const LoadCase reference = ReferenceCase(config, d.cases);
  std::vector<double> mass(members, 0.0);
  const double g = config.design.gravity;
  Eigen::MatrixXd base_forces;
  CaseEnvelope env;
  MinMassSolution solution;
  Eigen::VectorXd reference_forces;
  double previous_total = -1, previous_change = 1;
  for (d.self_weight_iterations = 1;; ++d.self_weight_iterations) {
    d.actions.base[kSelfWeight] = SelfWeightLoads(s, mass, g);
    Eigen::MatrixXd w(eq.A.rows(), kNumBaseActions);
    for (int a = 0; a < kNumBaseActions; ++a) w.col(a) = FreeLoads(eq, d.actions.base[a]);
    base_forces = solver.Particular(w);
    basis.load_residual =
        std::max(influence.load_residual, (eq.A * base_forces + w).cwiseAbs().maxCoeff());
    env = EnvelopeOf(d.cases, base_forces, travels ? &influence : nullptr);
    const Eigen::Matrix3Xd single_loads = d.actions.Loads(d.cases[0]);
    if (single) {
      basis.particular = solver.Particular(FreeLoads(eq, single_loads));
    } else {
      basis.particular.resize(members, 2);
      for (int j = 0; j < members; ++j)
        basis.particular(j, 0) = env.uls_max[j].force, basis.particular(j, 1) = env.min[j].force;
    }
    CheckBasis(basis);
    std::optional<ReducedMinMassProblem> problem;
    if (basis.basis_formed) problem.emplace(s, basis, settings);
    solution = SolveMinMass(problem ? &*problem : nullptr, basis.states, s,
                            single ? &single_loads : nullptr, settings, config.design, d.solver,
                            d.solver_form);
    reference_forces = single ? Eigen::VectorXd(solution.forces.col(0))
                              : Eigen::VectorXd(base_forces * reference.Factors());
    if (!single && solution.alpha.size()) reference_forces += basis.self_stress * solution.alpha;

    // Size every member for its largest force; rest lengths from the reference state.
    const Eigen::VectorXd largest = solution.forces.col(0);
    const double total = SizeMembers(d, in, rule, floor, largest, reference_forces, mass);
    if (SelfWeightSettled(config, d, total, previous_total, previous_change)) break;
    previous_total = total;
  }
  done(0.8);

  // Equilibrium of the reference state, and no member past its floor in any case.
  const Eigen::Matrix3Xd reference_loads = d.actions.Loads(reference);
  const Eigen::VectorXd residual = EquilibriumResidual(eq, reference_forces, reference_loads);
  d.equilibrium_residual = residual.size() ? residual.cwiseAbs().maxCoeff() : 0.0;
  RequireDesignFound(d, config, basis, settings, solution, sigma_w);
  UtiliseMembers(d, solution, rule, sigma_w, settings, single, env);
  CompleteDesign(d, config, solution, reference_forces, reference_loads, reference);
  done(1.0);
  return d;
}

}  // namespace tbridge
