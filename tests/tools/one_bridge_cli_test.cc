// One bridge for every command: `tbridge modes` of a config analyses the bridge `tbridge design`
// writes (verified and resized), not the first, unresized design.

#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "bridge/design_model.h"
#include "cli_support.h"
#include "dynamics/modal.h"
#include "io/design_reader.h"

namespace {

using nlohmann::json;
namespace fs = std::filesystem;
using tbridge::test::FreshDir;
using tbridge::test::Quote;
using tbridge::test::ReadText;
using tbridge::test::RunTbridge;

TEST_CASE("modes of a config are the modes of the design tbridge design writes", "[tools][modes]") {
  const fs::path dir = FreshDir("one_bridge");
  const std::string config = std::string(TBRIDGE_SOURCE_DIR) + "/configs/default.json";
  const fs::path design_file = dir / "design.json", modes_file = dir / "modes.json";
  REQUIRE(
      RunTbridge(dir, "design " + Quote(config) + " -q -o " + Quote(design_file.string())).code ==
      0);
  REQUIRE(
      RunTbridge(dir, "modes " + Quote(config) + " -q --modes 3 -o " + Quote(modes_file.string()))
          .code == 0);

  // The written design's modes, computed here from the file: the model tbridge modes builds
  // for an engineering config (the deck's inertia, no further gravity).
  const json written = json::parse(ReadText(design_file));
  REQUIRE(written["resizing"]["iterations"].get<int>() > 1);  // resized: the first design differs
  const tbridge::Design d = tbridge::ReadDesign(written);
  tbridge::ModelOptions options;
  options.deck_inertia = true;
  tbridge::ModalOptions modal;
  modal.count = 3;
  const tbridge::ModalResult mine =
      tbridge::ComputeModes(tbridge::BuildDynamicModel(d, options), modal);
  const json modes = json::parse(ReadText(modes_file));
  REQUIRE(modes["modes"].size() >= 1u);
  // 1e-9 relative: the same model, built from the file's 17 digits rather than in memory.
  CHECK(modes["modes"][0]["omega_rad_s"].get<double>() ==
        Approx(mine.modes.at(0).omega_rad_s).epsilon(1e-9));
}

}  // namespace
