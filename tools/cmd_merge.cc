// `tbridge merge OUTDIR1 OUTDIR2 ... -o OUT`: joins the sweep.json of shards of one sweep
// (same config fingerprint, together covering every candidate exactly once) into OUT/sweep.csv
// and OUT/sweep.json, byte-identical to the single run.

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "core/json_reader.h"
#include "sweep/sweep.h"
#include "tools/commands.h"
#include "tools/output.h"

namespace tbridge::cli {

namespace {

const CommandSpec& MergeSpec() {
  static const CommandSpec spec{
      "merge",
      {"OUTDIR..."},
      {{{"-o", "--output"}, "OUT", "directory for the merged sweep.csv and sweep.json", true}},
      "Joins the OUTDIR/sweep.json of the shards of one sweep (tbridge sweep --shard i/N). All\n"
      "must come from the same config; together they must hold every candidate exactly once."};
  return spec;
}

int RunMergeCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = MergeSpec();
  // Any number of directories: split them off, then parse the options as usual.
  std::vector<std::string> dirs, rest;
  for (size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    if (a == "-o" || a == "--output") {
      rest.push_back(a);
      if (k + 1 < args.size()) rest.push_back(args[++k]);
    } else if (!a.empty() && a[0] == '-') {
      rest.push_back(a);
    } else {
      dirs.push_back(a);
    }
  }
  rest.push_back("(dirs)");
  const ParsedArgs parsed = ParseArgs(rest, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  if (dirs.empty()) throw UsageError("merge needs at least one OUTDIR with a sweep.json");
  const std::string out_dir = parsed.Required("-o");

  std::optional<SweepSpec> sweep;
  std::string fingerprint, first;
  std::vector<std::optional<CandidateRow>> rows;
  for (const std::string& dir : dirs) {
    const std::string path = dir + "/sweep.json";
    const nlohmann::json j = ReadJsonFile(path);
    if (!j.is_object() || !j.contains("config") || !j.contains("rows") ||
        !j.contains("fingerprint")) {
      throw ConfigError(path, "(file)", "must be the sweep.json of `tbridge sweep`");
    }
    if (!sweep) {
      sweep = ParseSweepSpec(j["config"]);
      fingerprint = SweepFingerprint(*sweep);
      first = path;
      rows.assign(sweep->sweep.size(), std::nullopt);
    }
    if (j["fingerprint"] != fingerprint ||
        SweepFingerprint(ParseSweepSpec(j["config"])) != fingerprint) {
      throw ConfigError(path, j["fingerprint"].dump(),
                        "comes from another sweep config than " + first);
    }
    for (const nlohmann::json& r : j["rows"]) {
      CandidateRow row = RowFromJson(r);
      const int index = row.candidate.index;
      if (index < 0 || index >= static_cast<int>(rows.size())) {
        throw ConfigError(path, std::to_string(index), "candidate index out of the grid");
      }
      if (rows[index])
        throw ConfigError(path, std::to_string(index), "candidate already given by another shard");
      rows[index] = std::move(row);
    }
  }
  std::vector<CandidateRow> all;
  std::string missing;
  for (size_t k = 0; k < rows.size(); ++k) {
    if (rows[k]) {
      all.push_back(*rows[k]);
    } else if (missing.size() < 60) {
      missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    }
  }
  if (all.size() != rows.size()) {
    throw ConfigError("merge", "candidates " + missing, "missing: merge every shard of the sweep");
  }
  // The pair replaces the old one together, or not at all.
  OutputTransaction outputs;
  for (const std::string& dir : dirs) outputs.ProtectInput(dir + "/sweep.json");
  outputs.Stage(out_dir + "/sweep.csv", SweepCsv(all));
  outputs.Stage(out_dir + "/sweep.json", SweepJson(*sweep, all, std::nullopt));
  outputs.Commit();
  std::cout << "merged " << all.size() << " candidates from " << dirs.size() << " director"
            << (dirs.size() == 1 ? "y" : "ies") << " into " << out_dir << "\n";
  return 0;
}

const CommandRegistrar kRegisterMerge("merge", "join the shards of a sweep into one table",
                                      &RunMergeCommand);

}  // namespace

}  // namespace tbridge::cli
