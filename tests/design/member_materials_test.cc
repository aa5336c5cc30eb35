// The strings' and bars' own materials (material.strings, material.bars) against the
// resistances, masses and stiffnesses worked by hand from EN 1993-1-11 6.3.2 and the
// definitions: a cable's F_Rd = min(k_e f_uk / 1.5, f_k) A / gamma_R.

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/config.h"
#include "core/error.h"
#include "core/json_reader.h"
#include "design/design.h"
#include "io/design_report.h"

namespace tbridge {
namespace {

// The paper's n = 1 bridge (its switches: one case, no self-weight, the Euler load) with
// strings of spiral strand and bars of their own steel.
Config CableConfig() {
  Config c = LoadConfig(TBRIDGE_SOURCE_DIR "/configs/paper_n1.json");
  c.material.strings.density = 8000.0;
  c.material.strings.youngs_modulus = 1.5e11;
  c.material.strings.yield_stress = 1.2e9;     // f_k
  c.material.strings.breaking_stress = 1.5e9;  // f_uk
  c.material.strings.end_efficiency = 0.9;     // k_e
  c.material.strings.partial_factor = 0.9;     // gamma_R
  c.material.bars.density = 7000.0;
  return c;
}

// By hand: k_e f_uk / 1.5 = 0.9e9 < f_k = 1.2e9, over gamma_R = 0.9: 1e9 Pa.
constexpr double kCableStressPa = 1e9;

TEST_CASE("cable strings are sized, weighed and stiffened as the hand calculation says",
          "[design][material]") {
  const Config c = CableConfig();
  REQUIRE(StringMaterial(c).DesignStress() == Approx(kCableStressPa).epsilon(1e-15));
  const Design d = RunDesign(c);
  int yielding = 0;
  for (const MemberSizing& m : d.strings) {
    INFO("string " << m.name);
    // 1e-12: the sizer divides once and the design writes what it computed; only rounding.
    if (m.governed_by == LimitMode::kYield) {
      CHECK(m.area == Approx(m.force / kCableStressPa).epsilon(1e-12));
      ++yielding;
    }
    CHECK(m.mass == Approx(8000.0 * m.area * m.length).epsilon(1e-12));
    CHECK(m.rest_length ==
          Approx(m.length / (1 + m.reference_force / m.area / 1.5e11)).epsilon(1e-12));
    CHECK(m.stiffness == Approx(1.5e11 * m.area / m.rest_length).epsilon(1e-12));
  }
  CHECK(yielding > 0);  // the hand calculation was met, not only the floors
  for (const MemberSizing& b : d.bars) {
    INFO("bar " << b.name);
    CHECK(b.mass == Approx(7000.0 * b.area * b.length).epsilon(1e-12));
  }
  // Rods of the section's steel (f_y / 10 with the paper's factor) need 1e9 / 6.9e7 = 14.5
  // times the area for the same force: the design with cables has the lighter strings.
  const Design rods = RunDesign(LoadConfig(TBRIDGE_SOURCE_DIR "/configs/paper_n1.json"));
  CHECK(d.mass.strings < rods.mass.strings / 10);

  std::ostringstream out;
  WriteDesignJson(d, out);
  const nlohmann::json file = nlohmann::json::parse(out.str());
  CHECK(file["materials"]["strings"]["design_stress"].get<double>() ==
        Approx(kCableStressPa).epsilon(1e-15));
  CHECK(file["materials"]["strings"]["tension_clause"] == "EN 1993-1-11 6.3.2");
  CHECK(file["materials"]["bars"]["density"].get<double>() == 7000.0);
}

TEST_CASE("without material.strings and material.bars every member is of material",
          "[design][material]") {
  const Config c = LoadConfig(TBRIDGE_SOURCE_DIR "/configs/paper_n1.json");
  for (const MemberMaterial& m : {StringMaterial(c), BarMaterial(c)}) {
    CHECK(m.density == c.material.density);
    CHECK(m.yield_stress == c.material.yield_stress);
    CHECK(m.youngs_modulus == c.material.youngs_modulus);
    CHECK(m.DesignStress() == c.material.yield_stress / c.design.yield_safety_factor);
    CHECK(!m.cable());
  }
}

TEST_CASE("a cable's keys are checked against each other", "[design][material][config]") {
  auto refusal = [](const nlohmann::json& strings) {
    nlohmann::json j = ReadJsonFile(TBRIDGE_SOURCE_DIR "/configs/paper_n1.json");
    j["material"]["strings"] = strings;
    try {
      ParseConfig(j);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(refusal({{"end_efficiency", 0.9}}).find("material.strings.end_efficiency") !=
        std::string::npos);
  CHECK(refusal({{"breaking_stress", 5e8}}).find("material.strings.breaking_stress") !=
        std::string::npos);
  CHECK(refusal({{"youngs_modulus", 150}}).find("material.strings.youngs_modulus") !=
        std::string::npos);
  CHECK(refusal({{"modulus", 1.5e11}}).find("material.strings.modulus") != std::string::npos);
  CHECK(refusal({{"breaking_stress", 1.5e9}, {"yield_stress", 1.2e9}}) == "accepted");
}

}  // namespace
}  // namespace tbridge
