// `tbridge export DESIGN.json --format calculix|opensees -o FILE [--rigid-bars] [--modes K]`:
// a written design as an input file of an FE program (export/calculix.h, export/opensees.h).

#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/json_reader.h"
#include "export/export.h"
#include "export/truss_calculix.h"
#include "export/truss_opensees.h"
#include "io/design_reader.h"
#include "tools/commands.h"
#include "tools/output.h"
#include "truss/truss_design.h"

namespace tbridge::cli {

namespace {

const CommandSpec& ExportSpec() {
  static const CommandSpec spec{
      "export",
      {"DESIGN.json"},
      {{{"-f", "--format"}, "FORMAT", "calculix (an .inp deck) or opensees (a Tcl script)", true},
       {{"-o", "--output"}, "FILE", "where to write it", true},
       {{"--rigid-bars"},
        "",
        "bars 1e6 times stiffer than E A / l, as tbridge's rigid bars",
        false},
       {{"-m", "--modes"}, "K", "calculix: eigenmodes asked of *FREQUENCY (default 10)", false}},
      "Reads DESIGN.json, a design written by tbridge design or check, as tbridge check reads\n"
      "it, and writes the bridge for an FE program: nodes, supports, strings that carry no\n"
      "compression with their prestress, bars with their reference compression, the masses of\n"
      "the modal model, and every load case (each travelling station its own) as a static\n"
      "analysis from the prestressed reference state; CalculiX also gets the natural\n"
      "frequencies about the state `tbridge modes` analyses (README.md, \"Export\"). FILE is\n"
      "written whole or not at all. Exit 2 for a bad option or a DESIGN.json that is not a\n"
      "self-consistent design."};
  return spec;
}

int RunExportCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = ExportSpec();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  const std::string format = parsed.Required("-f");
  const std::optional<ExportFormat> chosen = ExportFormatOf(format);
  if (!chosen) throw OptionError("--format", "'" + format + "'", ExpectedExportFormats());
  CalculixOptions options;
  options.rigid_bars = parsed.Flag("--rigid-bars");
  options.modes = ParseWholeNumber(parsed, "-m", "--modes", options.modes, 1);
  if (parsed.Value("-m") && *chosen != ExportFormat::kCalculix)
    throw UsageError("--modes: only the calculix format computes modes");
  const std::string out_path = parsed.Required("-o");
  const nlohmann::json file = ReadJsonFile(parsed.positionals[0]);
  if (file.is_object() && file.value("kind", "") == "structure") {
    // A structure's design (truss/): its members elastic, E A / L.
    if (options.rigid_bars)
      throw UsageError("--rigid-bars: a structure's members are elastic, E A / L");
    const TrussDesign design = CheckTrussDesignFile(file);
    OutputTransaction outputs;
    outputs.ProtectInput(parsed.positionals[0]);
    if (*chosen == ExportFormat::kCalculix) {
      WriteTrussCalculix(design, options.modes, outputs.Stage(out_path));
    } else {
      WriteTrussOpenSees(design, outputs.Stage(out_path));
    }
    outputs.Commit();
    std::cout << "wrote " << out_path << " (" << format << ")\n";
    return kExitOk;
  }
  const Design design = ReadDesign(file);
  OutputTransaction outputs;
  outputs.ProtectInput(parsed.positionals[0]);
  std::ostream& out = outputs.Stage(out_path);
  WriteExport(design, *chosen, options, out);
  outputs.Commit();
  std::cout << "wrote " << out_path << " (" << format << ")\n";
  return kExitOk;
}

const CommandRegistrar kRegisterExport("export",
                                       "a written design as a CalculiX or OpenSees input file",
                                       &RunExportCommand);

}  // namespace

}  // namespace tbridge::cli
