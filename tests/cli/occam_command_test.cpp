// `t800sim occam build`: its errors are tested always; a build with a real toolset runs only when
// T800SIM_D7205 names one (the INMOS D7205A toolset is not part of t800sim: pahihu/t4 has it,
// itools/d7205/d7205a.tar.gz), and is reported as skipped otherwise.
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "tests/cli/cli_fixtures.hpp"

namespace {

namespace fs = std::filesystem;
using cli_test::fresh_dir;
using cli_test::run;

void write_at(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// A program that says hello through hostio, as the toolset's own examples do.
const char* kHello =
    "#INCLUDE \"hostio.inc\"\n"
    "PROC hello (CHAN OF SP fs, ts, []INT memory)\n"
    "  #USE \"hostio.lib\"\n"
    "  SEQ\n"
    "    so.write.string.nl (fs, ts, \"hello from oc\")\n"
    "    so.exit (fs, ts, sps.success)\n"
    ":\n";

TEST(OccamBuild, ANonDirectoryToolsetIsBadInputSayingWhatToGive) {
  const fs::path dir = fresh_dir();
  write_at(dir / "hello.occ", kHello);
  const auto o = run("occam build " + (dir / "hello.occ").string() + " --toolset " +
                     (dir / "nowhere").string() + " 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("--toolset"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("not a directory"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("D7205A"), std::string::npos) << o.out;
}

TEST(OccamBuild, AToolsetMissingItsToolsNamesEveryOneMissing) {
  const fs::path dir = fresh_dir();
  write_at(dir / "hello.occ", kHello);
  write_at(dir / "toolset" / "itools" / "oc.btl", "not a real compiler");
  const auto o = run("occam build " + (dir / "hello.occ").string() + " --toolset " +
                     (dir / "toolset").string() + " 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  for (const char* missing :
       {"itools/ilink.btl", "itools/icollect.btl", "libs/hostio.lib", "libs/occam8.lnk"})
    EXPECT_NE(o.out.find(missing), std::string::npos) << missing << "\n" << o.out;
  EXPECT_EQ(o.out.find("itools/oc.btl"), std::string::npos) << o.out;
}

TEST(OccamBuild, ASourceThatIsNotOccamOrIsMissingIsBadInput) {
  const fs::path dir = fresh_dir();
  for (const char* f : {"itools/oc.btl", "itools/ilink.btl", "itools/icollect.btl",
                        "libs/hostio.lib", "libs/occam8.lnk"})
    write_at(dir / "toolset" / f, "x");
  const std::string toolset = " --toolset " + (dir / "toolset").string() + " 2>&1";
  const auto missing = run("occam build " + (dir / "absent.occ").string() + toolset);
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
  EXPECT_NE(missing.out.find("no such file"), std::string::npos) << missing.out;
  write_at(dir / "prog.c", "int main() {}");
  const auto not_occam = run("occam build " + (dir / "prog.c").string() + toolset);
  EXPECT_EQ(not_occam.exit_code, 2) << not_occam.out;
  EXPECT_NE(not_occam.out.find("NAME.occ"), std::string::npos) << not_occam.out;
  write_at(dir / "bad name.occ", kHello);
  const auto bad_name = run("occam build '" + (dir / "bad name.occ").string() + "'" + toolset);
  EXPECT_EQ(bad_name.exit_code, 2) << bad_name.out;
  EXPECT_NE(bad_name.out.find("letters, digits"), std::string::npos) << bad_name.out;
}

// A file that is no boot file where oc.btl should be: the tool fails, and the command says which
// tool and where its files are, exit 1 (not bad input: the arguments were well formed).
TEST(OccamBuild, AToolThatFailsIsReportedWithItsFilesKept) {
  const fs::path dir = fresh_dir();
  write_at(dir / "hello.occ", kHello);
  for (const char* f : {"itools/oc.btl", "itools/ilink.btl", "itools/icollect.btl",
                        "libs/hostio.lib", "libs/occam8.lnk"})
    write_at(dir / "toolset" / f, "");
  const auto o = run("occam build " + (dir / "hello.occ").string() + " --toolset " +
                     (dir / "toolset").string() + " --work-dir " + (dir / "work").string() +
                     " --max-host-s 20 2>&1");
  EXPECT_EQ(o.exit_code, 1) << o.out;
  EXPECT_NE(o.out.find("oc hello -t8"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find((dir / "work").string()), std::string::npos) << o.out;
  EXPECT_TRUE(fs::exists(dir / "work" / "hello.occ"));
}

TEST(OccamBuild, WithAToolsetTheBuiltProgramBootsAndRuns) {
  const char* toolset = std::getenv("T800SIM_D7205");
  if (!toolset || !*toolset)
    GTEST_SKIP() << "no toolset: set T800SIM_D7205 to an INMOS D7205A toolset's directory";
  const fs::path dir = fresh_dir();
  write_at(dir / "hello.occ", kHello);
  const auto built = run("occam build " + (dir / "hello.occ").string() + " --toolset " + toolset +
                         " -o " + (dir / "hello.btl").string() + " 2>&1");
  ASSERT_EQ(built.exit_code, 0) << built.out;
  const auto ran = run("boot " + (dir / "hello.btl").string() + " 2>&1");
  EXPECT_EQ(ran.exit_code, 0) << ran.out;
  EXPECT_NE(ran.out.find("hello from oc"), std::string::npos) << ran.out;
}

}  // namespace
