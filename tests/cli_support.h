// Running the built `tbridge` executable from a test, as a user would.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace tbridge::test {

namespace fs = std::filesystem;

struct CliResult {
  bool exited = false;  // false if the process died from a signal (a crash)
  int code = -1;        // exit code of the shell running tbridge
  std::string out;
  std::string err;
};

inline std::string ReadText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh, empty directory per test case, unique to this process.
inline fs::path FreshDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("tbridge_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Everything below `dir`, by relative path: a file's bytes, a link's target ("-> t"), a
// FIFO ("(fifo)") or a folder ("(dir)"). Two equal snapshots mean nothing changed.
inline std::map<std::string, std::string> Snapshot(const fs::path& dir) {
  std::map<std::string, std::string> out;
  if (!fs::exists(fs::symlink_status(dir))) return out;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    const fs::file_status s = fs::symlink_status(e.path());
    if (fs::is_symlink(s)) {
      out[rel] = "-> " + fs::read_symlink(e.path()).string();
    } else if (fs::is_fifo(s)) {
      out[rel] = "(fifo)";
    } else if (fs::is_directory(s)) {
      out[rel] = "(dir)";
    } else {
      out[rel] = ReadText(e.path());
    }
  }
  return out;
}

inline std::string Quote(const std::string& s) { return "'" + s + "'"; }

// Runs `tbridge <args>` with stdout and stderr captured in `dir`.
inline CliResult RunTbridge(const fs::path& dir, const std::string& args) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = Quote(TBRIDGE_BINARY) + " " + args + " > " + Quote(out.string()) +
                              " 2> " + Quote(err.string());
  const int status = std::system(command.c_str());
  CliResult r;
  // The shell reports a child killed by signal s as exit code 128 + s; tbridge itself never
  // exits with more than 4.
  r.exited = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) < 128;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = ReadText(out);
  r.err = ReadText(err);
  return r;
}

// The exit code `tbridge design` or `check` owes a design file it wrote: 0 for a PASS, 1 for
// a FAIL or an INCOMPLETE verdict (read from the file's own "verdict"); -1 when unreadable.
inline int VerdictExit(const fs::path& design_file) {
  const std::string text = ReadText(design_file);
  const auto at = text.find("\"outcome\": \"");
  if (at == std::string::npos) return -1;
  return text.compare(at + 12, 5, "PASS\"") == 0 ? 0 : 1;
}

}  // namespace tbridge::test
