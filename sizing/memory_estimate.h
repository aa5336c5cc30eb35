// The memory a verified design will take, estimated from its config before any work, so that a
// design too large for the machine is refused at once (design.memory_limit_bytes, exit 2)
// rather than running for an hour into an out-of-memory.
//
// What grows in a design is the product of three counts: its members m, its combinations c
// (each load case once, a travelling family once per loaded deck station) and the states of its
// prestress s (as designed, after the loss, with the rest lengths short or long: design/
// prestress_states.h). The static check keeps a nonlinear solution (member forces, node
// positions, reactions) for every combination in every state, and the verified sizing's whole
// program a row per member, combination and state with the forces behind it: m·c·s "entries",
// about 4^n on the planar bridge (m ≈ 2^(n+2), c ≈ 3·2^n). Besides them a cost per member (the
// models, the designs the sizing keeps; the dynamic runs' workspaces are O(m) each), the
// process itself, and the posed program's dense Jacobian: rows posed (about two per member and
// state) × variables (an area per mirror group, about m / 2, and at most
// SizingProblem::kMaxStates self-stresses).
//
// The costs are measured (memory_estimate.cc): whole-process peaks (/usr/bin/time -v, maximum
// resident set) of `tbridge design` on the default config at n = 2..6, the 30 m steel
// footbridge at n = 3..6 and the 3D bridge at n = 2 and 3 (docs/verified_sizing.md, "Memory").
// The estimate is above each of them, by 1.02 to 1.27 times. Beyond n = 6 it extrapolates at 4x
// per level, which is an upper bound rather than a prediction there: the larger runs measured
// (an older build's n = 8 at 285 MB) grew more slowly.
#pragma once

#include <optional>
#include <string>

#include "core/config.h"

namespace tbridge {

struct MemoryEstimate {
  long long members = 0;       // m: bars and strings
  long long combinations = 0;  // c: cases, a travelling family once per loaded station
  long long states = 0;        // s: the prestress's states the design must pass in
  long long entries = 0;       // m·c·s
  bool sized = true;           // resized by the verified sizing; false: checked as designed
  double process_bytes = 0;    // [B] the process before the work: code, libraries
  double model_bytes = 0;      // [B] the models and the designs kept: members x cost
  double work_bytes = 0;       // [B] the checks' solutions and the sizing's rows: entries x cost
  double jacobian_bytes = 0;   // [B] the posed program's dense Jacobian
  double total_bytes() const { return process_bytes + model_bytes + work_bytes + jacobian_bytes; }
};

// The estimate of a bridge config's verified design (tbridge design): with the paper's switches
// (KeepsPaperSwitches) the design is checked as designed, not resized, and costs no sizing
// program and less per member. Throws ConfigError where
// the config's bridge cannot be built (as the design would). A `structure` config is a small
// program of its own (truss/): its estimate is the process alone.
MemoryEstimate EstimateDesignMemory(const Config& config);

// MemAvailable of /proc/meminfo [B]: the memory a new process can take without swapping; none
// where it cannot be read (another system).
std::optional<double> AvailableMemoryBytes();

// The limit a design is held to [B]: design.memory_limit_bytes, else the memory available; none
// where neither is known.
std::optional<double> MemoryLimitBytes(const Config& config);

// Why `config`'s design is refused: "" when its estimate is within MemoryLimitBytes(config),
// else a message naming design.memory_limit_bytes, the estimate with its largest part, the limit
// and the levers (a smaller bridge.n, or a larger limit).
std::string MemoryRefusal(const Config& config);

// Throws ConfigError with MemoryRefusal's message when it is not "".
void RefuseOverMemoryLimit(const Config& config);

}  // namespace tbridge
