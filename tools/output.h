// Helpers shared by every command: transactional result files and a small, strict argument
// parser.
#pragma once

#include <array>
#include <list>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
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

// All the output files of one command, written together or not at all.
//
// Each file is staged in a temporary sibling (".NAME.tmp.XXXXXX" in the target's folder, so
// the final rename stays on one file system and is atomic). Commit() moves every staged file
// into place only after all of them were written and flushed to disk, then removes the stale
// files the command owns but did not write this time. A transaction destroyed without
// Commit() (an exception, a failed run) removes its temporaries and the folders it created,
// so a failed run leaves the file system exactly as it found it. Files in the output folders
// that the command does not own are never touched.
//
// Targets:
// - A symbolic link is followed: the file it points to is replaced and the link stays (as
//   shell redirection does). A dangling link creates its target.
// - A target that exists and is not a regular file (directory, FIFO, device, socket) is
//   refused with OutputError: a result is a file, and writing into a pipe would block or be
//   lost.
// - A target that is one of the command's inputs (ProtectInput) is refused with UsageError
//   (exit 2): `-o` equal to the config would overwrite it.
//
// Stage early, before long work, so that an output location that cannot be written fails in
// a second, not after the run; the streams can be filled any time before Commit().
class OutputTransaction {
 public:
  OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;
  // Without Commit(): removes the temporaries and the folders Stage created (when empty).
  ~OutputTransaction();

  // An input file that no output may replace; nonexistent paths are ignored.
  void ProtectInput(const std::string& path);
  // Creates the temporary for `path` (and any missing parent folders) and returns a stream
  // writing to it, valid until Commit() or destruction. Throws OutputError (the path and the
  // reason) when the location cannot be written, UsageError when `path` is a protected
  // input, OutputError when `path` was already staged.
  std::ostream& Stage(const std::string& path);
  // Stage(path) << content.
  void Stage(const std::string& path, const std::string& content);
  // `path` is an output of this command that this run does not produce: Commit() removes it
  // if it is a file or a link (a link is removed, not its target); a folder or FIFO of that
  // name is not an old output and stays.
  void RemoveAtCommit(const std::string& path);
  // Commit() removes every file or link in folder `dir` named prefix + digits + suffix that
  // was not staged (e.g. "run_", ".vtp": the samples of a longer earlier run).
  void RemoveStaleAtCommit(const std::string& dir, const std::string& prefix,
                           const std::string& suffix);
  // Flushes every staged file to disk, renames each over its target, then removes the stale
  // ones. Throws OutputError naming the path when a write fails; until the first rename
  // nothing has changed. Call at most once.
  void Commit();

 private:
  struct Staged;
  std::vector<std::unique_ptr<Staged>> staged_;
  // The staged destinations, normalised: a second staging of one is refused in O(log n), not
  // by a scan (a run writing 10 000 VTK samples spent a minute on the scans).
  std::set<std::string> staged_paths_;
  std::list<std::string> created_dirs_;  // in creation order, parents first; a list keeps
                                         // each c_str() in place for the signal handler
  std::vector<std::string> inputs_;
  std::vector<std::string> remove_;
  std::vector<std::array<std::string, 3>> remove_patterns_;  // dir, prefix, suffix
  bool committed_ = false;
};

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove the temporaries and created
// folders of every transaction in flight, then die of the signal as before: an interrupted
// run leaves nothing behind either. Called once by main.
void InstallInterruptCleanup();

// One file written through a one-file OutputTransaction: readers see either the old file or
// the whole new one, never a partial file; OutputError on failure, `path` untouched.
void WriteFileAtomically(const std::string& path, const std::string& content);

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
  std::string summary;  // one paragraph shown by --help
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

// The whole number >= `minimum` given to option `name` (canonical name; `long_name` for the
// message), or `fallback` when absent; UsageError naming the option otherwise.
int ParseWholeNumber(const ParsedArgs& parsed, const std::string& name,
                     const std::string& long_name, int fallback, int minimum = 0);

// Parses `args` against `spec`. Throws UsageError naming the offending argument for an
// unknown option, a repeated option, a missing option value, a missing required option, or
// a wrong number of positionals. With -h/--help only `help` is set and nothing else is checked.
// "--" ends the options.
ParsedArgs ParseArgs(const std::vector<std::string>& args, const CommandSpec& spec);

// "usage: tbridge design CONFIG.json -o OUT.json [--quiet]" plus the options and summary.
std::string Usage(const CommandSpec& spec);

// Options several commands share, spelt once.
OptionSpec ProgressOption();  // --progress: progress line on stderr even when not a terminal
OptionSpec StrictOption();    // --strict: plausibility warnings are errors

// Prints each warning on stderr as "tbridge: warning: <text>". With `strict`, throws
// ConfigError (exit 2) listing them instead, before any output is written.
void ReportWarnings(const std::vector<std::string>& warnings, bool strict);

}  // namespace tbridge::cli
