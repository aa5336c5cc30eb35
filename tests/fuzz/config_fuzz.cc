// libFuzzer target on the config parser: any bytes in, either a Config out or a ConfigError.
// Anything else (another exception, a crash, a sanitizer report) is a defect. A parsed config
// must also survive its own echo: ParseConfig(ToJson(c)) gives the same ToJson.
//
// Build and run (clang):
//   CXX=clang++ cmake -S . -B build-fuzz -DTBRIDGE_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
//   cmake --build build-fuzz --target config_fuzz -j2
//   build-fuzz/tests/config_fuzz -max_total_time=300 -dict=tests/fuzz/config.dict
//       -max_len=4096 /tmp/fuzz-corpus tests/fuzz/corpus      (one command line)
// With g++ the same entry point is linked into config_fuzz_replay, which ctest runs on
// tests/fuzz/corpus/* (tests/CMakeLists.txt).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <nlohmann/json.hpp>
#include <string>

#include "core/config.h"
#include "core/error.h"
#include "core/json_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const tbridge::Config config = tbridge::ParseConfig(tbridge::ParseJsonText(text, "fuzz"));
    const nlohmann::json echo = tbridge::ToJson(config);
    if (tbridge::ToJson(tbridge::ParseConfig(echo)) != echo) {
      std::fprintf(stderr, "the echoed config does not parse back to itself\n");
      std::abort();
    }
  } catch (const tbridge::ConfigError&) {
    // The one allowed rejection.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "not a ConfigError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
