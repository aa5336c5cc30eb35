// Expecting a config to be rejected: the ConfigError's message must name the key path, show
// the value and say what is allowed.
#pragma once

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "core/config.h"
#include "core/error.h"

namespace tbridge::test {

// The message of the ConfigError that `parse` throws; fails the test if it throws anything
// else or nothing.
template <typename F>
std::string ConfigErrorOf(F&& parse) {
  try {
    parse();
  } catch (const ConfigError& e) {
    return e.what();
  } catch (const std::exception& e) {
    FAIL("expected ConfigError, got another exception: " << e.what());
  }
  FAIL("expected ConfigError, nothing was thrown");
  return "";
}

// Checks that `config` is rejected with a message naming `key`, showing `value` and saying
// what is allowed (`allowed` is a fragment of that phrase).
inline void ExpectRejected(const nlohmann::json& config, const std::string& key,
                           const std::string& value, const std::string& allowed) {
  const std::string message = ConfigErrorOf([&] { ParseConfig(config); });
  INFO("message: " << message);
  CHECK(message.find("'" + key + "'") != std::string::npos);
  CHECK(message.find(value) != std::string::npos);
  CHECK(message.find(allowed) != std::string::npos);
}

}  // namespace tbridge::test
