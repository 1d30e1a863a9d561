// Input built to break the readers: nesting and sizes beyond reason are refused before parsing,
// with the position (or the flag) and the limit, by every reader of TOML and by --set. Without the
// bounds a dotted key or table header some 50,000 levels deep overflowed the parser's stack
// (SIGSEGV).
#include <gtest/gtest.h>

#include "network/toml_limits.hpp"
#include "network/topology_file.hpp"
#include "test_util.hpp"
#include "tools/scene.hpp"

namespace {

using nettest::fails_at;
using nettest::write_file;
using network::TomlLimits;

std::string dotted(const std::string& part, std::size_t parts) {
  std::string key = part;
  for (std::size_t i = 1; i < parts; ++i) key += "." + part;
  return key;
}

std::string nested(std::size_t depth, const std::string& open, const std::string& inner,
                   const std::string& close) {
  std::string text;
  for (std::size_t i = 0; i < depth; ++i) text += open;
  text += inner;
  for (std::size_t i = 0; i < depth; ++i) text += close;
  return text;
}

// The deep cases, each on line 3 of a file whose first lines are fine; the column where it starts.
struct Deep {
  std::string name, line, limit;
  int column;
};

std::vector<Deep> deep_cases(std::size_t depth) {
  return {
      {"dotted key", dotted("k", depth) + " = 1", "dotted parts", 1},
      {"table header", "[" + dotted("t", depth) + "]", "dotted parts", 2},
      {"array of tables header", "[[" + dotted("t", depth) + "]]", "dotted parts", 3},
      {"arrays", "a = " + nested(depth, "[", "1", "]"), "nested more than",
       5 + int(TomlLimits::kMaxNesting)},
      {"inline tables", "a = " + nested(depth, "{b = ", "1", "}"), "nested more than",
       5 + 5 * int(TomlLimits::kMaxNesting)},
      {"dotted key in an inline table", "a = {" + dotted("k", depth) + " = 1}", "dotted parts", 6},
  };
}

TEST(HostileInput, DeepNestingInEveryReaderIsAnErrorAtItsPlace) {
  for (std::size_t depth : {TomlLimits::kMaxKeyParts + 1, std::size_t(100000)}) {
    for (const Deep& d : deep_cases(depth)) {
      const std::string text = "# fine\nname = \"x\"\n" + d.line + "\n";
      const std::string path = write_file("deep.toml", text);
      const std::string what = d.name + " at depth " + std::to_string(depth);
      EXPECT_TRUE(fails_at([&] { network::load_topology(path); }, path, 3, d.column, {d.limit}))
          << what;
      EXPECT_TRUE(fails_at([&] { tools::load_scene(path); }, path, 3, d.column, {d.limit})) << what;
      EXPECT_TRUE(fails_at([&] { tools::check_file(path); }, path, 3, d.column, {d.limit})) << what;
    }
  }
}

TEST(HostileInput, DeepOverridesNameTheFlag) {
  const std::string scene = nettest::source_dir() + "/configs/scenes/pingpong.toml";
  for (std::size_t depth : {TomlLimits::kMaxKeyParts + 1, std::size_t(60000)}) {
    const std::string key = "--set " + dotted("k", depth) + "=1";
    EXPECT_TRUE(
        fails_at([&] { tools::load_scene(scene, {key.substr(6)}); }, key, 0, 0, {"dotted parts"}));
    const std::string value = "--set workload.q=" + nested(depth, "[", "1", "]");
    EXPECT_TRUE(fails_at([&] { tools::load_scene(scene, {value.substr(6)}); }, value, 0, 0,
                         {"nested more than"}));
    const std::string table = "--set workload.q=" + nested(depth, "{a=", "1", "}");
    EXPECT_TRUE(fails_at([&] { tools::load_scene(scene, {table.substr(6)}); }, table, 0, 0,
                         {"nested more than"}));
  }
}

TEST(HostileInput, TheLimitsThemselvesAreAccepted) {
  const std::string ok = dotted("k", TomlLimits::kMaxKeyParts) + " = " +
                         nested(TomlLimits::kMaxNesting, "[", "1", "]") + "\n[" +
                         dotted("t", TomlLimits::kMaxKeyParts) + "]\ns = \"" +
                         std::string(TomlLimits::kMaxStringBytes, 'x') + "\"\n";
  EXPECT_NO_THROW(network::check_toml_limits(ok, "ok.toml"));
}

// What looks like depth inside strings, quoted keys and comments is not depth.
TEST(HostileInput, DotsAndBracketsInStringsAndCommentsDoNotCount) {
  const std::string many = dotted("x", 100);
  const std::string text = "# " + many + " [[[[[[\n\"" + many + "\" = 1\nb = \"" + many +
                           "[[[[\"\nc = '''\n" + nested(100, "[", "", "]") + "\n'''\nd = \"\\\"" +
                           many + "\"\n";
  EXPECT_NO_THROW(network::check_toml_limits(text, "strings.toml"));
}

TEST(HostileInput, HugeStringsAndFilesAreRefused) {
  const std::string big(TomlLimits::kMaxStringBytes + 1, 'x');
  for (const std::string& line : {"s = \"" + big + "\"", "s = '" + big + "'",
                                  "s = \"\"\"\n" + big + "\"\"\"", "\"" + big + "\" = 1"}) {
    const std::string path = write_file("string.toml", "\n" + line + "\n");
    EXPECT_TRUE(fails_at([&] { tools::load_scene(path); }, path, 2, line[0] == '"' ? 1 : 5,
                         {"a string longer than"}))
        << line.substr(0, 8);
  }
  const std::string path = write_file("big.toml", std::string(TomlLimits::kMaxBytes + 1, '#'));
  EXPECT_TRUE(fails_at([&] { network::load_topology(path); }, path, 0, 0, {"bytes; at most"}));
  const std::string scene = nettest::source_dir() + "/configs/scenes/pingpong.toml";
  const std::string flag = "workload.from=\"" + big + "\"";
  EXPECT_TRUE(fails_at([&] { tools::load_scene(scene, {flag}); }, "--set " + flag, 0, 0,
                       {"a string longer than"}));
}

// Found by fuzzing (fuzz/corpus/*/crash-*): toml++ 3.3 reached an unreachable point (undefined
// behaviour) on some non-ASCII characters outside strings, U+039A for one, and terminated on
// invalid UTF-8 in a --set value. Both are refused with their place first; non-ASCII text in
// strings and comments stays fine.
TEST(HostileInput, NonAsciiOutsideStringsAndInvalidUtf8AreErrorsAtTheirPlace) {
  const std::string kappa = "\xce\x9a";  // U+039A
  const std::string key = write_file("kappa.toml", "name = \"x\"\ntopology" + kappa + "\n");
  EXPECT_TRUE(fails_at([&] { network::load_topology(key); }, key, 2, 9,
                       {"a non-ASCII character outside a string"}));
  const std::string space = write_file("space.toml", "a = 1 \xc2\xa1\n");
  EXPECT_TRUE(fails_at([&] { tools::load_scene(space); }, space, 1, 7,
                       {"a non-ASCII character outside a string"}));
  const std::string bad = write_file("bad.toml",
                                     "# fine\nname = \"a\xb5"
                                     "b\"\n");
  EXPECT_TRUE(fails_at([&] { tools::check_file(bad); }, bad, 2, 10, {"invalid UTF-8"}));
  const std::string scene = nettest::source_dir() + "/configs/scenes/dynamics-farm.toml";
  const std::string flag = "workload.q=[0.1, 0.2, 0.5, 0.3, 0.4, 0\xb5\xb5.5]";
  EXPECT_TRUE(fails_at([&] { tools::load_scene(scene, {flag}); }, "--set " + flag, 0, 0,
                       {"invalid UTF-8"}));
  // Where toml++ would test a non-ASCII character for a space: in a bare value (quotes and '=' in
  // it included), in a string that does not end, after a backslash, after a line-ending backslash.
  for (const std::string& value : {"[1,2,3,4x'" + kappa + "]", "-[\"" + kappa + "\"]",
                                   "x=\"" + kappa + "\"", "1\"" + kappa + "\""}) {
    const std::string set = "--set workload.q=" + value;
    EXPECT_TRUE(fails_at([&] { tools::load_scene(scene, {set.substr(6)}); }, set, 0, 0,
                         {"a non-ASCII character outside a string"}))
        << value;
  }
  const std::string open = write_file("open.toml", "a = '" + kappa + "\n");
  EXPECT_TRUE(
      fails_at([&] { tools::check_file(open); }, open, 1, 6, {"in a string that does not end"}));
  const std::string escape = write_file("escape.toml", "a = \"x\\" + kappa + "\"\n");
  EXPECT_TRUE(fails_at([&] { tools::check_file(escape); }, escape, 1, 8,
                       {"a backslash before a non-ASCII"}));
  const std::string trimmed = write_file("trimmed.toml", "a = \"\"\"x\\\n   " + kappa + "\"\"\"\n");
  EXPECT_TRUE(fails_at([&] { tools::check_file(trimmed); }, trimmed, 2, 4,
                       {"after a line-ending backslash"}));
  EXPECT_NO_THROW(network::check_toml_limits(
      "name = \"" + kappa + "\" # " + kappa + "\n'" + kappa + "' = 1\n", "ok.toml"));
}

// Found by fuzzing: a value with a DEL character could not be quoted as a TOML string, and the
// parse error escaped without naming the flag (fuzz/corpus/set/crash-delete-character-in-value).
TEST(HostileInput, ControlCharactersInOverrideValuesNameTheFlag) {
  const std::string scene = nettest::source_dir() + "/configs/scenes/pingpong.toml";
  for (const std::string value : {"a\x7f"
                                  "b",
                                  "a\x01"
                                  "b",
                                  "a\x1f"
                                  "b"}) {
    const std::string flag = "workload.from=" + value;
    EXPECT_TRUE(fails_at([&] { tools::load_scene(scene, {flag}); }, "--set " + flag, 0, 0,
                         {"no processor 'a b'"}));
  }
}

// An absurd network is refused, not attempted: 40,000 transputers once ran the host out of memory
// maps.
TEST(HostileInput, MoreProcessorsThanSimulatedAreRefused) {
  std::string text = "host = \"P0.link0\"\n";
  for (int i = 0; i <= network::kMaxProcessors; ++i)
    text += "[[processor]]\nname = \"P" + std::to_string(i) + "\"\n";
  const std::string path = write_file("many.toml", text);
  // The processor after the last one simulated: line 2 + 2 * kMaxProcessors.
  EXPECT_TRUE(fails_at([&] { network::load_topology(path); }, path, 2 + 2 * network::kMaxProcessors,
                       1, {"has 1025 processors; at most 1024 are simulated"}));
}

// A value echoed in a message is cut, so a megabyte of input does not come back as a megabyte of
// error.
TEST(HostileInput, MessagesEchoAtMostAFewKilobytes) {
  const std::string scene = nettest::source_dir() + "/configs/scenes/pingpong.toml";
  const std::string name(60000, 'P');
  try {
    tools::load_scene(scene, {"workload.from=" + name});
    FAIL() << "accepted";
  } catch (const network::ConfigError& e) {
    EXPECT_LT(std::string(e.what()).size(), 1000u) << std::string(e.what()).substr(0, 300);
    EXPECT_NE(std::string(e.what()).find(" bytes]..."), std::string::npos)
        << std::string(e.what()).substr(0, 300);
  }
}

}  // namespace
