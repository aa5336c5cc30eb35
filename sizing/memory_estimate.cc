#include "sizing/memory_estimate.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "design/deck.h"
#include "design/load_cases.h"
#include "design/prestress_states.h"
#include "design/topology.h"
#include "sizing/sizing_problem.h"

namespace tbridge {

namespace {

// The three measured costs. Fitted by least squares to the whole-process peaks (MB of 2^20 B)
// of the default config at n = 2..6 (16.4, 17.8, 22.0, 35.5, 88.9) and of the 30 m steel
// footbridge at n = 3..6 (18.7, 24.4, 40.1, 98.0), each set gives 17 MB + 710 B per entry + a
// cost per member (15 kB on the default, 53 kB on the footbridge, whose angle search and
// abutment rows cost it a tenth more). The 3D bridge (bridge.planes 2: 24.1 MB at n = 2, 34.6 MB
// at n = 3) needs 60 kB per member. Raised to cover all three, so that the estimate is above
// every peak measured (1.02 to 1.27 times): an estimate below a peak would let through a design
// that does not fit, one far above it would refuse designs that fit.
// The process before its work [B]: code, libraries, the configs.
constexpr double kProcessBytes = 19.5e6;
// Per member [B]: the structure, the design and the dynamic and modal models, and the designs
// the verified sizing keeps (the best, the current, the restarts).
constexpr double kBytesPerMember = 60e3;
// Per entry, a member in a combination in a state of the prestress [B]: the static check's
// solutions and reactions, the sizing program's rows, margins and forces.
constexpr double kBytesPerEntry = 750.0;
// Per member of a design checked as designed, not resized (the paper's switches: the
// `"paper"` case alone) [B]: no sizing program, no designs kept. The paper's design at n = 12,
// 14 and 16 peaks at 36.7, 124 and 463 MB of 2^20 B, 1.8 kB per member over the 8.6 MB it
// takes at n = 3; 1.5 kB with the entry's 750 B puts the estimate 1.25 times above at n = 16.
constexpr double kBytesPerMemberChecked = 1.5e3;
// Rows posed per member and state in the verified sizing's program: its closest strength row,
// and its taut or serviceability row (sizing/verified_design.cc, NearLimits).
constexpr double kPosedRowsPerMember = 2.0;

// Each case once, a travelling family once per loaded deck station.
long long CombinationsOf(const Config& config, const BridgeTopology& topology) {
  std::vector<std::string> notes;
  const Deck deck = ComputeDeck(config.bridge, config.material, config.design);
  long long combinations = 0;
  for (const LoadCase& c : MakeLoadCases(config, deck, notes))
    combinations += c.station_load != 0 ? std::max(topology.loaded_stations, 1) : 1;
  return combinations;
}

// "2.52e+10 B (25.2 GB)": bytes as the key takes them, and as an engineer reads them.
std::string BytesText(double bytes) {
  std::ostringstream os;
  os.precision(3);
  os << bytes << " B (";
  if (bytes >= 1e9)
    os << bytes / 1e9 << " GB)";
  else
    os << bytes / 1e6 << " MB)";
  return os.str();
}

}  // namespace

MemoryEstimate EstimateDesignMemory(const Config& config) {
  MemoryEstimate e;
  e.process_bytes = kProcessBytes;
  if (config.structure) return e;
  const BridgeTopology topology = MakeBridge(config.bridge);
  e.members =
      static_cast<long long>(topology.structure.bars.size() + topology.structure.strings.size());
  e.combinations = CombinationsOf(config, topology);
  e.states = static_cast<long long>(PrestressStatesOf(config).size());
  e.entries = e.members * e.combinations * e.states;
  e.sized = !KeepsPaperSwitches(config);
  e.model_bytes =
      (e.sized ? kBytesPerMember : kBytesPerMemberChecked) * static_cast<double>(e.members);
  e.work_bytes = kBytesPerEntry * static_cast<double>(e.entries);
  if (!e.sized) return e;
  // Dense: every posed row reads every variable (an area per mirror group, at most half the
  // members plus the middle ones, and the symmetric self-stresses).
  const double rows = kPosedRowsPerMember * static_cast<double>(e.members * e.states);
  const double variables = static_cast<double>(e.members) / 2 + 1 + SizingProblem::kMaxStates;
  e.jacobian_bytes = sizeof(double) * rows * variables;
  return e;
}

std::optional<double> AvailableMemoryBytes() {
  std::ifstream in("/proc/meminfo");
  std::string name, unit;
  double value = 0;
  while (in >> name >> value) {
    std::getline(in, unit);
    if (name == "MemAvailable:") return value * 1024;  // the kernel writes it in kB (KiB)
  }
  return std::nullopt;
}

std::optional<double> MemoryLimitBytes(const Config& config) {
  if (config.design.memory_limit_bytes) return config.design.memory_limit_bytes;
  return AvailableMemoryBytes();
}

namespace {

constexpr const char* kMemoryLimitKey = "design.memory_limit_bytes";

// What is said of the limit where a design is refused: the key's value, or the memory available
// that its absence stands for.
std::string LimitValueText(const Config& config, double limit) {
  if (config.design.memory_limit_bytes) return NumberText(limit);
  return "null (the memory available, " + BytesText(limit) + ")";
}

// Why the design over `limit` is refused, and what moves it.
std::string RefusalText(const Config& config, const MemoryEstimate& e, double limit) {
  std::ostringstream os;
  os << "the design of this bridge (bridge.n = " << config.bridge.n << ", " << e.members
     << " members, " << e.combinations << " combinations, " << e.states
     << " states of the prestress) would take an estimated " << BytesText(e.total_bytes())
     << ", of which " << BytesText(e.work_bytes)
     << " the static check's solutions and the sizing's rows, over the limit of "
     << BytesText(limit) << "; refused before any work: a smaller bridge.n (each level takes "
     << "about a quarter), or a larger design.memory_limit_bytes (the estimate is an upper "
     << "bound, 1.02 to 1.27 times the peaks measured at n <= 6)";
  return os.str();
}

// The refusal of `config`'s design, where its estimate is over its limit.
std::optional<ConfigError> Refusal(const Config& config) {
  if (config.structure) return std::nullopt;  // its `design` section is not read
  const std::optional<double> limit = MemoryLimitBytes(config);
  if (!limit) return std::nullopt;
  const MemoryEstimate e = EstimateDesignMemory(config);
  if (e.total_bytes() <= *limit) return std::nullopt;
  return ConfigError(kMemoryLimitKey, LimitValueText(config, *limit),
                     RefusalText(config, e, *limit));
}

}  // namespace

std::string MemoryRefusal(const Config& config) {
  const std::optional<ConfigError> refusal = Refusal(config);
  return refusal ? refusal->what() : "";
}

void RefuseOverMemoryLimit(const Config& config) {
  if (std::optional<ConfigError> refusal = Refusal(config)) throw *refusal;
}

}  // namespace tbridge
