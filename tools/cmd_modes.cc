// `tbridge modes CONFIG.json -o OUT.json [--modes K] [--count K] [--quiet]`: the linearised
// vibration modes of a designed bridge, or of a custom "structure", about its static
// equilibrium (dynamics/modal.h).

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/modal_scene.h"
#include "core/config.h"
#include "core/error.h"
#include "core/progress.h"
#include "design/design.h"
#include "design/plausibility.h"
#include "dynamics/deck_motion.h"
#include "dynamics/modal.h"
#include "dynamics/model.h"
#include "tools/commands.h"
#include "tools/output.h"

namespace tbridge::cli {

namespace {

constexpr int kDefaultShapes = 6;
// Without --modes: every mode (dense, O(n_dof^3)) up to this many free DOFs, where it takes
// well under a second (planar n = 7, 508 DOFs: about 0.1 s); beyond, the lowest
// kDefaultLowestModes by the sparse solver (about linear in n_dof).
constexpr int kAllModesMaxDofs = 600;
constexpr int kDefaultLowestModes = 20;

const CommandSpec& ModesSpec() {
  static const CommandSpec spec{
      "modes",
      {"CONFIG.json"},
      {{{"-o", "--output"}, "OUT.json", "where to write the modes, a JSON file", true},
       {{"-m", "--modes"},
        "K",
        "modes to compute, lowest first (0 = all; default all up to 600 free DOFs, else the lowest "
        "20)",
        false},
       {{"-k", "--count"}, "K", "mode shapes to write, lowest first (default 6; 0 = none)", false},
       {{"-q", "--quiet"}, "", "do not print the frequency table", false},
       {{"-M", "--mass"},
        "MODEL",
        "a bridge's mass model: design (default: the deck, the superimposed dead load and the "
        "payload), "
        "crowd (the comfort check's: the traffic class's pedestrians in place of the payload) or "
        "empty "
        "(neither)",
        false},
       ProgressOption(),
       StrictOption()},
      "Designs the bridge of CONFIG.json (or takes its custom \"structure\"), builds its dynamic\n"
      "model (string masses on the bars, eq. 27, unless a \"dynamics\" section says otherwise)\n"
      "and writes its linearised natural frequencies about the static equilibrium, with the bar\n"
      "lengths held, to OUT.json (a structure out of equilibrium is linearised where it stands\n"
      "and its force imbalance reported as equilibrium_residual_N):\n"
      "omega [rad/s], f [Hz], T [s], the symmetry about mid-span, the deck motion each mode is\n"
      "(vertical, lateral, longitudinal, torsional, or local when the deck hardly moves: the "
      "shape\n"
      "projected on the deck's section motions), the shapes of the first K\n"
      "modes and the largest stable RK4 step (from the highest mode, computed in any case).\n"
      "Every mode is computed densely up to 600 free DOFs (planar n <= 7); larger models get\n"
      "the lowest 20 by a sparse Lanczos solver unless --modes says otherwise (all_modes in\n"
      "OUT.json says which). --modes 0 asks for every mode whatever the size: O(n_dof^3)."};
  return spec;
}

// Which modes to compute: --modes K, else all of a small model and the lowest
// kDefaultLowestModes of a large one.
ModalOptions ModalOptionsOf(const ParsedArgs& parsed, const DynamicModel& model) {
  int free_nodes = 0;
  for (const bool fixed : model.fixed) free_nodes += fixed ? 0 : 1;
  const int fallback = free_nodes * model.dim <= kAllModesMaxDofs ? 0 : kDefaultLowestModes;
  ModalOptions options;
  options.count = ParseWholeNumber(parsed, "-m", "--modes", fallback);
  return options;
}

// Symmetry of every mode, or nothing when the structure is not mirror-symmetric about
// mid-span (then some node has no partner and MirrorNodes throws). The mirror map is found
// once for all modes.
std::vector<std::optional<SymmetryReport>> Symmetries(const DynamicModel& model,
                                                      const ModalResult& modes) {
  std::vector<std::optional<SymmetryReport>> out(modes.modes.size());
  std::vector<int> mirror;
  try {
    mirror = MirrorNodes(model.positions);
  } catch (const ModelError&) {
    return out;
  }
  for (size_t k = 0; k < modes.modes.size(); ++k)
    out[k] = ClassifySymmetry(mirror, modes.modes[k].shape);
  return out;
}

// The deck motion of every mode of a model with deck nodes (a designed bridge); nothing for a
// custom structure.
std::vector<std::optional<DeckMotionReport>> Motions(const DynamicModel& model,
                                                     const ModalResult& modes) {
  std::vector<std::optional<DeckMotionReport>> out(modes.modes.size());
  if (model.deck_nodes.empty()) return out;
  for (size_t k = 0; k < modes.modes.size(); ++k)
    out[k] = ProjectOnDeckMotions(model, modes.modes[k].shape);
  return out;
}

nlohmann::json ModesToJson(const Config& config, const DynamicModel& model,
                           const ModalResult& result,
                           const std::vector<std::optional<SymmetryReport>>& symmetry,
                           const std::vector<std::optional<DeckMotionReport>>& motion, int shapes,
                           const std::string& mass_model) {
  nlohmann::json modes = nlohmann::json::array();
  bool stable = true;
  for (size_t k = 0; k < result.modes.size(); ++k) {
    const Mode& m = result.modes[k];
    stable = stable && m.omega_squared > 0;
    nlohmann::json entry = {
        {"index", k + 1},         {"omega_rad_s", m.omega_rad_s}, {"frequency_hz", m.frequency_hz},
        {"period_s", m.period_s}, {"symmetry", nullptr},          {"symmetry_correlation", nullptr},
        {"motion", nullptr},      {"motion_share", nullptr}};
    if (motion[k]) {
      entry["motion"] = NameOf(motion[k]->motion);
      const int which = static_cast<int>(motion[k]->motion);
      entry["motion_share"] = which < 4 ? motion[k]->share[which] : 0.0;
    }
    if (symmetry[k]) {
      entry["symmetry"] = SymmetryName(symmetry[k]->symmetry);
      entry["symmetry_correlation"] = symmetry[k]->correlation;
    }
    modes.push_back(entry);
  }
  nlohmann::json shape_list = nlohmann::json::array();
  for (int k = 0; k < shapes && k < static_cast<int>(result.modes.size()); ++k) {
    nlohmann::json nodes = nlohmann::json::array();
    const Eigen::Matrix3Xd& s = result.modes[k].shape;
    for (Eigen::Index a = 0; a < s.cols(); ++a) nodes.push_back({s(0, a), s(1, a), s(2, a)});
    shape_list.push_back({{"index", k + 1}, {"displacements", nodes}});
  }
  nlohmann::json out;
  out["config"] = ToJson(config);
  out["model"] = {{"mass", mass_model},
                  {"dim", model.dim},
                  {"nodes", model.num_nodes()},
                  {"bars", model.bars.size()},
                  {"strings", model.strings.size()},
                  {"free_dofs", result.free_dofs},
                  {"bar_constraints", result.constraints},
                  {"slack_strings", result.slack_strings},
                  {"equilibrium_residual_N", result.equilibrium_residual}};
  // With only the lowest modes, "stable" speaks for those (the sparse solver finds unstable
  // modes near zero first).
  out["stable"] = stable;
  out["all_modes"] = result.all_modes;
  out["rk4_stable_dt_s"] =
      result.modes.empty() ? nlohmann::json(nullptr) : nlohmann::json(Rk4StableStep(result));
  out["modes"] = modes;
  out["mode_shapes"] = shape_list;
  out["units"] = {{"omega_rad_s", "rad/s"},
                  {"frequency_hz", "Hz"},
                  {"period_s", "s"},
                  {"rk4_stable_dt_s", "s"},
                  {"equilibrium_residual_N", "N"},
                  {"displacements", "m/sqrt(kg), mass-normalised: shape^T M shape = 1"}};
  return out;
}

std::string ModesTable(const ModalResult& result,
                       const std::vector<std::optional<SymmetryReport>>& symmetry,
                       const std::vector<std::optional<DeckMotionReport>>& motion, int max_rows) {
  std::ostringstream out;
  if (!result.all_modes) out << "lowest " << result.modes.size() << " of ";
  out << result.total_modes << " modes (" << result.free_dofs << " free DOFs, "
      << result.constraints << " bar lengths held)\n";
  out << "  mode   omega [rad/s]      f [Hz]       T [s]  symmetry       motion\n";
  char line[160];
  for (size_t k = 0; k < result.modes.size() && static_cast<int>(k) < max_rows; ++k) {
    const Mode& m = result.modes[k];
    std::snprintf(line, sizeof line, "%6zu %15.4g %11.4g %11.4g  %-13s  %s\n", k + 1, m.omega_rad_s,
                  m.frequency_hz, m.period_s,
                  symmetry[k] ? SymmetryName(symmetry[k]->symmetry) : "-",
                  motion[k] ? NameOf(motion[k]->motion) : "-");
    out << line;
  }
  if (static_cast<int>(result.modes.size()) > max_rows) {
    out << "  ... " << result.modes.size() - max_rows << " more in the output file\n";
  }
  if (!result.modes.empty()) out << "RK4 stable for dt < " << Rk4StableStep(result) << " s\n";
  return out.str();
}

int RunModesCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = ModesSpec();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  const std::string out_path = parsed.Required("-o");
  const int shapes = ParseWholeNumber(parsed, "-k", "--count", kDefaultShapes);
  const Config config = LoadConfig(parsed.positionals[0]);
  // Staged before the work: an unwritable OUT.json fails at once and changes only at Commit().
  OutputTransaction outputs;
  outputs.ProtectInput(parsed.positionals[0]);
  std::ostream& json = outputs.Stage(out_path);
  ProgressReporter progress(ProgressReporter::Wanted(parsed.Flag("--progress")));
  const std::string mass_text = parsed.Value("-M").value_or("design");
  const std::optional<ModalMassModel> parsed_mass = ValueIn(kModalMassModelNames, mass_text);
  if (!parsed_mass) {
    throw UsageError("--mass expects design, crowd or empty, got '" + mass_text + "'");
  }
  const ModalMassModel mass_model = *parsed_mass;
  if (mass_model != ModalMassModel::kDesign && config.structure) {
    throw UsageError("--mass " + mass_text +
                     " needs a bridge config (a custom structure gives its own masses)");
  }
  // The verified bridge tbridge design writes, so that the modes are those of the bridge the
  // other commands analyse; or the custom structure.
  const ModalScene scene = ModalSceneOf(config, &progress, mass_model);
  const DynamicModel& model = scene.model;
  const std::optional<Design>& design = scene.design;
  progress.Stage("modes");
  const ModalResult result = ComputeModes(model, ModalOptionsOf(parsed, model));
  progress.Finish();
  if (design) ReportWarnings(PlausibilityWarnings(*design), parsed.Flag("--strict"));
  const auto symmetry = Symmetries(model, result);
  const auto motion = Motions(model, result);
  json << ModesToJson(config, model, result, symmetry, motion, shapes,
                      config.structure ? "structure" : NameOf(mass_model))
              .dump(2)
       << "\n";
  outputs.Commit();
  if (!parsed.Flag("-q"))
    std::cout << ModesTable(result, symmetry, motion, 20) << "wrote " << out_path << "\n";
  return 0;
}

const CommandRegistrar kRegisterModes(
    "modes", "linearised natural frequencies and mode shapes of a design or structure",
    &RunModesCommand);

}  // namespace

}  // namespace tbridge::cli
