// Reproduction of the paper's Tables 1-6 from the shipped configs, each computed value next
// to the printed one (reference values: configs/reference/paper_tables_*.json).
#pragma once

#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace tbridge {

class ProgressReporter;

// One compared number. Tables 1-4 use SPEC.md §5's rule (absolute: half a unit of the last
// printed digit, radii to 0.05 mm); Tables 5-6 use SPEC.md §9's relative tolerances.
struct PaperCheck {
  int table = 0;
  std::string item;  // e.g. "n=2 cable 4-7 r [mm]" or "n=3 delta=[0,0.1,0] omega [rad/s]"
  double computed = 0;
  double printed = 0;
  double tolerance = 0;  // absolute (tables 1-4) or relative (tables 5-6)
  bool relative = false;
  bool pass = false;
  double relative_error() const { return printed != 0 ? (computed - printed) / printed : 0.0; }
};

struct PaperReproduction {
  std::vector<PaperCheck> checks;
  // {table1: [...], tables2_4: [...], table5: [{n, delta, T_s, frequency_hz, omega_rad_s,
  //  paper_omega_rad_s}], table6: [{n, delta, prestrain, omega_rad_s, paper_omega_rad_s}],
  //  section7_3: [{run, peak_displacement_m {x, y, z}, peak_node, max_string_stress_pa,
  //  allowed_stress_pa, slack_transitions, max_bar_length_error}]}
  nlohmann::json json;
  int runs = 0;  // dynamic simulations actually run (identical configs run once)
};

// Relative tolerances of SPEC.md §9, with their reasons:
// Table 5: the paper's "mean angular frequency" of slack-cable bouncing is reproduced to a
// mean 3.8 % with a +-2 % spread across dt, stabilisation and estimator: 8 % per entry.
inline constexpr double kTable5Tolerance = 0.08;
// Table 5, n >= 2: the bouncing is chaotic; designs that differ by 1e-10 (the exact optimum,
// or an interior point on the self-stress or on the full problem) move n = 3, class 3 between
// 67.7 and 69.2 rad/s, a further 2 %: 10 %.
inline constexpr double kTable5ChaoticTolerance = 0.10;
// Table 6, n = 1: periodic motion, reproduced to 0.3 %: 2 %.
inline constexpr double kTable6PeriodicTolerance = 0.02;
// Table 6, n >= 2: the paper's values scatter by 5-19 % (probably read off its charts; its two
// n = 2 values differ by 1.41x while ours barely depend on the perturbed bars): 25 %.
inline constexpr double kTable6IrregularTolerance = 0.25;

// Table number of the paper's Sect. 7.3 runs (the 3D bridge under a travelling load and under
// wind): the paper gives figures only, so these rows report peaks, not comparisons.
inline constexpr int kSection73 = 7;

// Runs the requested tables (1..6, and kSection73) from the configs in `configs_dir`
// (paper_n*.json, paper_t5_*.json, paper_t6_*.json, paper_3d_*.json and reference/). Throws
// ConfigError when a config or the reference data is missing or bad, ModelError when a design or
// run fails. `progress` (optional) is told each design and run as a stage named after its config.
PaperReproduction ReproducePaper(const std::string& configs_dir, const std::set<int>& tables,
                                 ProgressReporter* progress = nullptr);

}  // namespace tbridge
