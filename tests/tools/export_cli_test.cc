// `tbridge export`: the design's bridge in an FE program. The CalculiX deck is run by ccx and
// its deflections, reactions and frequencies compared with tbridge's own; the OpenSees script
// is read back and compared with the design member by member.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cli_support.h"

namespace {

using nlohmann::json;
namespace fs = std::filesystem;
using tbridge::test::FreshDir;
using tbridge::test::Quote;
using tbridge::test::ReadText;
using tbridge::test::RunTbridge;

const std::string kDefaultConfig = std::string(TBRIDGE_SOURCE_DIR) + "/configs/default.json";

// dir/design.json, the design `tbridge design` writes for `config`.
fs::path DesignOf(const fs::path& dir, const std::string& config = kDefaultConfig) {
  const fs::path design = dir / "design.json";
  const int code =
      RunTbridge(dir, "design " + Quote(config) + " -q -o " + Quote(design.string())).code;
  REQUIRE(code == tbridge::test::VerdictExit(design));
  return design;
}

// What ccx printed at the end of each static step: per node (1-based) a vector.
struct CcxStep {
  std::map<int, std::vector<double>> u, rf;
};

// The .dat file's blocks by the total time they print, which is the step's number for a
// static step of period 1; `omega` the eigenvalue table's rad/s column. The blocks after it
// are mode shapes, not steps.
void ReadDat(const std::string& text, std::map<int, CcxStep>& steps, std::vector<double>& omega) {
  std::istringstream in(text);
  std::string line;
  std::map<int, std::vector<double>>* block = nullptr;
  bool eigen = false, modal = false;
  while (std::getline(in, line)) {
    const auto time_at = line.find("and time");
    if (time_at != std::string::npos && modal) block = nullptr;
    if (time_at != std::string::npos && !modal) {
      const int step = static_cast<int>(std::lround(std::stod(line.substr(time_at + 8))));
      block = line.find("displacements") != std::string::npos ? &steps[step].u
              : line.find("forces") != std::string::npos      ? &steps[step].rf
                                                              : nullptr;
      eigen = false;
      continue;
    }
    if (line.find("E I G E N V A L U E   O U T P U T") != std::string::npos) {
      eigen = modal = true;
      block = nullptr;
      continue;
    }
    if (line.find("P A R T I C I P A T I O N") != std::string::npos) eigen = false;
    std::istringstream fields(line);
    int id = 0;
    std::vector<double> v;
    double x = 0;
    if (!(fields >> id)) continue;
    while (fields >> x) v.push_back(x);
    if (eigen && v.size() == 4) omega.push_back(v[1]);
    if (block && v.size() == 3) (*block)[id] = v;
  }
}

// Exports the design of `config` with rigid bars, runs ccx on it in `dir` and compares every
// static step with the design file's deflections and reactions, and the lowest frequencies
// with `tbridge modes`.
void CompareWithCalculix(const fs::path& dir, const std::string& config) {
  const fs::path design_file = DesignOf(dir, config);
  const fs::path deck = dir / "bridge.inp";
  REQUIRE(RunTbridge(dir, "export " + Quote(design_file.string()) +
                              " --format calculix --rigid-bars -o " + Quote(deck.string()))
              .code == 0);
  const std::string ccx = "cd " + Quote(dir.string()) + " && ccx bridge > ccx.log 2>&1";
  INFO("ccx runs the deck (calculix-ccx, tools/setup.sh); its log: " << ReadText(dir / "ccx.log"));
  REQUIRE(std::system(ccx.c_str()) == 0);
  REQUIRE(ReadText(dir / "ccx.log").find("ERROR") == std::string::npos);

  // The static steps in order, as the deck's comments name them, and each one's loads.
  std::vector<std::string> labels;
  std::vector<std::map<int, std::vector<double>>> loads;
  {
    std::istringstream in(ReadText(deck));
    std::string line;
    const std::string mark = "** tbridge step: ";
    bool cload = false;
    while (std::getline(in, line)) {
      if (line.rfind(mark, 0) == 0 && line.substr(mark.size()) != "frequency") {
        labels.push_back(line.substr(mark.size()));
        loads.emplace_back();
      }
      if (line.rfind("*", 0) == 0) cload = line == "*CLOAD";
      if (!cload || line[0] == '*') continue;
      int node = 0, dof = 0;
      double value = 0;
      REQUIRE(std::sscanf(line.c_str(), "%d, %d, %lf", &node, &dof, &value) == 3);
      loads.back().try_emplace(node, 3, 0.0).first->second[dof - 1] = value;
    }
  }
  std::map<int, CcxStep> steps;
  std::vector<double> omega;
  ReadDat(ReadText(dir / "bridge.dat"), steps, omega);
  REQUIRE(steps.size() == labels.size());

  const json design = json::parse(ReadText(design_file));
  std::vector<int> deck_nodes;  // the deck is at y = 0 (core/structure.h)
  for (size_t v = 0; v < design["nodes"].size(); ++v) {
    if (design["nodes"][v][1].get<double>() == 0) deck_nodes.push_back(static_cast<int>(v) + 1);
  }
  std::map<std::string, double> deflection;
  for (const json& c : design["deflection_max"])
    deflection[c["case"]] = c["deflection"].get<double>();
  std::map<std::string, std::vector<json>> reactions;
  for (const json& r : design["reactions"]) reactions[r["case"]].push_back(r);

  const double limit = design["config"]["bridge"]["span"].get<double>() /
                       design["config"]["loads"]["deflection_limit"].get<double>();
  int compared = 0;
  double worst_deflection = 0, worst_reaction = 0;
  for (size_t k = 0; k < labels.size(); ++k) {
    const std::string& label = labels[k];
    const CcxStep& step = steps.at(static_cast<int>(k) + 1);
    if (label == "modes") continue;  // the modal base state; tbridge writes no reactions for it
    INFO("step " << k + 1 << ": " << label);
    double dy = 0;
    for (int v : deck_nodes) dy = std::max(dy, std::abs(step.u.at(v)[1]));
    REQUIRE(reactions.count(label));
    double largest = 0;
    for (const json& r : reactions[label]) {
      for (int a = 0; a < 3; ++a)
        largest = std::max(largest, std::abs(r["force"][a].get<double>()));
    }
    for (const json& r : reactions[label]) {
      const int node = r["node"].get<int>();
      for (int a = 0; a < 3; ++a) {
        // CalculiX's RF is what the members bring to the support; tbridge's reaction also
        // carries the load applied at the support itself (the members' weight lumped there).
        const double applied = loads[k].count(node) ? loads[k].at(node)[a] : 0.0;
        const double error =
            std::abs(step.rf.at(node)[a] - applied - r["force"][a].get<double>()) / largest;
        worst_reaction = std::max(worst_reaction, error);
        // 1e-5 of the case's largest reaction: CalculiX's residual is within 1e-5 of the
        // average force (its Newton steps end near 1e-8), and its rigid bars are 1e6 times
        // E A / l, not rigid.
        CHECK(error < 1e-5);
      }
    }
    if (label == "reference") {
      // The drawn geometry is the reference state's equilibrium: CalculiX moves it by nothing
      // a deflection check could see (1e-5 of the deflection limit).
      CHECK(dy < 1e-5 * limit);
      continue;
    }
    REQUIRE(deflection.count(label));
    ++compared;
    const double error = std::abs(dy - deflection[label]);
    if (deflection[label] > 0)
      worst_deflection = std::max(worst_deflection, error / deflection[label]);
    // 1e-5 of the case's deflection, for the reasons above; a case that does not move the
    // deck (dead load alone, favourable) is compared absolutely, to 1e-5 of a millimetre.
    CHECK(error <= std::max(1e-5 * deflection[label], 1e-8));
  }
  // Every case and station tbridge solved nonlinearly on the bridge as designed was compared (the
  // export is that bridge's; the static check's cases after the prestress loss are another
  // state's, tests/verify/prestress_loss_test.cc).
  int intact = 0;
  for (const json& c : design["deflection_max"])
    intact +=
        c["case"].get<std::string>().find("after the prestress loss") == std::string::npos ? 1 : 0;
  CHECK(intact * 2 == static_cast<int>(design["deflection_max"].size()));
  CHECK(compared == intact);
  WARN("CalculiX against tbridge: deflection " << worst_deflection << ", reactions "
                                               << worst_reaction << " over " << compared
                                               << " cases and stations");

  // The lowest modes against `tbridge modes` of the same config (the same verified bridge).
  const fs::path modes_file = dir / "modes.json";
  REQUIRE(RunTbridge(dir, "modes " + Quote(config) + " -q -o " + Quote(modes_file.string())).code ==
          0);
  const json modes = json::parse(ReadText(modes_file))["modes"];
  REQUIRE(omega.size() >= 5);
  double worst_mode = 0;
  for (size_t m = 0; m < omega.size(); ++m) {
    const double ours = modes[m]["omega_rad_s"].get<double>();
    INFO("mode " << m + 1 << ": CalculiX " << omega[m] << " rad/s, tbridge " << ours);
    worst_mode = std::max(worst_mode, std::abs(omega[m] - ours) / ours);
    // 1e-5: bars 1e6 times stiffer than E A / l stand for rigid ones to about 1e-6 in the
    // frequencies; the .dat prints 7 digits.
    CHECK(std::abs(omega[m] - ours) < 1e-5 * ours);
  }
  WARN("CalculiX against tbridge: " << omega.size() << " lowest frequencies within " << worst_mode);
}

TEST_CASE("export: CalculiX agrees with tbridge on every case, station and the lowest modes",
          "[tools]") {
  CompareWithCalculix(FreshDir("export_calculix"), kDefaultConfig);
}

TEST_CASE("export: CalculiX agrees with tbridge on the 3D bridge of two planes", "[tools]") {
  // The paper's 3D bridge (n = 2) designed with the engineering load cases.
  const fs::path dir = FreshDir("export_calculix_3d");
  json config = json::parse(ReadText(std::string(TBRIDGE_SOURCE_DIR) + "/configs/paper_3d.json"));
  config.erase("loads");
  std::ofstream(dir / "config.json") << config.dump(2);
  CompareWithCalculix(dir, (dir / "config.json").string());
}

}  // namespace

namespace {

// Each `analyze` of an OpenSees script run by tests/tools/opensees_standin.tcl under tclsh: the
// node and element counts, the loads (node, fx, fy, fz), the recorders (file, response) and the
// algorithm.
struct StandinRun {
  int nodes = 0, elements = 0;
  std::vector<double> loads;
  std::vector<std::string> recorders;
  std::string algorithm;
};

std::vector<StandinRun> RunStandin(const fs::path& dir, const fs::path& script) {
  const std::string command =
      "cd " + Quote(dir.string()) + " && tclsh " +
      Quote(std::string(TBRIDGE_SOURCE_DIR) + "/tests/tools/opensees_standin.tcl") + " " +
      Quote(script.string()) + " > standin.out 2> standin.err";
  INFO("stand-in's stderr: " << ReadText(dir / "standin.err"));
  REQUIRE(std::system(command.c_str()) == 0);
  std::vector<StandinRun> out;
  std::istringstream in(ReadText(dir / "standin.out"));
  std::string line;
  while (std::getline(in, line)) {
    // analysis N E {loads} {recorders} ALGORITHM
    const size_t a = line.find('{'), b = line.find('}'), c = line.find('{', b),
                 d = line.find('}', c);
    REQUIRE(line.rfind("analysis ", 0) == 0);
    REQUIRE(d != std::string::npos);
    StandinRun r;
    std::istringstream(line.substr(9, a - 9)) >> r.nodes >> r.elements;
    std::istringstream loads(line.substr(a + 1, b - a - 1)),
        recorders(line.substr(c + 1, d - c - 1));
    for (double x = 0; loads >> x;) r.loads.push_back(x);
    for (std::string w; recorders >> w;) r.recorders.push_back(w);
    std::istringstream(line.substr(d + 1)) >> r.algorithm;
    out.push_back(r);
  }
  return out;
}

TEST_CASE("export: the OpenSees scripts run as they stand, each case with its loads and recorders",
          "[tools]") {
  // OpenSees is not in Debian: a stand-in runs the script under tclsh, checking each command's
  // arguments as OpenSees's parser does, and reports what each analysis was given.
  SECTION("a structure: every case, its factored loads exactly, linear where the design is") {
    const std::pair<const char*, const char*> designs[] = {{"truss_10bar_displacement", "Linear"},
                                                           {"motes_prism_design", "Newton"}};
    for (const auto& [name, algorithm] : designs) {
      INFO(name);
      const fs::path dir = FreshDir(std::string("export_opensees_") + name);
      const fs::path design =
          DesignOf(dir, std::string(TBRIDGE_SOURCE_DIR) + "/configs/" + name + ".json");
      const fs::path script = dir / "structure.tcl";
      REQUIRE(RunTbridge(dir, "export " + Quote(design.string()) + " --format opensees -o " +
                                  Quote(script.string()))
                  .code == 0);
      const std::vector<StandinRun> runs = RunStandin(dir, script);
      const json d = json::parse(ReadText(design));
      const json& cases = d["config"]["structure"]["load_cases"];
      REQUIRE(runs.size() == cases.size());
      for (size_t c = 0; c < cases.size(); ++c) {
        const StandinRun& r = runs[c];
        CHECK(r.nodes == static_cast<int>(d["nodes"].size()));
        CHECK(r.elements == static_cast<int>(d["members"].size()));
        CHECK(r.algorithm == algorithm);
        // The config's loads times the case's factor (no self-weight in these configs), to the
        // 17 digits the script prints.
        std::vector<double> expected;
        for (const json& l : cases[c]["loads"]) {
          expected.push_back(l["node"].get<double>());
          for (int a = 0; a < 3; ++a)
            expected.push_back(cases[c]["factor"].get<double>() * l["force_n"][a].get<double>());
        }
        REQUIRE(r.loads.size() == expected.size());
        for (size_t k = 0; k < expected.size(); ++k)
          CHECK(r.loads[k] == Approx(expected[k]).epsilon(1e-15));
        const std::string tag = "case_" + std::to_string(c + 1);
        CHECK(r.recorders == std::vector<std::string>{tag + ".disp.out", "disp",
                                                      tag + ".reactions.out", "reaction"});
      }
    }
  }
  SECTION("a bridge: the reference state and every case, each from the drawn state") {
    const fs::path dir = FreshDir("export_opensees_runs");
    const fs::path design = DesignOf(dir);
    const fs::path script = dir / "bridge.tcl";
    REQUIRE(RunTbridge(dir, "export " + Quote(design.string()) + " --format opensees -o " +
                                Quote(script.string()))
                .code == 0);
    const std::vector<StandinRun> runs = RunStandin(dir, script);
    const std::string text = ReadText(script);
    size_t cases = 0;
    for (size_t at = text.find("\nproc case_"); at != std::string::npos;
         at = text.find("\nproc case_", at + 1))
      ++cases;
    REQUIRE(cases > 0);
    REQUIRE(runs.size() == cases + 1);
    for (size_t k = 0; k < runs.size(); ++k) {
      CHECK(runs[k].algorithm == "Newton");
      CHECK(!runs[k].loads.empty());
      const std::string tag = k == 0 ? "reference" : "case_" + std::to_string(k);
      CHECK(runs[k].recorders == std::vector<std::string>{tag + ".disp.out", "disp",
                                                          tag + ".reactions.out", "reaction"});
    }
  }
}

TEST_CASE("export: the OpenSees script read back is the design, member by member", "[tools]") {
  const fs::path dir = FreshDir("export_opensees");
  const fs::path design_file = DesignOf(dir);
  const fs::path script = dir / "bridge.tcl";
  REQUIRE(RunTbridge(dir, "export " + Quote(design_file.string()) + " --format opensees -o " +
                              Quote(script.string()))
              .code == 0);
  std::map<int, std::vector<double>> nodes;
  std::map<int, std::vector<double>> elastic;                 // tag -> E, Eneg (absent: E alone)
  std::map<int, std::pair<int, double>> prestrain;            // tag -> wrapped tag, initial strain
  std::map<int, std::tuple<int, int, double, int>> elements;  // i, j, A, material
  std::istringstream in(ReadText(script));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream f(line);
    std::string word, kind;
    f >> word;
    if (word == "node") {
      int id = 0;
      std::vector<double> x(3);
      f >> id >> x[0] >> x[1] >> x[2];
      nodes[id] = x;
    } else if (word == "uniaxialMaterial") {
      int tag = 0;
      f >> kind >> tag;
      if (kind == "Elastic") {
        std::vector<double> v;
        double x = 0;
        while (f >> x) v.push_back(x);
        elastic[tag] = v;
      } else {
        REQUIRE(kind == "InitStrainMaterial");
        f >> prestrain[tag].first >> prestrain[tag].second;
      }
    } else if (word == "element") {
      int id = 0, i = 0, j = 0, mat = 0;
      double area = 0;
      f >> kind >> id >> i >> j >> area >> mat;
      REQUIRE(kind == "corotTruss");
      elements[id] = {i, j, area, mat};
    }
  }
  const json design = json::parse(ReadText(design_file));
  REQUIRE(nodes.size() == design["nodes"].size());
  for (size_t v = 0; v < nodes.size(); ++v) {
    for (int a = 0; a < 3; ++a)
      CHECK(nodes.at(static_cast<int>(v) + 1)[a] == design["nodes"][v][a].get<double>());
  }
  // The script lists the strings first, then the bars; the design file the bars first.
  const json& members = design["members"];
  const int bars = design["topology"]["bars"].get<int>(),
            strings = design["topology"]["strings"].get<int>();
  REQUIRE(static_cast<int>(elements.size()) == bars + strings);
  const double E = design["config"]["material"]["youngs_modulus"].get<double>();
  for (int e = 1; e <= bars + strings; ++e) {
    const bool string = e <= strings;
    const json& m = members[string ? bars + e - 1 : e - strings - 1];
    INFO("element " << e << ", member " << m["name"]);
    const auto& [i, j, area, mat] = elements.at(e);
    CHECK(std::to_string(i) + "-" + std::to_string(j) == m["name"].get<std::string>());
    // Printed with 17 digits: the design's numbers, to their last bit or two.
    CHECK(area == Approx(m["area"].get<double>()).epsilon(1e-15));
    const auto [law, strain] = prestrain.at(mat);
    const std::vector<double>& el = elastic.at(law);
    const double s = m["length"].get<double>();
    if (string) {
      REQUIRE(el.size() == 3);
      CHECK(el[2] == 0.0);  // no compression modulus: a string never pushes
      // Tension E' A (l - s) / s + E' A strain: k = E' A / s, and k s strain is the reference
      // force.
      const double k = el[0] * area / s;
      CHECK(k == Approx(m["stiffness"].get<double>()).epsilon(1e-12));
      // The strain (s - L0) / s loses digits to cancellation, eps s / (s - L0): 1e-12 for a
      // string stretched 1e-4; 1e-10 holds it for strings stretched down to 1e-6.
      CHECK(k * s * strain == Approx(m["reference_force"].get<double>()).epsilon(1e-10));
      // The force is zero at the rest length: the strain there, (L0 - s) / s, cancels the
      // prestrain.
      CHECK((m["rest_length"].get<double>() - s) / s + strain == Approx(0).margin(1e-15));
    } else {
      REQUIRE(el.size() == 1);
      CHECK(el[0] == E);
      // A bar starts at its reference compression.
      CHECK(-el[0] * area * strain == Approx(m["reference_force"].get<double>()).epsilon(1e-12));
    }
  }
}

TEST_CASE("export: a bad format or option is refused with exit 2 and nothing written", "[tools]") {
  const fs::path dir = FreshDir("export_bad");
  const fs::path design_file = DesignOf(dir);
  const fs::path out = dir / "out" / "bridge.inp";
  const auto before = tbridge::test::Snapshot(dir / "out");
  for (const std::string& args :
       {std::string("--format abaqus"), std::string("--format opensees --modes 3"),
        std::string("--format calculix --modes 0")}) {
    INFO(args);
    const auto r = RunTbridge(
        dir, "export " + Quote(design_file.string()) + " " + args + " -o " + Quote(out.string()));
    CHECK(r.code == 2);
    CHECK(r.err.find(args.find("modes") == std::string::npos ? "--format" : "--modes") !=
          std::string::npos);
    CHECK(tbridge::test::Snapshot(dir / "out") == before);
  }
  // A design file that is not self-consistent: the key is named.
  json design = json::parse(ReadText(design_file));
  design["members"][8]["radius"] = design["members"][8]["radius"].get<double>() * 0.99;
  std::ofstream(dir / "edited.json") << design.dump(2);
  const auto r = RunTbridge(dir, "export " + Quote((dir / "edited.json").string()) +
                                     " --format calculix -o " + Quote(out.string()));
  CHECK(r.code == 2);
  CHECK(r.err.find("members[8]") != std::string::npos);
  CHECK(tbridge::test::Snapshot(dir / "out") == before);
}

// A structure's design (truss/) run by CalculiX: its deck's linear static steps give the design
// file's displacements, and its frequency step the file's lowest frequency (the 10-bar truss's
// 8 free motions allow ARPACK one mode).
// The config of a shipped structure, written into `dir` with structure.analysis `analysis`.
fs::path ShippedStructure(const fs::path& dir, const std::string& name, const char* analysis) {
  json config =
      json::parse(ReadText(std::string(TBRIDGE_SOURCE_DIR) + "/configs/" + name + ".json"));
  config["structure"]["analysis"] = analysis;
  const fs::path path = dir / (name + ".json");
  std::ofstream(path) << config.dump(2);
  return path;
}

TEST_CASE("export: a structure's design agrees with CalculiX", "[truss]") {
  // The 10-bar designs (linear, CalculiX's linear steps) and the prism designed with its
  // prestress by the nonlinear statics (CalculiX's geometrically nonlinear steps from the
  // prestressed state, its frequencies a perturbation about it).
  const std::pair<const char*, const char*> designs[] = {{"truss_10bar_displacement", "linear"},
                                                         {"truss_10bar_frequency", "linear"},
                                                         {"motes_prism_design", "nonlinear"}};
  for (const auto& [name, analysis] : designs) {
    INFO(name << ", " << analysis);
    const fs::path dir = FreshDir(std::string("export_truss_") + name);
    const fs::path design = DesignOf(dir, ShippedStructure(dir, name, analysis).string());
    REQUIRE(RunTbridge(dir, "export " + Quote(design.string()) + " --format calculix -o " +
                                Quote((dir / "truss.inp").string()))
                .code == 0);
    const std::string ccx = "cd " + Quote(dir.string()) + " && ccx truss > ccx.log 2>&1";
    INFO("ccx's log: " << ReadText(dir / "ccx.log"));
    REQUIRE(std::system(ccx.c_str()) == 0);
    std::map<int, CcxStep> steps;
    std::vector<double> omega;
    ReadDat(ReadText(dir / "truss.dat"), steps, omega);
    const json d = json::parse(ReadText(design));
    const int dim = d["config"]["structure"]["dim"].get<int>();
    for (size_t c = 0; c < d["cases"].size(); ++c) {
      const CcxStep& step = steps.at(static_cast<int>(c) + 1);
      const json& u = d["cases"][c]["displacements"];
      double largest = 0, worst = 0;
      for (size_t k = 0; k < u.size(); ++k) {
        for (int a = 0; a < dim; ++a) {
          largest = std::max(largest, std::abs(u[k][a].get<double>()));
          worst = std::max(worst,
                           std::abs(u[k][a].get<double>() - step.u.at(static_cast<int>(k) + 1)[a]));
        }
      }
      // The .dat prints 6 significant digits (e.g. -5.07999E-02): 1e-5 of the largest.
      CHECK(worst <= 1e-5 * largest);
    }
    // The frequencies (consistent member mass on both sides, the prestress's stiffness in
    // both): the .dat's 7 digits.
    REQUIRE(!omega.empty());
    for (size_t k = 0; k < omega.size(); ++k) {
      CHECK(omega[k] / (2 * M_PI) == Approx(d["frequencies_hz"][k].get<double>()).epsilon(1e-6));
    }
  }
}

}  // namespace
