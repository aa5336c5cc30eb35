// `tbridge design CONFIG.json -o OUT.json [--quiet] [--progress] [--strict]`: the minimum-mass
// design of one config.

#include <iostream>
#include <string>
#include <vector>

#include "checks/verdict.h"
#include "core/config.h"
#include "core/progress.h"
#include "design/design.h"
#include "design/plausibility.h"
#include "io/design_report.h"
#include "sizing/memory_estimate.h"
#include "sizing/verified_design.h"
#include "tools/commands.h"
#include "tools/output.h"
#include "truss/truss_design.h"
#include "truss/truss_report.h"

namespace tbridge::cli {

namespace {

const CommandSpec& DesignSpec() {
  static const CommandSpec spec{
      "design",
      {"CONFIG.json"},
      {{{"-o", "--output"}, "OUT.json", "where to write the design, a JSON file", true},
       {{"-q", "--quiet"}, "", "do not print the summary", false},
       ProgressOption(),
       StrictOption()},
      "Reads CONFIG.json (keys in configs/README.md), finds the minimum-mass design of its "
      "bridge,\n"
      "or of its structure's members in groups, and writes it to OUT.json (fields in README.md).\n"
      "OUT.json is written only when the design succeeds, and never partially; a failed run\n"
      "leaves it as it was. Implausible results (members under 1 mm, a deck under 1 mm or over\n"
      "span / 10, ...) are warned about on stderr. A design that is not statically stable "
      "(README.md, \"Reading a design\") is\n"
      "refused with exit 3. A design whose verdict is FAIL or INCOMPLETE (a check failed, or\n"
      "was not run) is written and exits 1. Draw the design with tools/plot_sweep.py bridge "
      "OUT.json -o FIG.png."};
  return spec;
}

// The design of a pin-jointed structure (truss/): sized, checked and written as a bridge's is.
int RunStructureDesign(const Config& config, const ParsedArgs& parsed,
                       const std::string& out_path) {
  OutputTransaction outputs;
  outputs.ProtectInput(parsed.positionals[0]);
  std::ostream& json = outputs.Stage(out_path);
  ProgressReporter progress(ProgressReporter::Wanted(parsed.Flag("--progress")));
  progress.Stage("sizing");
  const TrussDesign design = DesignTruss(config);
  progress.Stage("writing");
  WriteTrussDesignJson(design, json);
  progress.Finish();
  outputs.Commit();
  if (!parsed.Flag("-q")) std::cout << TrussDesignSummary(design) << "\nwrote " << out_path << "\n";
  return design.check.pass ? kExitOk : kExitNotOk;
}

int RunDesignCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = DesignSpec();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  const std::string out_path = parsed.Required("-o");
  const Config config = LoadConfig(parsed.positionals[0]);
  SetWorkSubject(config.structure
                     ? std::string("the design of the structure")
                     : "the design of the bridge at n = " + std::to_string(config.bridge.n));
  if (config.structure) return RunStructureDesign(config, parsed, out_path);
  // Before anything is staged: a design too large for the memory is refused at once (exit 2),
  // not found an hour later to be an out-of-memory (exit 4), and OUT.json is left as it was.
  RefuseOverMemoryLimit(config);
  // Staged before the design, so an output that cannot be written fails at once; nothing
  // replaces OUT.json before Commit().
  OutputTransaction outputs;
  outputs.ProtectInput(parsed.positionals[0]);
  std::ostream& json = outputs.Stage(out_path);
  ProgressReporter progress(ProgressReporter::Wanted(parsed.Flag("--progress")));
  // An unstable design is no design: exit 3, nothing written.
  const Design design = DesignAndVerify(config, &progress);
  progress.Stage("writing");
  WriteDesignJson(design, json);
  progress.Finish();
  if (parsed.Flag("--progress")) {
    // Where the run's time went (wall time: not in OUT.json, which is the same from run to run).
    const Resizing::Times& t = design.resizing.time_s;
    std::cerr << "time by part [s]: first design " << t.first_design << ", sizing " << t.sizing
              << ", static check " << t.static_check << ", dynamic check " << t.dynamic_check
              << ", comfort check " << t.comfort_check << " (" << design.resizing.iterations
              << " designs)\n";
  }
  ReportWarnings(PlausibilityWarnings(design), parsed.Flag("--strict"));
  outputs.Commit();
  if (!parsed.Flag("-q")) {
    std::cout << DesignSummary(design) << "\nwrote " << out_path << "\n";
  }
  // The design is written either way, so that what failed can be read; the exit says it.
  return DesignVerdict(design).pass ? kExitOk : kExitNotOk;
}

const CommandRegistrar kRegisterDesign("design",
                                       "minimum-mass design of CONFIG.json, written to OUT.json",
                                       &RunDesignCommand);

}  // namespace

}  // namespace tbridge::cli
