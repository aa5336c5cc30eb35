// Error messages: keys printed whole, options named as options, the nearest key suggested.

#include <catch2/catch.hpp>
#include <string>

#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {
namespace {

TEST_CASE("a key with control characters is printed whole, escaped") {
  const std::string key("bridge.span\0x", 13);
  CHECK(Printable(key) == "bridge.span\\u0000x");
  CHECK(Printable("a\nb\x7f") == "a\\u000ab\\u007f");
  const ConfigError e(key, "1", "unknown key");
  // what() is a C string: an unescaped NUL would end it after "bridge.span".
  CHECK(std::string(e.what()) == "config key 'bridge.span\\u0000x' = 1: unknown key");
  CHECK(std::string(ConfigError(std::string("file\0.json", 10)).what()) == "file\\u0000.json");
}

TEST_CASE("a bad option value is called an option") {
  CHECK(std::string(OptionError("--shard", "'3/2'", "must be i/N").what()) ==
        "option '--shard' = '3/2': must be i/N");
}

TEST_CASE("the nearest known key is suggested within a third of its length") {
  const std::vector<std::string> bridge = {"n",       "p",          "beta_deg", "span",
                                           "payload", "deck_width", "planes"};
  CHECK(NearestKey("payloads", bridge) == "payload");  // one insertion
  CHECK(NearestKey("sapn", bridge) == "span");         // one swap of neighbours
  CHECK(NearestKey("Span", bridge) == "span");         // case ignored
  CHECK(NearestKey("deckwidth", bridge) == "deck_width");
  CHECK(NearestKey("xyz", bridge).empty());  // 3 edits from any: no guess
  CHECK(NearestKey("q", {"n"}) == "n");      // 1 edit is always allowed
  CHECK(NearestKey(std::string(100, 'a'), bridge).empty());
}

TEST_CASE("an unknown key in a section gets the nearest key it knows") {
  JsonSection s(nlohmann::json::parse(R"({"spn": 12})"), "bridge");
  s.Number("span", 12.0, Range::Positive());
  s.Number("payload", 1.0, Range::Positive());
  CHECK_THROWS_WITH(s.Finish(),
                    Catch::Contains("'bridge.spn'") && Catch::Contains("did you mean 'span'?"));
}

}  // namespace
}  // namespace tbridge
