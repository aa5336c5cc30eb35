// The `tbridge` command-line tool: dispatches to the self-registered commands of
// tools/cmd_*.cc and turns every error into a message on stderr and an exit code.
//
// Exit codes: tools/commands.h (ExitCode), printed by `tbridge --help`.

#include <algorithm>
#include <exception>
#include <iostream>
#include <map>
#include <new>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/json_reader.h"
#include "core/progress.h"
#include "optim/solvers.h"
#include "tbridge_version.h"  // generated at build time (tools/version.cmake)
#include "tools/commands.h"
#include "tools/output.h"

namespace tbridge::cli {

namespace {

struct Registry {
  std::map<std::string, Command, std::less<>> commands;
  std::vector<std::string> problems;
};

// Function-local static: constructed on first use, so registrars in other translation units
// may run in any order.
Registry& TheRegistry() {
  static Registry registry;
  return registry;
}

}  // namespace

CommandRegistrar::CommandRegistrar(std::string name, std::string help, CommandFn run) {
  Registry& r = TheRegistry();
  if (name.empty() || name.front() == '-' || run == nullptr) {
    r.problems.push_back("command '" + name + "' has an empty or invalid name or no function");
    return;
  }
  if (r.commands.count(name) != 0) {
    r.problems.push_back("command '" + name + "' is registered twice");
    return;
  }
  Command c{name, std::move(help), run};
  r.commands.emplace(std::move(name), std::move(c));
}

std::vector<Command> RegisteredCommands() {
  std::vector<Command> out;
  for (const auto& [name, command] : TheRegistry().commands) out.push_back(command);
  return out;  // std::map keeps them sorted by name
}

const Command* FindCommand(std::string_view name) {
  const auto& commands = TheRegistry().commands;
  const auto it = commands.find(name);
  return it == commands.end() ? nullptr : &it->second;
}

const std::vector<std::string>& RegistrationProblems() { return TheRegistry().problems; }

namespace {

// "auto, direct, ipopt, nlopt", or fewer when a solver was left out of the build.
std::string SolverList() {
  std::string list;
  for (SolverKind s : BuiltInSolvers()) list += (list.empty() ? "" : ", ") + std::string(NameOf(s));
  return list;
}

void PrintUsage(std::ostream& os) {
  os << "tbridge: minimum-mass tensegrity bridges and their dynamics\n\n"
        "usage: tbridge COMMAND [ARGS...]\n"
        "       tbridge COMMAND --help   (the arguments of one command)\n\n"
        "commands:\n";
  const std::vector<Command> commands = RegisteredCommands();
  size_t width = 0;
  for (const Command& c : commands) width = std::max(width, c.name.size());
  for (const Command& c : commands) {
    os << "  " << c.name << std::string(width - c.name.size() + 2, ' ') << c.help << "\n";
  }
  os << "\nlooking at results:\n"
        "  tools/plot_dynamics.py snapshots|deck OUTDIR -o FIG.png   a simulate run (shapes, deck "
        "histories)\n"
        "  tools/plot_sweep.py mass|premium|frequency|feasible OUTDIR -o FIG.png   a sweep's "
        "trade-offs\n"
        "  tools/plot_sweep.py bridge DESIGN.json -o FIG.png          a design\n"
        "  tbridge simulate CONFIG.json -o OUTDIR --vtk DIR            DIR/run.pvd for ParaView\n"
        "\nA failed run leaves its output files and folders as they were. Progress (--progress or "
        "a\n"
        "terminal) and warnings go to stderr; --strict makes warnings errors.\n\n"
     << kExitCodesHelp
     << "\ntbridge --version   the version, git revision and design solvers built in\n"
     << "design.solver values this build accepts: " << SolverList() << "\n";
}

int Fail(const std::string& message, int code) {
  std::cerr << "tbridge: error: " << message << "\n";
  return code;
}

int Dispatch(const std::vector<std::string>& argv) {
  if (!RegistrationProblems().empty()) {
    std::string all;
    for (const std::string& p : RegistrationProblems()) all += (all.empty() ? "" : "; ") + p;
    return Fail("internal: " + all, kExitOther);
  }
  if (argv.empty() || argv[0] == "--help" || argv[0] == "-h" || argv[0] == "help") {
    PrintUsage(std::cout);
    return kExitOk;
  }
  if (argv[0] == "--version" || argv[0] == "version") {
    std::cout << "tbridge " << TBRIDGE_VERSION << " (git " << TBRIDGE_REVISION << ")\n"
              << "design solvers built in: " << SolverList() << "\n";
    return kExitOk;
  }
  const Command* command = FindCommand(argv[0]);
  if (command == nullptr) {
    std::string names;
    std::vector<std::string> list;
    for (const Command& c : RegisteredCommands()) {
      names += (names.empty() ? "" : ", ") + c.name;
      list.push_back(c.name);
    }
    const std::string nearest = NearestKey(argv[0], list);
    return Fail("unknown command '" + tbridge::Printable(argv[0]) + "'" +
                    (nearest.empty() ? "" : ", did you mean '" + nearest + "'?") +
                    " (commands: " + names + "; see 'tbridge --help')",
                kExitBadInput);
  }
  const std::vector<std::string> args(argv.begin() + 1, argv.end());
  return command->run(args);
}

}  // namespace

}  // namespace tbridge::cli

int main(int argc, char** argv) {
  using namespace tbridge::cli;
  const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
  InstallInterruptCleanup();
  try {
    const int code = Dispatch(args);
    std::cout.flush();
    if (!std::cout) return Fail("cannot write to standard output", kExitOther);
    return code;
  } catch (const tbridge::ConfigError& e) {
    return Fail(e.what(), kExitBadInput);
  } catch (const tbridge::ModelError& e) {
    return Fail(e.what(), kExitNoDesign);
  } catch (const std::bad_alloc&) {
    // The limits checked before a run (dynamics.limits, design.memory_limit_bytes) keep most
    // configs from getting here; an estimate under the memory can still be wrong, or the memory
    // taken by others meanwhile, so this names where the memory ran out: the stage and n.
    const std::string where = tbridge::WorkInProgress();
    return Fail("out of memory" + (where.empty() ? std::string() : " in " + where) +
                    ": a bridge's sizing and checks grow about fourfold per level of bridge.n; a "
                    "smaller bridge.n, or a machine with more memory (design.memory_limit_bytes "
                    "refuses a design before its work where its estimate is over the limit)",
                kExitOther);
  } catch (const std::exception& e) {
    return Fail(e.what(), kExitOther);
  } catch (...) {
    return Fail("unexpected error of unknown type", kExitOther);
  }
}
