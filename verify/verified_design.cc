#include "verify/verified_design.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "design/sizing_problem.h"
#include "design/solvers.h"
#include "verify/dynamic_check.h"
#include "verify/static_check.h"

namespace tbridge {

void RecordChecks(Design& d, StaticCheck statics, DynamicCheck dynamics) {
  const int nb = static_cast<int>(d.bars.size());
  for (const std::vector<MemberFinding>* found : {&statics.members, &dynamics.members}) {
    for (int j = 0; j < static_cast<int>(found->size()); ++j) {
      const MemberFinding& f = (*found)[j];
      MemberSizing& m = j < nb ? d.bars[j] : d.strings[j - nb];
      if (f.utilisation > 0) RaiseUtilisation(m, f.utilisation, f.governing_case, f.mode.c_str());
    }
  }
  d.statics = std::move(statics);
  d.dynamics = std::move(dynamics);
}

namespace {

// The solver of the sizing: the config's iterative solver, Ipopt where it leaves the choice.
std::string SizingSolver(const Config& config) {
  const std::string& asked = config.design.solver;
  if (asked == "ipopt" || asked == "nlopt") return asked;
  const std::vector<std::string> built = BuiltInIterativeSolvers();
  if (built.empty()) return "";
  return std::find(built.begin(), built.end(), "ipopt") != built.end() ? "ipopt" : built.front();
}

// The members' sizes and states of the design the sizing found: the linear analysis's
// governing demand as each member's force and utilisation, and what bounds it.
void RecordSizing(Design& d, const SizingProblem& problem, const Eigen::VectorXd& x, const std::vector<double>& floor) {
  const std::vector<SizingProblem::MemberDemand> demands = problem.Demands(x);
  const int nb = static_cast<int>(d.bars.size());
  for (int j = 0; j < static_cast<int>(demands.size()); ++j) {
    MemberSizing& m = j < nb ? d.bars[j] : d.strings[j - nb];
    const SizingProblem::MemberDemand& dm = demands[j];
    if (dm.row >= 0) {
      const SizingRow& row = problem.rows()[dm.row];
      m.force = std::max(dm.demand, 0.0);
      m.utilisation = std::max(dm.utilisation, 0.0);
      m.mode = SizingRowKindName(row.kind);
      m.governing_case = problem.combinations()[row.combination].label;
    }
    // What sizes it: its floor (within the solver's tolerance), its own strength where that
    // is used up, else the stiffness it gives (the deflection and taut-string rows).
    m.governed_by = m.area <= floor[j] * (1 + 1e-6) ? "min_radius" : m.utilisation >= 1 - 1e-3 ? m.mode : "stiffness";
  }
}

// Whether row r is near its limit: below `cap` (a utilisation above 0.3, a deflection above
// 0.3 of its limit, a tension below 0.1 of the largest force) and within `band` of the
// closest row of its member and kind (the combinations that govern it, not the others).
std::vector<char> NearLimits(const SizingProblem& full, const Eigen::VectorXd& g) {
  const std::vector<SizingRow>& rows = full.rows();
  std::map<std::pair<int, int>, double> closest;
  for (size_t r = 0; r < rows.size(); ++r) {
    const auto key = std::make_pair(static_cast<int>(rows[r].kind), rows[r].member);
    const auto it = closest.find(key);
    if (it == closest.end() || g[r] < it->second) closest[key] = g[r];
  }
  std::vector<char> near(rows.size(), 0);
  for (size_t r = 0; r < rows.size(); ++r) {
    const bool taut = rows[r].kind == SizingRow::kTaut || rows[r].kind == SizingRow::kReferenceTaut;
    const double cap = taut ? 0.1 : 0.7, band = taut ? 0.02 : 0.1;
    const double best = closest[{static_cast<int>(rows[r].kind), rows[r].member}];
    near[r] = !(g[r] >= cap) && !(g[r] > best + band);
  }
  return near;
}

// Solves the sizing by active sets: the rows near their limits at the start are posed; after
// each solve the whole problem is evaluated and the rows near their limits there join, until
// the solution violates no row of the whole problem (at most 8 rounds). The posed problem is
// about a hundred rows where the whole one has thousands, and the solver's linear algebra
// shrinks with it.
SolverOutcome SolveSizing(const Design& current, const SizingCorrections& corrections, const std::string& solver,
                          const SolverOptions& options, const SizingProblem& full, Eigen::VectorXd& x) {
  const int rows = full.num_constraints();
  std::vector<char> keep(rows, 0);
  Eigen::VectorXd g(rows), lo, hi;
  full.ConstraintBounds(lo, hi);
  SolverOutcome outcome;
  for (int round = 0; round < 8; ++round) {
    full.Constraints(x, g);
    bool added = false, violated = false;
    const std::vector<char> near = NearLimits(full, g);
    for (int r = 0; r < rows; ++r) {
      const bool bad = !(g[r] >= lo[r] - 1e-9);
      violated = violated || bad;
      if (!keep[r] && (near[r] || bad)) keep[r] = 1, added = true;
    }
    if (round > 0 && (!violated || !added)) break;
    const SizingProblem posed(current, corrections, &keep);
    outcome = SolveNlp(solver, posed, options, x);
    if (!outcome.success) break;
  }
  return outcome;
}

}  // namespace

Design DesignAndVerify(const Config& config, ProgressReporter* progress, int max_iterations) {
  Design first = RunDesign(config, progress);
  RequireStable(first);
  Resizing record;
  const std::string solver = SizingSolver(config);
  // The paper's design is the paper's: with its switches the checks report, and resize
  // nothing. A build without an iterative solver checks the first design as it is.
  if (KeepsPaperSwitches(config) || solver.empty() || first.unchecked_cases) {
    RecordChecks(first, CheckStatics(first), CheckDynamics(first));
    record.iterations = 1;
    record.structure_mass_kg.push_back(first.mass.structure);
    const Verdict verdict = DesignVerdict(first);
    record.converged = verdict.pass;
    if (!verdict.pass) record.why = verdict.summary;
    first.resizing = record;
    return first;
  }

  record.structure_mass_kg.push_back(first.mass.structure);
  SizingCorrections corrections;
  Design current = first;
  std::vector<double> areas;
  for (const auto* list : {&first.bars, &first.strings}) {
    for (const MemberSizing& m : *list) areas.push_back(m.area);
  }
  Eigen::VectorXd alpha;
  for (record.iterations = 1;; ++record.iterations) {
    // The sizing about the current design's weight, from the current sizes and prestress.
    const SizingProblem problem(current, corrections);
    if (record.iterations == 1) alpha = problem.AlphaOf(first.reference_forces);  // the first design's prestress
    Eigen::VectorXd x = problem.VariablesOf(areas, alpha);
    Eigen::VectorXd lo, hi;
    problem.VariableBounds(lo, hi);
    x = x.cwiseMax(lo);
    SolverOptions options;
    options.tolerance = 1e-8;
    options.max_iterations = config.design.max_iterations;
    options.verbose = std::getenv("TBRIDGE_SIZING_VERBOSE") != nullptr;
    options.nlopt_method = SolverOptions::NloptMethod::kMma;
    const SolverOutcome outcome = SolveSizing(current, corrections, solver, options, problem, x);
    areas = problem.Areas(x);
    alpha = problem.Alpha(x);
    Design d = SizedDesign(config, areas, alpha);
    d.solver = outcome;
    d.solver_form = "verified sizing";
    RequireStable(d);
    RecordSizing(d, problem, x, problem.Areas(lo));
    const StaticCheck statics = CheckStatics(d);
    const DynamicCheck dynamics = CheckDynamics(d);
    RecordChecks(d, statics, dynamics);
    record.structure_mass_kg.push_back(d.mass.structure);
    const Verdict verdict = DesignVerdict(d);
    record.converged = verdict.pass;
    const bool last = record.iterations >= max_iterations || !outcome.success || !d.statics.all_converged;
    if (verdict.outcome != VerdictOutcome::kFail || last) {
      if (!verdict.pass) {
        record.why = verdict.summary;
        if (!outcome.success) record.why += "; the sizing's solver stopped with " + outcome.status;
      }
      d.resizing = record;
      return d;
    }
    // Correct the linear model by what the checks found, member by member: the ratio of the
    // checks' utilisation to the linear one becomes a factor on the member's demand; a slack
    // taut string asks for the tension it lacked; a deflection past the linear one scales
    // the deflections.
    const std::vector<SizingProblem::MemberDemand> linear = problem.Demands(x);
    const int nb = static_cast<int>(d.bars.size());
    corrections.demand_factor.resize(areas.size(), 1.0);
    corrections.taut_margin_n.resize(areas.size(), 0.0);
    for (size_t j = 0; j < areas.size(); ++j) {
      for (const MemberFinding* f : {&statics.members[j], &dynamics.members[j]}) {
        if (f->utilisation <= 0) continue;
        if (f->mode == "slack") {
          const MemberSizing& m = d.strings[j - nb];
          corrections.taut_margin_n[j] += config.material.youngs_modulus * m.area * (f->demand - f->resistance) * 1.05;
        } else if (linear[j].utilisation > 0 && f->utilisation > linear[j].utilisation) {
          corrections.demand_factor[j] *= f->utilisation / linear[j].utilisation;
        }
      }
    }
    const double linear_deflection = problem.LargestDeflection(x) * corrections.deflection_factor;
    if (linear_deflection > 0 && d.statics.deflection_max_m > linear_deflection) {
      corrections.deflection_factor *= d.statics.deflection_max_m / linear_deflection;
    }
    current = std::move(d);
  }
}

}  // namespace tbridge
