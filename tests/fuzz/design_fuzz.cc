// libFuzzer target on the whole design path of small bridges: any bytes in; a config that
// parses and draws a bridge of n <= 2 is designed and verified (DesignAndVerify: the sizing, the
// static, dynamic and comfort checks), written (WriteDesignJson, the summary, the plausibility
// warnings) and read back as tbridge check reads it (ReadDesign). The allowed outcomes are a
// design, a ConfigError (bad input) and a ModelError (no design for it); anything else (another
// exception, a crash, a sanitizer report) is a defect. Larger bridges and custom scenes are
// left to the config target (config_fuzz.cc): a design of n = 3 takes seconds.
//
// Build and run (clang), as config_fuzz.cc says, with the target design_fuzz and its corpus:
//   build-fuzz/tests/design_fuzz -max_total_time=600 -timeout=120 -dict=tests/fuzz/config.dict
//       -max_len=4096 /tmp/design-corpus tests/fuzz/design_corpus      (one command line)
// With g++ the same entry point is linked into design_fuzz_replay, which ctest runs on
// tests/fuzz/design_corpus/* (tests/CMakeLists.txt).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/config.h"
#include "core/error.h"
#include "core/json_reader.h"
#include "design/plausibility.h"
#include "io/design_reader.h"
#include "io/design_report.h"
#include "sizing/verified_design.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const tbridge::Config config = tbridge::ParseConfig(tbridge::ParseJsonText(text, "fuzz"));
    if (config.structure || config.bridge.n > 2) return 0;
    const tbridge::Design design = tbridge::DesignAndVerify(config);
    std::ostringstream written;
    tbridge::WriteDesignJson(design, written);
    (void)tbridge::DesignSummary(design);
    (void)tbridge::PlausibilityWarnings(design);
    const tbridge::Design reread = tbridge::ReadDesign(nlohmann::json::parse(written.str()));
    if (reread.topology.structure.num_nodes() != design.topology.structure.num_nodes()) {
      std::fprintf(stderr, "the written design does not read back as itself\n");
      std::abort();
    }
  } catch (const tbridge::ConfigError&) {
    // Bad input, named.
  } catch (const tbridge::ModelError&) {
    // No design for this input, said why.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "neither a ConfigError nor a ModelError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
