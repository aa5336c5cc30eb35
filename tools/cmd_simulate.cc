// `tbridge simulate CONFIG.json|DESIGN.json -o OUTDIR [--vtk DIR] [--quiet] [--progress]
// [--strict]`: a dynamic scenario (the config's "dynamics" section) of the designed bridge or of
// the config's custom "structure", or of a written design file (its config's "dynamics" section,
// the design as written or, edited, as built). Writes OUTDIR/summary.json and, when nodes are
// recorded and record.csv is on, OUTDIR/history.csv, plus the VTK series with --vtk: all in one
// OutputTransaction, so a failed run changes nothing and a successful one removes its own
// stale files (an old history.csv, an earlier version's run.pvd and run_<k>.vtp).

#include <charconv>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/scenario.h"
#include "app/simulation_report.h"
#include "core/config.h"
#include "core/error.h"
#include "core/json_reader.h"
#include "core/progress.h"
#include "design/plausibility.h"
#include "dynamics/model.h"
#include "io/design_reader.h"
#include "tools/background_history.h"
#include "tools/commands.h"
#include "tools/fast_g12.h"
#include "tools/output.h"
#include "tools/vtk_export.h"

namespace tbridge::cli {

namespace {

const CommandSpec& SimulateSpec() {
  static const CommandSpec spec{
      "simulate",
      {"CONFIG.json|DESIGN.json"},
      {{{"-o", "--output"}, "OUTDIR", "directory for summary.json and history.csv", true},
       {{"-q", "--quiet"}, "", "do not print the summary", false},
       {{"--vtk"},
        "DIR",
        "also write a ParaView time series (DIR/run.xdmf + its data DIR/run.bin)",
        false},
       ProgressOption(),
       StrictOption()},
      "Designs the bridge of CONFIG.json (or takes its custom \"structure\"), builds its dynamic\n"
      "model and runs the scenario of its \"dynamics\" section (keys in configs/README.md). Given\n"
      "DESIGN.json, a file written by tbridge design or check, it runs the \"dynamics\" section "
      "of\n"
      "the design's own config on that design as written (edited members: as built, as tbridge\n"
      "check reads them). Writes OUTDIR/summary.json (the resolved\n"
      "config, frequency, stresses, slack events, bar-length error, energy balance) and\n"
      "OUTDIR/history.csv (t, then x, y[, z] of every recorded node). A run that fails\n"
      "changes nothing on disk; a successful run replaces its own files in OUTDIR (and DIR) and\n"
      "removes its stale ones (history.csv when record.csv is off), leaving other files alone.\n"
      "Steps and output bytes are checked before the run (dynamics.limits). Look at a result\n"
      "with tools/plot_dynamics.py snapshots|deck OUTDIR -o FIG.png, or open DIR/run.xdmf in\n"
      "ParaView."};
  return spec;
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

// The run's summary as the command prints it: the run, the deck frequency and displacement,
// the string stress, the slack and error measures and the prestrains.
void PrintSimulation(const DynamicModel& model, const SimulationSummary& s) {
  std::cout << "simulated " << s.duration << " s in " << s.steps << " steps (" << s.integrator;
  if (s.substeps > 1) std::cout << " x " << s.substeps << " sub-steps";
  std::cout << ", " << s.engine << ", " << s.wall_seconds << " s)\n";
  if (s.has_frequency) {
    std::cout << "deck frequency: T = " << s.frequency.period_s
              << " s, f = " << s.frequency.frequency_hz
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
    std::cout << "max string stress " << s.max_string_stress << " Pa (allowed " << s.allowed_stress
              << ")" << (s.stress_exceeds_allowed ? " EXCEEDS ALLOWED" : "") << "\n";
  }
  std::cout << "slack transitions " << s.slack.total << ", max bar-length error "
            << s.max_bar_length_error << ", energy drift " << s.energy.max_drift << "\n";
  for (const PrestrainReport& p : s.prestrain) {
    std::cout << "prestrain " << NameOf(p.group) << " " << p.ratio << ": implied stress "
              << p.max_stress << " Pa"
              << (p.exceeds_allowed ? " exceeds the allowed " : " within the allowed ")
              << p.allowed_stress << " Pa\n";
  }
}

int RunSimulateCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = SimulateSpec();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  const std::string out_dir = parsed.Required("-o");
  // A design file (written by tbridge design or check: config, nodes and members) or a config.
  const nlohmann::json input = ReadJsonFile(parsed.positionals[0]);
  std::optional<Design> written;
  if (input.is_object() && input.contains("members") && input.contains("config"))
    written = ReadDesign(input);
  const Config config = written ? written->config : ParseConfig(input);
  const auto vtk_dir = parsed.Value("--vtk");
  const bool csv =
      config.dynamics && config.dynamics->record.csv && !config.dynamics->record.nodes.empty();

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
  std::ostream* xdmf_out = nullptr;
  std::ostream* bin_out = nullptr;
  if (vtk_dir) {
    xdmf_out = &outputs.Stage(*vtk_dir + "/run.xdmf");
    bin_out = &outputs.Stage(*vtk_dir + "/run.bin");
    // The one-file-per-sample series of earlier versions (run.pvd, run_<k>.vtp): not this run's.
    outputs.RemoveAtCommit(*vtk_dir + "/run.pvd");
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
    vtk_history = std::make_unique<VtkHistory>(*xdmf_out, *bin_out);
    hooks.history.push_back(vtk_history.get());
  }
  if (vtk_dir)
    hooks.extra_bytes_per_record = [](const DynamicModel& m) { return VtkBytesPerSample(m); };
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
  const ScenarioResult scenario = written ? RunDesignScenario(*written, hooks, check_design)
                                          : RunSimulateScenario(config, hooks, check_design);
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
    PrintSimulation(model, result.summary);
    std::cout << "wrote " << out_dir << "/summary.json" << (csv ? " and history.csv" : "") << "\n";
  }
  return 0;
}

const CommandRegistrar kRegisterSimulate("simulate",
                                         "dynamic scenario of CONFIG.json, written to OUTDIR",
                                         &RunSimulateCommand);

}  // namespace

}  // namespace tbridge::cli
