// `tbridge check DESIGN.json -o OUT.json [--quiet] [--progress] [--strict]`: the checks of a
// written design run again on the design as written: the nonlinear static solve of every case and
// the dynamic runs; the plausibility warnings as `design` gives them.

#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "checks/verdict.h"
#include "core/json_reader.h"
#include "core/progress.h"
#include "design/plausibility.h"
#include "io/design_reader.h"
#include "io/design_report.h"
#include "sizing/verified_design.h"
#include "tools/commands.h"
#include "tools/output.h"
#include "truss/truss_design.h"
#include "truss/truss_report.h"

namespace tbridge::cli {

namespace {

const CommandSpec& CheckSpec() {
  static const CommandSpec spec{
      "check",
      {"DESIGN.json"},
      {{{"-o", "--output"}, "OUT.json", "where to write the checked design, a JSON file", true},
       ProgressOption(),
       StrictOption(),
       {{"-q", "--quiet"}, "", "do not print the summary", false}},
      "Reads DESIGN.json, a design written by tbridge design, and checks it as written (a\n"
      "structure's: each member at the area its file gives, by the linear analysis): every\n"
      "load case solved as a nonlinear static problem (deflections, reactions, member forces,\n"
      "slack strings) and the dynamic runs (README.md, \"Safe by design\"). Nothing is resized.\n"
      "Each member's utilisation is its largest over the ultimate static cases and the runs.\n"
      "OUT.json has the fields of a design file; it is written only when the checks ran, and\n"
      "never partially. Exit 0 when the design passes, 1 when it fails a check or a check was\n"
      "not run (verdict FAIL or INCOMPLETE; it says which), 2 when DESIGN.json is not a\n"
      "self-consistent design (the message names the key: a member whose area was edited\n"
      "without re-deriving its rest length and forces, or whose radius, mass or stiffness no\n"
      "longer is what its area gives: check reads a member from its area and rest length, so\n"
      "such an edit would be ignored)."};
  return spec;
}

// The check of a structure's design file (truss/): each member at the area the file gives.
int RunStructureCheck(const nlohmann::json& file, const ParsedArgs& parsed,
                      const std::string& out_path) {
  const TrussDesign design = CheckTrussDesignFile(file);
  OutputTransaction outputs;
  outputs.ProtectInput(parsed.positionals[0]);
  std::ostream& json = outputs.Stage(out_path);
  WriteTrussDesignJson(design, json);
  outputs.Commit();
  if (!parsed.Flag("-q")) std::cout << TrussDesignSummary(design) << "\nwrote " << out_path << "\n";
  return design.check.pass ? kExitOk : kExitNotOk;
}

int RunCheckCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = CheckSpec();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  const std::string out_path = parsed.Required("-o");
  const nlohmann::json file = ReadJsonFile(parsed.positionals[0]);
  if (file.is_object() && file.value("kind", "") == "structure")
    return RunStructureCheck(file, parsed, out_path);
  Design design = ReadDesign(file);
  OutputTransaction outputs;
  outputs.ProtectInput(parsed.positionals[0]);
  std::ostream& json = outputs.Stage(out_path);
  ProgressReporter progress(ProgressReporter::Wanted(parsed.Flag("--progress")));
  CheckAgain(design, &progress);
  progress.Finish();
  WriteDesignJson(design, json);
  // The checked design's own warnings (its abutment thrust, its members' sizes), as `design`
  // gives them: an edited design is checked as the engineer left it.
  ReportWarnings(PlausibilityWarnings(design), parsed.Flag("--strict"));
  outputs.Commit();
  if (!parsed.Flag("-q")) std::cout << DesignSummary(design) << "\nwrote " << out_path << "\n";
  return DesignVerdict(design).pass ? kExitOk : kExitNotOk;
}

const CommandRegistrar kRegisterCheck(
    "check", "the static and dynamic checks of a written design, run again", &RunCheckCommand);

}  // namespace

}  // namespace tbridge::cli
