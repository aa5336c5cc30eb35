// The command line an engineer can trust, one test per defect found by trying the tool as a
// new user would. Each test sets up the situation of the defect (before the fix it failed),
// then checks the exit code, that the message names the key, and the output folder byte for
// byte before and after.

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "bridge/design_model.h"
#include "cli_support.h"
#include "core/config.h"
#include "design/design.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "optim/solvers.h"
#include "test_support.h"

namespace tbridge {
namespace {

namespace fs = std::filesystem;
using test::CliResult;
using test::FreshDir;
using test::Quote;
using test::ReadText;
using test::Snapshot;

// `text`, a config, with the paper's switches (test::WithPaperSwitches), as JSON text.
std::string Paper(const std::string& text) {
  return test::WithPaperSwitches(nlohmann::json::parse(text)).dump();
}

fs::path Write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

CliResult Run(const fs::path& dir, const std::string& args) { return test::RunTbridge(dir, args); }

// A short n = 3 run (2000 RK4 steps) that records the deck node 1.
const char* kShortRun =
    R"({"bridge": {"n": 3}, "dynamics": {"duration": 0.02, "record": {"nodes": [1]}}})";

TEST_CASE("defect 1: a failed simulate changes nothing in a used folder and creates no fresh one") {
  const fs::path dir = FreshDir("trust_failed_run");
  const fs::path a =
      Write(dir / "A.json",
            R"({"bridge": {"n": 3}, "dynamics": {"duration": 0.03, "record": {"nodes": [1, 2]}}})");
  const fs::path b = Write(dir / "B.json", kShortRun);
  const fs::path out = dir / "out";
  REQUIRE(Run(dir, "simulate " + Quote(a.string()) + " -o " + Quote(out.string()) + " -q").code ==
          0);
  Write(out / "notes.txt", "the engineer's own file\n");
  const auto before = Snapshot(out);
  REQUIRE(before.count("summary.json") == 1);
  REQUIRE(before.count("history.csv") == 1);

  // /proc refuses new folders: the VTK output cannot be written.
  const CliResult r = Run(
      dir, "simulate " + Quote(b.string()) + " -o " + Quote(out.string()) + " --vtk /proc/vtk -q");
  INFO(r.err);
  REQUIRE(r.exited);
  CHECK(r.code == 4);  // an output that cannot be written (README, exit codes)
  CHECK_THAT(r.err, Catch::Contains("/proc/vtk"));
  CHECK(Snapshot(out) == before);  // byte for byte: no summary of B beside A's history

  const fs::path fresh = dir / "fresh";
  const CliResult f = Run(dir, "simulate " + Quote(b.string()) + " -o " + Quote(fresh.string()) +
                                   " --vtk /proc/vtk -q");
  CHECK(f.code == 4);
  CHECK_FALSE(fs::exists(fresh));  // not even the folder
}

TEST_CASE(
    "defect 1: a run that fails after its work (an export it cannot make) also changes nothing") {
  const fs::path dir = FreshDir("trust_failed_late");
  const fs::path b = Write(dir / "B.json", kShortRun);
  const fs::path out = dir / "out";
  REQUIRE(Run(dir, "simulate " + Quote(b.string()) + " -o " + Quote(out.string()) + " -q").code ==
          0);
  const auto before = Snapshot(dir);
  // The VTK export needs every free node recorded; the run records node 1 only. The check
  // comes after the simulation, when every output is already staged.
  const CliResult r = Run(dir, "simulate " + Quote(b.string()) + " -o " + Quote(out.string()) +
                                   " --vtk " + Quote((dir / "vtk").string()) + " -q");
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("dynamics.record.nodes"));
  auto after = Snapshot(dir);
  after.erase("stdout.txt");  // the test's own capture files
  after.erase("stderr.txt");
  auto expected = before;
  expected.erase("stdout.txt");
  expected.erase("stderr.txt");
  CHECK(after == expected);  // no temporaries left, no vtk folder
}

TEST_CASE("defect 2: record.csv false removes this command's old history.csv and nothing else") {
  const fs::path dir = FreshDir("trust_stale_history");
  const fs::path with_csv = Write(dir / "A.json", kShortRun);
  const fs::path no_csv = Write(
      dir / "C.json",
      R"({"bridge": {"n": 3}, "dynamics": {"duration": 0.02, "record": {"nodes": [1], "csv": false}}})");
  const fs::path out = dir / "out";
  REQUIRE(Run(dir, "simulate " + Quote(with_csv.string()) + " -o " + Quote(out.string()) + " -q")
              .code == 0);
  REQUIRE(fs::exists(out / "history.csv"));
  Write(out / "notes.txt", "keep me\n");

  const CliResult r =
      Run(dir, "simulate " + Quote(no_csv.string()) + " -o " + Quote(out.string()) + " -q");
  INFO(r.err);
  CHECK(r.code == 0);
  const auto after = Snapshot(out);
  CHECK(after.size() == 2);  // summary.json and notes.txt
  CHECK(after.count("history.csv") == 0);
  CHECK(after.at("notes.txt") == "keep me\n");
  const auto summary = nlohmann::json::parse(after.at("summary.json"));
  CHECK(summary["config"]["dynamics"]["record"]["csv"] == false);  // the new run's summary
}

TEST_CASE(
    "defect 2: a VTK series replaces the whole series of an earlier run, its own files and nothing "
    "else") {
  const fs::path dir = FreshDir("trust_stale_vtk");
  // Every free node of n = 3 (nodes 1-14; 15, 16 are the supports) recorded.
  const std::string nodes = "[1,2,3,4,5,6,7,8,9,10,11,12,13,14]";
  const fs::path longer = Write(
      dir / "L.json",
      R"({"bridge": {"n": 3}, "dynamics": {"duration": 0.004, "record": {"every": 100, "nodes": )" +
          nodes + "}}}");
  const fs::path shorter = Write(
      dir / "S.json",
      R"({"bridge": {"n": 3}, "dynamics": {"duration": 0.002, "record": {"every": 100, "nodes": )" +
          nodes + "}}}");
  const fs::path vtk = dir / "vtk";
  REQUIRE(Run(dir, "simulate " + Quote(longer.string()) + " -o " + Quote((dir / "o").string()) +
                       " --vtk " + Quote(vtk.string()) + " -q")
              .code == 0);
  // 0.004 s / (100 x 1e-5 s) + 1 samples: 0..4.
  CHECK(Snapshot(vtk).at("run.xdmf").find("<Grid Name=\"sample 4\"") != std::string::npos);
  // The one-file-per-sample series an earlier version wrote there, and a file of the user's.
  Write(vtk / "run.pvd", "<VTKFile/>\n");
  Write(vtk / "run_7.vtp", "<VTKFile/>\n");
  Write(vtk / "notes.txt", "keep me\n");
  REQUIRE(Run(dir, "simulate " + Quote(shorter.string()) + " -o " + Quote((dir / "o").string()) +
                       " --vtk " + Quote(vtk.string()) + " -q")
              .code == 0);
  const auto after = Snapshot(vtk);
  CHECK(after.size() == 3);  // run.xdmf, run.bin and notes.txt
  CHECK(after.at("notes.txt") == "keep me\n");
  CHECK(after.at("run.xdmf").find("<Grid Name=\"sample 2\"") != std::string::npos);
  CHECK(after.at("run.xdmf").find("<Grid Name=\"sample 3\"") == std::string::npos);
}

TEST_CASE("defect 3: a run beyond the step limit exits 2 at once and names dynamics.duration") {
  const fs::path dir = FreshDir("trust_limits");
  for (const char* frequency : {"true", "false"}) {
    const fs::path config = Write(
        dir / "long.json",
        std::string(
            R"({"bridge": {"n": 3}, "dynamics": {"duration": 1e6, "frequency": {"enabled": )") +
            frequency + "}}}");
    const CliResult r =
        Run(dir, "simulate " + Quote(config.string()) + " -o " + Quote((dir / "out").string()));
    INFO(r.err);
    REQUIRE(r.exited);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("'dynamics.duration'") && Catch::Contains("1e+11 steps") &&
                          Catch::Contains("dynamics.limits.max_steps"));
    CHECK_FALSE(fs::exists(dir / "out"));
  }
  // dopri5's step count is unknown before the run: it stops at its own limit.
  const fs::path adaptive =
      Write(dir / "dopri.json", R"({"bridge": {"n": 3}, "dynamics": {"duration": 1e6, "dt": 0.1,
      "integrator": "dopri5", "frequency": {"enabled": false}, "limits": {"max_steps": 100}}})");
  const CliResult r =
      Run(dir, "simulate " + Quote(adaptive.string()) + " -o " + Quote((dir / "out").string()));
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("'dynamics.limits.max_steps' = 100"));
  CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("run limits: 1e7 steps fit the defaults, a history of 1e9 steps does not") {
  Config config;
  config.bridge.n = 3;
  DynamicsConfig d;
  d.dt = 1e-5;
  d.duration = 100;  // 1e7 steps
  CHECK_NOTHROW(CheckStepLimit(d));
  const DynamicModel model = BuildDynamicModel(RunDesign(config), ModelOptionsOf(d));
  CHECK_NOTHROW(CheckRunLimits(model, d));  // deck signals: 1e6 samples x 16 B = 16 MB
  CHECK(EstimateRun(model, d).deck_bytes ==
        Approx((1e6 + 1) * 16.0));  // two doubles a sample, every 10th step and t = 0
  // Every node recorded for 1e9 steps: 1e9 rows x 29 values x ~20 B = 5.8e11 B > 1e10 B.
  d.duration = 1e4;
  for (int node = 1; node <= 16; ++node) d.record.nodes.push_back(node);
  const RunEstimate e = EstimateRun(model, d);
  CHECK(e.steps == 1000000000L);                             // ceil(1e4 / 1e-5), exact in double
  CHECK(e.records == 1000000001L);                           // every step and t = 0
  CHECK(e.history_bytes == Approx(1000000001.0 * 33 * 20));  // t + 2 x 16 coordinates
  CHECK_THROWS_WITH(CheckRunLimits(model, d), Catch::Contains("dynamics.limits.max_output_bytes"));
  d.limits.max_output_bytes = 1e15;
  CHECK_NOTHROW(CheckRunLimits(model, d));  // the key raises the limit
}

TEST_CASE("defect 4: overflowing inputs are bad input naming the key, not a solver failure") {
  const fs::path dir = FreshDir("trust_overflow");
  const std::pair<const char*, const char*> cases[] = {
      {R"({"bridge": {"n": 3, "deck_width": 1e300}})", "'bridge.deck_width' = 1e+300"},
      {R"({"bridge": {"n": 3}, "material": {"density": 1e300}})", "'material.density' = 1e+300"},
      {R"({"bridge": {"n": 3, "payload": 1e300}})", "'bridge.payload' = 1e+300"}};
  for (const auto& [text, named] : cases) {
    const fs::path config = Write(dir / "config.json", text);
    const CliResult r =
        Run(dir, "design " + Quote(config.string()) + " -o " + Quote((dir / "out.json").string()));
    INFO(text << "\n" << r.err);
    REQUIRE(r.exited);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains(named) && Catch::Contains("outside what can be computed"));
    CHECK_THAT(r.err, !Catch::Contains("Invalid_Number"));
    CHECK_FALSE(fs::exists(dir / "out.json"));
  }
}

TEST_CASE("defect 5: a key with a NUL in it is printed whole") {
  const fs::path dir = FreshDir("trust_nul");
  const fs::path config = Write(dir / "config.json", R"({"bridge": {"n": 3, "span\u0000x": 1}})");
  const CliResult r =
      Run(dir, "design " + Quote(config.string()) + " -o " + Quote((dir / "out.json").string()));
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("'bridge.span\\u0000x' = 1: unknown key"));
  CHECK_FALSE(fs::exists(dir / "out.json"));
}

TEST_CASE("defect 6: -o through a link replaces the link's target and keeps the link") {
  const fs::path dir = FreshDir("trust_link");
  const fs::path config = Write(dir / "config.json", R"({"bridge": {"n": 3}})");
  fs::create_directories(dir / "elsewhere");
  Write(dir / "elsewhere" / "design.json", "old\n");
  fs::create_symlink("elsewhere/design.json", dir / "link.json");
  const CliResult r = Run(dir, "design " + Quote(config.string()) + " -o " +
                                   Quote((dir / "link.json").string()) + " -q");
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(fs::is_symlink(dir / "link.json"));
  CHECK(fs::read_symlink(dir / "link.json") == "elsewhere/design.json");
  CHECK(nlohmann::json::parse(ReadText(dir / "elsewhere" / "design.json"))["topology"]["n"] == 3);
  // A dangling link creates its target, as shell redirection does.
  fs::create_symlink("elsewhere/new.json", dir / "dangling.json");
  CHECK(Run(dir, "design " + Quote(config.string()) + " -o " +
                     Quote((dir / "dangling.json").string()) + " -q")
            .code == 0);
  CHECK(fs::is_symlink(dir / "dangling.json"));
  CHECK(fs::is_regular_file(dir / "elsewhere" / "new.json"));
}

TEST_CASE("defect 6: -o naming a FIFO is refused and the FIFO stays") {
  const fs::path dir = FreshDir("trust_fifo");
  const fs::path config = Write(dir / "config.json", R"({"bridge": {"n": 3}})");
  REQUIRE(::mkfifo((dir / "pipe").c_str(), 0600) == 0);
  const auto before = Snapshot(dir);
  const CliResult r =
      Run(dir, "design " + Quote(config.string()) + " -o " + Quote((dir / "pipe").string()));
  INFO(r.err);
  REQUIRE(r.exited);
  CHECK(r.code == 4);  // an output that cannot be written
  CHECK_THAT(r.err, Catch::Contains("FIFO") && Catch::Contains("regular files only"));
  CHECK(fs::is_fifo(fs::symlink_status(dir / "pipe")));
  auto after = Snapshot(dir);
  CHECK(after.at("pipe") == before.at("pipe"));
  CHECK(after.at("config.json") == before.at("config.json"));
  CHECK(after.size() == before.size() + 2);  // only the test's stdout.txt and stderr.txt
}

TEST_CASE("defect 7: -o equal to the config is refused and the config is kept") {
  const fs::path dir = FreshDir("trust_same_path");
  const std::string text = R"({"bridge": {"n": 3}})";
  const fs::path config = Write(dir / "config.json", text);
  for (const std::string& out : {config.string(), (dir / "." / "config.json").string()}) {
    const CliResult r = Run(dir, "design " + Quote(config.string()) + " -o " + Quote(out));
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("is the input"));
    CHECK(ReadText(config) == text);
  }
}

TEST_CASE("defect 7: a directory given as CONFIG is named as a directory") {
  const fs::path dir = FreshDir("trust_dir_config");
  const CliResult r =
      Run(dir, "design " + Quote(dir.string()) + " -o " + Quote((dir / "out.json").string()));
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("is a directory") && !Catch::Contains("malformed JSON"));
  CHECK_FALSE(fs::exists(dir / "out.json"));
}

TEST_CASE("defect 7: a bad --shard is called an option, not a config key") {
  const fs::path dir = FreshDir("trust_shard");
  const fs::path config = Write(dir / "config.json", R"({"bridge": {"n": 1}, "sweep": {}})");
  const CliResult r = Run(dir, "sweep " + Quote(config.string()) + " -o " +
                                   Quote((dir / "out").string()) + " --shard 3/2");
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::StartsWith("tbridge: error: option '--shard' = '3/2'") &&
                        !Catch::Contains("config key"));
  CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("defect 7: paper prints each table's header once, over the error its tolerance uses") {
  const fs::path dir = FreshDir("trust_paper");
  const CliResult r = Run(
      dir, "paper --tables 2,3,4 --configs " + Quote(std::string(TBRIDGE_SOURCE_DIR) + "/configs"));
  INFO(r.err);
  CHECK(r.code == 0);
  for (const char* header : {"Table 2 (absolute tolerance)", "Table 3 (absolute tolerance)",
                             "Table 4 (absolute tolerance)"}) {
    const size_t first = r.out.find(header);
    CHECK(first != std::string::npos);
    CHECK(r.out.find(header, first + 1) == std::string::npos);  // once
  }
  CHECK_THAT(r.out, Catch::Contains("abs.err") && !Catch::Contains("rel.err"));
}

TEST_CASE("defect 7: the exit codes are listed once with 1 and --version names the revision") {
  const fs::path dir = FreshDir("trust_help");
  const CliResult help = Run(dir, "--help");
  CHECK(help.code == 0);
  CHECK_THAT(help.out, Catch::Contains("exit codes: 0 ok, 1 ") && Catch::Contains("2 bad input") &&
                           Catch::Contains("3 no design") && Catch::Contains("4 other error"));
  // Looking at a result: the plot tools and the VTK export.
  CHECK_THAT(help.out, Catch::Contains("tools/plot_dynamics.py") &&
                           Catch::Contains("tools/plot_sweep.py") && Catch::Contains("--vtk"));
  const CliResult paper = Run(dir, "paper --help");
  CHECK_THAT(paper.out, Catch::Contains("Exits 1") && Catch::Contains("tbridge --help"));
  const CliResult version = Run(dir, "--version");
  CHECK(version.code == 0);
  CHECK_THAT(version.out, Catch::StartsWith("tbridge 0.") && Catch::Contains("(git "));
  // The solvers the build has (CMake options TBRIDGE_WITH_IPOPT/NLOPT), each named iff built in.
  CHECK_THAT(version.out, Catch::Contains("design solvers built in: auto, direct"));
  for (const SolverKind solver : {SolverKind::kIpopt, SolverKind::kNlopt}) {
    INFO(NameOf(solver));
    CHECK((version.out.find(NameOf(solver)) != std::string::npos) == SolverBuiltIn(solver));
  }
}

TEST_CASE(
    "plausibility: implausible designs warn on stderr, --strict refuses them and writes nothing") {
  const fs::path dir = FreshDir("trust_plausible");
  const std::pair<std::string, const char*> cases[] = {
      // 1e-6 m span: members of 1e-8 m, masses that print as 0.000 kg
      {Paper(R"({"bridge": {"n": 3, "span": 1e-6}})"), "shorter than 1 mm"},
      // 1.1e9 N payload: 1.6 m thick bars 0.13 m long, a 1.22 m deck on a 12 m span. The
      // deck strings at their 1 m maximum radius keep the prestress (2.2e8 N) strong enough
      // for the bars to stand: the design is stable, only implausible.
      {Paper(
           R"({"bridge": {"n": 3, "payload": 1.1e9}, "design": {"deck_string_min_radius": 1.0}})"),
       "thicker than long"},
      {Paper(
           R"({"bridge": {"n": 3, "payload": 1.1e9}, "design": {"deck_string_min_radius": 1.0}})"),
       "exceeds span / 10"}};
  for (const auto& [text, warning] : cases) {
    const fs::path config = Write(dir / "config.json", text);
    const fs::path out = dir / "out.json";
    fs::remove(out);
    const CliResult r =
        Run(dir, "design " + Quote(config.string()) + " -o " + Quote(out.string()) + " -q");
    INFO(text << "\n" << r.err);
    CHECK(r.code == tbridge::test::VerdictExit(out));
    CHECK_THAT(r.err, Catch::Contains("tbridge: warning: ") && Catch::Contains(warning));
    CHECK(fs::exists(out));
    fs::remove(out);
    const CliResult strict =
        Run(dir, "design " + Quote(config.string()) + " -o " + Quote(out.string()) + " --strict");
    CHECK(strict.code == 2);
    CHECK_THAT(strict.err, Catch::Contains("--strict") && Catch::Contains(warning));
    CHECK_FALSE(fs::exists(out));
  }
  // A 1e12 N payload with the 10 mm deck strings: their 2.2e4 N prestress cannot hold bars
  // loaded by 1e12 N upright (as with no deck prestress at all), so the design is refused as
  // unstable before any plausibility check: exit 3, nothing written.
  {
    const fs::path config =
        Write(dir / "config.json", Paper(R"({"bridge": {"n": 3, "payload": 1e12}})"));
    const fs::path out = dir / "out.json";
    fs::remove(out);
    const CliResult r =
        Run(dir, "design " + Quote(config.string()) + " -o " + Quote(out.string()) + " -q");
    CHECK(r.code == 3);
    CHECK_THAT(r.err, Catch::Contains("unstable"));
    CHECK_FALSE(fs::exists(out));
  }
  // The paper's n = 3 design is plausible: no warning.
  const fs::path config = Write(dir / "config.json", Paper(R"({"bridge": {"n": 3}})"));
  const CliResult r = Run(dir, "design " + Quote(config.string()) + " -o " +
                                   Quote((dir / "out.json").string()) + " --strict -q");
  CHECK(r.code == tbridge::test::VerdictExit(dir / "out.json"));
  CHECK(r.code != 2);
  CHECK(r.err.empty());
}

TEST_CASE("plausibility: every shipped engineering bridge warns of its abutment thrust") {
  const fs::path dir = FreshDir("trust_abutment");
  // The supports are free in the minimum-mass problem, so prestress against them is the
  // cheapest stiffness, and each of these bridges takes it: the warning is true of them. As
  // measured, H over the load path's own thrust W L / (8 d): default 2518 kN, 16.4 times;
  // footbridge_aluminium_20m 1849 kN, 3.89; footbridge_cables_20m 1279 kN, 2.32;
  // footbridge_steel_40m 3898 kN, 2.68. The paper's configs keep its switches and do not warn.
  for (const char* name :
       {"default", "footbridge_aluminium_20m", "footbridge_cables_20m", "footbridge_steel_40m"}) {
    const fs::path out = dir / "out.json";
    const CliResult r =
        Run(dir, "design " + Quote(std::string(TBRIDGE_SOURCE_DIR "/configs/") + name + ".json") +
                     " -o " + Quote(out.string()) + " -q");
    INFO(name << "\n" << r.err);
    CHECK(r.code == tbridge::test::VerdictExit(out));
    CHECK_THAT(r.err, Catch::Contains("tbridge: warning: the abutment at x = 0 m (node ") &&
                          Catch::Contains("times the load path's own thrust W L / (8 d)") &&
                          Catch::Contains("prestress, not the load, sets the thrust"));
    fs::remove(out);
  }
  // So --strict refuses the README's first design (exit 2, nothing written) until the abutment
  // thrust is designed for or the prestress bounded.
  const fs::path out = dir / "strict.json";
  const CliResult strict = Run(dir, "design " + Quote(TBRIDGE_SOURCE_DIR "/configs/default.json") +
                                        " -o " + Quote(out.string()) + " --strict");
  CHECK(strict.code == 2);
  CHECK_THAT(strict.err,
             Catch::Contains("--strict") && Catch::Contains("the abutment at x = 0 m (node 15)"));
  CHECK_FALSE(fs::exists(out));
  // `check` of that design warns as `design` does, and under --strict refuses it, writing nothing.
  const fs::path design = dir / "design.json", checked = dir / "checked.json";
  REQUIRE(Run(dir, "design " + Quote(TBRIDGE_SOURCE_DIR "/configs/default.json") + " -o " +
                       Quote(design.string()) + " -q")
              .code == 0);
  const CliResult check =
      Run(dir, "check " + Quote(design.string()) + " -o " + Quote(checked.string()) + " -q");
  CHECK(check.code == 0);
  CHECK_THAT(check.err, Catch::Contains("tbridge: warning: the abutment at x = 0 m (node 15)"));
  fs::remove(checked);
  const CliResult strict_check = Run(
      dir, "check " + Quote(design.string()) + " -o " + Quote(checked.string()) + " -q --strict");
  CHECK(strict_check.code == 2);
  CHECK_FALSE(fs::exists(checked));
}

TEST_CASE(
    "plausibility and progress: n = 12 and 16 on a 12 m span warn of their tiny members and deck") {
  const fs::path dir = FreshDir("trust_n12");
  // n = 12 on the default 12 m span: bars 0.26 mm long, a deck 7.9 um thick.
  const fs::path config = Write(dir / "config.json", Paper(R"({"bridge": {"n": 12}})"));
  CliResult r = Run(dir, "design " + Quote(config.string()) + " -o " +
                             Quote((dir / "out.json").string()) + " -q --progress");
  INFO(r.err);
  // Written; at this n the dynamic run is not done, so the verdict is INCOMPLETE and exits 1.
  CHECK(r.code == tbridge::test::VerdictExit(dir / "out.json"));
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Catch::Contains("members shorter than 1 mm (worst"));
  CHECK_THAT(r.err, Catch::Contains("deck thickness 7.89e-06 m is below 1 mm"));
  // n = 16 takes about 2 s, longer than the progress line's 1 s delay: a line is drawn (the
  // design's fraction done, or the writing's elapsed time, whichever stage runs at 1 s).
  const fs::path config16 = Write(dir / "config16.json", Paper(R"({"bridge": {"n": 16}})"));
  const auto start = std::chrono::steady_clock::now();
  r = Run(dir, "design " + Quote(config16.string()) + " -o " +
                   Quote((dir / "out16.json").string()) + " -q --progress");
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(r.code == tbridge::test::VerdictExit(dir / "out16.json"));
  CHECK_THAT(r.err, Catch::Contains("elapsed "));
  // The last line: the wall time by part. The paper's design is checked as designed, so it is
  // the first design and the checks, with no sizing; the parts are within the whole process's
  // time (a part counted twice would not be: the design is most of the 2 s).
  const std::string tag = "time by part [s]: first design ";
  const size_t at = r.err.rfind(tag);
  REQUIRE(at != std::string::npos);
  double first = -1, sizing = -1, statics = -1, dynamics = -1, comfort = -1;
  REQUIRE(std::sscanf(r.err.c_str() + at + tag.size(),
                      "%lf, sizing %lf, static check %lf, dynamic check %lf, comfort check %lf",
                      &first, &sizing, &statics, &dynamics, &comfort) == 5);
  CHECK(first > 0);
  CHECK(sizing == 0);
  CHECK(statics > 0);
  CHECK(first + sizing + statics + dynamics + comfort <= wall_s);
  // Not in the design's JSON, which is the same from run to run.
  CHECK_THAT(ReadText(dir / "out16.json"),
             !Catch::Contains("time by part") && !Catch::Contains("time_s"));
  // The progress line is ended before the first warning, which starts a line of its own.
  CHECK_THAT(r.err, Catch::Contains("\ntbridge: warning: "));
}

TEST_CASE("plausibility: simulate --strict stops an implausible design before its run") {
  const fs::path dir = FreshDir("trust_plausible_simulate");
  // 1e6 steps would take seconds; the refusal comes after the design, before the first one.
  const fs::path config =
      Write(dir / "config.json",
            Paper(R"({"bridge": {"n": 3, "payload": 1e12}, "dynamics": {"duration": 10}})"));
  const auto start = std::chrono::steady_clock::now();
  const CliResult r = Run(dir, "simulate " + Quote(config.string()) + " -o " +
                                   Quote((dir / "out").string()) + " --strict");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--strict") && Catch::Contains("thicker than long"));
  CHECK(seconds < 1.5);  // the run (about 2 s at 1e6 steps) never started
  CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("an interrupted run (SIGINT) leaves no temporaries and no folder") {
  const fs::path dir = FreshDir("trust_interrupt");
  const fs::path config =
      Write(dir / "long.json", R"({"bridge": {"n": 3}, "dynamics": {"duration": 30}})");
  // timeout sends SIGINT after a second, in the middle of a run of about 6 s.
  const std::string command = "timeout -s INT 1 " + Quote(TBRIDGE_BINARY) + " simulate " +
                              Quote(config.string()) + " -o " +
                              Quote((dir / "out" / "deeper").string()) + " 2> /dev/null";
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 124);     // timeout's code: the command was stopped by the signal
  CHECK_FALSE(fs::exists(dir / "out"));  // neither out/ nor out/deeper/ nor a temporary
  CHECK(Snapshot(dir).size() == 1);      // the config alone
}

TEST_CASE("did you mean: a misspelt key or option gets the nearest one") {
  const fs::path dir = FreshDir("trust_did_you_mean");
  const fs::path config = Write(dir / "config.json", R"({"bridge": {"n": 3, "payloads": 12000}})");
  const CliResult r =
      Run(dir, "design " + Quote(config.string()) + " -o " + Quote((dir / "out.json").string()));
  CHECK(r.code == 2);
  CHECK_THAT(r.err,
             Catch::Contains("'bridge.payloads'") && Catch::Contains("did you mean 'payload'?"));
  const CliResult option = Run(dir, "design " + Quote(config.string()) + " -o x.json --quite");
  CHECK(option.code == 2);
  CHECK_THAT(option.err, Catch::Contains("did you mean '--quiet'?"));
  const CliResult command = Run(dir, "desing");
  CHECK(command.code == 2);
  CHECK_THAT(command.err, Catch::Contains("did you mean 'design'?"));
}

TEST_CASE(
    "progress: a run longer than a second draws a line with an ETA on stderr and a short one stays "
    "quiet") {
  const fs::path dir = FreshDir("trust_progress");
  // About 3 s of RK4 on n = 3 (1.5e6 steps), longer than the reporter's 1 s delay.
  const fs::path longer =
      Write(dir / "long.json", R"({"bridge": {"n": 3}, "dynamics": {"duration": 15}})");
  const CliResult r = Run(dir, "simulate " + Quote(longer.string()) + " -o " +
                                   Quote((dir / "out").string()) + " -q --progress");
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK_THAT(r.err, Catch::Contains("simulate") && Catch::Contains("ETA") && Catch::EndsWith("\n"));
  // Short: a structure scene, with no design before its run (designing the n = 3 bridge of
  // kShortRun alone can take more than the reporter's second on a slow machine).
  std::string scene = ReadText(TBRIDGE_SOURCE_DIR "/configs/motes_prism.json");
  scene.replace(scene.find("\"duration\": 5"), 13, "\"duration\": 0.02");
  const fs::path shorter = Write(dir / "short.json", scene);
  const CliResult s = Run(dir, "simulate " + Quote(shorter.string()) + " -o " +
                                   Quote((dir / "out2").string()) + " -q --progress");
  CHECK(s.code == 0);
  CHECK(s.err.empty());
}

}  // namespace
}  // namespace tbridge
