// Error types shared by every layer. Each carries enough context for the user to act on it.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace tbridge {

// A number as every message shows it: ostream's default, at most 6 significant digits ("1e+160",
// not std::to_string's 161 characters), "inf", "nan".
inline std::string NumberText(double value) {
  std::ostringstream os;
  os << value;
  return os.str();
}

// `text` with every control character written as \u00XX (JSON's escape), so that a key
// holding a NUL or a newline neither cuts an error message short (what() is a C string) nor
// breaks its line.
inline std::string Printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += "\\u00";
      out += hex[u >> 4];
      out += hex[u & 15];
    } else {
      out += c;
    }
  }
  return out;
}

// Bad user input: names the JSON key path, the value seen and what is allowed.
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& key, const std::string& value, const std::string& allowed)
      : std::runtime_error("config key '" + Printable(key) + "' = " + value + ": " + allowed),
        key_(key) {}
  // A message of its own; a NUL in it is escaped so that what() shows all of it.
  explicit ConfigError(const std::string& message) : std::runtime_error(EscapeNul(message)) {}
  const std::string& key() const { return key_; }

 private:
  static std::string EscapeNul(const std::string& message) {
    std::string out;
    for (const char c : message) out += c == '\0' ? std::string("\\u0000") : std::string(1, c);
    return out;
  }
  std::string key_;
};

// A bad value of a command-line option, reported like a bad key (exit 2):
// "option '--shard' = "3/2": ...".
inline ConfigError OptionError(const std::string& option, const std::string& value,
                               const std::string& allowed) {
  return ConfigError("option '" + Printable(option) + "' = " + value + ": " + allowed);
}

// A model that cannot be built or solved (infeasible design, solver failure, blown-up run).
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tbridge
