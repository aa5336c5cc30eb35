// The design's self-stress form against the full minimum-mass problem it replaces: the sparse
// equilibrium basis against a dense rank count, the optimum against the full NLP with both
// solvers, and every derivative an adapter sees against finite differences.
#include "design/reduced_min_mass.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "design/design.h"
#include "design/equilibrium.h"
#include "design/equilibrium_basis.h"
#include "design/min_mass.h"
#include "optim/solvers.h"
#include "test_support.h"

namespace tbridge {
namespace {

struct Case {
  std::string label;
  Config config;
};

Config Variant(int n, int p, int planes) {
  Config c = test::PaperConfig(n);
  c.bridge.p = p;
  c.bridge.planes = planes;
  if (planes == 2) c.bridge.beta_deg = 20.0;  // the paper's 3D bridge (Sect. 7.3)
  return c;
}

// Planar p = 1..3 and the 3D bridge for n = 1..max_n.
std::vector<Case> Topologies(int max_n) {
  std::vector<Case> cases;
  for (int n = 1; n <= max_n; ++n) {
    for (int p = 1; p <= 3; ++p)
      cases.push_back(
          {"p = " + std::to_string(p) + ", n = " + std::to_string(n), Variant(n, p, 1)});
    cases.push_back({"3D, n = " + std::to_string(n), Variant(n, 1, 2)});
  }
  return cases;
}

EquilibriumBasis BasisOf(const DesignInputs& in) {
  const EquilibriumSystem eq = BuildEquilibrium(in.topology.structure);
  return FactorEquilibrium(eq, FreeLoads(eq, in.loads));
}

TEST_CASE("Sparse equilibrium basis: rank, self-stresses and particular solution",
          "[design][self-stress]") {
  for (const Case& c : Topologies(5)) {
    INFO(c.label);
    const DesignInputs in = PrepareDesign(c.config);
    const EquilibriumSystem eq = BuildEquilibrium(in.topology.structure);
    const EquilibriumBasis basis = BasisOf(in);
    // A second algorithm: the dense column-pivoted QR count of design/equilibrium.h.
    CHECK(basis.self_stress_states() == CountSelfStresses(eq));
    if (c.config.bridge.planes == 1) CHECK(basis.self_stress_states() == 1);  // the deck chain
    const Eigen::MatrixXd& N = basis.self_stress;
    const Eigen::Index s = N.cols();
    // Orthonormal to rounding (Householder products: ~1e-15 per entry).
    CHECK((N.transpose() * N - Eigen::MatrixXd::Identity(s, s)).cwiseAbs().maxCoeff() <= 1e-12);
    // In the null space: entries of A are direction cosines, so rounding is ~1e-15.
    CHECK((eq.A * N).cwiseAbs().maxCoeff() <= 1e-12);
    // The particular solution balances the loads to rounding of its largest force.
    const double scale = basis.particular.cwiseAbs().maxCoeff();
    CHECK((eq.A * basis.particular + FreeLoads(eq, in.loads)).cwiseAbs().maxCoeff() <=
          1e-12 * scale);
  }
}

TEST_CASE("One self-stress for p = 1 at every complexity up to 16", "[design][self-stress]") {
  for (int n : {8, 12, 16}) {
    INFO("n = " << n);
    const EquilibriumBasis basis = BasisOf(PrepareDesign(test::PaperConfig(n)));
    CHECK(basis.self_stress_states() == 1);
    CHECK(basis.basis_residual <= 1e-12);
  }
}

TEST_CASE("A self-stress basis too large to form is counted and not formed",
          "[design][self-stress][ipopt]") {
  // The 3D bridge has 2^(n+3) - 6 self-stresses (10, 26, 58, ... : the dense count above for
  // n <= 5); past the entry limit the count stays and the design takes the full problem.
  const DesignInputs in = PrepareDesign(Variant(2, 1, 2));
  const EquilibriumSystem eq = BuildEquilibrium(in.topology.structure);
  const EquilibriumBasis counted =
      FactorEquilibrium(eq, FreeLoads(eq, in.loads), /*max_basis_entries=*/0.0);
  CHECK_FALSE(counted.basis_formed);
  CHECK(counted.self_stress_states() == 26);
  CHECK(counted.self_stress.cols() == 0);
  const double scale = counted.particular.cwiseAbs().maxCoeff();
  CHECK((eq.A * counted.particular + FreeLoads(eq, in.loads)).cwiseAbs().maxCoeff() <=
        1e-12 * scale);
  CHECK_THROWS_AS(ReducedMinMassProblem(in.topology.structure, counted, in.settings), ModelError);

  REQUIRE(test::HaveSolvers(
      {SolverKind::kIpopt}));  // tagged [ipopt]: ctest leaves it out of a build without
  const Design d = RunDesign(Variant(8, 1, 2));  // 5102 members x 2042 states: over the limit
  CHECK(d.self_stress_states == (1 << 11) - 6);
  CHECK(d.solver_form == "full");
  // Equilibrium to 1e-9 of the largest node load, as every design.
  const Eigen::VectorXd r =
      EquilibriumResidual(BuildEquilibrium(d.topology.structure), MemberForces(d), d.loads);
  CHECK(r.cwiseAbs().maxCoeff() <= 1e-9 * d.deck.node_load);
}

struct Optimum {
  double mass = 0;         // structure mass [kg]
  Eigen::VectorXd forces;  // [C; T] in N
  std::string status;
};

// SLSQP stops when the objective changes by less than ftol_rel = tolerance in a step: at
// 1e-12 it stops on the 3D n = 6 bridge 5e-5 above the optimum after a short step, at 1e-14 it
// reaches it (1.5e-11 from Ipopt's). Ipopt's tolerance is on the KKT conditions.
SolverOptions OptionsFor(SolverKind solver) {
  SolverOptions options;
  options.tolerance = solver == SolverKind::kNlopt ? 1e-14 : 1e-12;
  options.max_iterations = 3000;
  return options;
}

Optimum SolveFull(const DesignInputs& in, SolverKind solver) {
  const MinMassProblem full(in.topology.structure, in.loads, in.settings);
  Eigen::VectorXd x = full.StartingPoint();
  const SolverOptions options = OptionsFor(solver);
  const SolverOutcome out = SolveNlp(solver, full, options, x);
  return {full.Objective(x) * full.MassScale(), full.MemberForces(x), out.status};
}

Optimum SolveReduced(const DesignInputs& in, SolverKind solver) {
  const ReducedMinMassProblem reduced(in.topology.structure, BasisOf(in), in.settings);
  Eigen::VectorXd x;
  SolverOutcome out;
  if (solver == SolverKind::kDirect) {
    out = reduced.SolveDirect(x);
  } else {
    x = reduced.StartingPoint();
    const SolverOptions options = OptionsFor(solver);
    out = SolveNlp(solver, reduced, options, x);
  }
  return {reduced.Objective(x) * reduced.MassScale(), reduced.MemberForces(x, 0), out.status};
}

TEST_CASE("The self-stress form and the full NLP find the same optimum",
          "[design][self-stress][solvers]") {
  for (const Case& c : Topologies(6)) {
    const DesignInputs in = PrepareDesign(c.config);
    const bool planar = c.config.bridge.planes == 1;
    const int full_variables =
        2 * in.topology.structure.num_bars() + in.topology.structure.num_strings();
    for (const SolverKind solver : {SolverKind::kIpopt, SolverKind::kNlopt}) {
      // SLSQP's dense quadratic subproblems cost (variables)^3 per iteration: the full problem
      // goes to NLopt up to 600 variables (planar p = 1 up to n = 6, 3D up to n = 4); beyond,
      // NLopt's self-stress solution is held to the full problem solved by Ipopt.
      const SolverKind full_solver =
          solver == SolverKind::kNlopt && full_variables > 600 ? SolverKind::kIpopt : solver;
      if (!test::HaveSolvers({solver, full_solver})) {
        WARN("skipped for " << NameOf(solver) << ": " << NameOf(full_solver) << " or "
                            << NameOf(solver) << " not built in (its TBRIDGE_WITH_ option is off)");
        continue;
      }
      INFO(c.label << ", " << NameOf(solver) << " (full problem: " << NameOf(full_solver) << ")");
      const Optimum full = SolveFull(in, full_solver);
      // The direct solve (planar) or the product's own self-stress NLP (3D: the same as below).
      const Optimum reduced = SolveReduced(in, planar ? SolverKind::kDirect : solver);
      const Optimum reduced_nlp = planar ? SolveReduced(in, solver) : reduced;
      INFO("full " << full.mass << " kg (" << full.status << "), reduced " << reduced.mass
                   << " kg, reduced " << NameOf(solver) << " " << reduced_nlp.mass << " kg ("
                   << reduced_nlp.status << ")");
      // The acceptance bound, 1e-9 relative: both forms are solved to 1e-12, so only the
      // solvers' tolerance separates them.
      if (planar) CHECK(reduced.mass == Approx(full.mass).epsilon(1e-9));
      CHECK(reduced_nlp.mass == Approx(full.mass).epsilon(1e-9));
      if (planar) {
        // The optimum is unique (the deck chain at its floor, every other force fixed by
        // equilibrium): the forces agree to the solvers' tolerance on the largest force.
        const double scale = full.forces.cwiseAbs().maxCoeff();
        CHECK((reduced.forces - full.forces).cwiseAbs().maxCoeff() <= 1e-8 * scale);
        CHECK((reduced_nlp.forces - full.forces).cwiseAbs().maxCoeff() <= 1e-8 * scale);
      }
      // 3D: buckling makes the problem non-convex and its 26+ self-stresses leave ties, so
      // optima with equal mass may split forces differently; only the masses are compared.
    }
  }
}

// Finite-difference checks of what an adapter reads: gradient, Jacobian, Lagrangian Hessian.
Eigen::MatrixXd DenseJacobian(const NlpProblem& p, const Eigen::VectorXd& x) {
  std::vector<double> values(p.JacobianPattern().size());
  p.JacobianValues(x, values.data());
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(p.num_constraints(), p.num_variables());
  for (size_t k = 0; k < values.size(); ++k)
    j(p.JacobianPattern()[k].first, p.JacobianPattern()[k].second) += values[k];
  return j;
}

void CheckDerivatives(const NlpProblem& p, const Eigen::VectorXd& x,
                      const Eigen::VectorXd& lambda) {
  const int n = p.num_variables(), m = p.num_constraints();
  const double h = 1e-6;
  Eigen::VectorXd grad(n), g_plus(m), g_minus(m);
  p.ObjectiveGradient(x, grad);
  const Eigen::MatrixXd jac = DenseJacobian(p, x);
  // Lagrangian gradient sigma grad f + J^T lambda, and its FD derivative for the Hessian.
  const double sigma = 0.7;
  auto lagrangian_gradient = [&](const Eigen::VectorXd& at) {
    Eigen::VectorXd gf(n);
    p.ObjectiveGradient(at, gf);
    return Eigen::VectorXd(sigma * gf + DenseJacobian(p, at).transpose() * lambda);
  };
  std::vector<double> hess_values(p.HessianPattern().size());
  p.HessianValues(x, sigma, lambda.data(), hess_values.data());
  Eigen::MatrixXd hess = Eigen::MatrixXd::Zero(n, n);
  for (size_t k = 0; k < hess_values.size(); ++k) {
    const auto [r, c] = p.HessianPattern()[k];
    REQUIRE(r >= c);  // lower triangle, as the adapters promise their solvers
    hess(r, c) += hess_values[k];
    if (r != c) hess(c, r) += hess_values[k];
  }
  for (int i = 0; i < n; ++i) {
    Eigen::VectorXd plus = x, minus = x;
    plus[i] += h;
    minus[i] -= h;
    // The objective is linear and the constraints at most quadratic in every variable, so
    // central differences are exact but for rounding: ~eps * |value| / h ~ 1e-10 relative.
    const double fd_grad = (p.Objective(plus) - p.Objective(minus)) / (2 * h);
    CHECK(fd_grad == Approx(grad[i]).margin(1e-8 * (1 + std::abs(grad[i]))));
    p.Constraints(plus, g_plus);
    p.Constraints(minus, g_minus);
    const Eigen::VectorXd fd_col = (g_plus - g_minus) / (2 * h);
    CHECK((fd_col - jac.col(i)).cwiseAbs().maxCoeff() <=
          1e-7 * (1 + jac.col(i).cwiseAbs().maxCoeff()));
    const Eigen::VectorXd fd_hess =
        (lagrangian_gradient(plus) - lagrangian_gradient(minus)) / (2 * h);
    CHECK((fd_hess - hess.col(i)).cwiseAbs().maxCoeff() <=
          1e-7 * (1 + hess.col(i).cwiseAbs().maxCoeff()));
  }
}

TEST_CASE("Derivatives of both problem forms against finite differences",
          "[design][self-stress][derivatives]") {
  // The 3D bridge has bars in its self-stresses (buckling rows, a nonzero Hessian); a second,
  // duplicated load case gives the reduced form string envelopes. Random x and multipliers.
  const DesignInputs in = PrepareDesign(Variant(2, 1, 2));
  const MinMassProblem full(in.topology.structure, in.loads, in.settings);
  const EquilibriumBasis basis = BasisOf(in);
  EquilibriumBasis two_cases = basis;
  two_cases.particular = Eigen::MatrixXd(basis.particular.rows(), 2);
  two_cases.particular << basis.particular, 0.5 * basis.particular;
  const ReducedMinMassProblem reduced(in.topology.structure, basis, in.settings);
  const ReducedMinMassProblem reduced2(in.topology.structure, two_cases, in.settings);
  REQUIRE(reduced.num_active_bars() > 0);
  std::srand(7);
  for (const NlpProblem* p : std::vector<const NlpProblem*>{&full, &reduced, &reduced2}) {
    const Eigen::VectorXd x = Eigen::VectorXd::Random(p->num_variables()).cwiseAbs() +
                              Eigen::VectorXd::Constant(p->num_variables(), 0.5);
    const Eigen::VectorXd lambda = Eigen::VectorXd::Random(p->num_constraints());
    CheckDerivatives(*p, x, lambda);
  }
}

TEST_CASE("A load case that only repeats another changes nothing", "[design][self-stress]") {
  // The envelope over identical cases is each case: same optimum as one case (3D, Ipopt), to
  // the solver's tolerance.
  const DesignInputs in = PrepareDesign(Variant(2, 1, 2));
  const EquilibriumBasis basis = BasisOf(in);
  EquilibriumBasis twice = basis;
  twice.particular = Eigen::MatrixXd(basis.particular.rows(), 2);
  twice.particular << basis.particular, basis.particular;
  const ReducedMinMassProblem one(in.topology.structure, basis, in.settings);
  const ReducedMinMassProblem two(in.topology.structure, twice, in.settings);
  Eigen::VectorXd x1 = one.StartingPoint(), x2 = two.StartingPoint();
  SolverOptions options;
  options.tolerance = 1e-12;
  options.max_iterations = 3000;
  const SolverKind solver =
      BuiltInIterativeSolvers().empty() ? SolverKind::kNone : BuiltInIterativeSolvers().front();
  if (solver == SolverKind::kNone) return;  // a build with neither Ipopt nor NLopt
  REQUIRE(SolveNlp(solver, one, options, x1).success);
  REQUIRE(SolveNlp(solver, two, options, x2).success);
  CHECK(two.Objective(x2) * two.MassScale() ==
        Approx(one.Objective(x1) * one.MassScale()).epsilon(1e-9));
}

TEST_CASE("design.solver: direct where it applies, a named error where it does not",
          "[design][self-stress]") {
  Config planar = test::PaperConfig(3, SolverKind::kDirect);
  const Design d = RunDesign(planar);
  CHECK(d.solver.solver == SolverKind::kDirect);
  CHECK(d.solver.iterations == 0);
  CHECK(RunDesign(test::PaperConfig(3)).solver.solver == SolverKind::kDirect);  // "auto"
  Config spatial = Variant(2, 1, 2);
  // "auto" on the 3D bridge: the first iterative solver built in (Ipopt, else NLopt).
  if (!BuiltInIterativeSolvers().empty()) {
    CHECK(RunDesign(spatial).solver.solver == BuiltInIterativeSolvers().front());
  }
  spatial.design.solver = SolverKind::kDirect;
  try {
    RunDesign(spatial);
    FAIL("expected a ConfigError");
  } catch (const ConfigError& e) {
    CHECK(std::string(e.what()).find("design.solver") != std::string::npos);
  }
}

TEST_CASE("design.solver names only the solvers built in", "[design][solvers]") {
  // Each iterative solver either designs the 3D bridge (26 self-stresses: the direct solve
  // does not apply) under its own name, or, in a build without it, is refused before any work
  // with the key, the value and the solvers this build has.
  for (const SolverKind solver : {SolverKind::kIpopt, SolverKind::kNlopt}) {
    INFO(NameOf(solver));
    Config c = Variant(2, 1, 2);
    c.design.solver = solver;
    if (SolverBuiltIn(solver)) {
      CHECK(RunDesign(c).solver.solver == solver);
    } else {
      try {
        RunDesign(c);
        FAIL("expected a ConfigError");
      } catch (const ConfigError& e) {
        CHECK(e.key() == "design.solver");
        CHECK_THAT(e.what(), Catch::Contains("built in: \"auto\", \"direct\"") &&
                                 Catch::Contains("TBRIDGE_WITH_"));
      }
    }
  }
}

}  // namespace
}  // namespace tbridge
