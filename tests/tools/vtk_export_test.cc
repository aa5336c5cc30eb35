// `tbridge simulate --vtk`: a ParaView time series that parses and has the model's counts.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_support.h"

namespace tbridge {
namespace {

namespace fs = std::filesystem;

// The paper's n = 1 bridge (4 nodes, 1 bar, 4 strings), perturbed, 0.01 s recorded every
// 1e-3 s: 11 samples.
fs::path WriteScenario(const fs::path& dir, const std::string& record_nodes) {
  const fs::path path = dir / "n1.json";
  std::ofstream(path) << R"({"bridge": {"n": 1}, "dynamics": {"duration": 0.01, "dt": 1e-5,
    "perturbation": {"bar_class": 1, "delta": 0.1},
    "record": {"nodes": )" << record_nodes << R"(, "every": 100}}})";
  return path;
}

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A minimal XML nesting check: every element closes in the order it opened (self-closing
// ones close at once). Returns each DataArray's parent element, in document order, or
// throws std::runtime_error at the first mismatch; the prolog <?...?> is skipped.
std::vector<std::string> DataArrayParents(const std::string& xml) {
  std::vector<std::string> open, parents;
  for (size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    const size_t end = xml.find('>', at);
    if (end == std::string::npos) throw std::runtime_error("unterminated tag at " + std::to_string(at));
    const std::string tag = xml.substr(at + 1, end - at - 1);
    if (tag.empty() || tag[0] == '?') continue;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) {
        throw std::runtime_error("</" + tag.substr(1) + "> closes " + (open.empty() ? "nothing" : "<" + open.back() + ">"));
      }
      open.pop_back();
      continue;
    }
    const std::string name = tag.substr(0, tag.find_first_of(" \n/"));
    if (name == "DataArray") parents.push_back(open.empty() ? "" : open.back());
    if (tag.back() != '/') open.push_back(name);
  }
  if (!open.empty()) throw std::runtime_error("<" + open.back() + "> never closes");
  return parents;
}

TEST_CASE("simulate --vtk writes a .pvd series of .vtp files", "[tools][vtk]") {
  const fs::path dir = test::FreshDir("vtk");
  const fs::path config = WriteScenario(dir, "[1, 2]");
  const auto r = test::RunTbridge(dir, "simulate " + test::Quote(config.string()) + " -o " +
                                           test::Quote((dir / "out").string()) + " -q --vtk " +
                                           test::Quote((dir / "vtk").string()));
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::string pvd = test::ReadText(dir / "vtk" / "run.pvd");
  // One data set per recorded sample: t = 0, 0.001, ..., 0.01.
  REQUIRE(Count(pvd, "<DataSet ") == 11);
  CHECK(pvd.find("timestep=\"0.01\"") != std::string::npos);
  const std::string piece = test::ReadText(dir / "vtk" / "run_10.vtp");
  CHECK(piece.find("NumberOfPoints=\"4\"") != std::string::npos);
  CHECK(piece.find("NumberOfLines=\"5\"") != std::string::npos);  // 1 bar + 4 strings
  // VTK's PolyData layout (vtk.org file formats): the points, one point array, the lines'
  // connectivity and offsets, three cell arrays (type, tension, slack), each inside its own
  // element of a properly nested document.
  const std::vector<std::string> expected{"Points", "PointData", "Lines", "Lines", "CellData", "CellData", "CellData"};
  CHECK(DataArrayParents(piece) == expected);
  // At t = 0 the bar's nodes sit 0.1 m below the design: displacement y = -0.1 at nodes 1, 2.
  const std::string first = test::ReadText(dir / "vtk" / "run_0.vtp");
  const std::regex displacement(R"(Name="displacement"[^>]*>\n0 -0.1 0\n0 -0.1 0\n0 0 0\n0 0 0\n)");
  CHECK(std::regex_search(first, displacement));
}

TEST_CASE("simulate --vtk without every free node recorded is refused, nothing written",
          "[tools][vtk]") {
  const fs::path dir = test::FreshDir("vtk_bad");
  const fs::path config = WriteScenario(dir, "[1]");
  const auto r = test::RunTbridge(dir, "simulate " + test::Quote(config.string()) + " -o " +
                                           test::Quote((dir / "out").string()) + " --vtk " +
                                           test::Quote((dir / "vtk").string()));
  CHECK(r.code == 2);
  CHECK(r.err.find("dynamics.record.nodes") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "out" / "summary.json"));
  CHECK_FALSE(fs::exists(dir / "vtk"));
}

TEST_CASE("simulate: the periodic n = 1 run has one period by both estimators", "[tools][frequency]") {
  // SPEC §9: the n = 1 motion at delta = 0.1 m is periodic (T = 0.1178 s by an exact
  // quadrature of the energy). The summary's spectral peak and its mean crossing spacing
  // measure that one period independently; 1 % covers the crossings' unequal half-periods of
  // a non-sinusoidal wave averaged over the 8.5 periods of the 1 s record.
  const fs::path dir = test::FreshDir("crossings");
  const auto r = test::RunTbridge(dir, "simulate " + test::Quote(TBRIDGE_SOURCE_DIR "/configs/paper_t5_n1.json") +
                                           " -o " + test::Quote((dir / "out").string()) + " -q");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json summary = nlohmann::json::parse(test::ReadText(dir / "out" / "summary.json"));
  const nlohmann::json& frequency = summary.at("frequency");
  REQUIRE(frequency.at("crossings").is_object());
  const double spectral = frequency.at("period_s"), crossings = frequency.at("crossings").at("period_s");
  CHECK(crossings == Approx(spectral).epsilon(0.01));
  CHECK(crossings == Approx(0.1178).epsilon(0.01));  // SPEC §9's quadrature, the same 1 %
}

}  // namespace
}  // namespace tbridge
