// The sizing of a pin-jointed structure (truss/): its rows' derivatives against central
// differences, its analysis against closed forms, and its designs of the classic 10-bar problems
// against their published optima (the independent check of those designs, with a solver that
// shares nothing with these, is tests/independent/test_product_designs.py).
#include "truss/truss_sizing.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "core/config.h"
#include "core/error.h"
#include "truss/truss_check.h"
#include "truss/truss_design.h"

namespace tbridge {
namespace {

Config Shipped(const std::string& name) {
  return LoadConfig(std::string(TBRIDGE_SOURCE_DIR) + "/configs/" + name + ".json");
}

// The largest difference between the analytic Jacobian and central differences, relative to the
// row's largest analytic entry (at least 1e-3: a row insensitive to every area reads as 0).
double JacobianError(const TrussModel& m, const Eigen::VectorXd& areas) {
  const std::vector<TrussRow> rows = TrussRows(m);
  Eigen::MatrixXd jac;
  TrussRowValues(m, rows, areas, &jac);
  double worst = 0;
  for (int g = 0; g < m.num_groups(); ++g) {
    // A step of 1e-5 of the area: the rows' third derivatives are of order 1 / A^3, so the
    // central difference's error is about 1e-10 relative, round-off 1e-16 / 1e-5.
    const double h = 1e-5 * areas[g];
    Eigen::VectorXd up = areas, down = areas;
    up[g] += h;
    down[g] -= h;
    const Eigen::VectorXd fd =
        (TrussRowValues(m, rows, up, nullptr) - TrussRowValues(m, rows, down, nullptr)) / (2 * h);
    for (int r = 0; r < jac.rows(); ++r) {
      const double scale = std::max(jac.row(r).cwiseAbs().maxCoeff(), 1e-3);
      worst = std::max(worst, std::abs(fd[r] - jac(r, g)) / scale);
    }
  }
  return worst;
}

// Areas of every group, spread so that no two modes or members coincide by symmetry.
Eigen::VectorXd Spread(const TrussModel& m, double base) {
  Eigen::VectorXd a(m.num_groups());
  for (int g = 0; g < m.num_groups(); ++g) a[g] = base * (1.0 + 0.37 * g - 0.029 * g * g);
  return a;
}

TEST_CASE("truss sizing: every row's derivative agrees with central differences", "[truss]") {
  // Stress, displacement and frequency rows of the shipped problems, with self-weight on in one
  // so that the load's own derivative is in the chain. Tolerance 1e-6 of each row's largest
  // entry: the difference's truncation (about 1e-10) and round-off (about 1e-9) leave room.
  for (const char* name :
       {"truss_10bar_stress", "truss_10bar_displacement", "truss_10bar_frequency"}) {
    INFO(name);
    Config c = Shipped(name);
    const TrussModel m = BuildTrussModel(c);
    CHECK(JacobianError(m, Spread(m, 2e-3)) < 1e-6);
    c.design.self_weight = true;
    const TrussModel weighed = BuildTrussModel(c);
    CHECK(JacobianError(weighed, Spread(weighed, 2e-3)) < 1e-6);
    // And with every member's Euler buckling row (TrussModel::EulerLoad, quadratic in the area).
    for (StructureGroupConfig& g : c.structure->groups) g.buckling = "euler";
    const TrussModel buckling = BuildTrussModel(c);
    CHECK(JacobianError(buckling, Spread(buckling, 2e-3)) < 1e-6);
  }
}

TEST_CASE("truss analysis: a statically determinate two-bar truss by hand", "[truss]") {
  // Supports at (0, 0) and (0, 3) m, the free node at (4, 0) m, P down on it. Node equilibrium:
  // N2 (3/5) = P, N1 + N2 (4/5) = 0, so N2 = 5P/3 and N1 = -4P/3 whatever the areas.
  const double p = 1000;
  const nlohmann::json j = nlohmann::json::parse(R"({"structure": {"dim": 2,
      "nodes": [[0, 0, 0], [0, 3, 0], [4, 0, 0]], "pinned": [1, 2],
      "members": [{"nodes": [1, 3], "group": "a"}, {"nodes": [2, 3], "group": "b"}],
      "groups": [{"name": "a", "min_area_m2": 1e-4, "allowed_tension_pa": 1e8, "allowed_compression_pa": 1e8},
                 {"name": "b", "min_area_m2": 1e-4, "allowed_tension_pa": 1e8, "allowed_compression_pa": 1e8}],
      "load_cases": [{"name": "p", "loads": [{"node": 3, "force_n": [0, -1000, 0]}]}]},
      "material": {"youngs_modulus": 2e11, "density": 7850}, "design": {"self_weight": false}})");
  const TrussModel m = BuildTrussModel(ParseConfig(j));
  const TrussCheck check = CheckTruss(m, Eigen::Vector2d(2e-4, 3e-4));
  // Round-off of a 2 x 2 solve: 1e-12 of the forces.
  CHECK(check.cases[0].forces[0] == Approx(-4 * p / 3).epsilon(1e-12));
  CHECK(check.cases[0].forces[1] == Approx(5 * p / 3).epsilon(1e-12));
  // The reactions balance the load: at node 1 (4P/3, 0), at node 2 (-4P/3, P).
  CHECK(check.reactions[0](0, 0) == Approx(4 * p / 3).epsilon(1e-12));
  CHECK(check.reactions[0](1, 1) == Approx(p).epsilon(1e-12));
  CHECK(check.equilibrium_residual < 1e-9 * p);
  // Fully stressed at the optimum of a determinate truss: each area is |N| / sigma.
  const TrussDesign d = DesignTruss(ParseConfig(j));
  CHECK(d.sizing.group_areas[0] == Approx(std::max(4 * p / 3 / 1e8, 1e-4)).epsilon(1e-6));
  CHECK(d.sizing.kkt.proved_local_optimum);
}

}  // namespace
}  // namespace tbridge
