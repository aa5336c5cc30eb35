// `tbridge simulate --vtk`: a ParaView time series that parses, has the model's counts and
// holds the run's numbers where its XML says.
#include <catch2/catch.hpp>
#include <cstring>
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
    "record": {"nodes": )"
                      << record_nodes << R"(, "every": 100}}})";
  return path;
}

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A minimal XML nesting check: every element closes in the order it opened (self-closing
// ones close at once). Returns each DataItem's parent element, in document order, or throws
// std::runtime_error at the first mismatch; the prolog <?...?> is skipped.
std::vector<std::string> DataItemParents(const std::string& xml) {
  std::vector<std::string> open, parents;
  for (size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    const size_t end = xml.find('>', at);
    if (end == std::string::npos)
      throw std::runtime_error("unterminated tag at " + std::to_string(at));
    const std::string tag = xml.substr(at + 1, end - at - 1);
    if (tag.empty() || tag[0] == '?') continue;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) {
        throw std::runtime_error("</" + tag.substr(1) + "> closes " +
                                 (open.empty() ? "nothing" : "<" + open.back() + ">"));
      }
      open.pop_back();
      continue;
    }
    const std::string name = tag.substr(0, tag.find_first_of(" \n/"));
    if (name == "DataItem") parents.push_back(open.empty() ? "" : open.back());
    if (tag.back() != '/') open.push_back(name);
  }
  if (!open.empty()) throw std::runtime_error("<" + open.back() + "> never closes");
  return parents;
}

// The byte offsets (Seek) of the DataItems in document order.
std::vector<long long> Seeks(const std::string& xml) {
  std::vector<long long> out;
  const std::regex seek(R"re(Seek="(\d+)")re");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), seek); it != std::sregex_iterator();
       ++it) {
    out.push_back(std::stoll((*it)[1]));
  }
  return out;
}

template <class T>
std::vector<T> ReadAt(const std::string& bin, long long offset, size_t count) {
  std::vector<T> out(count);
  REQUIRE(offset + static_cast<long long>(count * sizeof(T)) <= static_cast<long long>(bin.size()));
  std::memcpy(out.data(), bin.data() + offset, count * sizeof(T));
  return out;
}

TEST_CASE("simulate --vtk writes one XDMF time series: run.xdmf and its data run.bin",
          "[tools][vtk]") {
  const fs::path dir = test::FreshDir("vtk");
  const fs::path config = WriteScenario(dir, "[1, 2]");
  const auto r = test::RunTbridge(dir, "simulate " + test::Quote(config.string()) + " -o " +
                                           test::Quote((dir / "out").string()) + " -q --vtk " +
                                           test::Quote((dir / "vtk").string()));
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::string xml = test::ReadText(dir / "vtk" / "run.xdmf");
  const std::string bin = test::ReadText(dir / "vtk" / "run.bin");
  // One grid per recorded sample: t = 0, 0.001, ..., 0.01.
  REQUIRE(Count(xml, "<Grid Name=\"sample ") == 11);
  CHECK(xml.find("<Time Value=\"0.01\"/>") != std::string::npos);
  CHECK(xml.find("NumberOfElements=\"5\"") != std::string::npos);  // 1 bar + 4 strings
  // XDMF 2's layout (xdmf.org, "XDMF Model and Format"): per grid the topology, the geometry
  // and four attributes, each holding one DataItem, in a properly nested document.
  std::vector<std::string> expected;
  for (int k = 0; k < 11; ++k) {
    for (const char* e :
         {"Topology", "Geometry", "Attribute", "Attribute", "Attribute", "Attribute"})
      expected.push_back(e);
  }
  REQUIRE(DataItemParents(xml) == expected);
  // run.bin holds what the XML says: connectivity and types at its head (5 x 2 + 5 ints), then
  // per sample 4 x 3 points, 4 x 3 displacements, 5 tensions (8 B) and 5 flags (4 B).
  const std::vector<long long> seek = Seeks(xml);
  CHECK(seek[0] == 0);
  CHECK(static_cast<long long>(bin.size()) == 15 * 4 + 11 * (24 * 8 + 5 * 8 + 5 * 4));
  CHECK(ReadAt<int>(bin, 0, 2) == std::vector<int>{0, 1});  // the bar: nodes 1-2, 0-based
  // At t = 0 the bar's nodes sit 0.1 m below the design: displacement y = -0.1 at nodes 1, 2.
  const std::vector<double> u = ReadAt<double>(bin, seek[2], 12);
  // 1e-14 m: the displacement is a position less the design's, a few roundings of numbers of
  // a few metres.
  const std::vector<double> perturbed{0, -0.1, 0, 0, -0.1, 0, 0, 0, 0, 0, 0, 0};
  for (size_t k = 0; k < 12; ++k) CHECK(u[k] == Approx(perturbed[k]).margin(1e-14));
  // Points minus displacements are the same design positions in the last sample as in the first.
  const size_t last = seek.size() - 6;
  const std::vector<double> p0 = ReadAt<double>(bin, seek[1], 12),
                            p1 = ReadAt<double>(bin, seek[last + 1], 12);
  const std::vector<double> u1 = ReadAt<double>(bin, seek[last + 2], 12);
  for (size_t k = 0; k < 12; ++k) CHECK(p1[k] - u1[k] == Approx(p0[k] - u[k]).margin(1e-14));
  // The strings are taut (the flags 0) with a tension of k (s - L0) > 0; the bar's is 0.
  const std::vector<double> tension = ReadAt<double>(bin, seek[last + 4], 5);
  CHECK(tension[0] == 0.0);
  for (size_t k = 1; k < 5; ++k) CHECK(tension[k] > 0);
  CHECK(ReadAt<int>(bin, seek[last + 5], 5) == std::vector<int>{0, 0, 0, 0, 0});
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

TEST_CASE("simulate: the periodic n = 1 run has one period by both estimators",
          "[tools][frequency]") {
  // SPEC §9: the n = 1 motion at delta = 0.1 m is periodic (T = 0.1178 s by an exact
  // quadrature of the energy). The summary's spectral peak and its mean crossing spacing
  // measure that one period independently; 1 % covers the crossings' unequal half-periods of
  // a non-sinusoidal wave averaged over the 8.5 periods of the 1 s record.
  const fs::path dir = test::FreshDir("crossings");
  const auto r = test::RunTbridge(
      dir, "simulate " + test::Quote(TBRIDGE_SOURCE_DIR "/configs/paper_t5_n1.json") + " -o " +
               test::Quote((dir / "out").string()) + " -q");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json summary =
      nlohmann::json::parse(test::ReadText(dir / "out" / "summary.json"));
  const nlohmann::json& frequency = summary.at("frequency");
  REQUIRE(frequency.at("crossings").is_object());
  const double spectral = frequency.at("period_s"),
               crossings = frequency.at("crossings").at("period_s");
  CHECK(crossings == Approx(spectral).epsilon(0.01));
  CHECK(crossings == Approx(0.1178).epsilon(0.01));  // SPEC §9's quadrature, the same 1 %
}

}  // namespace
}  // namespace tbridge
