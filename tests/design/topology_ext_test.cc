// Planar p >= 2 bridges, the coupled 3D bridge and the tangent-stiffness stability check.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include "core/error.h"
#include "design/cable_pieces.h"
#include "design/design.h"
#include "design/equilibrium.h"
#include "design/stability.h"
#include "design/topology.h"
#include "test_support.h"

namespace tbridge {
namespace {

constexpr double kPi = std::numbers::pi;

Config MultiBarConfig(int n, int p, SolverKind solver = SolverKind::kAuto) {
  Config c = test::PaperConfig(n, solver);
  c.bridge.p = p;
  return c;
}

// The paper's 3D bridge (Sect. 7.3): n = 2, beta = 20 deg, two planes.
Config Bridge3DConfig(SolverKind solver = SolverKind::kAuto) {
  Config c = test::PaperConfig(2, solver);
  c.bridge.beta_deg = 20.0;
  c.bridge.planes = 2;
  return c;
}

// Shortest distance between segments [p0, p1] and [q0, q1] (sampled closest-point search is
// not needed: the classic clamped solution is exact for non-degenerate segments).
double SegmentDistance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                       const Eigen::Vector3d& q0, const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r), c = d1.dot(r), b = d1.dot(d2);
  const double denom = a * e - b * b;
  double s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return (p0 + s * d1 - q0 - t * d2).norm();
}

TEST_CASE("p >= 2 counts follow eq. (2) after merging", "[topology][multibar]") {
  for (int p = 2; p <= 3; ++p) {
    for (int n = 1; n <= 4; ++n) {
      const BridgeTopology t = PlanarSubstructure(n, p, 10.0, 12.0);
      const Structure& s = t.structure;
      const int modules = (1 << n) - 1;
      INFO("p = " << p << ", n = " << n);
      // Exact integer counts: eq. (2) of the paper.
      CHECK(s.num_bars() == p * modules);
      CHECK(s.num_strings() == (p + 1) * modules + (1 << n));
      // Nodes: deck nodes, p vertices per module, two supports (docs/topology.md; eq. (1)
      // does not give the node count, SPEC.md §2).
      CHECK(s.num_nodes() == (p + 1) * modules + 2);
      // Class p: the p bars of a module share its deck node, vertices carry one bar each.
      CHECK(s.TensegrityClass() == p);
      const std::vector<int> bars_at = s.BarsPerNode();
      for (int k = 0; k < modules; ++k) CHECK(bars_at[k] == p);
      CHECK(static_cast<int>(t.deck_nodes.size()) == modules);
    }
  }
  // Large n stays cheap and keeps the counts (n = 12, p = 8: 32760 bars).
  const BridgeTopology big = PlanarSubstructure(12, 8, 10.0, 12.0);
  CHECK(big.structure.num_bars() == 8 * 4095);
  CHECK(big.structure.num_strings() == 9 * 4095 + 4096);
}

TEST_CASE("p >= 2 numbering: deck nodes first in x order, supports last", "[topology][multibar]") {
  const int n = 3, p = 2, modules = 7;
  const BridgeTopology t = PlanarSubstructure(n, p, 10.0, 12.0);
  const Structure& s = t.structure;
  for (int k = 0; k < modules; ++k) {
    // Exact: deck x are dyadic fractions of the span.
    CHECK(s.nodes(0, k) == Approx(1.5 * (k + 1)).epsilon(1e-15));
    CHECK(s.nodes(1, k) == 0.0);
  }
  for (int v = modules; v < s.num_nodes() - 2; ++v) {
    CHECK(s.nodes(1, v) < 0.0);  // every vertex hangs below the deck
    CHECK_FALSE(s.fixed[v]);
  }
  CHECK(s.fixed[s.num_nodes() - 2]);
  CHECK(s.fixed[s.num_nodes() - 1]);
  CHECK(s.nodes(0, s.num_nodes() - 2) == 0.0);
  CHECK(s.nodes(0, s.num_nodes() - 1) == 12.0);
}

TEST_CASE("p >= 2 members meet only at shared nodes", "[topology][multibar]") {
  for (int p = 2; p <= 5; ++p) {
    for (int n = 1; n <= 3; ++n) {
      for (double beta : {5.0, 10.0, 40.0}) {
        const Structure s = PlanarSubstructure(n, p, beta, 12.0).structure;
        std::vector<Member> all = s.bars;
        all.insert(all.end(), s.strings.begin(), s.strings.end());
        double closest = 1e300;
        for (size_t a = 0; a < all.size(); ++a) {
          for (size_t b = a + 1; b < all.size(); ++b) {
            const Member &m = all[a], &o = all[b];
            if (m.i == o.i || m.i == o.j || m.j == o.i || m.j == o.j) continue;
            closest = std::min(closest, SegmentDistance(s.nodes.col(m.i), s.nodes.col(m.j),
                                                        s.nodes.col(o.i), s.nodes.col(o.j)));
          }
        }
        INFO("p = " << p << ", n = " << n << ", beta = " << beta << ": closest " << closest);
        // 1 mm on a 12 m span: far above rounding, far below the smallest member gap here.
        CHECK(closest > 1e-3);
      }
    }
  }
}

TEST_CASE("Cable runs are split at nodes on them and shared pieces merged", "[topology]") {
  Eigen::Matrix3Xd nodes(3, 4);
  nodes << 0, 1, 2, 1, 0, 0, 0, 1, 0, 0, 0, 0;
  // Run 0-2 passes through node 1; run 0-1 repeats a piece; run 1-3 has nothing on it.
  const auto pieces = SplitAndMergeCables(nodes, {{0, 2}, {1, 0}, {3, 1}}, 1e-12);
  const std::vector<std::pair<int, int>> expected{{0, 1}, {1, 2}, {1, 3}};
  CHECK(pieces == expected);
  CHECK_THROWS_AS(SplitAndMergeCables(nodes, {{0, 0}}, 1e-12), ModelError);
}

TEST_CASE("3D bridge: the paper's counts, class 2, loads on both planes", "[topology][3d]") {
  const BridgeTopology t = CoupledBridge3D(2, 20.0, 12.0, 1.5);
  const Structure& s = t.structure;
  // Paper Sect. 7.3: exact integer counts.
  CHECK(s.num_nodes() == 16);
  CHECK(s.num_bars() == 12);
  CHECK(s.num_strings() == 50);
  CHECK(s.TensegrityClass() == 2);
  CHECK_FALSE(s.planar);
  int transverse_bars = 0, transverse_strings = 0;
  for (const Member& m : s.bars) transverse_bars += m.group == MemberGroup::kTransverse;
  for (const Member& m : s.strings) transverse_strings += m.group == MemberGroup::kTransverse;
  CHECK(transverse_bars == 6);
  CHECK(transverse_strings == 30);
  // Class 2 with every bar node meeting exactly one transverse bar: 2 bars at each of the
  // 12 free nodes, none at the 4 supports.
  const std::vector<int> bars_at = s.BarsPerNode();
  for (int v = 0; v < s.num_nodes(); ++v) CHECK(bars_at[v] == (s.fixed[v] ? 0 : 2));
  // Supports: the four end nodes (x = 0 or L), numbered last.
  for (int v = 0; v < 16; ++v) {
    const bool end = s.nodes(0, v) == 0.0 || s.nodes(0, v) == 12.0;
    CHECK(s.fixed[v] == end);
    CHECK(s.fixed[v] == (v >= 12));
  }
  // Deck nodes: the 3 free deck nodes of each plane, first in the numbering.
  REQUIRE(t.deck_nodes.size() == 6);
  for (int i = 0; i < 6; ++i) {
    CHECK(t.deck_nodes[i] == i);
    CHECK(s.nodes(1, i) == 0.0);
    CHECK(s.nodes(2, i) == (i < 3 ? 0.0 : 1.5));
  }
  // Members meet only at shared nodes, except the two diagonals of each X brace, which
  // cross (unjoined) at the centre of their rectangle, as in ordinary cross bracing. A bar
  // never touches a member it does not share a node with (1 mm: as in the planar test).
  for (int b = 0; b < s.num_bars(); ++b) {
    for (const auto* list : {&s.bars, &s.strings}) {
      for (const Member& o : *list) {
        const Member& m = s.bars[b];
        if (&o == &m || m.i == o.i || m.i == o.j || m.j == o.i || m.j == o.j) continue;
        const double gap =
            SegmentDistance(s.nodes.col(m.i), s.nodes.col(m.j), s.nodes.col(o.i), s.nodes.col(o.j));
        INFO("bar " << Structure::Name(m) << " vs " << Structure::Name(o));
        CHECK(gap > 1e-3);
      }
    }
  }
}

TEST_CASE("3D bridge for other n keeps class 2 with rungs at every bar node", "[topology][3d]") {
  for (int n = 1; n <= 4; ++n) {
    const Structure s = CoupledBridge3D(n, 20.0, 12.0, 1.5).structure;
    const int nb = (1 << n) - 1;
    INFO("n = " << n);
    CHECK(s.num_nodes() == 4 * nb + 4);
    CHECK(s.num_bars() == 4 * nb);  // 2 nb in-plane + 2 nb rungs
    CHECK(s.TensegrityClass() == 2);
  }
  CHECK_THROWS_AS(CoupledBridge3D(2, 20.0, 12.0, 0.0), ConfigError);
}

void CheckDesignEquilibrium(const Design& d) {
  const Eigen::VectorXd r =
      EquilibriumResidual(BuildEquilibrium(d.topology.structure), MemberForces(d), d.loads);
  INFO("max residual " << r.cwiseAbs().maxCoeff() << " N, node load " << d.deck.node_load);
  // The acceptance bound: 1e-9 of the largest node load.
  // The forces are magnitudes (a bar's compression, a string's tension), so the residual also
  // holds their signs: a member whose force had the wrong sign would leave it unbalanced.
  CHECK(r.cwiseAbs().maxCoeff() <= 1e-9 * d.deck.node_load);
}

TEST_CASE("p = 2 and p = 3 designs are in equilibrium", "[design][multibar]") {
  for (int p = 2; p <= 3; ++p) {
    for (int n = 1; n <= 3; ++n) {
      const Design d = RunDesign(MultiBarConfig(n, p));
      INFO("p = " << p << ", n = " << n << ": total " << d.mass.total << " kg");
      CheckDesignEquilibrium(d);
      // Free nodes (p + 1)(2^n - 1) give 2 (p + 1)(2^n - 1) rows; members exceed them by one,
      // and the rows are independent: one self-stress, the deck chain, as for p = 1.
      CHECK(d.self_stress_states == 1);
    }
  }
}

TEST_CASE("p = 2, n = 1: bar forces by hand", "[design][multibar][closed-form]") {
  // One module: two bars from the deck node to vertices at xi = 3/8 and 5/8, depth
  // 2 tan(beta/2) (3/8)(5/8) W. Their vertical components carry f: C = f l / (2 depth).
  const Design d = RunDesign(MultiBarConfig(1, 2));
  const double depth = 12.0 * 2.0 * std::tan(5.0 * kPi / 180.0) * (3.0 / 8.0) * (5.0 / 8.0);
  const double length = std::hypot(12.0 / 8.0, depth);
  REQUIRE(d.bars.size() == 2);
  for (const MemberSizing& b : d.bars) {
    CHECK(b.length == Approx(length).epsilon(1e-14));  // geometry, rounding only
    // Relative 1e-9: the forces are unique (one self-stress, in the deck chain), so only
    // the solver's tolerance separates them from the hand value.
    CHECK(b.force == Approx(d.deck.node_load * length / (2.0 * depth)).epsilon(1e-9));
  }
}

TEST_CASE("3D bridge design: equilibrium, prestressed transverse strings", "[design][3d]") {
  const Design d = RunDesign(Bridge3DConfig());
  CheckDesignEquilibrium(d);
  // Sect. 7.3: f = 3701.44 N per deck node, half of the planar n = 2 load on each plane
  // (printed to 6 digits, so 0.5e-2 N absolute).
  CHECK(d.deck.node_load == Approx(3701.44).margin(0.005));
  // 62 members, 36 free DOFs, no mechanism: 26 self-stress states.
  CHECK(d.self_stress_states == 26);
  // Every transverse string is at least at its 5 mm floor, prestressed at sigma_w
  // (relative 1e-8: interior-point distance to an active bound).
  const Structure& s = d.topology.structure;
  for (int k = 0; k < s.num_strings(); ++k) {
    if (s.strings[k].group != MemberGroup::kTransverse) continue;
    INFO(d.strings[k].name);
    CHECK(d.strings[k].radius >= 0.005 * (1 - 1e-8));
    CHECK(d.strings[k].stress == Approx(6.9e7).epsilon(1e-8));
  }
}

TEST_CASE("Ipopt and NLopt agree on p = 2 and the 3D bridge", "[design][solvers][ipopt][nlopt]") {
  for (const auto& [name, a, b] :
       {std::tuple{"p = 2, n = 2", MultiBarConfig(2, 2, SolverKind::kIpopt),
                   MultiBarConfig(2, 2, SolverKind::kNlopt)},
        std::tuple{"3D", Bridge3DConfig(SolverKind::kIpopt), Bridge3DConfig(SolverKind::kNlopt)}}) {
    REQUIRE(test::HaveSolvers(
        {SolverKind::kIpopt, SolverKind::kNlopt}));  // tagged: left out of a build without them
    const Design da = RunDesign(a), db = RunDesign(b);
    INFO(name << ": ipopt " << da.mass.total << " kg, nlopt " << db.mass.total << " kg");
    CHECK(db.solver.solver == SolverKind::kNlopt);
    // The acceptance bound: 1e-6 relative in total mass.
    CHECK(db.mass.total == Approx(da.mass.total).epsilon(1e-6));
  }
}

// A guyed mast: bar from a pin at the origin up to node T = (0, l), two strings from T down
// to pins at (+-a, 0). With bar lengths held, T moves only horizontally (and in z in 3D).
Structure GuyedMast(bool planar, double a, double l) {
  Structure s;
  s.nodes.setZero(3, 4);
  s.nodes.col(1) << 0, l, 0;
  s.nodes.col(2) << a, 0, 0;
  s.nodes.col(3) << -a, 0, 0;
  s.fixed = {true, false, true, true};
  s.bars = {{0, 1, MemberGroup::kVertical}};
  s.strings = {{1, 2, MemberGroup::kSubstructure}, {1, 3, MemberGroup::kSubstructure}};
  s.planar = planar;
  s.Validate();
  return s;
}

TEST_CASE("Stability check: guyed mast against its closed form", "[stability][closed-form]") {
  const double a = 3.0, l = 4.0, len = 5.0, T = 1000.0, k = 2.0e5;
  // Equilibrium at T: the bar carries C = 2 T l / len.
  Eigen::VectorXd forces(3);
  forces << 2 * T * l / len, T, T;
  // Horizontal stiffness: 2 (k a^2/len^2 + T l^2/len^3) from the strings, -C/l from the bar:
  // K = 2 k a^2/len^2 - 2 T a^2/len^3.
  const double expected = 2 * k * a * a / (len * len) - 2 * T * a * a / std::pow(len, 3);
  const StabilityReport planar = CheckStability(GuyedMast(true, a, l), forces, {k, k});
  CHECK(planar.free_dofs == 2);
  CHECK(planar.bar_constraints == 1);
  REQUIRE(planar.reduced_dofs == 1);
  // Relative 1e-12: a 2 x 2 dense computation, rounding only.
  CHECK(planar.min_eigenvalue == Approx(expected).epsilon(1e-12));
  CHECK(planar.positive_definite);
  // Without axial stiffness the prestress alone cannot hold the compressed bar upright.
  const StabilityReport soft = CheckStability(GuyedMast(true, a, l), forces, {0.0, 0.0});
  CHECK(soft.min_eigenvalue == Approx(-2 * T * a * a / std::pow(len, 3)).epsilon(1e-12));
  CHECK_FALSE(soft.positive_definite);
  // In 3D the strings' q = T/len out of plane exactly cancels the bar's -C/l: a zero mode.
  const StabilityReport spatial = CheckStability(GuyedMast(false, a, l), forces, {k, k});
  CHECK(spatial.reduced_dofs == 2);
  CHECK(spatial.non_positive == 1);
  CHECK_FALSE(spatial.positive_definite);
  CHECK_THROWS_AS(CheckStability(GuyedMast(true, a, l), forces, {k}), ModelError);
}

TEST_CASE("The 3D bridge and the p >= 2 bridges are stable", "[stability][3d]") {
  const Design d = RunDesign(Bridge3DConfig());
  const StabilityReport r = CheckStability(d);
  INFO("3D: smallest eigenvalue " << r.min_eigenvalue << " N/m of " << r.reduced_dofs);
  CHECK(r.free_dofs == 36);
  CHECK(r.bar_constraints == 12);
  CHECK(r.positive_definite);
  // Margin: the prestress stiffness q = T/l of a 5 mm transverse string is ~3e3 N/m; the
  // smallest eigenvalue must stand clearly above zero, not at rounding level (~1e-8 N/m).
  CHECK(r.min_eigenvalue > 1e3);
  for (int p = 2; p <= 3; ++p) {
    const StabilityReport rp = CheckStability(RunDesign(MultiBarConfig(2, p)));
    INFO("p = " << p << ": smallest eigenvalue " << rp.min_eigenvalue << " N/m");
    CHECK(rp.positive_definite);
  }
}

TEST_CASE("Stability fails without the prestress floors", "[stability]") {
  // 3D bridge without transverse prestress: the rungs, in compression, buckle the coupling.
  Config c = Bridge3DConfig();
  c.design.transverse_string_min_radius = 0.0;
  const StabilityReport r3 = CheckStability(RunDesign(c));
  INFO("3D, no transverse floor: smallest eigenvalue " << r3.min_eigenvalue << " N/m");
  CHECK_FALSE(r3.positive_definite);
  CHECK(r3.non_positive >= 1);
  // Planar p = 1 without deck strings: each bar is an inverted pendulum on its V.
  Config c1 = test::PaperConfig(2);
  c1.design.deck_string_min_radius = 0.0;
  const StabilityReport r1 = CheckStability(RunDesign(c1));
  INFO("p = 1, no deck floor: smallest eigenvalue " << r1.min_eigenvalue << " N/m");
  CHECK_FALSE(r1.positive_definite);
  // The same p = 1 bridge with its 10 mm deck strings is stable.
  CHECK(CheckStability(RunDesign(test::PaperConfig(2))).positive_definite);
}

TEST_CASE("Sparse stability verdict: guyed mast against its closed form",
          "[stability][closed-form]") {
  const double a = 3.0, l = 4.0, len = 5.0, T = 1000.0, k = 2.0e5;
  Eigen::VectorXd forces(3);
  forces << 2 * T * l / len, T, T;
  // One reduced DOF (the horizontal sway), so its one pivot is the closed-form stiffness
  // 2 k a^2/len^2 - 2 T a^2/len^3 (relative 1e-12: a few operations, rounding only).
  const StabilityVerdict planar = AssessStability(GuyedMast(true, a, l), forces, {k, k}, true);
  CHECK(planar.stable);
  CHECK(planar.reduced_dofs == 1);
  CHECK(planar.min_pivot ==
        Approx(2 * k * a * a / (len * len) - 2 * T * a * a / std::pow(len, 3)).epsilon(1e-12));
  // Scaling every force by c: 2 k a^2/len^2 - c 2 T a^2/len^3 = 0 at c = k len / T = 1000
  // (relative 1e-10: a 1 x 1 generalised eigenproblem, rounding only).
  REQUIRE(planar.critical_load_factor.has_value());
  CHECK(*planar.critical_load_factor == Approx(k * len / T).epsilon(1e-10));
  // No axial stiffness: one negative eigenvalue, -2 T a^2/len^3.
  const StabilityVerdict soft = AssessStability(GuyedMast(true, a, l), forces, {0.0, 0.0}, false);
  CHECK_FALSE(soft.stable);
  CHECK(soft.negative_pivots == 1);
  CHECK(soft.min_pivot == Approx(-2 * T * a * a / std::pow(len, 3)).epsilon(1e-12));
  CHECK_FALSE(soft.critical_load_factor_computed);
  // In 3D the out-of-plane sway has exactly zero stiffness (q = T/len cancels -C/l): a zero
  // pivot, not a negative one.
  const StabilityVerdict spatial = AssessStability(GuyedMast(false, a, l), forces, {k, k}, false);
  CHECK_FALSE(spatial.stable);
  CHECK(spatial.reduced_dofs == 2);
  CHECK(spatial.negative_pivots == 0);
  CHECK(spatial.zero_pivots == 1);
  CHECK_THROWS_AS(AssessStability(GuyedMast(true, a, l), forces, {k}, false), ModelError);
}

TEST_CASE("Sparse LDL^T inertia agrees with the dense eigenvalues", "[stability]") {
  // Sylvester's law of inertia: the negative pivots of any LDL^T of K_r are its negative
  // eigenvalues, counted here by a second algorithm (one dense QR null space for all bars,
  // then a symmetric eigensolver), on stable and unstable designs of every class.
  std::vector<std::pair<std::string, Config>> cases;
  for (int n = 1; n <= 4; ++n)
    cases.push_back({"planar n = " + std::to_string(n), test::PaperConfig(n)});
  cases.push_back({"p = 2", MultiBarConfig(2, 2)});
  cases.push_back({"p = 3", MultiBarConfig(2, 3)});
  cases.push_back({"3D", Bridge3DConfig()});
  Config no_deck = test::PaperConfig(2);
  no_deck.design.deck_string_min_radius = 0.0;
  cases.push_back({"planar n = 2 without deck prestress", no_deck});
  Config no_transverse = Bridge3DConfig();
  no_transverse.design.transverse_string_min_radius = 0.0;
  cases.push_back({"3D without transverse prestress", no_transverse});
  int unstable = 0;
  for (const auto& [label, config] : cases) {
    const Design d = RunDesign(config);
    const StabilityReport dense = CheckStability(d);
    const StabilityVerdict& sparse = d.stability;
    // Negative eigenvalues, with the same 1e-10 relative zero band as the verdict.
    const double band = 1e-10 * dense.eigenvalues.cwiseAbs().maxCoeff();
    const int negative = static_cast<int>((dense.eigenvalues.array() < -band).count());
    INFO(label << ": dense smallest eigenvalue " << dense.min_eigenvalue
               << " N/m, sparse smallest pivot " << sparse.min_pivot << " N/m");
    CHECK(sparse.reduced_dofs == dense.reduced_dofs);
    CHECK(sparse.stable == dense.positive_definite);
    CHECK(sparse.negative_pivots == negative);
    CHECK((sparse.min_pivot < 0) == (dense.min_eigenvalue < 0));
    unstable += !sparse.stable;
  }
  CHECK(unstable == 2);  // the two designs without their prestress floors
}

TEST_CASE("Critical load factor: K_m + c K_g turns singular there and not before", "[stability]") {
  // The factor comes from a generalised eigenproblem; the dense eigenvalues of K_r at scaled
  // member forces (K_g is linear in the forces, K_m does not depend on them) check it.
  for (const Config& config : {test::PaperConfig(2), Bridge3DConfig()}) {
    const Design d = RunDesign(config);
    REQUIRE(d.stability.critical_load_factor_computed);
    REQUIRE(d.stability.critical_load_factor.has_value());
    const double c = *d.stability.critical_load_factor;
    INFO("n = " << config.bridge.n << ", planes " << config.bridge.planes << ": critical factor "
                << c);
    CHECK(c > 1);  // a stable design with positive definite K_m
    std::vector<double> k(d.strings.size());
    for (size_t i = 0; i < k.size(); ++i) k[i] = d.strings[i].stiffness;
    const Eigen::VectorXd forces = MemberForces(d);
    auto smallest = [&](double factor) {
      const StabilityReport r = CheckStability(d.topology.structure, factor * forces, k);
      return r.min_eigenvalue / r.eigenvalues.cwiseAbs().maxCoeff();
    };
    // Singular at c: the smallest eigenvalue vanishes to 1e-9 of the largest (the eigensolvers'
    // rounding, ~1e-13, times the spread of the stiffness). 0.1 % either side it has turned
    // positive and negative, so c is the first root and not a later one.
    CHECK(std::abs(smallest(c)) < 1e-9);
    CHECK(smallest(0.999 * c) > 0);
    CHECK(smallest(1.001 * c) < 0);
  }
}

}  // namespace
}  // namespace tbridge
