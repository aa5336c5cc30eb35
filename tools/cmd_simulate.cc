// `tbridge simulate CONFIG.json -o OUTDIR [--vtk DIR] [--quiet] [--progress] [--strict]`: a
// dynamic scenario (the config's "dynamics" section) of the designed bridge or of the config's
// custom "structure". Writes OUTDIR/summary.json and, when nodes are recorded and
// record.csv is on, OUTDIR/history.csv, plus the VTK series with --vtk: all in one
// OutputTransaction, so a failed run changes nothing and a successful one removes its own
// stale files (an old history.csv, surplus run_<k>.vtp).

#include <charconv>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/error.h"
#include "core/progress.h"
#include "design/plausibility.h"
#include "dynamics/model.h"
#include "app/scenario.h"
#include "tools/background_history.h"
#include "tools/fast_g12.h"
#include "tools/commands.h"
#include "tools/output.h"
#include "verify/verified_design.h"
#include "tools/vtk_export.h"

namespace tbridge::cli {

namespace {

const CommandSpec& SimulateSpec() {
  static const CommandSpec spec{
      "simulate",
      {"CONFIG.json"},
      {{{"-o", "--output"}, "OUTDIR", "directory for summary.json and history.csv", true},
       {{"-q", "--quiet"}, "", "do not print the summary", false},
       {{"--vtk"}, "DIR", "also write a ParaView time series (DIR/run.pvd + run_<k>.vtp)", false},
       ProgressOption(),
       StrictOption()},
      "Designs the bridge of CONFIG.json (or takes its custom \"structure\"), builds its dynamic\n"
      "model and runs the scenario of its \"dynamics\" section (keys in configs/README.md). Writes OUTDIR/summary.json (the resolved\n"
      "config, frequency, stresses, slack events, bar-length error, energy balance) and\n"
      "OUTDIR/history.csv (t, then x, y[, z] of every recorded node). A run that fails\n"
      "changes nothing on disk; a successful run replaces its own files in OUTDIR (and DIR) and\n"
      "removes its stale ones (history.csv when record.csv is off), leaving other files alone.\n"
      "Steps and output bytes are checked before the run (dynamics.limits). Look at a result\n"
      "with tools/plot_dynamics.py snapshots|deck OUTDIR -o FIG.png, or open DIR/run.pvd in\n"
      "ParaView."};
  return spec;
}

std::string MemberName(int i, int j) { return std::to_string(i + 1) + "-" + std::to_string(j + 1); }

// The model's geometry as plots need it: equilibrium node positions (1-based order), bars,
// and strings with their rest lengths (after prestrain), so that slack strings (s < L0) can be
// found from any recorded state.
nlohmann::json ModelMembersJson(const DynamicModel& model) {
  nlohmann::json nodes = nlohmann::json::array(), bars = nlohmann::json::array(),
                 strings = nlohmann::json::array();
  for (int v = 0; v < model.num_nodes(); ++v) {
    nodes.push_back({model.positions(0, v), model.positions(1, v), model.positions(2, v)});
  }
  for (const DynamicBar& b : model.bars) bars.push_back({{"nodes", {b.i + 1, b.j + 1}}});
  for (size_t k = 0; k < model.strings.size(); ++k) {
    const DynamicString s = model.strings[k];
    strings.push_back({{"nodes", {s.i + 1, s.j + 1}},
                       {"group", model.names.string_group[k]},
                       {"rest_length_m", s.rest_length}});
  }
  std::vector<int> fixed;
  for (int v = 0; v < model.num_nodes(); ++v) {
    if (model.fixed[v]) fixed.push_back(v + 1);
  }
  return {{"positions", nodes}, {"fixed", fixed}, {"bars", bars}, {"strings", strings}};
}

nlohmann::json SummaryJson(const Config& config, const DynamicModel& model, const SimulationResult& r) {
  const SimulationSummary& s = r.summary;
  nlohmann::json j;
  j["config"] = ToJson(config);
  nlohmann::json classes = nlohmann::json::array();
  const auto groups = BarLengthClasses(model);
  for (size_t c = 0; c < groups.size(); ++c) {
    nlohmann::json bars = nlohmann::json::array();
    for (const int k : groups[c]) bars.push_back(MemberName(model.bars[k].i, model.bars[k].j));
    classes.push_back({{"class", c + 1}, {"length_m", model.bars[groups[c].front()].length}, {"bars", bars}});
  }
  j["model"] = {{"dim", model.dim},
                {"nodes", model.num_nodes()},
                {"bars", model.bars.size()},
                {"strings", model.strings.size()},
                {"moving_mass_kg", MovingMass(model)},
                {"bar_length_classes", classes},
                {"members", ModelMembersJson(model)}};
  j["run"] = {{"integrator", s.integrator}, {"substeps", s.substeps}, {"engine", s.engine}, {"steps", s.steps},
              {"rejected_steps", s.rejected},
              {"evaluations", s.evaluations}, {"duration_s", s.duration}, {"wall_s", s.wall_seconds}};
  if (s.has_frequency) {
    j["frequency"] = {{"method", "dominant spectral peak of the summed vertical deck displacement"},
                      {"periods", {s.frequency.period_s}},
                      {"period_s", s.frequency.period_s},
                      {"frequency_hz", s.frequency.frequency_hz},
                      {"omega_rad_s", s.frequency.omega_rad_s},
                      {"amplitude_m", s.frequency.amplitude}};
    // A second estimate of the same signal: agrees with the spectral peak for periodic motion.
    j["frequency"]["crossings"] =
        s.crossing_frequency
            ? nlohmann::json{{"method", "mean spacing of the mean-level crossings"},
                             {"period_s", s.crossing_frequency->period_s},
                             {"omega_rad_s", s.crossing_frequency->omega_rad_s},
                             {"cycles", s.crossing_frequency->cycles}}
            : nlohmann::json(nullptr);
    // The summed signal shows only the symmetric modes; the mirror-odd projection the rest.
    j["frequency"]["antisymmetric"] =
        s.antisymmetric_frequency
            ? nlohmann::json{{"method", "dominant spectral peak of the deck displacement projected on the "
                                        "mirror-odd shape (+1 left of mid-span, -1 right)"},
                             {"period_s", s.antisymmetric_frequency->period_s},
                             {"omega_rad_s", s.antisymmetric_frequency->omega_rad_s},
                             {"frequency_hz", s.antisymmetric_frequency->frequency_hz}}
            : nlohmann::json(nullptr);
  } else if (!s.frequency_note.empty()) {
    j["frequency"] = {{"note", s.frequency_note}};
  }
  j["max_string_stress"] = {{"stress_pa", s.max_string_stress},
                            {"string", s.max_stress_string},
                            {"time_s", s.max_stress_time},
                            {"allowed_pa", s.allowed_stress},
                            {"exceeds_allowed", s.stress_exceeds_allowed}};
  nlohmann::json per_string = nlohmann::json::object();
  for (size_t k = 0; k < s.slack.per_string.size(); ++k) {
    if (s.slack.per_string[k] > 0) per_string[model.names.string_name[k]] = s.slack.per_string[k];
  }
  j["slack"] = {{"transitions", s.slack.total},
                {"per_string", per_string},
                {"slack_at_start", s.slack.slack_at_start},
                {"slack_at_end", s.slack.slack_at_end},
                {"strings_ever_slack", s.slack.ever_slack}};
  j["max_bar_length_error"] = s.max_bar_length_error;
  nlohmann::json peak = nlohmann::json::object();
  for (int d = 0; d < model.dim; ++d) {
    const int node = s.peak_deck_node[d];
    peak[std::string(1, "xyz"[d])] = {{"displacement_m", s.peak_deck_displacement[d]},
                                      {"node", node >= 0 ? nlohmann::json(node + 1) : nlohmann::json()},
                                      {"time_s", s.peak_deck_time[d]}};
  }
  j["peak_deck_displacement"] = peak;
  if (!s.peak_bar_compression.empty()) {
    nlohmann::json bars = nlohmann::json::array();
    for (size_t k = 0; k < model.bars.size(); ++k) {
      bars.push_back({{"bar", MemberName(model.bars[k].i, model.bars[k].j)},
                      {"compression_n", s.peak_bar_compression[k]},
                      {"tension_n", s.peak_bar_tension[k]}});
    }
    j["bar_force_peaks"] = bars;
  }
  const EnergyBalance& e = s.energy;
  j["energy"] = {{"kinetic_start_j", e.kinetic_start}, {"elastic_start_j", e.elastic_start},
                 {"kinetic_end_j", e.kinetic_end},     {"elastic_end_j", e.elastic_end},
                 {"external_work_j", e.external_work}, {"dissipated_j", e.dissipated},
                 {"reference_j", e.reference},         {"max_relative_drift", e.max_drift},
                 {"final_relative_drift", e.final_drift}};
  if (!s.prestrain.empty()) {
    nlohmann::json p = nlohmann::json::array();
    for (const PrestrainReport& pr : s.prestrain) {
      p.push_back({{"group", pr.group},
                   {"ratio", pr.ratio},
                   {"strings", pr.strings},
                   {"implied_stress_pa", pr.max_stress},
                   {"allowed_pa", pr.allowed_stress},
                   {"yield_pa", pr.yield_stress},
                   {"exceeds_allowed", pr.exceeds_allowed}});
    }
    j["prestrain"] = p;
  }
  return j;
}

// history.csv as the run records: t, then x, y[, z] of every recorded node, 12 digits. Rows
// gather in a buffer of kFlushBytes and more before they go to the stream: the file stream
// hands a write of 1 kB or more straight to the kernel, and a system call per row of the
// MOTES prism (73 values) cost more than formatting it.
class CsvHistory : public HistorySink {
 public:
  // The buffer is made with the history's stream, when the output is staged, as the stream's
  // own buffer is made when it is opened: its pages' first touch (10-18 us each on this
  // machine) then falls before the run, not in its first rows. Begin grows it for a row wider
  // than kRowRoom.
  explicit CsvHistory(std::ostream& out) : out_(out), buffer_(kFlushBytes + kRowRoom) {}
  void Begin(const DynamicModel& model, const std::vector<int>& recorded_nodes) override {
    columns_ = model.dim * static_cast<int>(recorded_nodes.size());
    const size_t row_chars = static_cast<size_t>(columns_ + 1) * kMaxNumberChars + 1;
    if (buffer_.size() < kFlushBytes + row_chars) buffer_.resize(kFlushBytes + row_chars);
    // The header goes into the buffer too (",z123" is at most a number's room): the stream's
    // own buffer is then never touched.
    char* p = buffer_.data();
    *p++ = 't';
    for (const int node : recorded_nodes) {
      for (int d = 0; d < model.dim; ++d) {
        *p++ = ',';
        *p++ = "xyz"[d];
        p = std::to_chars(p, p + 16, node + 1).ptr;
      }
    }
    *p++ = '\n';
    used_ = static_cast<size_t>(p - buffer_.data());
    if (used_ >= kFlushBytes) Flush();
  }
  // 12 significant digits, as printf's %.12g, formatted by FormatG12 into one buffer per row:
  // the stream's own formatting cost 2 us a row of 73 values (the MOTES prism's history every
  // 10 steps was two thirds of its run), std::to_chars 60-90 ns a value, FormatG12 10-20.
  void Row(double t, const double* coordinates) override {
    char* const start = buffer_.data() + used_;
    char* p = Append(start, t);
    for (int c = 0; c < columns_; ++c) {
      *p++ = ',';
      p = Append(p, coordinates[c]);
    }
    *p++ = '\n';
    used_ += static_cast<size_t>(p - start);
    if (used_ >= kFlushBytes) Flush();
  }
  // The rows still buffered, to the stream: after the run's last row.
  void Flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(used_));
    used_ = 0;
  }

 private:
  // "-1.23456789012e-308" and the comma are 20; FormatG12 may store up to 32 from a number's
  // start, so every number is given 32.
  static constexpr int kMaxNumberChars = 32;
  // 16 kB: on this machine a first touch of a fresh page costs 10-18 us, so a 64 kB buffer cost
  // 0.3 ms before its first row; 4 kB made four times the system calls. Measured in-run on the
  // MOTES prism, best of 15 interleaved: 7.45 ms (4 kB), 7.38 (8), 7.23 (16), 7.35 (32), 7.50 (64).
  static constexpr size_t kFlushBytes = 16 * 1024;
  static constexpr size_t kRowRoom = 4096;  // a row of up to 127 numbers
  static char* Append(char* p, double v) { return FormatG12(p, p + 24, v); }
  std::ostream& out_;
  int columns_ = 0;
  std::vector<char> buffer_;  // kFlushBytes and room for one more row
  size_t used_ = 0;
};

class DiscardHistory : public HistorySink {
 public:
  void Begin(const DynamicModel&, const std::vector<int>&) override {}
  void Row(double, const double*) override {}
};

int RunSimulateCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = SimulateSpec();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  const std::string out_dir = parsed.Required("-o");
  const Config config = LoadConfig(parsed.positionals[0]);
  const auto vtk_dir = parsed.Value("--vtk");
  const bool csv = config.dynamics && config.dynamics->record.csv && !config.dynamics->record.nodes.empty();

  // Every output staged before the run, so a location that cannot be written fails at once;
  // nothing in OUTDIR or DIR changes before Commit().
  OutputTransaction outputs;
  outputs.ProtectInput(parsed.positionals[0]);
  std::ostream& summary_out = outputs.Stage(out_dir + "/summary.json");
  std::ostream* history_out = nullptr;
  if (csv) {
    history_out = &outputs.Stage(out_dir + "/history.csv");
  } else {
    outputs.RemoveAtCommit(out_dir + "/history.csv");  // an earlier run's, not this one's
  }
  std::ostream* pvd_out = nullptr;
  if (vtk_dir) {
    pvd_out = &outputs.Stage(*vtk_dir + "/run.pvd");
    outputs.RemoveStaleAtCommit(*vtk_dir, "run_", ".vtp");
  }

  ProgressReporter progress(ProgressReporter::Wanted(parsed.Flag("--progress")));
  RunHooks hooks;
  hooks.progress = &progress;
  // History and VTK stream to their staged files as the run records.
  std::unique_ptr<CsvHistory> csv_history;
  std::unique_ptr<VtkHistory> vtk_history;
  if (history_out != nullptr) {
    csv_history = std::make_unique<CsvHistory>(*history_out);
    hooks.history.push_back(csv_history.get());
  }
  if (vtk_dir) {
    vtk_history = std::make_unique<VtkHistory>(
        *pvd_out, [&](const std::string& name, const std::string& content) { outputs.Stage(*vtk_dir + "/" + name, content); });
    hooks.history.push_back(vtk_history.get());
  }
  if (vtk_dir) hooks.extra_bytes_per_record = [](const DynamicModel& m) { return VtkBytesPerSample(m); };
  // Without the CSV and VTK the rows have nowhere to go: dropped, not held in memory.
  DiscardHistory discard;
  if (hooks.history.empty()) hooks.history.push_back(&discard);
  // Formatted on a second thread while the run steps on; after the sinks, so it stops first.
  std::unique_ptr<BackgroundHistory> background;
  if (history_out != nullptr || vtk_dir) {
    background = std::make_unique<BackgroundHistory>(hooks.history, /*always=*/vtk_dir.has_value());
    hooks.history = {background.get()};
  }
  // Under --strict an implausible design stops before the run; otherwise its warnings are
  // printed after the run, not across the progress line.
  std::vector<std::string> warnings;
  const auto check_design = [&](const Design& design) {
    warnings = PlausibilityWarnings(design);
    if (parsed.Flag("--strict")) ReportWarnings(warnings, true);
  };
  // The bridge tbridge design writes: verified and resized (the paper's configs keep the
  // paper's design, which needs no check to be simulated).
  const bool paper = KeepsPaperSwitches(config);
  const auto verified = [](const Config& c) { return DesignAndVerify(c); };
  const ScenarioResult scenario =
      RunScenario(config, hooks, check_design, paper ? std::function<Design(const Config&)>{} : verified);
  if (background) background->Finish();
  if (csv_history) csv_history->Flush();
  progress.Finish();
  ReportWarnings(warnings, false);
  const DynamicModel& model = scenario.model;
  const SimulationResult& result = scenario.simulation;

  summary_out << SummaryJson(config, model, result).dump(2) << "\n";
  if (vtk_history) vtk_history->Finish();
  outputs.Commit();
  if (!parsed.Flag("-q")) {
    const SimulationSummary& s = result.summary;
    std::cout << "simulated " << s.duration << " s in " << s.steps << " steps (" << s.integrator;
    if (s.substeps > 1) std::cout << " x " << s.substeps << " sub-steps";
    std::cout << ", " << s.engine << ", " << s.wall_seconds << " s)\n";
    if (s.has_frequency) {
      std::cout << "deck frequency: T = " << s.frequency.period_s << " s, f = " << s.frequency.frequency_hz
                << " Hz, omega = " << s.frequency.omega_rad_s << " rad/s\n";
    } else if (!s.frequency_note.empty()) {
      std::cout << s.frequency_note << "\n";  // "no deck frequency: ..." and why
    }
    if (!model.deck_nodes.empty()) {
      std::cout << "peak deck displacement";
      for (int d = 0; d < model.dim; ++d) {
        std::cout << (d > 0 ? ", " : " ") << "xyz"[d] << " " << s.peak_deck_displacement[d] << " m";
      }
      std::cout << "\n";
    }
    if (s.allowed_stress > 0) {  // a structure without string areas has no stress to report
      std::cout << "max string stress " << s.max_string_stress << " Pa (allowed " << s.allowed_stress << ")"
                << (s.stress_exceeds_allowed ? " EXCEEDS ALLOWED" : "") << "\n";
    }
    std::cout << "slack transitions " << s.slack.total << ", max bar-length error " << s.max_bar_length_error
              << ", energy drift " << s.energy.max_drift << "\n";
    for (const PrestrainReport& p : s.prestrain) {
      std::cout << "prestrain " << p.group << " " << p.ratio << ": implied stress " << p.max_stress << " Pa"
                << (p.exceeds_allowed ? " exceeds the allowed " : " within the allowed ") << p.allowed_stress
                << " Pa\n";
    }
    std::cout << "wrote " << out_dir << "/summary.json" << (csv ? " and history.csv" : "") << "\n";
  }
  return 0;
}

const CommandRegistrar kRegisterSimulate("simulate",
                                         "dynamic scenario of CONFIG.json, written to OUTDIR",
                                         &RunSimulateCommand);

}  // namespace

}  // namespace tbridge::cli
