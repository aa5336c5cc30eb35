#include "tools/output.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <streambuf>
#include <vector>
#include <system_error>

namespace tbridge::cli {

namespace {

namespace fs = std::filesystem;

std::string Reason(int error_number) { return std::strerror(error_number); }

// Closes the descriptor and removes the temporary file unless Release() was called.
class TempFile {
 public:
  TempFile(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
  }
  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  // Closes the descriptor; returns 0 or errno.
  int Close() {
    const int rc = ::close(fd_);
    fd_ = -1;
    return rc == 0 ? 0 : errno;
  }
  void Release() { path_.clear(); }

 private:
  int fd_;
  std::string path_;
};

// An output buffer over a file descriptor: streamed results go to the file as they are made,
// in 1 MiB writes, instead of through a string of the whole document.
class FdStreamBuf : public std::streambuf {
 public:
  explicit FdStreamBuf(int fd) : fd_(fd), buffer_(1 << 20) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (Drain() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return Drain(); }

 private:
  int Drain() {
    const char* data = pbase();
    size_t left = static_cast<size_t>(pptr() - pbase());
    while (left > 0 && error_ == 0) {
      const ssize_t n = ::write(fd_, data, left);
      if (n < 0) {
        if (errno != EINTR) error_ = errno;
        continue;
      }
      data += n;
      left -= static_cast<size_t>(n);
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return error_ == 0 ? 0 : -1;
  }

  int fd_;
  int error_ = 0;
  std::vector<char> buffer_;
};

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& content) {
  WriteFileAtomically(path, [&content](std::ostream& os) { os.write(content.data(), static_cast<std::streamsize>(content.size())); });
}

void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  if (path.empty()) throw OutputError("output path is empty");
  const fs::path target(path);
  if (!target.has_filename()) {
    throw OutputError("cannot write '" + path + "': the path names a directory, not a file");
  }
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    throw OutputError("cannot create directory '" + dir.string() + "' for '" + path +
                      "': " + ec.message());
  }
  if (fs::is_directory(target, ec)) {
    throw OutputError("cannot write '" + path + "': it is a directory");
  }

  // The temporary file lives next to the target so that rename() stays on one file system
  // and is atomic.
  std::string temp_name = ".";  // appended, not "." + name: GCC 12 warns falsely (-Wrestrict)
  temp_name += target.filename().string();
  temp_name += ".tmp.XXXXXX";
  std::string pattern = (dir / temp_name).string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) {
    throw OutputError("cannot create a temporary file in '" + dir.string() + "' for '" + path +
                      "': " + Reason(errno));
  }
  TempFile temp(fd, pattern);

  // mkstemp creates the file with mode 0600; give the result the usual umask-based mode.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  if (::fchmod(temp.fd(), 0666 & ~mask) != 0) {
    throw OutputError("cannot set the mode of '" + temp.path() + "': " + Reason(errno));
  }

  FdStreamBuf buffer(temp.fd());
  std::ostream stream(&buffer);
  write(stream);
  stream.flush();
  if (!stream || buffer.error() != 0) {
    throw OutputError("cannot write '" + path + "': " + Reason(buffer.error() ? buffer.error() : EIO));
  }
  // Flush to disk before the rename, so a crash cannot leave a renamed but empty file.
  if (::fsync(temp.fd()) != 0) {
    throw OutputError("cannot write '" + path + "': " + Reason(errno));
  }
  if (const int err = temp.Close(); err != 0) {
    throw OutputError("cannot write '" + path + "': " + Reason(err));
  }
  if (::rename(temp.path().c_str(), path.c_str()) != 0) {
    throw OutputError("cannot write '" + path + "': " + Reason(errno));
  }
  temp.Release();
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

std::string Hint(const CommandSpec& spec) {
  return " (see 'tbridge " + spec.name + " --help')";
}

std::string OptionUsage(const OptionSpec& o) {
  return o.names.front() + (o.value_name.empty() ? "" : " " + o.value_name);
}

}  // namespace

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
    if (option == nullptr) throw UsageError("unknown option '" + name + "'" + Hint(spec));
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
      throw UsageError("option '" + name + "' needs a value (" + option->value_name + ")" + Hint(spec));
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
    throw UsageError("expected " + std::to_string(spec.positionals.size()) +
                     " argument(s) " + (expected.empty() ? "(none)" : expected) + ", got " +
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
    s += "  -h, --help" + std::string(width > 10 ? width - 10 + 2 : 2, ' ') +
         "show this help\n";
  }
  return s;
}

}  // namespace tbridge::cli
