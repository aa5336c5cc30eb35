// The sizing of a pin-jointed structure (truss/): its rows' derivatives against central
// differences, its analysis against closed forms, and its designs of the classic 10-bar problems
// against their published optima (the independent check of those designs, with a solver that
// shares nothing with these, is tests/independent/test_product_designs.py).
#include "truss/truss_sizing.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/design_choices.h"
#include "core/error.h"
#include "truss/truss_check.h"
#include "truss/truss_design.h"
#include "truss/truss_report.h"

namespace tbridge {
namespace {

Config Shipped(const std::string& name) {
  return LoadConfig(std::string(TBRIDGE_SOURCE_DIR) + "/configs/" + name + ".json");
}

// The largest difference between the analytic Jacobian and central differences, at the sizing's
// variables v (the group areas, then any self-stress amplitudes), with a central step of `step`
// times each variable. Both are read per relative change of the variable (dg/dv times |v|, as
// the sizing scales them), relative to the row's largest entry (at least 1e-3: a row insensitive
// to every variable reads as 0).
double JacobianError(const TrussModel& m, const Eigen::VectorXd& areas, double step = 1e-5) {
  const std::vector<TrussRow> rows = TrussRows(m);
  Eigen::MatrixXd jac;
  TrussRowValues(m, rows, areas, &jac);
  double worst = 0;
  for (int g = 0; g < m.num_variables(); ++g) {
    // A step of 1e-5 of the variable: the rows' third derivatives are of order 1 / A^3 (and
    // 1 / s^3 in an amplitude s), so the central difference's error is about 1e-10 relative,
    // round-off 1e-16 / 1e-5 times the stiffness matrix's condition.
    const double h = step * std::abs(areas[g]);
    Eigen::VectorXd up = areas, down = areas;
    up[g] += h;
    down[g] -= h;
    const Eigen::VectorXd fd =
        (TrussRowValues(m, rows, up, nullptr) - TrussRowValues(m, rows, down, nullptr)) / (2 * h);
    for (int r = 0; r < jac.rows(); ++r) {
      const double scale =
          std::max((jac.row(r).transpose().cwiseProduct(areas)).cwiseAbs().maxCoeff(), 1e-3);
      worst = std::max(worst, std::abs(fd[r] - jac(r, g)) * std::abs(areas[g]) / scale);
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
    for (StructureGroupConfig& g : c.structure->groups) g.buckling = BucklingRule::kEuler;
    const TrussModel buckling = BuildTrussModel(c);
    CHECK(JacobianError(buckling, Spread(buckling, 2e-3)) < 1e-6);
    // And the nonlinear statics' rows (truss/truss_nonlinear.h), their own derivatives.
    c.structure->analysis = TrussAnalysisKind::kNonlinear;
    const TrussModel nonlinear = BuildTrussModel(c);
    CHECK(JacobianError(nonlinear, Spread(nonlinear, 2e-3)) < 1e-6);
  }
}

TEST_CASE("truss sizing: a prestress's rows and their derivatives in its amplitude", "[truss]") {
  // The prism's one self-stress amplitude moves every force and, through its geometric
  // stiffness, every displacement and frequency: its column of the Jacobian against central
  // differences, with the stress, taut, buckling and displacement rows of the shipped config and
  // a frequency limit added. The stiffness matrix's condition is about 1e7 here (the mechanism
  // held by its geometric stiffness, N0 / L, against the members' E A / L), so a displacement
  // row's round-off is about 1e-9: a step of 1e-3 keeps it at 1e-6 of the derivative and the
  // truncation at about 1e-6 too (measured: 1e-5 reads round-off of 1e-4); tolerance 1e-5.
  Config c = Shipped("motes_prism_design");
  c.structure->limits.min_frequencies_hz = {5.0};
  const TrussModel m = BuildTrussModel(c);
  REQUIRE(m.num_prestress() == 1);
  Eigen::VectorXd v(m.num_variables());
  // Areas about the design's, the amplitude that puts 50 kN in a bar.
  v << Spread(m, 2e-4), 5e4 / m.self_stress.col(0).head(3).cwiseAbs().maxCoeff();
  if (m.self_stress(0, 0) > 0) v[m.num_groups()] = -v[m.num_groups()];  // bars in compression
  CHECK(JacobianError(m, v, 1e-3) < 1e-5);
  c.structure->analysis = TrussAnalysisKind::kNonlinear;
  const TrussModel nonlinear = BuildTrussModel(c);
  CHECK(JacobianError(nonlinear, v, 1e-3) < 1e-5);
  // Without the prestress the prism is a mechanism on its pinned base: the analysis says so.
  v[m.num_groups()] = 0;
  CHECK_THROWS_AS(TrussRowValues(m, TrussRows(m), v, nullptr), ModelError);
}

TEST_CASE("truss sizing: the mass attribution adds up to the mass", "[truss]") {
  // At a proved optimum (stationarity <= 1e-6 of the mass gradient) the multipliers' terms add
  // up to the mass to about that: 1e-5 of it leaves room for the terms' sum over a few dozen
  // rows. The displacement problem is displacement-governed, the prism's prestress too.
  for (const char* name :
       {"truss_10bar_stress", "truss_10bar_displacement", "motes_prism_design"}) {
    INFO(name);
    const TrussDesign d = DesignTruss(Shipped(name));
    REQUIRE(d.sizing.kkt.proved_local_optimum);
    const TrussMassAttribution& a = d.sizing.attribution;
    double sum = 0, displacement = 0;
    for (const auto& [kind, kg] : a.by_constraint_kg) {
      sum += kg;
      if (kind == "displacement") displacement = kg;
    }
    CHECK(a.structure_kg == Approx(d.model.Mass(d.sizing.group_areas)).epsilon(1e-12));
    CHECK(sum == Approx(a.structure_kg).epsilon(1e-5));
    if (std::string(name) != "truss_10bar_stress") CHECK(displacement > 0.5 * a.structure_kg);
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
  // It has no self-stress: a variable prestress is refused, naming the key.
  nlohmann::json prestressed = j;
  prestressed["structure"]["prestress"] = "variable";
  try {
    BuildTrussModel(ParseConfig(prestressed));
    FAIL("a determinate truss took a variable prestress");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(),
               Catch::Contains("structure.prestress") && Catch::Contains("no self-stress state"));
  }
}

TEST_CASE("truss check: a design file's prestress is held to be a self-stress", "[truss]") {
  const TrussDesign d = DesignTruss(Shipped("motes_prism_design"));
  std::ostringstream os;
  WriteTrussDesignJson(d, os);
  nlohmann::json file = nlohmann::json::parse(os.str());
  // Read back as written, the same check: the prestress and the forces to round-off of 17 digits.
  const TrussDesign again = CheckTrussDesignFile(file);
  CHECK(again.check.pass);
  CHECK((again.check.prestress - d.check.prestress).cwiseAbs().maxCoeff() <=
        1e-12 * d.check.prestress.cwiseAbs().maxCoeff());
  // One string's prestress edited alone leaves its nodes unbalanced: refused, naming the key and
  // a node.
  file["members"][9]["prestress_n"] = file["members"][9]["prestress_n"].get<double>() * 1.01;
  try {
    CheckTrussDesignFile(file);
    FAIL("an unbalanced prestress was checked");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(),
               Catch::Contains("members[].prestress_n") && Catch::Contains("unbalanced at node"));
  }
  // Every member's prestress scaled alike stays a self-stress: checked, and the lower prestress
  // loosens the mechanism past its displacement limit (the design's governing row).
  file = nlohmann::json::parse(os.str());
  for (nlohmann::json& member : file["members"])
    member["prestress_n"] = member["prestress_n"].get<double>() * 0.5;
  const TrussDesign loosened = CheckTrussDesignFile(file);
  CHECK_FALSE(loosened.check.pass);
  CHECK_THAT(loosened.check.governing, Catch::Contains("displacement"));
}

TEST_CASE("truss check: a design file naming no solver tbridge has is refused, naming the key",
          "[truss]") {
  const TrussDesign d = DesignTruss(Shipped("motes_prism_design"));
  std::ostringstream os;
  WriteTrussDesignJson(d, os);
  nlohmann::json file = nlohmann::json::parse(os.str());
  // As written, the solver that ran is one of the names the reader knows.
  REQUIRE(ValueIn(kSolverNames, file["solver"]["name"].get<std::string>()));
  for (const nlohmann::json& name : {nlohmann::json("abaqus"), nlohmann::json(7)}) {
    file["solver"]["name"] = name;
    try {
      CheckTrussDesignFile(file);
      FAIL("a solver named " << name.dump() << " was read");
    } catch (const ConfigError& e) {
      CHECK_THAT(e.what(), Catch::Contains("solver.name") && Catch::Contains("ipopt"));
    }
  }
  file["solver"].erase("name");
  CHECK_THROWS_WITH(CheckTrussDesignFile(file),
                    Catch::Contains("solver.name") && Catch::Contains("(missing)"));
}

// `file` read by CheckTrussDesignFile: "" where it is read, else the ConfigError's text; any
// other exception (a JSON library's type error) fails the test.
std::string RefusalOf(const nlohmann::json& file) {
  try {
    CheckTrussDesignFile(file);
    return "";
  } catch (const ConfigError& e) {
    return e.what();
  }
}

TEST_CASE("truss check: every record of a design file of another type, or missing, is named",
          "[truss]") {
  const TrussDesign d = DesignTruss(Shipped("truss_10bar_stress"));
  std::ostringstream os;
  WriteTrussDesignJson(d, os);
  const nlohmann::json written = nlohmann::json::parse(os.str());
  REQUIRE(RefusalOf(written).empty());
  // Each leaf of the solver's record and of the mass attribution given an object, which no
  // writer writes there: refused, naming the key by its path.
  std::vector<std::string> leaves;
  for (const char* section : {"/solver", "/solver/kkt", "/mass_attribution"}) {
    for (const auto& [key, value] : written.at(nlohmann::json::json_pointer(section)).items()) {
      if (!value.is_object()) leaves.push_back(std::string(section) + "/" + key);
    }
  }
  REQUIRE(leaves.size() >= 15);  // name, status, ..., the certificate's eleven, the attribution's
  for (const std::string& pointer : leaves) {
    nlohmann::json file = written;
    file[nlohmann::json::json_pointer(pointer)] = nlohmann::json::object();
    std::string path = pointer.substr(1);
    std::replace(path.begin(), path.end(), '/', '.');
    INFO(pointer);
    CHECK_THAT(RefusalOf(file), Catch::Contains(path));
  }
  // Each top-level key the reader needs taken away: refused, naming it.
  for (const char* key : {"kind", "config", "members", "groups", "solver"}) {
    nlohmann::json file = written;
    file.erase(key);
    INFO(key);
    CHECK_THAT(RefusalOf(file), Catch::Contains(key) && Catch::Contains("missing"));
  }
  // A null where a number of the certificate stands is the NaN the writer wrote there.
  nlohmann::json nan = written;
  nan["solver"]["kkt"]["stationarity"] = nullptr;
  CHECK(RefusalOf(nan).empty());
}

}  // namespace
}  // namespace tbridge
