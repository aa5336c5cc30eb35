// Error types shared by every layer. Each carries enough context for the user to act on it.
#pragma once

#include <stdexcept>
#include <string>

namespace tbridge {

// Bad user input: names the JSON key path, the value seen and what is allowed.
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& key, const std::string& value, const std::string& allowed)
      : std::runtime_error("config key '" + key + "' = " + value + ": " + allowed), key_(key) {}
  explicit ConfigError(const std::string& message) : std::runtime_error(message) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// A model that cannot be built or solved (infeasible design, solver failure, blown-up run).
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tbridge
