// The verified sizing problem: its gradients against central differences, its rows against
// their margins, its combinations against the load cases, and its mirror-image groups.

#include "sizing/sizing_problem.h"

#include <Eigen/QR>
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <random>

#include "design/design.h"
#include "design/equilibrium.h"
#include "design/equilibrium_basis.h"

namespace tbridge {
namespace {

Design SmallDesign() {
  Config config;  // engineering defaults at n = 2: every case, travelling stations, prestress
  config.bridge.n = 2;
  return RunDesign(config);
}

Config ThreeD(int n) {
  Config config;  // the engineering defaults on both planes
  config.bridge.n = n;
  config.bridge.planes = 2;
  return config;
}

// Abutment capacities, so that the problem has support rows (values that bind nowhere: the rows'
// gradients and images are what the tests read).
Config WithCapacities(Config config) {
  config.supports.horizontal_capacity_n = 5e6;
  config.supports.vertical_capacity_n = 1e6;
  return config;
}

int CountKind(const SizingProblem& problem, SizingRow::Kind kind) {
  return static_cast<int>(std::count_if(problem.rows().begin(), problem.rows().end(),
                                        [kind](const SizingRow& row) { return row.kind == kind; }));
}

void CheckJacobian(const Design& d) {
  SizingCorrections corrections;
  corrections.demand_factor.assign(d.bars.size() + d.strings.size(),
                                   1.3);  // kappa enters every row
  corrections.deflection_factor = 1.2;
  corrections.horizontal_reaction_factor = 1.1;
  corrections.vertical_reaction_factor = 1.05;
  const SizingProblem problem(d, corrections);
  const Eigen::VectorXd x =
      problem.VariablesOf(MemberAreas(d), problem.AlphaOf(d.reference_forces));
  const int n = problem.num_variables(), m = problem.num_constraints();
  REQUIRE(n >= 2);
  std::vector<double> values(problem.JacobianPattern().size());
  problem.JacobianValues(x, values.data());
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(m, n);
  for (size_t e = 0; e < values.size(); ++e) {
    jac(problem.JacobianPattern()[e].first, problem.JacobianPattern()[e].second) = values[e];
  }
  REQUIRE(jac.allFinite());  // a stable point in every state of the prestress
  // Central differences at 1e-6 of each variable (areas in cm^2 and the prestress in units of
  // the largest member force are O(1)): truncation O(h^2) ~ 1e-12 times the curvature, rounding
  // ~ 1e-16 / 1e-6 = 1e-10 per unit of g; 1e-6 of each column's largest entry holds both with
  // room for the rows' curvature (the buckling resistance's 1/A^2 terms).
  for (int v = 0; v < n; ++v) {
    const double h = 1e-6 * std::max(1.0, std::abs(x[v]));
    Eigen::VectorXd plus = x, minus = x, gp(m), gm(m);
    plus[v] += h;
    minus[v] -= h;
    problem.Constraints(plus, gp);
    problem.Constraints(minus, gm);
    const Eigen::VectorXd fd = (gp - gm) / (2 * h);
    INFO("variable " << v << " of " << n);
    const double scale = std::max(jac.col(v).cwiseAbs().maxCoeff(), 1e-12);
    CHECK((jac.col(v) - fd).cwiseAbs().maxCoeff() <= 1e-6 * scale);
  }
  // The dense form the SQP reads is the same matrix, evaluated again at x (the differences
  // above left the problem at another point): the same numbers, so equal exactly.
  Eigen::MatrixXd dense;
  REQUIRE(problem.DenseJacobian(x, dense));
  CHECK(dense.rows() == m);
  CHECK(dense.cols() == n);
  CHECK(dense == jac);
  // The objective's gradient: the mass is linear in the areas, so differences are exact to
  // rounding.
  Eigen::VectorXd grad(n);
  problem.ObjectiveGradient(x, grad);
  for (int v = 0; v < n; ++v) {
    Eigen::VectorXd plus = x;
    plus[v] += 1.0;
    CHECK(problem.Objective(plus) - problem.Objective(x) == Approx(grad[v]).epsilon(1e-9));
  }
}

TEST_CASE("the sizing problem's Jacobian agrees with central differences", "[design]") {
  SECTION("planar, n = 2: one self-stress state") {
    const Design d = SmallDesign();
    REQUIRE(CountKind(SizingProblem(d, {}), SizingRow::kServiceStress) > 0);
    CheckJacobian(d);
  }
  SECTION("3D, n = 1: the symmetric self-stresses as variables") {
    const Design d = RunDesign(ThreeD(1));
    REQUIRE(SizingProblem::SymmetricStates(d) >= 2);
    CheckJacobian(d);
  }
  // The support rows read several members' forces each (|(H_x, H_z)| and |V| of an abutment's
  // nodes); on the 3D bridge the wind gives H_z, so both components of the in-plan norm move.
  SECTION("planar, n = 2, with abutment capacities") {
    const Design d = RunDesign(WithCapacities(SmallDesign().config));
    REQUIRE(CountKind(SizingProblem(d, {}), SizingRow::kSupportHorizontal) > 0);
    CheckJacobian(d);
  }
  // The rows with the prestress at its highest and lowest follow the areas and the prestress
  // through the tolerance's change of the self-stress (its flexibilities): 0.1 % makes that term
  // large beside the others (a third of the deck chain's strain at sigma_w; 1 % would leave the
  // chain slack at the lowest, an unstable point).
  SECTION("planar, n = 2, a rest-length tolerance of 0.1 %") {
    Config config = SmallDesign().config;
    config.design.rest_length_tolerance = 1e-3;
    config.design.prestress_loss = 0;
    const Design d = RunDesign(config);
    REQUIRE(SizingProblem(d, {}).num_constraints() ==
            3 * SizingProblem(RunDesign([] {
                                Config c = SmallDesign().config;
                                c.design.rest_length_tolerance = 0;
                                c.design.prestress_loss = 0;
                                return c;
                              }()),
                              {})
                    .num_constraints());
    CheckJacobian(d);
  }
  SECTION("3D, n = 1, with abutment capacities") {
    CheckJacobian(RunDesign(WithCapacities(ThreeD(1))));
  }
  // Warmer and colder (the temperature's states): every member's stress-free length moves, the
  // bars' on the compatibility's right-hand side; 40 K either way (60 K at the factors: 7.2e-4
  // of strain, a quarter of the deck chain's at sigma_w) keeps the chain taut and the term large.
  SECTION("planar, n = 2, the temperature either way") {
    Config config = SmallDesign().config;
    config.design.prestress_loss = 0;
    config.loads.cases.push_back(LoadFamily::kTemperature);
    config.loads.temperature_delta_k = 40;
    CheckJacobian(RunDesign(config));
  }
}

TEST_CASE("the sizing problem's Hessian is the reciprocal diagonal, in Ipopt's sign", "[design]") {
  // What could be wrong is the sign and where it lands: NlpProblem's Lagrangian is
  // sigma f + sum lambda g, and a binding row g >= lo has lambda <= 0 there (Ipopt's). A row
  // weighted so (lambda_r = -1) adds 2 max(0, dg_r/dx_v) / x_v on each area and nothing on the
  // prestress; a row weighted the other way, or the mass alone (it rises with every area), adds
  // nothing. Exact: the same sums in the same order.
  const Design d = SmallDesign();
  const SizingProblem problem(d, {});
  const Eigen::VectorXd x =
      problem.VariablesOf(MemberAreas(d), problem.AlphaOf(d.reference_forces));
  const int n = problem.num_variables(), m = problem.num_constraints();
  const int groups = *std::max_element(problem.group_of().begin(), problem.group_of().end()) + 1;
  REQUIRE(problem.HessianPattern().size() == static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) CHECK(problem.HessianPattern()[v] == std::make_pair(v, v));
  Eigen::MatrixXd jac;
  REQUIRE(problem.DenseJacobian(x, jac));
  // The row that rises most with the first area.
  Eigen::Index r = 0;
  jac.col(0).maxCoeff(&r);
  REQUIRE(jac(r, 0) > 0);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m), h(n);
  lambda[r] = -1;
  problem.HessianValues(x, 1.0, lambda.data(), h.data());
  for (int v = 0; v < n; ++v) {
    const double expected = v < groups ? 2 * std::max(0.0, jac(r, v)) / x[v] : 0.0;
    CHECK(h[v] == expected);
  }
  lambda[r] = 1;  // the wrong sign for a binding row: no curvature
  problem.HessianValues(x, 1.0, lambda.data(), h.data());
  CHECK(h.cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("the sizing's prestress: every self-stress that gives mirror images one force",
          "[design]") {
  // Counted by a second algorithm: those self-stresses are x = G y with A G y = 0 (G the
  // members' group indicator), so there are groups - rank(A G) of them (dense QR). The planar
  // bridge has one state (the deck chain's), symmetric; the 3D bridge 10, 26, 58, 122 and
  // 250 at n = 1..5, of which 4, 9, 19, 39 and 79 are symmetric.
  for (const Config& config : {Config{}, ThreeD(1), ThreeD(2), ThreeD(3), ThreeD(4), ThreeD(5)}) {
    Design d;
    d.config = config;
    d.topology = PrepareDesign(config).topology;
    const Structure& s = d.topology.structure;
    const std::vector<int> group = MirrorGroups(s, config.bridge.span);
    const int groups = *std::max_element(group.begin(), group.end()) + 1;
    const EquilibriumSystem eq = BuildEquilibrium(s);
    const Eigen::MatrixXd A(eq.A);
    Eigen::MatrixXd AG = Eigen::MatrixXd::Zero(A.rows(), groups);
    for (int j = 0; j < A.cols(); ++j) AG.col(group[j]) += A.col(j);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(AG);
    INFO("planes " << config.bridge.planes << ", n = " << config.bridge.n << ": " << groups
                   << " groups, " << EquilibriumSolver(eq).states() << " states, "
                   << SizingProblem::SymmetricStates(d) << " symmetric");
    CHECK(SizingProblem::SymmetricStates(d) == groups - static_cast<int>(qr.rank()));
    if (config.bridge.planes == 1) CHECK(SizingProblem::SymmetricStates(d) == 1);
  }
  // Beyond kMaxSoughtStates (the 3D bridge from n = 6) the symmetric states are not sought.
  Design large;
  large.config = ThreeD(6);
  large.topology = PrepareDesign(large.config).topology;
  REQUIRE(EquilibriumSolver(BuildEquilibrium(large.topology.structure)).states() >
          SizingProblem::kMaxSoughtStates);
  CHECK(SizingProblem::SymmetricStates(large) == -1);
  // The prestress of each variable gives the members of a group one force (to rounding of the
  // orthonormal basis: 1e-9 of the largest).
  const Design d = RunDesign(ThreeD(1));
  const SizingProblem problem(d, {});
  const EquilibriumSolver solver(BuildEquilibrium(d.topology.structure));
  const int groups = *std::max_element(problem.group_of().begin(), problem.group_of().end()) + 1;
  REQUIRE(problem.num_variables() > groups);
  for (int v = groups; v < problem.num_variables(); ++v) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(problem.num_variables());
    x[v] = 1;
    const Eigen::VectorXd forces = solver.SelfStresses() * problem.Alpha(x);
    const double largest = forces.cwiseAbs().maxCoeff();
    REQUIRE(largest > 0);
    std::vector<double> first(groups, std::nan(""));
    for (int j = 0; j < forces.size(); ++j) {
      double& f = first[problem.group_of()[j]];
      if (std::isnan(f)) f = forces[j];
      INFO("variable " << v << ", member " << j);
      CHECK(std::abs(forces[j] - f) <= 1e-9 * largest);
    }
  }
}

TEST_CASE("the sizing's mirror images share an area, and its stations are the load cases'",
          "[design]") {
  const Design d = SmallDesign();
  const SizingProblem problem(d, {});
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars();
  // Every member's mirror image about mid-span (found here by coordinates) is in its group.
  const double span = d.config.bridge.span;
  for (int j = 0; j < nb + s.num_strings(); ++j) {
    const Member& m = s.MemberAt(j);
    const double xi = span - s.nodes(0, m.i), xj = span - s.nodes(0, m.j);
    for (int k = 0; k < nb + s.num_strings(); ++k) {
      const Member& o = s.MemberAt(k);
      const bool same_ends =
          (std::abs(s.nodes(0, o.i) - xi) < 1e-9 && std::abs(s.nodes(0, o.j) - xj) < 1e-9 &&
           std::abs(s.nodes(1, o.i) - s.nodes(1, m.i)) < 1e-9 &&
           std::abs(s.nodes(1, o.j) - s.nodes(1, m.j)) < 1e-9) ||
          (std::abs(s.nodes(0, o.j) - xi) < 1e-9 && std::abs(s.nodes(0, o.i) - xj) < 1e-9 &&
           std::abs(s.nodes(1, o.j) - s.nodes(1, m.i)) < 1e-9 &&
           std::abs(s.nodes(1, o.i) - s.nodes(1, m.j)) < 1e-9);
      if (same_ends && (k < nb) == (j < nb)) {
        INFO("member " << j << " and its image " << k);
        CHECK(problem.group_of()[j] == problem.group_of()[k]);
      }
    }
  }
  // One combination per case, and one per station of each travelling family.
  size_t expected = 0;
  for (const LoadCase& c : d.cases)
    expected += c.station_load != 0 ? d.actions.station_nodes.size() : 1;
  CHECK(problem.combinations().size() == expected);
}

TEST_CASE("the sizing poses no constant row and its strength rows hold where their margins do",
          "[design]") {
  for (const int planes : {1, 2}) {
    Config config = planes == 1 ? Config{} : ThreeD(1);
    config.bridge.n = planes == 1 ? 6 : 1;  // n = 6: a string that no self-stress reaches
    const Design d = RunDesign(config);
    SizingCorrections corrections;
    corrections.demand_factor.assign(d.bars.size() + d.strings.size(), 1.3);
    const SizingProblem problem(d, corrections);
    const int n = problem.num_variables(), m = problem.num_constraints();
    const Eigen::VectorXd x0 =
        problem.VariablesOf(MemberAreas(d), problem.AlphaOf(d.reference_forces));
    std::vector<double> values(problem.JacobianPattern().size());
    problem.JacobianValues(x0, values.data());
    // A row that no variable moves is a fact of the model, not a constraint: violated, no
    // sizing mends it. Each row reads its own member's area, its stiffness or a self-stress.
    for (int r = 0; r < m; ++r) {
      double largest = 0;
      for (int v = 0; v < n; ++v)
        largest = std::max(largest, std::abs(values[static_cast<size_t>(r) * n + v]));
      const SizingRow& row = problem.rows()[r];
      INFO("planes " << planes << ", row " << r << " (" << SizingRowKindName(row.kind)
                     << ") of member or node " << row.member
                     << (row.combination >= 0
                             ? " in " + problem.combinations()[row.combination].label
                             : ""));
      CHECK(largest > 0);
    }
    // The posed rows and the margins: the same sign on every row, at the start and with the
    // areas scaled by 0.25 to 4, where the two forms differ most.
    const int groups = *std::max_element(problem.group_of().begin(), problem.group_of().end()) + 1;
    int negative = 0, positive = 0;
    for (const double scale : {0.25, 0.5, 1.0, 2.0, 4.0}) {
      Eigen::VectorXd x = x0;
      x.head(groups) *= scale;  // the areas; the prestress as it was
      Eigen::VectorXd posed(m), margin;
      problem.Constraints(x, posed);
      problem.Margins(x, margin);
      if (!posed.allFinite()) continue;  // an unstable point: both NaN
      for (int r = 0; r < m; ++r) {
        INFO("scale " << scale << ", row " << r);
        CHECK((posed[r] >= 0) == (margin[r] >= 0));
        (margin[r] < 0 ? negative : positive)++;
      }
    }
    // Both signs occur, so the agreement is not of rows that all hold.
    CHECK(negative > 0);
    CHECK(positive > 0);
  }
}

TEST_CASE(
    "the sizing's mirror-image rows are one function of the variables and keep the feasible set",
    "[design]") {
  for (const int planes : {1, 2}) {
    // Planar at n = 2 (mirror about mid-span; the payload on the left the image of the right's);
    // 3D at n = 1, whose wind breaks the mirror between the planes but not the one about mid-span.
    // With abutment capacities: a support row's image is the other abutment's.
    const Design d = RunDesign(WithCapacities(planes == 1 ? SmallDesign().config : ThreeD(1)));
    const int nm = static_cast<int>(d.bars.size() + d.strings.size());
    // Corrections that differ between a member and its images, as the moving load's run leaves
    // them.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    SizingCorrections own;
    own.demand_factor.resize(static_cast<size_t>(nm));
    own.taut_margin_n.resize(static_cast<size_t>(nm));
    for (int j = 0; j < nm; ++j) {
      own.demand_factor[static_cast<size_t>(j)] = 1 + 0.5 * u(rng);
      own.taut_margin_n[static_cast<size_t>(j)] = 200 * u(rng);
    }
    const SizingProblem by_member(d, own);
    const SizingProblem merged(d, by_member.ImageCorrections(own));
    const std::vector<int>& first = merged.representatives();
    const int m = merged.num_constraints();
    REQUIRE(by_member.representatives() == first);
    // Areas off the design's by up to 30 % per group (the groups are symmetric), its prestress.
    Eigen::VectorXd x = merged.VariablesOf(MemberAreas(d), merged.AlphaOf(d.reference_forces));
    const int groups = *std::max_element(merged.group_of().begin(), merged.group_of().end()) + 1;
    for (int g = 0; g < groups; ++g) x[g] *= 0.7 + 0.6 * u(rng);
    Eigen::VectorXd g_own, g_merged;
    by_member.Margins(x, g_own);
    merged.Margins(x, g_merged);
    REQUIRE(g_merged.allFinite());
    // The symmetry is found: a planar bridge's rows pair up about mid-span (the members on the
    // axis and the symmetric cases' own images aside), a 3D bridge's likewise (its wind keeps
    // only that mirror).
    int images = 0;
    for (int r = 0; r < m; ++r) images += first[static_cast<size_t>(r)] != r;
    INFO("planes " << planes << ": " << images << " of " << m << " rows are images");
    CHECK(images > 0.4 * m);
    // Each row reads as its orbit's first, to rounding: the loads and the stiffness are mirror
    // images to 1e-15 and one linear solve loses a few digits (1e-9 of the margin, which is O(1)).
    // And the orbit's tightest row with each member's own corrections is the merged row: the
    // feasible set is the same. (A strength row whose force pulls the other way, margin above
    // 1, is tightest with the smallest factor instead; it binds nowhere.)
    std::map<int, double> tightest;
    for (int r = 0; r < m; ++r) {
      const auto [it, added] = tightest.try_emplace(first[static_cast<size_t>(r)], g_own[r]);
      if (!added) it->second = std::min(it->second, g_own[r]);
    }
    for (int r = 0; r < m; ++r) {
      const int f = first[static_cast<size_t>(r)];
      INFO("row " << r << " (" << SizingRowKindName(merged.rows()[r].kind)
                  << "), its orbit's first " << f);
      CHECK(std::abs(g_merged[r] - g_merged[f]) <= 1e-9 * std::max(1.0, std::abs(g_merged[f])));
      if (r == f && g_merged[f] < 1)
        CHECK(std::abs(tightest[f] - g_merged[f]) <= 1e-9 * std::max(1.0, std::abs(g_merged[f])));
    }
    // Their gradients too: a row and its image, posed together, give one Jacobian row (to 1e-9
    // of its largest entry, as the values).
    std::vector<char> keep(static_cast<size_t>(m), 0);
    std::vector<std::pair<int, int>> pairs;
    for (int r = 0; r < m && pairs.size() < 60; r += 7) {
      const int f = first[static_cast<size_t>(r)];
      if (f == r || keep[static_cast<size_t>(f)] || keep[static_cast<size_t>(r)]) continue;
      keep[static_cast<size_t>(f)] = keep[static_cast<size_t>(r)] = 1;
      pairs.emplace_back(f, r);
    }
    REQUIRE(pairs.size() >= 20);
    const SizingProblem posed(d, by_member.ImageCorrections(own), &keep);
    std::vector<int> index(static_cast<size_t>(m), -1);
    for (int r = 0, i = 0; r < m; ++r) {
      if (keep[static_cast<size_t>(r)]) index[static_cast<size_t>(r)] = i++;
    }
    Eigen::MatrixXd jac;
    REQUIRE(posed.DenseJacobian(x, jac));
    for (const auto& [f, r] : pairs) {
      const Eigen::RowVectorXd a = jac.row(index[static_cast<size_t>(f)]),
                               b = jac.row(index[static_cast<size_t>(r)]);
      INFO("rows " << f << " and " << r << " ("
                   << SizingRowKindName(posed.rows()[index[static_cast<size_t>(f)]].kind)
                   << "): " << a << " / " << b);
      CHECK((a - b).cwiseAbs().maxCoeff() <= 1e-9 * std::max(a.cwiseAbs().maxCoeff(), 1e-300));
    }
  }
}

}  // namespace
}  // namespace tbridge
