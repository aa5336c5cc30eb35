// Plain config structs with the paper's defaults (SI units), and their strict JSON parsing.
// Every key is described once (core/config_fields.h and the files it includes): name, unit,
// range and meaning; the parse, the echo, Validate() and the README's key tables all come
// from there.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

#include "core/dynamics_config.h"
#include "core/material.h"
#include "core/structure_config.h"

namespace tbridge {

struct BridgeConfig {
  int n = 2;                // complexity: self-similar iterations, 1..16
  int p = 1;                // bars per substructure module, 1..8
  double beta_deg = 10.0;   // aspect angle [deg], (0, 90)
  double span = 12.0;       // L [m]
  double payload = 12000.0; // F, total external payload [N]
  double deck_width = 1.5;  // w_d, deck beam width and distance between planes [m]
  int planes = 1;           // 1 = planar bridge, 2 = 3D bridge of two coupled planes
};

struct DesignConfig {
  double yield_safety_factor = 10.0;     // sigma_w = yield_stress / this, for members and deck
  double buckling_safety_factor = 1.0;   // multiplies the bar force in the Euler check
  double deck_string_min_radius = 0.01;  // [m]; deck strings are prestressed at sigma_w
  // [m], [0, 1]; strings of group "transverse" (3D bridge) are prestressed at sigma_w. They
  // carry nothing under symmetric vertical loads, so without this floor min mass would
  // leave them at zero area and the coupled bridge would be a mechanism.
  double transverse_string_min_radius = 0.005;
  double bar_min_radius = 0.0;           // [m]; 0 = no minimum
  double gravity = 9.81;                 // g [m/s^2], for the deck self-weight
  // "auto" | "direct" | "ipopt" | "nlopt": how the self-stress coefficients are found. "direct"
  // applies when there is at most one self-stress and it loads no bar (every planar bridge);
  // "auto" takes it there and Ipopt elsewhere (the 3D bridge).
  std::string solver = "auto";
  double tolerance = 1e-10;              // relative optimality tolerance of the solver
  int max_iterations = 3000;             // solver iteration limit
};

// A config describes either a designed bridge ("bridge", with "material" and "design") or a
// custom scene ("structure"); `structure` is set exactly in the second case, and then
// `bridge`, `material` and `design` keep their defaults and are not echoed.
struct Config {
  BridgeConfig bridge;
  Material material;
  DesignConfig design;
  std::optional<StructureConfig> structure;  // present when the file has a "structure" section
  std::optional<DynamicsConfig> dynamics;    // present when the file has a "dynamics" section
};

// Allowed structural limits checked by ParseConfig (exposed for messages and tests).
inline constexpr int kMaxComplexity = 16;
inline constexpr int kMaxBarsPerModule = 8;

// Parses a whole config; throws ConfigError (key, value, allowed) on any bad or unknown key.
Config ParseConfig(const nlohmann::json& root);
Config LoadConfig(const std::string& path);
// Checks a config built in code as ParseConfig checks a file: every described key of
// `bridge`, `material` and `design` (or `structure`) and of `dynamics` in its range, and the
// rules across keys. Throws ConfigError naming the key path, the value and what is allowed.
void Validate(const Config& config);
// The resolved config, every default filled in, for echoing into outputs.
nlohmann::json ToJson(const Config& config);

}  // namespace tbridge
