// Helpers shared by every command: atomic result files and a small, strict argument parser.
#pragma once

#include <functional>
#include <iosfwd>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"

namespace tbridge::cli {

// Bad command line (unknown flag, missing value or argument). A ConfigError, so the tool
// exits with 2 like any other bad input.
class UsageError : public ConfigError {
 public:
  explicit UsageError(const std::string& message) : ConfigError(message) {}
};

// Writing a result file failed (exit 4). The message names the path and the reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes `content` to `path` so that readers see either the old file or the whole new one,
// never a partial file: the text goes to a temporary file in the same directory, is flushed
// to disk, and is then renamed over `path`. Missing parent directories are created. On any
// failure the temporary file is removed and OutputError is thrown; `path` is left untouched.
void WriteFileAtomically(const std::string& path, const std::string& content);
// Same, with the content streamed by `write` straight into the temporary file (large results).
void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// One option a command accepts. `names` are aliases, the first is the canonical one used to
// look the value up ("-o", "--output"). Options with `value_name` take a value (next
// argument, or "--name=value" for long names); the others are flags.
struct OptionSpec {
  std::vector<std::string> names;
  std::string value_name;  // e.g. "OUT.json"; empty for a flag
  std::string help;
  bool required = false;  // ParseArgs fails when a required option is absent
};

struct CommandSpec {
  std::string name;                      // "design"
  std::vector<std::string> positionals;  // names of the required positional arguments
  std::vector<OptionSpec> options;
  std::string summary;                   // one paragraph shown by --help
};

struct ParsedArgs {
  std::vector<std::string> positionals;
  std::map<std::string, std::string> values;  // canonical option name -> value
  std::set<std::string> flags;                // canonical names of flags given
  bool help = false;                          // -h or --help was given

  bool Flag(const std::string& name) const { return flags.count(name) != 0; }
  std::optional<std::string> Value(const std::string& name) const;
  // The value of option `name`; UsageError naming the option when it was not given.
  std::string Required(const std::string& name) const;
};

// Parses `args` against `spec`. Throws UsageError naming the offending argument for an
// unknown option, a repeated option, a missing option value, a missing required option, or
// a wrong number of positionals. With -h/--help only `help` is set and nothing else is checked. "--" ends the
// options.
ParsedArgs ParseArgs(const std::vector<std::string>& args, const CommandSpec& spec);

// "usage: tbridge design CONFIG.json -o OUT.json [--quiet]" plus the options and summary.
std::string Usage(const CommandSpec& spec);

}  // namespace tbridge::cli
