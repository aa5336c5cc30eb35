// `tbridge keys`: the key tables of the config sections described once (core/config_fields.h
// and sweep/sweep_fields.h), as configs/README.md shows them (tests/core/config_fields_test.cc
// and tests/sweep/sweep_fields_test.cc fail when the README differs).

#include <iostream>
#include <string>
#include <vector>

#include "core/config_fields.h"
#include "sweep/sweep_fields.h"
#include "tools/commands.h"
#include "tools/output.h"

namespace tbridge::cli {

namespace {

const CommandSpec& KeysSpec() {
  static const CommandSpec spec{
      "keys",
      {},
      {},
      "Prints the Markdown key tables (key, unit, default, allowed, what it controls) of the\n"
      "config sections bridge, material, design, loads, dynamics, structure and sweep, each after "
      "its\n"
      "heading and rules, as configs/README.md has them (the README keeps paragraphs of its own\n"
      "between a heading and its rules)."};
  return spec;
}

int RunKeysCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = KeysSpec();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  for (const SectionInfo* section :
       {&kBridgeSection, &kMaterialSection, &kDesignSection, &kLoadsSection, &kComfortSection,
        &kSupportsSection, &kDynamicsSection, &kStructureSection}) {
    std::cout << ConfigSectionText(*section) << "\n";
  }
  std::cout << SweepSectionText() << "\n";
  return 0;
}

const CommandRegistrar kRegisterKeys(
    "keys", "the config key tables of configs/README.md, from their one description",
    &RunKeysCommand);

}  // namespace

}  // namespace tbridge::cli
