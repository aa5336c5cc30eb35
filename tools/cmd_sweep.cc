// `tbridge sweep CONFIG.json -o OUTDIR [--threads K] [--shard i/N] [--resume] [--progress]`:
// the outer loop (sweep/sweep.h). Every finished candidate is stored at once as
// OUTDIR/candidates/<index>.json (atomically), so an interrupted sweep loses at most the
// candidates in flight; --resume reuses the stored ones of the same config (fingerprint).
// OUTDIR/sweep.csv and sweep.json are written at the end.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "core/error.h"
#include "core/json_reader.h"
#include "core/progress.h"
#include "sweep/sweep.h"
#include "tools/commands.h"
#include "tools/output.h"

namespace tbridge::cli {

namespace {

const CommandSpec& SweepSpecOfCommand() {
  static const CommandSpec spec{
      "sweep",
      {"CONFIG.json"},
      {{{"-o", "--output"}, "OUTDIR", "directory for sweep.csv, sweep.json and candidates/", true},
       {{"-j", "--threads"}, "K", "worker threads (default: the number of cores)", false},
       {{"--shard"}, "i/N", "evaluate only the candidates with index % N == i - 1", false},
       {{"--resume"}, "", "reuse OUTDIR/candidates/*.json of the same config", false},
       ProgressOption(),
       {{"-q", "--quiet"}, "", "do not print the choice", false}},
      "Evaluates every candidate of the config's \"sweep\" grid (n x p x beta x deck prestrain):\n"
      "minimum-mass design, joint mass, first frequency and the travelling-load run where asked,\n"
      "then the constraints. Writes OUTDIR/sweep.csv (the trade-off table), OUTDIR/sweep.json\n"
      "(resolved config, rows, the chosen design and what decided it) and one\n"
      "OUTDIR/candidates/<index>.json per candidate. The outputs are the same bytes for any\n"
      "thread count; shards are joined with `tbridge merge`. Keys: configs/README.md, \"sweep\"."};
  return spec;
}

int ParseThreads(const ParsedArgs& parsed) {
  const std::optional<std::string> text = parsed.Value("-j");
  if (!text) return std::max(1u, std::thread::hardware_concurrency());
  if (!text->empty() && text->size() <= 4 &&
      text->find_first_not_of("0123456789") == std::string::npos) {
    const int k = std::stoi(*text);
    if (k >= 1 && k <= 1024) return k;
  }
  throw UsageError("--threads expects a whole number in [1, 1024], got '" + *text + "'");
}

std::optional<CandidateRow> ReadStoredRow(const std::string& path, const std::string& fingerprint,
                                          int index) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  try {
    const nlohmann::json j = nlohmann::json::parse(text.str());
    if (j.at("fingerprint").get<std::string>() != fingerprint) return std::nullopt;
    CandidateRow row = RowFromJson(j.at("row"));
    if (row.candidate.index != index) return std::nullopt;
    return row;
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable or from another version: evaluate again
  }
}

int RunSweepCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = SweepSpecOfCommand();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  const std::string out_dir = parsed.Required("-o");
  const int threads = ParseThreads(parsed);
  std::optional<Shard> shard;
  if (const auto text = parsed.Value("--shard")) shard = ParseShard(*text, "--shard");
  const SweepSpec sweep = LoadSweepSpec(parsed.positionals[0]);
  const std::string fingerprint = SweepFingerprint(sweep);

  SweepRunOptions options;
  options.threads = threads;
  if (shard) options.shard = *shard;
  const std::string store = out_dir + "/candidates/";
  if (parsed.Flag("--resume")) {
    options.reuse = [&](const Candidate& c) {
      return ReadStoredRow(store + std::to_string(c.index) + ".json", fingerprint, c.index);
    };
  }
  options.on_done = [&](const CandidateRow& row) {
    const nlohmann::json j = {{"fingerprint", fingerprint}, {"row", RowToJson(row)}};
    WriteFileAtomically(store + std::to_string(row.candidate.index) + ".json", j.dump(2) + "\n");
  };
  // sweep.csv and sweep.json are staged first, so an output folder that cannot be written
  // fails before the candidates run, and they replace the old pair together at the end.
  OutputTransaction outputs;
  outputs.ProtectInput(parsed.positionals[0]);
  std::ostream& csv_out = outputs.Stage(out_dir + "/sweep.csv");
  std::ostream& json_out = outputs.Stage(out_dir + "/sweep.json");
  ProgressReporter progress(ProgressReporter::Wanted(parsed.Flag("--progress")));
  progress.Stage("candidates");
  options.on_progress = [&](int done, int total) { progress.Update(done, total); };

  const auto start = std::chrono::steady_clock::now();
  SweepStats stats;
  const std::vector<CandidateRow> rows = RunSweep(sweep, options, &stats);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.Finish();
  csv_out << SweepCsv(rows);
  json_out << SweepJson(sweep, rows, shard);
  outputs.Commit();

  if (!parsed.Flag("-q")) {
    std::cout << "candidates " << rows.size()
              << (shard ? " (shard " + std::to_string(shard->index) + "/" +
                              std::to_string(shard->count) + ")"
                        : std::string())
              << ": evaluated " << stats.evaluated << ", reused " << stats.reused << ", " << threads
              << " thread(s), " << wall << " s\n";
    if (!shard) {
      const SweepChoice c = Choose(rows);
      if (c.found) {
        const CandidateRow& r = rows[c.index];
        std::cout << "chosen: index " << c.index << ", n = " << r.candidate.n
                  << ", p = " << r.candidate.p << ", beta = " << r.candidate.beta_deg
                  << " deg, deck prestrain " << r.candidate.deck_prestrain << ", objective "
                  << r.objective << " kg\n";
      }
      std::cout << "decided by: " << c.binding << "\n" << c.reason << "\n";
    }
    std::cout << "wrote " << out_dir << "/sweep.csv and sweep.json\n";
  }
  return 0;
}

const CommandRegistrar kRegisterSweep(
    "sweep", "outer loop over n, p, beta and prestrain; choice and trade-off table",
    &RunSweepCommand);

}  // namespace

}  // namespace tbridge::cli
