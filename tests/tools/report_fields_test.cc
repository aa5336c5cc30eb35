// What a checking engineer reads in a design file and in check's output, field by field: each
// member's utilisation is its demand over its resistance, with the rule that compares them;
// the support reactions' envelope is the extremes of the per-case reactions the file lists;
// each run's group figures are its peaks' ratio; mirror members of the symmetric bridge have
// equal areas.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_support.h"

namespace {

using nlohmann::json;
using namespace tbridge::test;  // FreshDir, Quote, ReadText, RunTbridge, Snapshot; fs

// Every member: utilisation = demand / resistance, to 1e-9 relative (two doubles written in
// their shortest exact form and one division: a few ulps), and a rule named where it governs.
void CheckMembers(const json& file) {
  for (const json& m : file["members"]) {
    INFO("member " << m["name"] << " (" << m["mode"] << ")");
    const double u = m["utilisation"].get<double>(), demand = m["demand"].get<double>();
    const double resistance = m["resistance"].get<double>();
    if (resistance > 0) {
      CHECK(demand / resistance == Approx(u).epsilon(1e-9).margin(1e-300));
    } else {
      CHECK(u == 0.0);
    }
    if (u > 0) CHECK_FALSE(m["clause"].get<std::string>().empty());
  }
}

// The envelope's extremes are those of the file's per-case reactions of the ultimate cases.
void CheckEnvelope(const json& file) {
  std::map<std::string, bool> ultimate;
  for (const json& c : file["cases"]) ultimate[c["name"]] = c["limit_state"] == "ultimate";
  const json& supports = file["reaction_envelope"]["supports"];
  REQUIRE(!supports.empty());
  CHECK_THAT(file["reaction_envelope"]["includes"].get<std::string>(),
             Catch::Contains("loads applied at the support node"));
  for (const json& s : supports) {
    const int node = s["node"];
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const json& r : file["reactions"]) {
      const std::string label = r["case"];
      const std::string name = label.substr(0, label.find(" at "));
      if (r["node"] != node || !ultimate.count(name) || !ultimate[name]) continue;
      lo = std::min(lo, r["force"][1].get<double>());
      hi = std::max(hi, r["force"][1].get<double>());
    }
    INFO("support " << node);
    CHECK(s["y"]["min"].get<double>() == lo);
    CHECK(s["y"]["max"].get<double>() == hi);
  }
}

}  // namespace

TEST_CASE(
    "report: demand / resistance = utilisation, the reaction envelope, the group peaks, mirror "
    "areas",
    "[tools]") {
  const fs::path dir = FreshDir("report_fields");
  const fs::path design = dir / "design.json", checked = dir / "checked.json";
  const std::string config = std::string(TBRIDGE_SOURCE_DIR) + "/configs/default.json";
  const auto r = RunTbridge(dir, "design " + Quote(config) + " -q -o " + Quote(design.string()));
  REQUIRE(r.code == 0);
  const json a = json::parse(ReadText(design));
  CheckMembers(a);
  CheckEnvelope(a);
  // The same fields, with the same meanings, in check's output.
  const auto c =
      RunTbridge(dir, "check " + Quote(design.string()) + " -q -o " + Quote(checked.string()));
  REQUIRE(c.code == 0);
  const json b = json::parse(ReadText(checked));
  CheckMembers(b);
  CheckEnvelope(b);
  // check's force is the static check's largest ultimate force, as the design's: the same
  // nonlinear solves of the same bridge (1e-9: the file's reread).
  for (size_t k = 0; k < a["members"].size(); ++k) {
    INFO("member " << a["members"][k]["name"]);
    CHECK(b["members"][k]["force"].get<double>() ==
          Approx(a["members"][k]["force"].get<double>()).epsilon(1e-9));
    CHECK(b["members"][k]["force_min"].get<double>() ==
          Approx(a["members"][k]["force_min"].get<double>()).epsilon(1e-9).margin(1e-6));
  }
  // Each run's group figure is its peaks' ratio; the largest member ratio is beside it.
  for (const json& run : a["dynamic_check"]["runs"]) {
    for (const json& g : run["amplification"]) {
      INFO(run["name"] << " " << g["group"]);
      if (g["static_peak"].get<double>() > 0) {
        CHECK(g["peak_ratio"].get<double>() ==
              Approx(g["dynamic_peak"].get<double>() / g["static_peak"].get<double>())
                  .epsilon(1e-15));
      }
    }
  }
  // Mirror members (x -> span - x) have equal areas: one variable in the sizing (1e-9 relative).
  const double span = a["config"]["bridge"]["span"];
  const json& nodes = a["nodes"];
  auto mirror_of = [&](int v) {
    for (size_t w = 0; w < nodes.size(); ++w) {
      if (std::abs(nodes[w][0].get<double>() - (span - nodes[v][0].get<double>())) < 1e-9 &&
          std::abs(nodes[w][1].get<double>() - nodes[v][1].get<double>()) < 1e-9 &&
          std::abs(nodes[w][2].get<double>() - nodes[v][2].get<double>()) < 1e-9) {
        return static_cast<int>(w) + 1;
      }
    }
    return -1;
  };
  int pairs = 0;
  for (const json& m : a["members"]) {
    const int i = mirror_of(m["nodes"][0].get<int>() - 1),
              j = mirror_of(m["nodes"][1].get<int>() - 1);
    REQUIRE((i > 0 && j > 0));
    for (const json& n : a["members"]) {
      const int p = n["nodes"][0], q = n["nodes"][1];
      if ((p == i && q == j) || (p == j && q == i)) {
        INFO(m["name"] << " ~ " << n["name"]);
        CHECK(n["area"].get<double>() == Approx(m["area"].get<double>()).epsilon(1e-9));
        ++pairs;
      }
    }
  }
  CHECK(pairs == static_cast<int>(a["members"].size()));  // every member has its mirror
}
