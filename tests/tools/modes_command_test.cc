// `tbridge modes` end to end: the executable on a paper config.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace {

namespace fs = std::filesystem;

// Exit code of `tbridge modes <args>`, output discarded; -1 when it did not exit.
int RunModes(const std::string& args) {
  const std::string command =
      std::string("'") + TBRIDGE_BINARY + "' modes " + args + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_CASE("tbridge modes writes the n = 1 frequencies, shapes and RK4 step", "[tools][modes]") {
  const fs::path dir = fs::temp_directory_path() / "tbridge_modes_test";
  fs::remove_all(dir);
  const fs::path out = dir / "modes.json";
  const std::string config = std::string(TBRIDGE_SOURCE_DIR) + "/configs/paper_n1.json";
  REQUIRE(RunModes("'" + config + "' -o '" + out.string() + "' --count 1 -q") == 0);
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  REQUIRE(j.at("modes").size() == 3u);  // 4 free DOFs minus one bar length
  // SPEC §9 (independent re-implementation, 4 printed digits): 100.8 and 1.24e-3 s.
  CHECK(j["modes"][0]["omega_rad_s"].get<double>() == Approx(100.8).epsilon(0.01));
  CHECK(j["modes"][0]["symmetry"] == "symmetric");
  CHECK(j["rk4_stable_dt_s"].get<double>() == Approx(1.24e-3).margin(0.005e-3));
  CHECK(j["mode_shapes"].size() == 1u);
  CHECK(j["mode_shapes"][0]["displacements"].size() == 4u);  // every node, pinned ones at 0
  CHECK(j["config"]["bridge"]["n"] == 1);
  CHECK(j["stable"] == true);
  CHECK(j["all_modes"] == true);  // 4 free DOFs: every mode by default
  // A bad count is a usage error (exit 2) and leaves the earlier file alone.
  CHECK(RunModes("'" + config + "' -o '" + out.string() + "' --count -3") == 2);
  CHECK(fs::exists(out));
  fs::remove_all(dir);
}

TEST_CASE("tbridge modes --modes keeps the lowest modes and the RK4 step", "[tools][modes]") {
  const fs::path dir = fs::temp_directory_path() / "tbridge_modes_count_test";
  fs::remove_all(dir);
  const fs::path all = dir / "all.json", lowest = dir / "lowest.json";
  const std::string config = std::string(TBRIDGE_SOURCE_DIR) + "/configs/paper_n3.json";
  REQUIRE(RunModes("'" + config + "' -o '" + all.string() + "' -q") == 0);
  REQUIRE(RunModes("'" + config + "' -o '" + lowest.string() + "' --modes 3 -q") == 0);
  const nlohmann::json j_all = nlohmann::json::parse(std::ifstream(all));
  const nlohmann::json j_low = nlohmann::json::parse(std::ifstream(lowest));
  REQUIRE(j_all.at("modes").size() == 21u);  // 28 free DOFs minus 7 bar lengths
  REQUIRE(j_low.at("modes").size() == 3u);
  CHECK(j_low["all_modes"] == false);
  for (int k = 0; k < 3; ++k) {
    // The same dense solve, truncated: identical numbers.
    CHECK(j_low["modes"][k]["omega_rad_s"] == j_all["modes"][k]["omega_rad_s"]);
    CHECK(j_low["modes"][k]["symmetry"] == j_all["modes"][k]["symmetry"]);
  }
  CHECK(j_low["rk4_stable_dt_s"] == j_all["rk4_stable_dt_s"]);  // from the highest mode in both
  CHECK(j_low["mode_shapes"].size() == 3u);  // --count 6 by default, but only 3 modes
  // A bad mode count is a usage error (exit 2).
  CHECK(RunModes("'" + config + "' -o '" + lowest.string() + "' --modes x") == 2);
  fs::remove_all(dir);
}

TEST_CASE("tbridge modes gives the lowest 20 modes of a large bridge by default",
          "[tools][modes]") {
  const fs::path dir = fs::temp_directory_path() / "tbridge_modes_large_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string base = std::string(TBRIDGE_SOURCE_DIR) + "/configs/paper_n3.json";
  nlohmann::json config = nlohmann::json::parse(std::ifstream(base));
  config["bridge"]["n"] = 8;  // 1020 free DOFs, past the 600 of every mode
  const std::string config_path = (dir / "n8.json").string();
  const fs::path out = dir / "modes.json";
  std::ofstream(config_path) << config.dump();
  REQUIRE(RunModes("'" + config_path + "' -o '" + out.string() + "' -q") == 0);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(out));
  CHECK(j["all_modes"] == false);
  REQUIRE(j["modes"].size() == 20u);
  CHECK(j["model"]["free_dofs"] == 1020);
  for (size_t k = 1; k < j["modes"].size(); ++k) {
    CHECK(j["modes"][k]["omega_rad_s"].get<double>() >=
          j["modes"][k - 1]["omega_rad_s"].get<double>());
  }
  // A second algorithm: every mode of the same model by the dense solve (--modes 0, 765 modes
  // in 1.4 s). The Lanczos eigenvalues are converged to 1e-10 (measured: they agree to 4e-10),
  // so 1e-8 relative; the same symmetry.
  const fs::path dense_out = dir / "dense.json";
  REQUIRE(RunModes("'" + config_path + "' -o '" + dense_out.string() + "' -q --modes 0") == 0);
  const nlohmann::json dense = nlohmann::json::parse(std::ifstream(dense_out));
  REQUIRE(dense["all_modes"] == true);
  for (size_t k = 0; k < j["modes"].size(); ++k) {
    INFO("mode " << k + 1);
    CHECK(j["modes"][k]["omega_rad_s"].get<double>() ==
          Approx(dense["modes"][k]["omega_rad_s"].get<double>()).epsilon(1e-8));
    CHECK(j["modes"][k]["symmetry"] == dense["modes"][k]["symmetry"]);
  }
  // The RK4 limit from the highest mode, which the sparse path finds by its own Lanczos run:
  // RK4's stability interval on the imaginary axis is |omega dt| <= 2 sqrt(2), so dt =
  // 2 sqrt(2) / omega_max with the dense solve's highest omega; that Lanczos run stops at a Ritz
  // residual of 1e-6 (ModalOptions::highest_tolerance), which bounds its relative error.
  const double omega_max = dense["modes"].back()["omega_rad_s"].get<double>();
  CHECK(j["rk4_stable_dt_s"].get<double>() == Approx(2 * std::sqrt(2.0) / omega_max).epsilon(1e-6));
  fs::remove_all(dir);
}

}  // namespace

namespace {

// Exit code of `tbridge <command> <args>`, output discarded.
int RunCommand(const std::string& command_and_args) {
  const std::string command =
      std::string("'") + TBRIDGE_BINARY + "' " + command_and_args + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE(
    "tbridge modes --mass crowd gives the comfort check's frequencies and names each mode's motion",
    "[tools][modes][comfort]") {
  const fs::path dir = fs::temp_directory_path() / "tbridge_modes_comfort_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path config = dir / "n2.json";
  std::ofstream(config) << R"({"bridge": {"n": 2}})";
  const fs::path design = dir / "design.json", modes = dir / "modes.json";
  REQUIRE(RunCommand("design '" + config.string() + "' -o '" + design.string() + "' -q") <= 1);
  REQUIRE(RunCommand("modes '" + config.string() + "' -o '" + modes.string() +
                     "' --mass crowd -q") == 0);
  std::ifstream design_in(design), modes_in(modes);
  const nlohmann::json d = nlohmann::json::parse(design_in), m = nlohmann::json::parse(modes_in);
  CHECK(m["model"]["mass"] == "crowd");
  const nlohmann::json& comfort = d.at("comfort");
  REQUIRE(comfort["done"] == true);
  REQUIRE(!comfort["modes"].empty());
  for (const nlohmann::json& mode : comfort["modes"]) {
    const nlohmann::json& same = m["modes"][mode["index"].get<int>() - 1];
    // The same model, the same dense eigen-decomposition: the design file's shortest
    // round-trip digits give the frequency back to 1e-9 (the contract of the comfort report).
    CHECK(same["frequency_hz"].get<double>() ==
          Approx(mode["frequency_hz"].get<double>()).epsilon(1e-9));
    CHECK(same["motion"] == mode["direction"]);
  }
  // A planar bridge: only vertical, longitudinal or local motions.
  for (const nlohmann::json& mode : m["modes"]) {
    const std::string motion = mode["motion"];
    CHECK((motion == "vertical" || motion == "longitudinal" || motion == "local"));
  }
  // A mass model the command does not know is a usage error.
  CHECK(RunCommand("modes '" + config.string() + "' -o '" + modes.string() + "' --mass full") == 2);
  fs::remove_all(dir);
}
