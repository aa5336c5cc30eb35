// Tables 5 and 6 reproduced from the shipped configs (configs/paper_t5_*.json,
// configs/paper_t6_*.json) with SPEC.md §9's model and measurement.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "app/paper_tables.h"

namespace tbridge {
namespace {

const PaperReproduction& Tables56() {
  static const PaperReproduction r = ReproducePaper(std::string(TBRIDGE_SOURCE_DIR) + "/configs", {5, 6});
  return r;
}

// One test case with sections: ctest runs each test case in its own process, and the 18
// simulations behind these checks should run once.
TEST_CASE("Tables 5 and 6 reproduce within SPEC §9's tolerances", "[paper][table5][table6]") {
  SECTION("Table 5: mean angular frequencies of the perturbed bridges") {
    const auto& rows = Tables56().json.at("table5");
    REQUIRE(rows.size() == 6);
    for (const auto& row : rows) {
      const double omega = row.at("omega_rad_s"), paper = row.at("paper_omega_rad_s");
      const double T = row.at("T_s"), paper_T = row.at("paper_T_s");
      INFO("n = " << row.at("n") << ", delta " << row.at("delta").dump() << ": omega " << omega
                  << " rad/s, paper " << paper);
      // SPEC §9: the paper's "mean omega" of slack-cable bouncing is reproduced to a mean 3.8 %
      // with a +-2 % spread across dt, stabilisation and estimator: 8 % per entry. For n >= 2
      // the bouncing is chaotic: designs that differ by 1e-10 (the exact optimum, Ipopt's
      // interior point on the self-stress or on the full problem) give 67.7, 68.8 and
      // 69.2 rad/s for n = 3, class 3, a further 2 % spread: 10 % there.
      const double tolerance = row.at("n").get<int>() == 1 ? 0.08 : 0.10;
      CHECK(std::abs(omega / paper - 1.0) <= tolerance);
      // The period is the same measurement: its frequency 2 pi / T lies in the same band.
      CHECK(std::abs(paper_T / T - 1.0) <= tolerance);
    }
  }

  SECTION("Table 5, n = 1: periodic motion matches the energy quadrature") {
    // SPEC §9: for n = 1 the motion is periodic; an exact quadrature of the energy gives
    // T = 0.1178 s (omega = 53.34), 6 % above the paper. Printed to 4 digits: tolerance 1e-3
    // relative (half a unit of the last digit is 4e-4, plus the spectral estimate's resolution
    // over a 1 s record with 8.5 periods).
    const auto& row = Tables56().json.at("table5").at(0);
    REQUIRE(row.at("n") == 1);
    CHECK(row.at("T_s").get<double>() == Approx(0.1178).epsilon(1e-3));
  }

  SECTION("Table 6: frequencies under deck-string prestrain") {
    const auto& rows = Tables56().json.at("table6");
    REQUIRE(rows.size() == 18);
    for (const auto& row : rows) {
      const int n = row.at("n");
      const double omega = row.at("omega_rad_s"), paper = row.at("paper_omega_rad_s");
      const bool design_state = row.at("prestrain").is_string();
      INFO("n = " << n << ", delta " << row.at("delta").dump() << ", prestrain "
                  << row.at("prestrain").dump() << ": omega " << omega << " rad/s, paper " << paper);
      if (design_state) {
        // SPEC §9: the p1 column is the design state, identical to Table 5 (and its bound).
        CHECK(std::abs(omega / paper - 1.0) <= (n == 1 ? 0.08 : 0.10));
      } else if (n == 1) {
        // SPEC §9: periodic motion; p = 0.95 and 0.90 reproduce to 0.3 %: 2 %.
        CHECK(std::abs(omega / paper - 1.0) <= 0.02);
      } else {
        // SPEC §9: the paper's n >= 2 values scatter by 5-19 % (its two n = 2 values differ by
        // 1.41x while ours barely depend on the perturbed bars; probably read off its charts):
        // 25 %.
        CHECK(std::abs(omega / paper - 1.0) <= 0.25);
      }
    }
  }

  SECTION("Table 6: prestrain raises every frequency") {
    // A tauter deck chain stiffens the bridge: within each row omega must rise with prestrain
    // (the paper's own trend, and the linearised frequencies of SPEC §9 rise likewise).
    const auto& rows = Tables56().json.at("table6");
    for (size_t r = 0; r + 2 < rows.size(); r += 3) {
      INFO("row starting " << rows[r].dump());
      CHECK(rows[r].at("omega_rad_s").get<double>() < rows[r + 1].at("omega_rad_s").get<double>());
      CHECK(rows[r + 1].at("omega_rad_s").get<double>() < rows[r + 2].at("omega_rad_s").get<double>());
    }
  }

  SECTION("Table 6's design column is Table 5") {
    // SPEC §9: the p1 column is the design state (rest/stretched 0.99967), identical to
    // Table 5: the same n and perturbed bars must give the same frequency, bit for bit (one
    // deterministic run of one resolved config). Rows are read from each table separately.
    const auto& t5 = Tables56().json.at("table5");
    int matched = 0;
    for (const auto& row : Tables56().json.at("table6")) {
      if (!row.at("prestrain").is_string()) continue;
      for (const auto& five : t5) {
        if (five.at("n") != row.at("n") || five.at("delta") != row.at("delta")) continue;
        INFO("n = " << row.at("n") << ", delta " << row.at("delta").dump());
        CHECK(row.at("omega_rad_s").get<double>() == five.at("omega_rad_s").get<double>());
        ++matched;
      }
    }
    CHECK(matched == 6);  // every Table 5 row has its design-state twin in Table 6
  }
}

}  // namespace
}  // namespace tbridge
