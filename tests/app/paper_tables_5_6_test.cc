// Tables 5 and 6 reproduced from the shipped configs (configs/paper_t5_*.json,
// configs/paper_t6_*.json) with SPEC.md §9's model and measurement.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "app/paper_tables.h"

namespace tbridge {
namespace {

const PaperReproduction& Tables56() {
  static const PaperReproduction r =
      ReproducePaper(std::string(TBRIDGE_SOURCE_DIR) + "/configs", {5, 6});
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
                  << row.at("prestrain").dump() << ": omega " << omega << " rad/s, paper "
                  << paper);
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
      CHECK(rows[r + 1].at("omega_rad_s").get<double>() <
            rows[r + 2].at("omega_rad_s").get<double>());
    }
  }

  SECTION("The design-state rows of both tables match independent results") {
    // SPEC §9's independent results for the design state, by n and perturbed class (the index
    // of the 0.1 m in delta): for n = 1 the exact quadrature of the energy, T = 0.1178 s; for
    // n >= 2 an independent re-implementation's spectral peaks, printed to 0.1 rad/s. A row
    // that took a prestrained run's frequency (over twice as high) or another class's misses
    // them; only n = 3's classes 2 and 3, 9 % apart, are close enough for one of them to pass
    // in the other's place (67.7 rad/s against 64.0), so a swap fails but a duplicate may not.
    const std::map<std::pair<int, int>, double> independent = {{{1, 0}, 2 * M_PI / 0.1178},
                                                               {{2, 0}, 48.4},
                                                               {{2, 1}, 53.7},
                                                               {{3, 0}, 51.3},
                                                               {{3, 1}, 64.0},
                                                               {{3, 2}, 70.0}};
    std::set<std::pair<int, int>> seen5, seen6;
    for (const char* table : {"table5", "table6"}) {
      for (const auto& row : Tables56().json.at(table)) {
        if (row.contains("prestrain") && !row.at("prestrain").is_string()) continue;
        const int n = row.at("n");
        const std::vector<double> delta = row.at("delta");
        const int cls =
            static_cast<int>(std::max_element(delta.begin(), delta.end()) - delta.begin());
        const double omega = row.at("omega_rad_s"), truth = independent.at({n, cls});
        INFO(table << ", n = " << n << ", class " << cls + 1 << ": omega " << omega
                   << " rad/s, independent " << truth);
        if (n == 1) {
          // Periodic motion: 1e-3 relative, the quadrature printed to 4 digits (4e-4) plus the
          // spectral estimate's resolution over a 1 s record of 8.5 periods.
          CHECK(std::abs(omega / truth - 1.0) <= 1e-3);
        } else {
          // Chaotic bouncing: SPEC §9's spread of +-2 % across dt, stabilisation and estimator
          // for each implementation (4 % between two), plus 2 % for designs that differ by
          // 1e-10 (67.7 to 69.2 rad/s for n = 3, class 3): 6 %.
          CHECK(std::abs(omega / truth - 1.0) <= 0.06);
        }
        (std::string(table) == "table5" ? seen5 : seen6).insert({n, cls});
      }
    }
    CHECK(seen5.size() == independent.size());  // every n and class in each table
    CHECK(seen6.size() == independent.size());
  }
}

}  // namespace
}  // namespace tbridge
