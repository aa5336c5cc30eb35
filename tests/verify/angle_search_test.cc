// bridge.beta_deg "auto": the angle chosen by the verified design's mass, held to designs at
// angles given, and a design file that draws its geometry from the angle chosen.

#include "sizing/angle_search.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "checks/verdict.h"
#include "io/design_reader.h"
#include "io/design_report.h"
#include "sizing/verified_design.h"

namespace tbridge {
namespace {

// The default at n = 3 with comfort off and its abutments held to 400 kN (half the thrust its
// prestress puts on them at 10 deg): the shallow angles fail the capacity or pay for it, so the
// angle matters, and every design is quick (about a second).
Config Held() {
  Config config;
  config.bridge.n = 3;
  config.comfort.check = false;
  config.supports.horizontal_capacity_n = 4e5;
  return config;
}

TEST_CASE("bridge.beta_deg auto chooses an angle no given angle beats", "[verify]") {
  Config config = Held();
  config.bridge.beta_auto = true;
  const Design d = DesignAndVerify(config);
  const AngleSearch& s = d.angle;
  INFO(d.mass.structure << " kg at " << d.config.bridge.beta_deg << " deg; " << s.note);
  REQUIRE(s.done);
  REQUIRE(DesignVerdict(d).pass);
  CHECK(s.chosen_deg == d.config.bridge.beta_deg);
  CHECK(s.chosen_deg >= 10.0);
  CHECK(s.chosen_deg <= 60.0);
  // The scan (every 5 deg from 60 deg down, to where the abutments' thrust rose past their
  // capacity twice) and a golden section to 0.5 deg.
  const bool stopped = s.note.find("not tried") != std::string::npos;
  CHECK(s.trials.size() >= (stopped ? 5u : 11u));
  // The echo says "auto", as the config did; the design file's topology holds the angle.
  CHECK(ToJson(d.config)["bridge"]["beta_deg"] == "auto");
  // Independent of the search: designs with the angle given, at the range's ends, the middle and
  // a degree either side of the angle chosen. None passes lighter by more than 5e-4, the
  // search's tolerance on mass (its bracket of 0.5 deg is below what moves the mass by that
  // much here).
  for (const double beta : {10.0, 35.0, 60.0, s.chosen_deg - 1, s.chosen_deg + 1}) {
    Config given = Held();
    given.bridge.beta_deg = beta;
    const Design other = DesignAndVerify(given);
    INFO("beta = " << beta << " deg: " << other.mass.structure << " kg, "
                   << DesignVerdict(other).summary);
    if (DesignVerdict(other).pass) CHECK(other.mass.structure >= d.mass.structure * (1 - 5e-4));
    // Below where the scan stopped, the angle fails as the rule foretold.
    if (stopped && beta == 10.0) CHECK_FALSE(DesignVerdict(other).pass);
  }
  // The same design as the angle chosen given outright: the search's last step designs it so.
  Config at = Held();
  at.bridge.beta_deg = s.chosen_deg;
  CHECK(DesignAndVerify(at).mass.structure == d.mass.structure);
  // Read back (tbridge check), the geometry is drawn at the angle chosen, not the default 10 deg.
  std::ostringstream file;
  WriteDesignJson(d, file);
  const Design read = ReadDesign(nlohmann::json::parse(file.str()));
  CHECK(read.config.bridge.beta_auto);
  CHECK(read.config.bridge.beta_deg == s.chosen_deg);
  CHECK((read.topology.structure.nodes - d.topology.structure.nodes).cwiseAbs().maxCoeff() <= 1e-9);
}

// The search starts each angle from the nearest passing angle's sizes (SizingStart). Another
// path to the same optimum: from a design 8 deg away, the sizing reaches the fresh design's
// mass at that angle within 5e-4 (the search's own tolerance on mass; both are converged to the
// loop's 5e-4 and proved or polished, so they may differ by the loop's settling), and passes.
TEST_CASE("a verified design started from another angle's sizes meets the fresh one", "[verify]") {
  Config near = Held();
  near.bridge.beta_deg = 38.0;
  const Design from = DesignAndVerify(near);
  REQUIRE(DesignVerdict(from).pass);
  Config at = Held();
  at.bridge.beta_deg = 30.0;
  const Design fresh = DesignAndVerify(at);
  const SizingStart start{MemberAreas(from), PrestressForces(from)};
  const Design warm = DesignAndVerify(at, nullptr, &start);
  INFO("fresh " << fresh.mass.structure << " kg, warm " << warm.mass.structure << " kg, from "
                << from.mass.structure << " kg at 38 deg");
  REQUIRE(DesignVerdict(fresh).pass);
  CHECK(DesignVerdict(warm).pass);
  CHECK(std::abs(warm.mass.structure - fresh.mass.structure) <= 5e-4 * fresh.mass.structure);
  // The start was used: the first sizing began from the other angle's sizes, not the equilibrium
  // design's (the record's first mass is the start's).
  CHECK(warm.resizing.structure_mass_kg.front() != fresh.resizing.structure_mass_kg.front());
  // A start of another bridge (other members) is not used: the design is the fresh one exactly.
  const SizingStart other{std::vector<double>(3, 1e-3), Eigen::VectorXd::Ones(3)};
  CHECK(DesignAndVerify(at, nullptr, &other).mass.structure == fresh.mass.structure);
}

}  // namespace
}  // namespace tbridge
