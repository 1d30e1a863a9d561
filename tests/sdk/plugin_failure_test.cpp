// A plugin that fails -- throws while it is loaded, from its program's build() or from a process's
// body, declares what run refuses, or is no plugin file at all -- is an error naming the plugin,
// the workload kind and, for a process, the process and its processor: never an abort, SystemC's
// "UNKNOWN EXCEPTION" or its own name for the thread. `check` refuses whatever `run` refuses
// before simulating. The plugins are built from tests/sdk/plugins/faulty_plugin.cpp; what they
// throw is T800SIM_TEST_MESSAGE.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../cli/cli_fixtures.hpp"
#include "plugin_scene.hpp"
#include "t800sim/version.hpp"

namespace {

namespace fs = std::filesystem;
using plugin_test::PluginScene;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// What no message of these may be: the C++ runtime's abort or SystemC's words for an exception.
void expect_no_crash_words(const std::string& out) {
  EXPECT_FALSE(has(out, "terminate called")) << out;
  EXPECT_FALSE(has(out, "UNKNOWN EXCEPTION")) << out;
  EXPECT_FALSE(has(out, "sc_except")) << out;
  EXPECT_FALSE(has(out, "proc_")) << out;  // SystemC's name for the thread, not the process's
}

// The line of `out` that says "error:".
std::string error_line(const std::string& out) {
  const auto at = out.find("error:");
  if (at == std::string::npos) return "";
  const auto begin = out.rfind('\n', at);
  const auto start = begin == std::string::npos ? 0 : begin + 1;
  return out.substr(start, out.find('\n', at) - start);
}

std::string kind_line(const std::string& kind) {
  return "kind = \"" + kind + "\"\n";
}

// A plugin that throws while it is loaded, `thrown` naming what it throws: check, run and sweep
// refuse the scene at its workload.plugin line, exit 2, naming the plugin and the kind asked for.
void expect_refused_at_load(const std::string& variant, const std::string& thrown) {
  const PluginScene scene(variant, "plugins/" + variant + ".so", kind_line("faulty_build"));
  const std::string csv = (scene.dir / "sweep.csv").string();
  for (const std::string& command :
       {"check " + scene.file.string(), "run " + scene.file.string(),
        "sweep " + scene.file.string() + " --vary network.link_speed_mbps=10,20 -j 1 -o " + csv}) {
    const auto o = cli_test::run(command + " 2>&1");
    EXPECT_EQ(o.exit_code, 2) << command << "\n" << o.out;
    EXPECT_TRUE(has(o.out, scene.plugin_line())) << o.out;
    EXPECT_TRUE(has(o.out, "plugins/" + variant + ".so")) << o.out;
    EXPECT_TRUE(has(o.out, "faulty_build")) << o.out;
    EXPECT_TRUE(has(o.out, "static initialiser")) << o.out;
    EXPECT_TRUE(has(o.out, thrown)) << o.out;
    expect_no_crash_words(o.out);
  }
}

TEST(PluginFailure, AStaticInitialiserThrowingAStdExceptionIsAnErrorAtThePluginLine) {
  expect_refused_at_load("faulty_throws_at_load",
                         std::string("std::runtime_error: ") + T800SIM_TEST_MESSAGE);
}

TEST(PluginFailure, AStaticInitialiserThrowingAnIntIsAnErrorNamingItsType) {
  expect_refused_at_load("faulty_throws_int_at_load", "int");
}

// What `check` and `run` print for a scene of the faulty plugin's `kind`: both refuse it, exit 2,
// with the same error, which names the plugin and the kind.
std::string expect_check_and_run_refuse(const std::string& kind) {
  const PluginScene scene("faulty", "plugins/faulty.so", kind_line(kind), "pair");
  const auto checked = cli_test::run("check " + scene.file.string() + " 2>&1");
  const auto ran = cli_test::run("run " + scene.file.string() + " 2>&1");
  EXPECT_EQ(checked.exit_code, 2) << checked.out;
  EXPECT_EQ(ran.exit_code, 2) << ran.out;
  EXPECT_FALSE(error_line(checked.out).empty()) << checked.out;
  EXPECT_EQ(error_line(checked.out), error_line(ran.out));
  EXPECT_TRUE(has(ran.out, "workload " + kind)) << ran.out;
  EXPECT_TRUE(has(ran.out, (scene.dir / "plugins" / "faulty.so").string())) << ran.out;
  EXPECT_FALSE(has(ran.out, "simulated_us")) << ran.out;  // nothing ran
  expect_no_crash_words(checked.out + ran.out);
  return ran.out;
}

TEST(PluginFailure, ABuildThatThrowsIsRefusedByCheckAsByRun) {
  const std::string out = expect_check_and_run_refuse("faulty_build");
  EXPECT_TRUE(has(out, std::string("std::runtime_error: ") + T800SIM_TEST_MESSAGE)) << out;
  EXPECT_TRUE(has(out, "build()")) << out;
}

TEST(PluginFailure, TwoWritersOnOneChannelAreRefusedByCheckAsByRun) {
  const std::string out = expect_check_and_run_refuse("faulty_two_writers");
  EXPECT_TRUE(has(out, "channel shared")) << out;
  EXPECT_TRUE(has(out, "first")) << out;
  EXPECT_TRUE(has(out, "second")) << out;
}

TEST(PluginFailure, PlacementOnAMissingProcessorIsRefusedByCheckAsByRun) {
  const std::string out = expect_check_and_run_refuse("faulty_missing_processor");
  EXPECT_TRUE(has(out, "lost")) << out;
  EXPECT_TRUE(has(out, "P9")) << out;
}

// A process whose body throws ends the run: exit 1 (the simulated program did not finish), the
// message naming the process as the program declared it and the processor it ran on.
void expect_process_failure(const std::string& kind, const std::string& process,
                            const std::string& thrown) {
  const PluginScene scene("faulty", "plugins/faulty.so", kind_line(kind), "pair");
  const auto o = cli_test::run("run " + scene.file.string() + " 2>&1");
  EXPECT_EQ(o.exit_code, 1) << o.out;
  EXPECT_TRUE(has(o.out, "workload " + kind)) << o.out;
  EXPECT_TRUE(has(o.out, (scene.dir / "plugins" / "faulty.so").string())) << o.out;
  EXPECT_TRUE(has(o.out, "process " + process + " on P1")) << o.out;
  EXPECT_TRUE(has(o.out, thrown)) << o.out;
  expect_no_crash_words(o.out);
}

TEST(PluginFailure, AProcessBodyThatThrowsIsNamedWithItsProcessor) {
  expect_process_failure("faulty_body", "thrower",
                         std::string("std::runtime_error: ") + T800SIM_TEST_MESSAGE);
}

TEST(PluginFailure, AProcessBodyThatThrowsAnIntIsNamedWithItsProcessor) {
  expect_process_failure("faulty_body_int", "int_thrower", "int");
}

// After a run that ended: exit 1 (the run failed), no report, the kind and plugin named.
TEST(PluginFailure, ResultsThatThrowAreAFailedRunNamingTheWorkload) {
  const PluginScene scene("faulty", "plugins/faulty.so", kind_line("faulty_results"));
  const auto o = cli_test::run("run " + scene.file.string() + " 2>&1");
  EXPECT_EQ(o.exit_code, 1) << o.out;
  EXPECT_TRUE(has(o.out, "workload faulty_results")) << o.out;
  EXPECT_TRUE(has(o.out, (scene.dir / "plugins" / "faulty.so").string())) << o.out;
  EXPECT_TRUE(has(o.out, "results()")) << o.out;
  EXPECT_TRUE(has(o.out, "int")) << o.out;
  expect_no_crash_words(o.out);
}

// A plugin file `why` refuses without running any of it: exit 2 at the plugin's line.
void expect_file_refused(const PluginScene& scene, const std::string& shown,
                         const std::string& why) {
  const auto o = cli_test::run("check " + scene.file.string() + " 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_TRUE(has(o.out, scene.plugin_line())) << o.out;
  EXPECT_TRUE(has(o.out, shown)) << o.out;
  EXPECT_TRUE(has(o.out, why)) << o.out;
  EXPECT_FALSE(has(o.out, "cannot be loaded")) << o.out;  // never given to dlopen
}

TEST(PluginFailure, ADirectoryIsRefused) {
  const PluginScene scene("", "plugins");
  expect_file_refused(scene, "plugins", "directory");
}

// 2 GiB of a sparse file that begins as ELF does: refused by its size, before it is read.
TEST(PluginFailure, AHugeFileIsRefusedByItsSize) {
  const PluginScene scene("", "plugins/huge.so");
  const fs::path huge = scene.dir / "plugins" / "huge.so";
  std::ofstream(huge, std::ios::binary) << "\x7f"
                                           "ELF";
  const std::uintmax_t bytes = std::uintmax_t(2) << 30;
  fs::resize_file(huge, bytes);
  expect_file_refused(scene, "plugins/huge.so", std::to_string(bytes) + " bytes");
}

// A file that carries the plugin marker and this SDK's version but is not a shared library: its
// first bytes tell, and it never reaches dlopen.
TEST(PluginFailure, AFileThatIsNotElfIsRefusedByItsFirstBytes) {
  const PluginScene scene("", "plugins/marked.so");
  std::ofstream(scene.dir / "plugins" / "marked.so", std::ios::binary)
      << "a text that claims " << T800SIM_PLUGIN_MARKER T800SIM_VERSION << '\0' << "\n";
  expect_file_refused(scene, "plugins/marked.so", "ELF");
}

}  // namespace
