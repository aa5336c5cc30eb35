#include "tools/output.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <system_error>

#include "core/json_reader.h"

namespace tbridge::cli {

namespace {

namespace fs = std::filesystem;

std::string Reason(int error_number) { return std::strerror(error_number); }

// The file a path finally names: symbolic links followed (relative ones from their folder),
// the path itself when it is no link. At most 40 links, as the kernel allows.
fs::path FollowLinks(const std::string& path) {
  fs::path p(path);
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) return p;
    const fs::path target = fs::read_symlink(p, ec);
    if (ec) throw OutputError("cannot read the link '" + p.string() + "': " + ec.message());
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  throw OutputError("cannot write '" + path + "': too many levels of symbolic links");
}

const char* KindOf(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::fifo:
      return "a FIFO (named pipe)";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

// Opens `path` and flushes it with `flush`: fsync (the file) or syncfs (its whole file system:
// one call for many files, where a file each costs a millisecond; ext4 here: 10 000 VTK
// samples took 12 s file by file). Returns 0 or the errno.
int Flush(const std::string& path, int (*flush)(int)) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  const int rc = flush(fd) == 0 ? 0 : errno;
  ::close(fd);
  return rc;
}

// What an interrupted process (Ctrl-C, kill) must remove: the temporaries and the folders of
// the transactions in flight. Fixed slots of lock-free atomics, so that the signal handler
// may read them (async-signal-safe); a transaction with more files than slots leaves the
// rest, hidden, to chance.
constexpr int kFileSlots = 1024, kDirSlots = 64;
std::atomic<const char*> g_files[kFileSlots];
std::atomic<const char*> g_dirs[kDirSlots];

void Register(std::atomic<const char*>* slots, int count, const char* path) {
  for (int k = 0; k < count; ++k) {
    const char* expected = nullptr;
    if (slots[k].compare_exchange_strong(expected, path)) return;
  }
}

void Unregister(std::atomic<const char*>* slots, int count, const char* path) {
  for (int k = 0; k < count; ++k) {
    const char* expected = path;
    if (slots[k].compare_exchange_strong(expected, nullptr)) return;
  }
}

extern "C" void RemoveStagedAndDie(int signal_number) {
  for (auto& slot : g_files) {
    if (const char* path = slot.load()) ::unlink(path);
  }
  // Nested folders go deepest first; a pass per level (rmdir refuses a folder not empty).
  for (int pass = 0; pass < 8; ++pass) {
    for (auto& slot : g_dirs) {
      if (const char* path = slot.load()) ::rmdir(path);
    }
  }
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

}  // namespace

void InstallInterruptCleanup() {
  struct sigaction action {};
  action.sa_handler = RemoveStagedAndDie;
  sigemptyset(&action.sa_mask);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP})
    ::sigaction(signal_number, &action, nullptr);
}

struct OutputTransaction::Staged {
  std::string target;    // as given, for messages
  fs::path destination;  // links followed: the path renamed over
  std::string temp;      // the temporary sibling
  std::ofstream stream;
};

OutputTransaction::OutputTransaction() = default;

OutputTransaction::~OutputTransaction() {
  for (const auto& s : staged_) {
    Unregister(g_files, kFileSlots, s->temp.c_str());
    if (!committed_) {
      s->stream.close();
      ::unlink(s->temp.c_str());
    }
  }
  // Deepest first; rmdir refuses a folder that is not empty, so nothing else is lost.
  for (auto it = created_dirs_.rbegin(); it != created_dirs_.rend(); ++it) {
    Unregister(g_dirs, kDirSlots, it->c_str());
    if (!committed_) ::rmdir(it->c_str());
  }
}

void OutputTransaction::ProtectInput(const std::string& path) { inputs_.push_back(path); }

std::ostream& OutputTransaction::Stage(const std::string& path) {
  if (committed_) throw OutputError("internal: output '" + path + "' staged after the commit");
  if (path.empty()) throw OutputError("output path is empty");
  const fs::path destination = FollowLinks(path);
  if (!destination.has_filename()) {
    throw OutputError("cannot write '" + path + "': the path names a directory, not a file");
  }
  std::error_code ec;
  const fs::file_status status = fs::status(destination, ec);
  if (fs::exists(status)) {
    if (!fs::is_regular_file(status)) {
      throw OutputError("cannot write '" + path + "': it is " + KindOf(status.type()) +
                        "; results are written to regular files only");
    }
    for (const std::string& input : inputs_) {
      if (fs::equivalent(destination, input, ec)) {
        throw UsageError("output '" + path + "' is the input '" + input +
                         "': writing it would replace the input; choose another output path");
      }
    }
  }
  if (!staged_paths_.insert(destination.lexically_normal().string()).second) {
    throw OutputError("internal: output '" + path + "' is written twice in one run");
  }

  // Missing parent folders, each recorded so that a failed run removes it again.
  const fs::path dir = destination.has_parent_path() ? destination.parent_path() : fs::path(".");
  std::vector<fs::path> missing;
  for (fs::path d = dir; !d.empty() && !fs::exists(d, ec); d = d.parent_path()) {
    missing.push_back(d);
    if (d == d.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, ec) && ec) {
      throw OutputError("cannot create directory '" + it->string() + "' for '" + path +
                        "': " + ec.message());
    }
    created_dirs_.push_back(it->string());
    Register(g_dirs, kDirSlots, created_dirs_.back().c_str());
  }
  if (!fs::is_directory(dir, ec)) {
    throw OutputError("cannot write '" + path + "': '" + dir.string() + "' is not a directory");
  }

  std::string temp_name = ".";  // appended, not "." + name: GCC 12 warns falsely (-Wrestrict)
  temp_name += destination.filename().string();
  temp_name += ".tmp.XXXXXX";
  std::string pattern = (dir / temp_name).string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) {
    throw OutputError("cannot create a temporary file in '" + dir.string() + "' for '" + path +
                      "': " + Reason(errno));
  }
  // mkstemp creates the file with mode 0600; give the result the usual umask-based mode.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  const int chmod_error = ::fchmod(fd, 0666 & ~mask) == 0 ? 0 : errno;
  ::close(fd);
  auto staged = std::make_unique<Staged>();
  staged->target = path;
  staged->destination = destination;
  staged->temp = pattern;
  staged_.push_back(std::move(staged));  // from here on the destructor removes the temporary
  Register(g_files, kFileSlots, staged_.back()->temp.c_str());
  if (chmod_error != 0)
    throw OutputError("cannot set the mode of '" + pattern + "': " + Reason(chmod_error));
  Staged& s = *staged_.back();
  s.stream.open(s.temp, std::ios::binary | std::ios::trunc);
  if (!s.stream) throw OutputError("cannot open '" + s.temp + "' for '" + path + "'");
  return s.stream;
}

void OutputTransaction::Stage(const std::string& path, const std::string& content) {
  std::ostream& out = Stage(path);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
}

void OutputTransaction::RemoveAtCommit(const std::string& path) { remove_.push_back(path); }

void OutputTransaction::RemoveStaleAtCommit(const std::string& dir, const std::string& prefix,
                                            const std::string& suffix) {
  remove_patterns_.push_back({dir, prefix, suffix});
}

void OutputTransaction::Commit() {
  if (committed_) throw OutputError("internal: outputs committed twice");
  // 1. Every file complete and on disk before any of them replaces an old one: each file
  // flushed, or, for more than a few (a VTK series), their file systems at once.
  constexpr size_t kSyncEachUpTo = 8;
  std::set<std::string> folders;  // one temporary per folder stands for its file system
  for (const auto& s : staged_) {
    s->stream.flush();
    const bool ok = static_cast<bool>(s->stream);
    s->stream.close();
    if (!ok || s->stream.fail())
      throw OutputError("cannot write '" + s->target + "': write failed (disk full?)");
    const std::string folder = fs::path(s->temp).parent_path().string();
    const bool each = staged_.size() <= kSyncEachUpTo;
    if (!each && !folders.insert(folder).second) continue;
    if (const int err = Flush(s->temp, each ? ::fsync : ::syncfs); err != 0) {
      throw OutputError("cannot write '" + s->target + "': " + Reason(err));
    }
  }
  // 2. Into place. Each rename is atomic; they run only once every file is ready.
  std::set<fs::path> written;
  for (const auto& s : staged_) {
    if (::rename(s->temp.c_str(), s->destination.c_str()) != 0) {
      throw OutputError("cannot write '" + s->target + "': " + Reason(errno));
    }
    Unregister(g_files, kFileSlots, s->temp.c_str());  // a result now, not a temporary
    written.insert(fs::path(s->target).lexically_normal());
    written.insert(s->destination.lexically_normal());
  }
  committed_ = true;
  // 3. The command's own stale outputs. A failure here leaves an old file beside the new ones,
  // which must not pass unnoticed: it is an error.
  std::error_code ec;
  for (const std::string& path : remove_) {
    if (written.count(fs::path(path).lexically_normal()) != 0) continue;
    // Only a file or a link can be an old output; anything else under the name is not ours.
    const fs::file_status status = fs::symlink_status(path, ec);
    if (!fs::is_regular_file(status) && !fs::is_symlink(status)) continue;
    if (::unlink(path.c_str()) != 0) {
      throw OutputError("cannot remove the stale output '" + path + "': " + Reason(errno));
    }
  }
  for (const auto& [dir, prefix, suffix] : remove_patterns_) {
    if (!fs::is_directory(dir, ec)) continue;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
      const std::string name = e.path().filename().string();
      if (name.size() <= prefix.size() + suffix.size() || name.rfind(prefix, 0) != 0 ||
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) {
        continue;
      }
      const std::string middle =
          name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
      if (middle.find_first_not_of("0123456789") != std::string::npos) continue;
      if (written.count(e.path().lexically_normal()) != 0) continue;
      const fs::file_status status = e.symlink_status(ec);
      if (!fs::is_regular_file(status) && !fs::is_symlink(status)) continue;
      if (::unlink(e.path().c_str()) != 0) {
        throw OutputError("cannot remove the stale output '" + e.path().string() +
                          "': " + Reason(errno));
      }
    }
  }
}

void WriteFileAtomically(const std::string& path, const std::string& content) {
  OutputTransaction transaction;
  transaction.Stage(path, content);
  transaction.Commit();
}

std::optional<std::string> ParsedArgs::Value(const std::string& name) const {
  const auto it = values.find(name);
  if (it == values.end()) return std::nullopt;
  return it->second;
}

std::string ParsedArgs::Required(const std::string& name) const {
  const std::optional<std::string> v = Value(name);
  if (!v) throw UsageError("missing option " + name);
  return *v;
}

namespace {

const OptionSpec* FindOption(const CommandSpec& spec, const std::string& name) {
  for (const OptionSpec& o : spec.options) {
    for (const std::string& n : o.names) {
      if (n == name) return &o;
    }
  }
  return nullptr;
}

std::string Hint(const CommandSpec& spec) { return " (see 'tbridge " + spec.name + " --help')"; }

std::string OptionUsage(const OptionSpec& o) {
  return o.names.front() + (o.value_name.empty() ? "" : " " + o.value_name);
}

}  // namespace

int ParseWholeNumber(const ParsedArgs& parsed, const std::string& name,
                     const std::string& long_name, int fallback, int minimum) {
  const std::optional<std::string> text = parsed.Value(name);
  if (!text) return fallback;
  try {
    size_t used = 0;
    const int count = std::stoi(*text, &used);
    if (used == text->size() && count >= minimum) return count;
  } catch (const std::exception&) {
  }
  throw UsageError(long_name + " expects a whole number >= " + std::to_string(minimum) + ", got '" +
                   *text + "'");
}

ParsedArgs ParseArgs(const std::vector<std::string>& args, const CommandSpec& spec) {
  ParsedArgs out;
  for (const std::string& a : args) {
    if (a == "--") break;
    if (a == "-h" || a == "--help") {
      out.help = true;
      return out;
    }
  }
  bool options_done = false;
  for (size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    if (options_done || a.size() < 2 || a[0] != '-') {
      out.positionals.push_back(a);
      continue;
    }
    if (a == "--") {
      options_done = true;
      continue;
    }
    std::string name = a;
    std::optional<std::string> inline_value;
    if (a.rfind("--", 0) == 0) {
      if (const size_t eq = a.find('='); eq != std::string::npos) {
        name = a.substr(0, eq);
        inline_value = a.substr(eq + 1);
      }
    }
    const OptionSpec* option = FindOption(spec, name);
    if (option == nullptr) {
      std::vector<std::string> names;
      for (const OptionSpec& o : spec.options)
        names.insert(names.end(), o.names.begin(), o.names.end());
      const std::string nearest = NearestKey(name, names);
      throw UsageError("unknown option '" + Printable(name) + "'" +
                       (nearest.empty() ? "" : ", did you mean '" + nearest + "'?") + Hint(spec));
    }
    const std::string& canonical = option->names.front();
    if (out.values.count(canonical) != 0 || out.flags.count(canonical) != 0) {
      throw UsageError("option '" + name + "' given twice" + Hint(spec));
    }
    if (option->value_name.empty()) {
      if (inline_value) throw UsageError("option '" + name + "' takes no value" + Hint(spec));
      out.flags.insert(canonical);
      continue;
    }
    if (inline_value) {
      out.values[canonical] = *inline_value;
    } else if (k + 1 < args.size()) {
      out.values[canonical] = args[++k];
    } else {
      throw UsageError("option '" + name + "' needs a value (" + option->value_name + ")" +
                       Hint(spec));
    }
    if (out.values[canonical].empty()) {
      throw UsageError("option '" + name + "' has an empty value" + Hint(spec));
    }
  }
  for (const OptionSpec& o : spec.options) {
    if (o.required && out.values.count(o.names.front()) == 0) {
      throw UsageError("missing option " + OptionUsage(o) + " (" + o.help + ")" + Hint(spec));
    }
  }
  if (out.positionals.size() != spec.positionals.size()) {
    std::string expected;
    for (const std::string& p : spec.positionals) expected += (expected.empty() ? "" : " ") + p;
    std::string got;
    for (const std::string& p : out.positionals) got += (got.empty() ? "'" : "', '") + p;
    throw UsageError("expected " + std::to_string(spec.positionals.size()) + " argument(s) " +
                     (expected.empty() ? "(none)" : expected) + ", got " +
                     std::to_string(out.positionals.size()) +
                     (got.empty() ? "" : " (" + got + "')") + Hint(spec));
  }
  return out;
}

std::string Usage(const CommandSpec& spec) {
  std::string s = "usage: tbridge " + spec.name;
  for (const std::string& p : spec.positionals) s += " " + p;
  for (const OptionSpec& o : spec.options) {
    s += o.required ? " " : " [";
    s += OptionUsage(o);
    if (!o.required) s += "]";
  }
  s += "\n";
  if (!spec.summary.empty()) s += "\n" + spec.summary + "\n";
  if (!spec.options.empty()) {
    s += "\noptions:\n";
    size_t width = 0;
    std::vector<std::string> left;
    for (const OptionSpec& o : spec.options) {
      std::string names;
      for (const std::string& n : o.names) names += (names.empty() ? "" : ", ") + n;
      if (!o.value_name.empty()) names += " " + o.value_name;
      width = std::max(width, names.size());
      left.push_back(names);
    }
    for (size_t k = 0; k < spec.options.size(); ++k) {
      s += "  " + left[k] + std::string(width - left[k].size() + 2, ' ') + spec.options[k].help +
           "\n";
    }
    s += "  -h, --help" + std::string(width > 10 ? width - 10 + 2 : 2, ' ') + "show this help\n";
  }
  return s;
}

OptionSpec ProgressOption() {
  return {{"--progress"},
          "",
          "progress line with an ETA on stderr even when it is not a terminal",
          false};
}

OptionSpec StrictOption() {
  return {{"--strict"},
          "",
          "treat plausibility warnings as errors (exit 2; thresholds in configs/README.md)",
          false};
}

void ReportWarnings(const std::vector<std::string>& warnings, bool strict) {
  if (warnings.empty()) return;
  if (strict) {
    std::string all;
    for (const std::string& w : warnings) all += (all.empty() ? "" : "; ") + w;
    throw ConfigError("implausible result under --strict: " + all);
  }
  for (const std::string& w : warnings) std::cerr << "tbridge: warning: " << w << "\n";
}

}  // namespace tbridge::cli
