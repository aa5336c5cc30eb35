// `tbridge keys`: the key tables of the config sections described once in
// core/config_fields.h, as configs/README.md shows them (tests/core/config_fields_test.cc
// fails when the README differs).

#include <iostream>
#include <string>
#include <vector>

#include "core/config_fields.h"
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
      "config sections bridge, material and design, each after its heading and rules, as\n"
      "configs/README.md has them."};
  return spec;
}

int RunKeysCommand(const std::vector<std::string>& args) {
  const CommandSpec& spec = KeysSpec();
  const ParsedArgs parsed = ParseArgs(args, spec);
  if (parsed.help) {
    std::cout << Usage(spec);
    return 0;
  }
  for (const SectionInfo* section : {&kBridgeSection, &kMaterialSection, &kDesignSection}) {
    std::cout << ConfigSectionText(*section) << "\n";
  }
  return 0;
}

const CommandRegistrar kRegisterKeys("keys", "the config key tables of configs/README.md, from their one description",
                                     &RunKeysCommand);

}  // namespace

}  // namespace tbridge::cli
