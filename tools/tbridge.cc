// The `tbridge` command-line tool: dispatches to the self-registered commands of
// tools/cmd_*.cc and turns every error into a message on stderr and an exit code.
//
// Exit codes: 0 success, 1 a command's own "not ok" result, 2 bad input (config or command
// line), 3 no design / model failure, 4 any other error (I/O, internal).

#include <algorithm>
#include <exception>
#include <iostream>
#include <map>
#include <new>
#include <string>
#include <vector>

#include "core/error.h"
#include "tools/commands.h"

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
  os << "\nexit codes: 0 ok, 2 bad input, 3 no design or model failure, 4 other error\n";
}

int Fail(const std::string& message, int code) {
  std::cerr << "tbridge: error: " << message << "\n";
  return code;
}

int Dispatch(const std::vector<std::string>& argv) {
  if (!RegistrationProblems().empty()) {
    std::string all;
    for (const std::string& p : RegistrationProblems()) all += (all.empty() ? "" : "; ") + p;
    return Fail("internal: " + all, 4);
  }
  if (argv.empty() || argv[0] == "--help" || argv[0] == "-h" || argv[0] == "help") {
    PrintUsage(std::cout);
    return 0;
  }
  const Command* command = FindCommand(argv[0]);
  if (command == nullptr) {
    std::string names;
    for (const Command& c : RegisteredCommands()) names += (names.empty() ? "" : ", ") + c.name;
    return Fail("unknown command '" + argv[0] + "' (commands: " + names +
                    "; see 'tbridge --help')",
                2);
  }
  const std::vector<std::string> args(argv.begin() + 1, argv.end());
  return command->run(args);
}

}  // namespace

}  // namespace tbridge::cli

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
  try {
    const int code = tbridge::cli::Dispatch(args);
    std::cout.flush();
    if (!std::cout) return tbridge::cli::Fail("cannot write to standard output", 4);
    return code;
  } catch (const tbridge::ConfigError& e) {
    return tbridge::cli::Fail(e.what(), 2);
  } catch (const tbridge::ModelError& e) {
    return tbridge::cli::Fail(e.what(), 3);
  } catch (const std::bad_alloc&) {
    return tbridge::cli::Fail("out of memory", 4);
  } catch (const std::exception& e) {
    return tbridge::cli::Fail(e.what(), 4);
  } catch (...) {
    return tbridge::cli::Fail("unexpected error of unknown type", 4);
  }
}
