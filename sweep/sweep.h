// The outer loop: evaluate every candidate of a sweep (on a thread pool, optionally one shard
// of the grid, reusing finished candidates), choose the lightest feasible design and say what
// decided it, and write the trade-off table as CSV and JSON.
//
// Determinism: each candidate is evaluated by one thread from the same inputs, rows are kept
// in candidate order and numbers are written with fixed formats, so the outputs are the same
// bytes for any thread count and for a merge of shards.
#pragma once

#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sweep/candidate.h"
#include "sweep/sweep_config.h"

namespace tbridge {

struct SweepChoice {
  bool found = false;
  int index = -1;  // chosen candidate
  // What decided: a constraint name (candidate.h), "joint_mass", "mass (monotone: largest n
  // in grid)", "mass", or "none feasible".
  std::string binding;
  std::string reason;  // one sentence
};

// The lightest feasible candidate (objective = total + joint mass; ties: lower index), and
// why: when lighter candidates exist, the constraint violated by the lightest-objective one
// just below the choice; otherwise the joint-mass term when a candidate with lighter members
// exists, else the monotone mass.
SweepChoice Choose(const std::vector<CandidateRow>& rows);

struct Shard {
  int index = 1;  // 1-based
  int count = 1;
  bool Has(int candidate) const { return candidate % count == index - 1; }
};
// "i/N" with 1 <= i <= N; throws ConfigError naming `option`, the text and the form allowed.
Shard ParseShard(const std::string& text, const std::string& option);

struct SweepRunOptions {
  int threads = 1;  // >= 1
  Shard shard;
  // A finished row of an earlier run, or nothing (then the candidate is evaluated).
  std::function<std::optional<CandidateRow>(const Candidate&)> reuse;
  // Called once per newly evaluated row, from the worker thread (calls are serialised).
  std::function<void(const CandidateRow&)> on_done;
  // Called after every finished candidate of this run (serialised): done, total of the shard.
  std::function<void(int, int)> on_progress;
};

struct SweepStats {
  int evaluated = 0;  // candidates computed in this run
  int reused = 0;     // taken from `reuse`
};

// Rows of the candidates of options.shard, in candidate order. Exceptions other than
// ModelError (which makes a failed row) stop the sweep and are rethrown.
std::vector<CandidateRow> RunSweep(const SweepSpec& spec, const SweepRunOptions& options,
                                   SweepStats* stats = nullptr);

// One row as JSON (exact doubles) and back; RowFromJson throws ConfigError on a malformed row.
nlohmann::json RowToJson(const CandidateRow& row);
CandidateRow RowFromJson(const nlohmann::json& j);

// 64-bit FNV-1a of the resolved config, hex: ties candidate files and shards to one sweep.
std::string SweepFingerprint(const SweepSpec& spec);

// sweep.csv: one line per row, fixed formats (%.10g), empty cells for what was not computed.
std::string SweepCsv(const std::vector<CandidateRow>& rows);
// sweep.json: config, fingerprint, candidates, shard (null for the whole grid), rows and,
// for the whole grid, the choice.
std::string SweepJson(const SweepSpec& spec, const std::vector<CandidateRow>& rows,
                      const std::optional<Shard>& shard);

}  // namespace tbridge
