// `tbridge design CONFIG.json -o OUT.json [--quiet]`: the minimum-mass design of one config.

#include <iostream>
#include <string>
#include <vector>

#include "core/config.h"
#include "design/design.h"
#include "design/design_report.h"
#include "tools/commands.h"
#include "tools/output.h"

namespace tbridge::cli {

namespace {

const CommandSpec& DesignSpec() {
  static const CommandSpec spec{
      "design",
      {"CONFIG.json"},
      {{{"-o", "--output"}, "OUT.json", "where to write the design, a JSON file", true},
       {{"-q", "--quiet"}, "", "do not print the summary", false}},
      "Reads CONFIG.json (keys in configs/README.md), finds the minimum-mass design and writes\n"
      "it to OUT.json (fields in README.md). OUT.json is written only when the design\n"
      "succeeds, and never partially."};
  return spec;
}

int RunDesignCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = DesignSpec();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  const std::string out_path = parsed.Required("-o");
  // Everything that can fail runs before the output file is touched.
  const Design design = RunDesign(LoadConfig(parsed.positionals[0]));
  WriteFileAtomically(out_path, [&design](std::ostream& os) { WriteDesignJson(design, os); });
  if (!parsed.Flag("-q")) {
    std::cout << DesignSummary(design) << "\nwrote " << out_path << "\n";
  }
  return 0;
}

const CommandRegistrar kRegisterDesign("design",
                                       "minimum-mass design of CONFIG.json, written to OUT.json",
                                       &RunDesignCommand);

}  // namespace

}  // namespace tbridge::cli
