// `tbridge paper [--tables LIST] [--json FILE] [--configs DIR]`: reproduces the paper's
// Tables 1-6 from the shipped configs and prints each value beside the printed one.

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "dynamics/paper_tables.h"
#include "tools/commands.h"
#include "tools/output.h"

namespace tbridge::cli {

namespace {

const CommandSpec& PaperSpec() {
  static const CommandSpec spec{
      "paper",
      {},
      {{{"--tables"}, "LIST", "comma-separated tables to run, e.g. 1,2,5 (default: 1-6)", false},
       {{"--json"}, "FILE", "also write the reproduced tables as JSON", false},
       {{"--configs"}, "DIR", "folder with paper_*.json and reference/ (default: ./configs, "
                              "else the source tree's configs/)", false}},
      "Designs the paper's bridges and runs its dynamic cases from the shipped configs, then\n"
      "prints every number of Tables 1-6 beside the printed value with its error and tolerance\n"
      "(SPEC rules: Tables 1-4 to half a unit of the last printed digit, Table 5 to 8 %,\n"
      "Table 6 to 2 % for n = 1 and 25 % for n >= 2). Exits 1 if any value is out of tolerance."};
  return spec;
}

std::set<int> ParseTables(const std::string& list) {
  std::set<int> tables;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.size() != 1 || item[0] < '1' || item[0] > '6') {
      throw ConfigError("--tables", "\"" + list + "\"", "must list table numbers 1-6, e.g. 1,5,6");
    }
    tables.insert(item[0] - '0');
  }
  if (tables.empty()) throw ConfigError("--tables", "\"\"", "must list at least one table 1-6");
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
  const std::set<int> tables = ParseTables(parsed.Value("--tables").value_or("1,2,3,4,5,6"));
  const std::string dir = parsed.Value("--configs").value_or(DefaultConfigs());
  const PaperReproduction r = ReproducePaper(dir, tables);

  int failed = 0;
  int table = 0;
  for (const PaperCheck& c : r.checks) {
    if (c.table != table) {
      table = c.table;
      std::printf("\nTable %d%s\n%-48s %14s %14s %10s %9s\n", table,
                  table >= 5 ? " (relative tolerance)" : " (absolute tolerance)", "item",
                  "computed", "paper", "rel.err", "status");
    }
    const bool ok = c.pass;
    failed += ok ? 0 : 1;
    std::printf("%-48s %14.6g %14.6g %+9.2f%% %9s\n", c.item.c_str(), c.computed, c.printed,
                100.0 * c.relative_error(), ok ? "ok" : "OUT");
  }
  std::printf("\n%zu values compared, %d out of tolerance, %d dynamic runs\n", r.checks.size(),
              failed, r.runs);
  if (const auto path = parsed.Value("--json")) WriteFileAtomically(*path, r.json.dump(2) + "\n");
  return failed == 0 ? 0 : 1;
}

const CommandRegistrar kRegisterPaper("paper", "reproduce the paper's Tables 1-6 beside the printed values",
                                      &RunPaper);

}  // namespace

}  // namespace tbridge::cli
