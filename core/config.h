// Plain config structs with engineering defaults (SI units), and their strict JSON parsing.
// Every key is described once (core/config_fields.h and the files it includes): name, unit,
// range and meaning; the parse, the echo, Validate() and the README's key tables all come
// from there.
#pragma once

#include <algorithm>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/design_choices.h"
#include "core/dynamics_config.h"
#include "core/material.h"
#include "core/structure_config.h"

namespace tbridge {

struct BridgeConfig {
  int n = 2;                 // complexity: self-similar iterations, 1..16
  int p = 1;                 // bars per substructure module, 1..8
  double beta_deg = 10.0;    // aspect angle [deg], (0, 90); with beta_auto, the angle chosen
  double span = 12.0;        // L [m]
  double payload = 12000.0;  // F, total external payload [N]
  double deck_width = 1.5;   // w_d, deck beam width and distance between planes [m]
  int planes = 1;            // 1 = planar bridge, 2 = 3D bridge of two coupled planes
  // beta_deg given as "auto": the verified design chooses it in design.beta_range_deg
  // (sizing/angle_search.h), and beta_deg then holds the angle chosen.
  bool beta_auto = false;
};

// The defaults are an engineer's (EN 1993-2's recommended partial factors for steel bridges,
// a column curve for the bars, self-weight in the loads); ApplyPaperSwitches sets the paper's.
struct DesignConfig {
  double yield_safety_factor = 1.1;      // gamma_M: sigma_w = yield_stress / this (members, deck)
  double buckling_safety_factor = 1.1;   // gamma_M1 on a bar's buckling resistance
  double deck_string_min_radius = 0.01;  // [m]; deck strings are prestressed at sigma_w
  // [m], [0, 1]; strings of group "transverse" (3D bridge) are prestressed at sigma_w. They
  // carry nothing under symmetric vertical loads, so without this floor min mass would
  // leave them at zero area and the coupled bridge would be a mechanism.
  double transverse_string_min_radius = 0.005;
  double bar_min_radius = 0.0;  // [m]; 0 = no minimum
  double gravity = 9.81;        // g [m/s^2], for the deck self-weight
  // "auto" | "direct" | "ipopt" | "nlopt": how the self-stress coefficients are found. "direct"
  // applies when there is at most one self-stress and it loads no bar (every planar bridge);
  // "auto" takes it there and Ipopt elsewhere (the 3D bridge).
  SolverKind solver = SolverKind::kAuto;
  double tolerance = 1e-10;   // relative optimality tolerance of the solver
  int max_iterations = 3000;  // solver iteration limit
  // Members' own weight in the permanent load, iterated with the sizing to a fixed point.
  bool self_weight = true;
  // "column_curve": N <= chi(lambda) A f_y / gamma_M1 (EN 1993-1-1 6.3.1.2); "euler": the
  // paper's A >= 2 l sqrt(SF C / (pi E)) with SF = buckling_safety_factor.
  BarResistanceRule bar_resistance = BarResistanceRule::kColumnCurve;
  double imperfection_factor = 0.49;  // alpha of the column curve (curve c: solid sections)
  // What carries the deck between two stations: "plate", the paper's solid plate of the deck's
  // width; "girders", two steel I-girders under the deck's edges (design/deck_beams.h).
  DeckSection deck_section = DeckSection::kPlate;
  int max_sizings = 25;  // the verified sizing's designs at most (outer iterations)
  // The static utilisation above which the verified sizing does not run the dynamic runs on
  // one of its own designs (it fails whatever they find); the design it delivers runs them.
  double dynamic_screen = 1.1;
  // [deg]: where bridge.beta_deg "auto" searches (config_fields.h says why these ends).
  std::vector<double> beta_range_deg{10.0, 60.0};
  // The strings' stress under the characteristic (serviceability) combinations is held to a
  // serviceability limit (MemberMaterial::ServiceStress): a rod's f_y / gamma_M,ser (EN 1993-2
  // 7.3), a cable's f_const = this ratio x f_uk (EN 1993-1-11 7.2).
  double rod_gamma_m_ser = 1.0;
  double cable_f_const_ratio = 0.5;
  // The fraction of the prestress lost over the bridge's life (relaxation, creep, anchorage
  // set): the design passes with the self-stress reduced by it, the permanent part kept.
  double prestress_loss = 0.05;
  // Each string's fabricated rest length may be off by up to this fraction of its length: the
  // design passes with the prestress at its highest and its lowest so made
  // (design/prestress_states.h).
  double rest_length_tolerance = 0.0;
  // [B]: a design whose estimated peak memory (sizing/memory_estimate.h) exceeds this is refused
  // before any work. Absent: the memory available when the design starts (MemAvailable).
  std::optional<double> memory_limit_bytes;
};

// The actions on a designed bridge and how they combine (EN 1990 6.4.3.2 and 6.5.3), each
// factor configurable. Characteristic actions: permanent G (deck beams, members' self-weight,
// superimposed dead load), payload Q (bridge.payload over the full span and per metre over
// each half), a travelling point load Q_t, transverse wind W (3D bridge) and the paper's
// travelling load (eqs 50-51). Prestress is not factored.
struct LoadsConfig {
  // Which actions enter the design: kPaper (the paper's one case: deck and payload at the
  // drawn geometry, unfactored) or any of the others. The paper's travelling load (eqs 50-51)
  // is the paper's, not a code's action: it is checked when asked for, and is not among the
  // defaults.
  std::vector<LoadFamily> cases{LoadFamily::kPermanent, LoadFamily::kPayload,
                                LoadFamily::kTravelling, LoadFamily::kWind};
  // Whether `cases` lists `family`.
  bool Asks(LoadFamily family) const {
    return std::find(cases.begin(), cases.end(), family) != cases.end();
  }
  double superimposed_dead_n_per_m = 0.0;    // surfacing, railings [N/m], on the deck
  double travelling_load_n = 10000.0;        // Q_t [N]: EN 1991-2 5.3.2.2 Q_fwk for footbridges
  double travelling_speed_m_s = 1.5;         // v [m/s]: walking pace
  double travelling_contact_length_m = 0.1;  // c [m]: Q_fwk's square (EN 1991-2 5.3.2.2)
  double wind_n_per_m = 1200.0;              // transverse line load on the deck [N/m] (3D)
  double wind_rise_s = 1.0;                  // the dynamic check's gust rises over this [s]
  double dynamic_dt_s = 1e-4;                // the step the dynamic check's runs ask for [s]
  // A run of more member-steps (steps x members) is not done: the dynamic check is then not
  // run, and the design INCOMPLETE.
  double dynamic_max_member_steps = 2e9;
  // How the walking load runs: "modal" (checks/modal_run.h: the modes to
  // dynamic_modal_cutoff_hz, the nonlinear run where a string changes state) or "rk4".
  DynamicMethod dynamic_method = DynamicMethod::kModal;
  double dynamic_modal_cutoff_hz = 100.0;  // [Hz]
  // The modal run is done where the bridge's linear deck response to a station's load is within
  // this fraction of its nonlinear one; beyond it the nonlinear run.
  double dynamic_modal_max_nonlinearity = 0.03;
  double gamma_g_sup = 1.35;  // unfavourable permanent
  double gamma_g_inf = 1.0;   // favourable permanent
  double gamma_q = 1.5;       // payload and travelling load
  double gamma_w = 1.5;       // wind
  double psi0_wind = 0.3;     // wind accompanying traffic (EN 1990 A2, footbridges)
  // The "temperature" case: Delta T_N [K] either way, accompanying at psi_0 with gamma_t.
  double temperature_delta_k = 0.0;
  double psi0_temperature = 0.6;
  double gamma_t = 1.5;
  double deflection_limit = 500.0;  // serviceability: deflection <= span / this
  double deck_sag_limit = 300.0;    // serviceability: a deck beam's sag <= its length / this
  double station_margin = 1.0;      // the static check's nonlinear stations (config_fields.h)
};

// Footbridge comfort under pedestrians (checks/comfort_check.h): the Sétra footbridge guide
// (2006) and HiVoSS (2008) load models, and EN 1990 A2.4.3.2's triggers and limits. Each
// constant's source is beside it in design/pedestrian_loads.h.
struct ComfortConfig {
  bool check = true;                               // checked (never with the paper's switches)
  bool sizing_constraint = true;                   // the verified sizing designs to it
  TrafficClass traffic_class = TrafficClass::kII;  // Sétra Stage 1: "I" | "II" | "III" | "IV"
  ComfortLevel comfort_level =
      ComfortLevel::kMean;  // Sétra Stage 2: "maximum" | "mean" | "minimum"
  Construction construction =
      Construction::kSteel;             // the damping ratio's default (Sétra, HiVoSS 4.4.2)
  std::optional<double> damping_ratio;  // xi, (0, 1); absent: the construction's
  double pedestrian_mass_kg = 70.0;     // one pedestrian's mass [kg] (Sétra: 700 N)
  double vertical_trigger_hz = 5.0;     // EN 1990 A2.4.3.2(2): check below this (vertical)
  double horizontal_trigger_hz = 2.5;   // EN 1990 A2.4.3.2(2): lateral
  double torsional_trigger_hz = 5.0;    // Sétra 2006 2.3: torsional modes in the vertical ranges
  double vertical_limit_m_s2 = 0.7;     // EN 1990 A2.4.3.2(1)
  double horizontal_limit_m_s2 = 0.2;   // EN 1990 A2.4.3.2(1), normal use
  double crowd_horizontal_limit_m_s2 = 0.4;  // EN 1990 A2.4.3.2(1), exceptional crowd conditions
};

// The abutments' capacities (checks/static_check.h checks them, the verified sizing designs to
// them). Unset: rigid hinges of unlimited capacity, the paper's supports.
struct SupportsConfig {
  std::optional<double> horizontal_capacity_n;  // [N], per abutment, in-plan vector sum
  std::optional<double> vertical_capacity_n;    // [N], per abutment, |V| (uplift included)
};

// A config describes either a designed bridge ("bridge", with "material" and "design") or a
// custom scene ("structure"); `structure` is set exactly in the second case, and then
// `bridge`, `material` and `design` keep their defaults and are not echoed.
struct Config {
  BridgeConfig bridge;
  Material material;
  DesignConfig design;
  LoadsConfig loads;
  ComfortConfig comfort;
  SupportsConfig supports;
  std::optional<StructureConfig> structure;  // present when the file has a "structure" section
  std::optional<DynamicsConfig> dynamics;    // present when the file has a "dynamics" section
};

// The strings' and bars' materials as resolved from `material` and `design`.
inline MemberMaterial StringMaterial(const Config& c) {
  return StringMaterial(c.material, c.design.yield_safety_factor);
}
inline MemberMaterial BarMaterial(const Config& c) {
  return BarMaterial(c.material, c.design.yield_safety_factor);
}
// The strings' serviceability stress limit [Pa] under the characteristic combinations.
inline double StringServiceStress(const Config& c) {
  return StringMaterial(c).ServiceStress(c.design.rod_gamma_m_ser, c.design.cable_f_const_ratio);
}

// Allowed structural limits checked by ParseConfig (exposed for messages and tests).
inline constexpr int kMaxComplexity = 16;
inline constexpr int kMaxBarsPerModule = 8;

// Parses a whole config; throws ConfigError (key, value, allowed) on any bad or unknown key.
Config ParseConfig(const nlohmann::json& root);
Config LoadConfig(const std::string& path);
// Checks a config built in code as ParseConfig checks a file: every described key of
// `bridge`, `material`, `design`, `loads`, `comfort` and `supports` (or `structure`) and of
// `dynamics` in its range, and the rules across keys. Throws ConfigError naming the key path, the
// value and what is allowed.
void Validate(const Config& config);
// The paper's switches (SPEC.md): its one unfactored load case, no self-weight, yield factor
// 10, plain Euler buckling with factor 1, and in a run no deck inertia and no structure
// weight. The paper's configs write them out.
void ApplyPaperSwitches(Config& config);
// Whether `config` keeps the paper's switches: its one load case, "paper". Such a design is the
// paper's: checked and reported, not resized, and run without the deck's inertia.
bool KeepsPaperSwitches(const Config& config);
// The resolved config, every default filled in, for echoing into outputs.
nlohmann::json ToJson(const Config& config);

}  // namespace tbridge
