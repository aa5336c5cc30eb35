// Independent checks of the minimum-mass design: closed forms, equilibrium, the Euler formula
// and a second solver.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

#include "core/error.h"
#include "design/design.h"
#include "design/equilibrium.h"
#include "test_support.h"

namespace tbridge {
namespace {

constexpr double kPi = std::numbers::pi;

TEST_CASE("Equilibrium residual is below 1e-9 of the largest load", "[design][equilibrium]") {
  for (int n = 1; n <= 8; ++n) {
    const Design d = RunDesign(test::PaperConfig(n));
    const Eigen::VectorXd r =
        EquilibriumResidual(BuildEquilibrium(d.topology.structure), MemberForces(d), d.loads);
    INFO("n = " << n << ": max residual " << r.cwiseAbs().maxCoeff() << " N");
    // The acceptance bound: 1e-9 of the largest node load.
    CHECK(r.cwiseAbs().maxCoeff() <= 1e-9 * d.deck.node_load);
  }
}

TEST_CASE("Support reactions carry what the deck nodes do not", "[design][equilibrium]") {
  const Design d = RunDesign(test::PaperConfig(3));
  const Eigen::Matrix3Xd R = SupportReactions(d.topology.structure, MemberForces(d), d.loads);
  // Total vertical reaction = applied load; horizontal reactions cancel (symmetric bridge).
  // Tolerance 1e-9 relative: the solution satisfies equilibrium to solver precision.
  const double applied = -d.loads.row(1).sum();
  CHECK(R.row(1).sum() == Approx(applied).epsilon(1e-9));
  CHECK(std::abs(R.row(0).sum()) <= 1e-9 * applied);
  // SPEC §3: the supports take F_tot minus what the 2^n - 1 deck nodes carry.
  CHECK(applied + d.deck.station_load == Approx(d.deck.total_load).epsilon(1e-12));
}

TEST_CASE("The design's reactions balance the applied loads", "[design][equilibrium]") {
  // The product's reactions (Design::reactions, in the JSON and the summary) against global
  // equilibrium: forces and moments about the origin sum to zero with the applied loads, to
  // 1e-9 of the total load (the solution satisfies node equilibrium to ~1e-12 relative).
  for (const Config& config : {test::PaperConfig(3), test::PaperConfig(7)}) {
    const Design d = RunDesign(config);
    const Structure& s = d.topology.structure;
    const double total = d.loads.cwiseAbs().sum();
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    for (int v = 0; v < s.num_nodes(); ++v) {
      const Eigen::Vector3d f = d.loads.col(v) + d.reactions.col(v);
      if (!s.fixed[v]) CHECK(d.reactions.col(v).isZero(0.0));
      force += f;
      moment += s.nodes.col(v).cross(f);
    }
    INFO("n = " << config.bridge.n << ": net force " << force.transpose() << " N, net moment "
                << moment.transpose());
    CHECK(force.norm() <= 1e-9 * total);
    CHECK(moment.norm() <= 1e-9 * total * config.bridge.span);
    // A symmetric bridge: each support carries half of what the 2^n - 1 loaded deck nodes do.
    const double half = 0.5 * ((1 << config.bridge.n) - 1) * d.deck.node_load;
    for (int v = 0; v < s.num_nodes(); ++v) {
      if (s.fixed[v]) CHECK(d.reactions(1, v) == Approx(half).epsilon(1e-9));
    }
  }
}

TEST_CASE("Closed forms: V string of n = 1 and bar forces 2^v2(k) f", "[design][closed-form]") {
  const Design d1 = RunDesign(test::PaperConfig(1));
  const double f1 = d1.deck.node_load;
  const double beta = 10.0 * kPi / 180.0;
  // The V string carries f / (2 sin(beta/2)); relative 1e-9 = solver tolerance headroom.
  for (const char* name : {"2-3", "2-4"}) {
    CHECK(FindMember(d1, name)->force == Approx(f1 / (2 * std::sin(beta / 2))).epsilon(1e-9));
  }
  for (int n = 1; n <= 6; ++n) {
    const Design d = RunDesign(test::PaperConfig(n));
    for (int k = 1; k <= d.topology.structure.num_bars(); ++k) {
      const int v2_power = k & -k;  // 2^v2(k)
      INFO("n = " << n << ", bar " << k);
      CHECK(d.bars[k - 1].force == Approx(v2_power * d.deck.node_load).epsilon(1e-9));
    }
  }
}

TEST_CASE("Exactly one self-stress for p = 1: the deck-string chain", "[design][equilibrium]") {
  for (int n = 1; n <= 4; ++n) {
    const Design d = RunDesign(test::PaperConfig(n));
    CHECK(d.self_stress_states == 1);
    // Minimum mass leaves the chain at its prestress floor: every deck string at sigma_w on
    // the minimum radius (relative 1e-8: interior-point distance to an active bound).
    for (const MemberSizing& s : d.strings) {
      if (s.kind != MemberKind::kDeckString) continue;
      CHECK(s.radius == Approx(0.01).epsilon(1e-8));
      CHECK(s.stress == Approx(6.9e7).epsilon(1e-8));
    }
  }
}

TEST_CASE("Ipopt and NLopt agree on the total mass", "[design][solvers][ipopt][nlopt]") {
  REQUIRE(test::HaveSolvers(
      {SolverKind::kIpopt, SolverKind::kNlopt}));  // tagged: left out of a build without them
  for (int n = 1; n <= 5; ++n) {
    const Design a = RunDesign(test::PaperConfig(n, SolverKind::kIpopt));
    const Design b = RunDesign(test::PaperConfig(n, SolverKind::kNlopt));
    INFO("n = " << n << ": ipopt " << a.mass.total << " kg, nlopt " << b.mass.total << " kg ("
                << b.solver.status << ")");
    CHECK(a.solver.solver == SolverKind::kIpopt);
    CHECK(b.solver.solver == SolverKind::kNlopt);
    // The acceptance bound: 1e-6 relative in total mass.
    CHECK(b.mass.total == Approx(a.mass.total).epsilon(1e-6));
    CHECK(b.mass.bars + b.mass.strings == Approx(a.mass.bars + a.mass.strings).epsilon(1e-6));
  }
}

TEST_CASE("Designs may run on several threads at once", "[design][solvers][ipopt][nlopt]") {
  // Ipopt's sequential MUMPS keeps global state; unserialised concurrent solves crash it.
  // Every thread must get the single-threaded answer, bit for bit (same start, same solver).
  REQUIRE(test::HaveSolvers(
      {SolverKind::kIpopt, SolverKind::kNlopt}));  // tagged: left out of a build without them
  const double expected = RunDesign(test::PaperConfig(4, SolverKind::kIpopt)).mass.total;
  std::vector<double> masses(4, 0.0);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < masses.size(); ++t) {
    threads.emplace_back([&masses, t] {
      masses[t] = RunDesign(test::PaperConfig(4, t % 2 ? SolverKind::kNlopt : SolverKind::kIpopt))
                      .mass.total;
    });
  }
  for (std::thread& th : threads) th.join();
  for (size_t t = 0; t < masses.size(); t += 2) CHECK(masses[t] == expected);
  // NLopt threads: the solvers' agreement bound, 1e-6 relative.
  for (size_t t = 1; t < masses.size(); t += 2) CHECK(masses[t] == Approx(expected).epsilon(1e-6));
}

TEST_CASE("Buckling governs a long, lightly loaded, steep bridge", "[design][buckling]") {
  // 60 m span, 200 N payload, beta = 40 deg, no deck self-weight: the n = 1 bar is 10.9 m
  // long under a light load, where Euler needs far more area than yield.
  Config c = test::PaperConfig(1);
  c.bridge.span = 60.0;
  c.bridge.payload = 200.0;
  c.bridge.beta_deg = 40.0;
  c.design.gravity = 0.0;
  const Design d = RunDesign(c);
  const MemberSizing& bar = d.bars.at(0);
  REQUIRE(bar.governed_by == LimitMode::kBuckling);
  // By hand: bar length (L/2) tan(beta/2) = 30 tan(20 deg); it carries the whole node load.
  const double l = 30.0 * std::tan(20.0 * kPi / 180.0);
  const double C = d.deck.node_load;
  CHECK(bar.length == Approx(l).epsilon(1e-12));
  CHECK(bar.force == Approx(C).epsilon(1e-9));
  // Euler, pinned-pinned: P_cr = pi^2 E I / l^2 with I = pi r^4 / 4 equals the force.
  const double E = 2.06e11;
  const double I = kPi * std::pow(bar.radius, 4) / 4.0;
  CHECK(kPi * kPi * E * I / (l * l) == Approx(C).epsilon(1e-9));
  // and the yield area would have been smaller.
  CHECK(C / 6.9e7 < bar.area);
  // A buckling safety factor of 4 doubles the radius' square: A ~ sqrt(SF).
  c.design.buckling_safety_factor = 4.0;
  const Design d4 = RunDesign(c);
  CHECK(d4.bars.at(0).area == Approx(2.0 * bar.area).epsilon(1e-8));
}

TEST_CASE("A solver that cannot finish is a clear error, never a silent answer",
          "[design][errors]") {
  Config c = test::PaperConfig(3);
  c.design.max_iterations = 1;
  for (const SolverKind kind : {SolverKind::kIpopt, SolverKind::kNlopt}) {
    const char* solver = NameOf(kind);
    if (!test::HaveSolvers({kind})) {
      WARN("skipped for " << solver << ": not built in (its TBRIDGE_WITH_ option is off)");
      continue;
    }
    c.design.solver = kind;
    INFO(solver);
    try {
      RunDesign(c);
      FAIL("expected a ModelError");
    } catch (const ModelError& e) {
      const std::string what = e.what();
      CHECK(what.find("status") != std::string::npos);
      CHECK(what.find(solver) != std::string::npos);
    }
  }
}

}  // namespace
}  // namespace tbridge
