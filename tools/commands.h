// Subcommands of the `tbridge` executable and their self-registration.
//
// Each tools/cmd_*.cc defines one command and registers it with a file-scope registrar:
//
//   namespace {
//   int RunModes(const std::vector<std::string>& args) { ... return 0; }
//   const tbridge::cli::CommandRegistrar kRegisterModes(
//       "modes", "linearised frequencies of a design", &RunModes);
//   }  // namespace
//
// tbridge.cc never names a command, so adding one means adding one file. Every tools/*.cc is
// compiled straight into the executable (see CMakeLists.txt), not into a static library, so
// the linker cannot drop a registrar whose symbols nothing references.
//
// A command receives the arguments after its name, returns the process exit code, and
// reports failures by throwing: ConfigError (bad input, exit 2), ModelError (no design or
// blown-up model, exit 3), anything else derived from std::exception (exit 4). The top-level
// main prints "tbridge: error: <message>" on stderr for each of them. The codes are listed
// once, below, and `tbridge --help` prints kExitCodesHelp.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace tbridge::cli {

// The process exit codes of every command.
enum ExitCode : int {
  kExitOk = 0,
  kExitNotOk = 1,     // the command ran but its own check failed (paper: a value out of tolerance)
  kExitBadInput = 2,  // config, command line, limits, --strict warnings (ConfigError)
  kExitNoDesign = 3,  // no design found, or the model failed (ModelError)
  kExitOther = 4,     // anything else: an output that cannot be written, out of memory, internal
};

inline constexpr const char* kExitCodesHelp =
    "exit codes: 0 ok, 1 a check of the command failed (paper: a value out of tolerance),\n"
    "            2 bad input (config, command line, limits, warnings under --strict),\n"
    "            3 no design found or the model failed, 4 other error (output not writable, "
    "internal)\n";

// Entry point of a command: `args` excludes the program and the command name.
using CommandFn = int (*)(const std::vector<std::string>& args);

struct Command {
  std::string name;  // word typed after `tbridge`, e.g. "design"
  std::string help;  // one line for `tbridge --help`
  CommandFn run = nullptr;
};

// Registers a command during static initialisation. Registering a name twice, an empty name
// or a null function is recorded, not thrown (nothing can catch during static
// initialisation); main reports it as an internal error before running any command.
class CommandRegistrar {
 public:
  CommandRegistrar(std::string name, std::string help, CommandFn run);
};

// All registered commands, sorted by name.
std::vector<Command> RegisteredCommands();
// The command called `name`, or nullptr.
const Command* FindCommand(std::string_view name);
// Problems seen while registering (duplicate or empty names); empty when all is well.
const std::vector<std::string>& RegistrationProblems();

}  // namespace tbridge::cli
