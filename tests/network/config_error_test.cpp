#include "network/config_error.hpp"

#include <gtest/gtest.h>

namespace {

using network::ConfigError;

TEST(NetworkConfigError, FormatsFileLineColumn) {
  const ConfigError e({"scenes/a.toml", 12, 5}, "bad thing");
  EXPECT_STREQ(e.what(), "scenes/a.toml:12:5: error: bad thing");
  EXPECT_EQ(e.message(), "bad thing");
  EXPECT_EQ(e.where().line, 12);
  EXPECT_EQ(e.where().column, 5);
}

TEST(NetworkConfigError, OmitsPositionForWholeFileOrFlag) {
  EXPECT_STREQ(ConfigError({"a.toml", 0, 0}, "empty").what(), "a.toml: error: empty");
  EXPECT_STREQ(ConfigError({"--set workload.bytes", 0, 0}, "no value").what(),
               "--set workload.bytes: error: no value");
}

TEST(NetworkConfigError, IsARuntimeError) {
  try {
    throw ConfigError({"f", 1, 2}, "m");
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "f:1:2: error: m");
  }
}

}  // namespace

namespace {

// A value quoted into a message may hold anything a TOML string can: the message stays one line
// a terminal shows as written, and a NUL does not cut it short.
TEST(NetworkConfigError, ControlCharactersAreEscapedNotPrinted) {
  const std::string value = std::string("a\nb\tc") + '\0' + "d\x1b" + "e\x7f";
  const ConfigError e({"dir\nname.toml", 3, 1}, "bad '" + value + "'");
  EXPECT_EQ(std::string(e.what()), "dir\\nname.toml:3:1: error: bad 'a\\nb\\tc\\x00d\\x1be\\x7f'");
}

}  // namespace
