// `tbridge paper [--tables LIST] [--json FILE] [--configs DIR]`: reproduces the paper's
// Tables 1-6 from the shipped configs and prints each value beside the printed one.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/paper_tables.h"
#include "core/error.h"
#include "core/progress.h"
#include "tools/commands.h"
#include "tools/output.h"

namespace tbridge::cli {

namespace {

const CommandSpec& PaperSpec() {
  static const CommandSpec spec{
      "paper",
      {},
      {{{"--tables"},
        "LIST",
        "comma-separated tables to run, e.g. 1,2,5; 7 = the 3D runs of "
        "Sect. 7.3 (default: 1-7)",
        false},
       {{"--json"}, "FILE", "also write the reproduced tables as JSON", false},
       {{"--configs"},
        "DIR",
        "folder with paper_*.json and reference/ (default: ./configs, "
        "else the source tree's configs/)",
        false},
       ProgressOption()},
      "Designs the paper's bridges and runs its dynamic cases from the shipped configs, then\n"
      "prints every number of Tables 1-6 beside the printed value with its error and tolerance,\n"
      "and the peaks of the 3D runs of Sect. 7.3 (travelling load, wind)\n"
      "(SPEC rules: Tables 1-4 to half a unit of the last printed digit, Table 5 to 8 %\n"
      "for n = 1 and 10 % for the chaotic n >= 2, Table 6 to 2 % for n = 1 and 25 % for\n"
      "n >= 2). Exits 1 if any value is out of tolerance (the exit codes are listed by\n"
      "'tbridge --help')."};
  return spec;
}

std::set<int> ParseTables(const std::string& list) {
  std::set<int> tables;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.size() != 1 || item[0] < '1' || item[0] > '7') {
      throw OptionError("--tables", "\"" + list + "\"",
                        "must list table numbers 1-6 (7: Sect. 7.3's 3D runs), e.g. 1,5,6");
    }
    tables.insert(item[0] - '0');
  }
  if (tables.empty()) throw OptionError("--tables", "\"\"", "must list at least one table 1-7");
  return tables;
}

std::string DefaultConfigs() {
  if (std::filesystem::exists("configs/reference/paper_tables_1_4.json")) return "configs";
  return std::string(TBRIDGE_SOURCE_DIR) + "/configs";
}

int RunPaper(const std::vector<std::string>& args) {
  const CommandSpec& spec = PaperSpec();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  const std::set<int> tables = ParseTables(parsed.Value("--tables").value_or("1,2,3,4,5,6,7"));
  const std::string dir = parsed.Value("--configs").value_or(DefaultConfigs());
  // Staged before the runs: an unwritable --json fails at once, not after them.
  OutputTransaction outputs;
  std::ostream* json_out = nullptr;
  if (const auto path = parsed.Value("--json")) json_out = &outputs.Stage(*path);
  ProgressReporter progress(ProgressReporter::Wanted(parsed.Flag("--progress")));
  PaperReproduction r = ReproducePaper(dir, tables, &progress);
  progress.Finish();

  // The checks of Tables 2-4 arrive interleaved (per design n); one block per table.
  std::stable_sort(r.checks.begin(), r.checks.end(),
                   [](const PaperCheck& a, const PaperCheck& b) { return a.table < b.table; });
  int failed = 0;
  int table = 0;
  for (const PaperCheck& c : r.checks) {
    if (c.table != table) {
      table = c.table;
      // Tables 1-4 are held to an absolute tolerance (half a unit of the printed digit), so
      // their column is the absolute error; Tables 5-6 to a relative one.
      std::printf("\nTable %d%s\n%-48s %14s %14s %10s %9s\n", table,
                  c.relative ? " (relative tolerance)" : " (absolute tolerance)", "item",
                  "computed", "paper", c.relative ? "rel.err" : "abs.err", "status");
    }
    const bool ok = c.pass;
    failed += ok ? 0 : 1;
    if (c.relative) {
      std::printf("%-48s %14.6g %14.6g %+9.2f%% %9s\n", c.item.c_str(), c.computed, c.printed,
                  100.0 * c.relative_error(), ok ? "ok" : "OUT");
    } else {
      std::printf("%-48s %14.6g %14.6g %10.3g %9s\n", c.item.c_str(), c.computed, c.printed,
                  std::abs(c.computed - c.printed), ok ? "ok" : "OUT");
    }
  }
  if (r.json.contains("section7_3")) {
    std::printf(
        "\nSect. 7.3: the 3D bridge (the paper shows figures only)\n%-11s %12s %12s %12s %14s %9s "
        "%6s\n",
        "run", "peak x [mm]", "peak y [mm]", "peak z [mm]", "max stress/allowed", "engine",
        "slack");
    for (const auto& row : r.json["section7_3"]) {
      const auto& peak = row["peak_displacement_m"];
      std::printf(
          "%-11s %12.4f %12.4f %12.4f %14.2f %9s %6d\n", row["run"].get<std::string>().c_str(),
          1e3 * peak["x"].get<double>(), 1e3 * peak["y"].get<double>(),
          1e3 * peak["z"].get<double>(),
          row["max_string_stress_pa"].get<double>() / row["allowed_stress_pa"].get<double>(),
          row["engine"].get<std::string>().c_str(), row["slack_transitions"].get<int>());
    }
  }
  std::printf("\n%zu values compared, %d out of tolerance, %d dynamic runs\n", r.checks.size(),
              failed, r.runs);
  if (json_out != nullptr) {
    *json_out << r.json.dump(2) << "\n";
    outputs.Commit();
  }
  return failed == 0 ? kExitOk : kExitNotOk;
}

const CommandRegistrar kRegisterPaper("paper",
                                      "reproduce the paper's Tables 1-6 beside the printed values",
                                      &RunPaper);

}  // namespace

}  // namespace tbridge::cli
