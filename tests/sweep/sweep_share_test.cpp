// Sweeps that share one results table lose nothing: a second sweep on the same -o waits for the
// first (the lock `.NAME.lock` beside the table), says which process holds it, then reads what the
// first wrote; a table that is not a regular file is written through once and never read.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <sys/wait.h>

#include <cstdlib>
#include <string>
#include <thread>
#include <utility>

#include "sweep_fixtures.hpp"
#include "tests/test_paths.hpp"

namespace {

using namespace sweep_test;
using cli_test::run;

std::size_t rows_with_status_ok(const std::string& path) {
  const auto t = table(path);
  std::size_t ok = 0;
  for (std::size_t i = 1; i < t.size(); ++i) ok += t[i][column(t, "status")] == "ok";
  return ok;
}

// Issue 27: the sweep finishing last rewrote the table from its own view, the other's rows lost.
TEST(SweepShare, TwoSweepsOnOneTableKeepEveryRow) {
  const std::string dir = fresh_dir(), out = dir + "/r.csv";
  const std::string sweep = "sweep configs/scenes/pingpong.toml --set workload.iterations=2 -j 1 ";
  const std::string t800sim = test_paths::binary_dir() + "/t800sim ";
  const std::string both = std::string("cd ") + test_paths::source_dir() +
                           " && SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 sh -c '" + t800sim + sweep +
                           "--vary workload.bytes=1..6 -o " + out + " 2>" + dir +
                           "/a.err & a=$!; " + t800sim + sweep + "--vary workload.bytes=7..12 -o " +
                           out + " 2>" + dir + "/b.err; b=$?; wait $a && exit $b'";
  const int status = std::system(both.c_str());
  const cli_test::Output o{WIFEXITED(status) ? WEXITSTATUS(status) : -1, both};
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_EQ(rows_with_status_ok(out), 12u)
      << read_file(out) << read_file(dir + "/a.err") << read_file(dir + "/b.err");
  EXPECT_EQ(table(out).size(), 13u);
}

// The test holds the table's lock as a sweep would: the sweep says who holds it and waits; once
// the lock is released it reads the rows the holder wrote, skips their points and keeps them.
TEST(SweepShare, ASecondSweepWaitsForTheFirstNamingIt) {
  const std::string dir = fresh_dir(), out = dir + "/r.csv", err = dir + "/sweep.err";
  // Close-on-exec, or the sweep (started through a shell) would inherit the held lock.
  const int lock = open((dir + "/.r.csv.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  ASSERT_GE(lock, 0);
  ASSERT_EQ(flock(lock, LOCK_EX), 0);
  const std::string holder = "the sweep pid 4242 (a test)\n";
  ASSERT_EQ(pwrite(lock, holder.data(), holder.size(), 0), ssize_t(holder.size()));
  // The holder's table so far: point bytes=8 done.
  const auto first =
      run("sweep configs/scenes/pingpong.toml --set workload.iterations=2 "
          "--vary workload.bytes=8 -o " +
          dir + "/first.csv 2>&1");
  ASSERT_EQ(first.exit_code, 0) << first.out;
  int exit_code = -1;
  std::thread sweep([&] {
    exit_code = run("sweep configs/scenes/pingpong.toml --set workload.iterations=2 --vary "
                    "workload.bytes=8,16 -o " +
                    out + " 2>" + err)
                    .exit_code;
  });
  const bool waiting = cli_test::wait_until(
      [&] {
        return read_file(err).find("is in use by the sweep pid 4242 (a test)") != std::string::npos;
      },
      120);
  EXPECT_TRUE(waiting) << read_file(err);
  std::filesystem::copy_file(dir + "/first.csv", out);
  const std::string kept = lines(read_file(out)).at(1);
  close(lock);  // releases it
  sweep.join();
  EXPECT_EQ(exit_code, 0) << read_file(err);
  EXPECT_NE(read_file(err).find("1 of 2 points already in"), std::string::npos) << read_file(err);
  const auto t = lines(read_file(out));
  ASSERT_EQ(t.size(), 3u) << read_file(out);
  EXPECT_EQ(t[1], kept);  // the holder's row, as it wrote it
  EXPECT_EQ(rows_with_status_ok(out), 2u);
}

TEST(SweepShare, ATableThatIsAFifoIsWrittenOnceAndNeverRead) {
  const std::string dir = fresh_dir(), fifo = dir + "/table";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::string text;
  std::thread reader([&] { text = read_file(fifo); });
  const auto o =
      run("sweep configs/scenes/pingpong.toml --set workload.iterations=2 --vary "
          "workload.bytes=8,16 -o " +
          fifo + " 2>&1");
  reader.join();
  EXPECT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find("is not a regular file: the table is written to it once"), std::string::npos)
      << o.out;
  EXPECT_EQ(lines(text).size(), 3u) << text;
  struct stat st {};
  ASSERT_EQ(lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(SweepShare, AJobsResultOnALinkStaysALink) {
  const std::string dir = fresh_dir();
  std::filesystem::create_symlink("real.json", dir + "/point.json");
  const auto o =
      run("sweep configs/scenes/pingpong.toml --set workload.iterations=2 --vary "
          "workload.bytes=8,16 --point 1 -o " +
          dir + "/point.json 2>&1");
  EXPECT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(std::filesystem::is_symlink(dir + "/point.json"));
  EXPECT_NE(read_file(dir + "/real.json").find("\"status\""), std::string::npos);
}

// A point outside the sweep is refused before anything runs (-1 once ran the whole sweep into the
// .json path, exit 0).
TEST(SweepShare, APointOutsideTheSweepIsAnError) {
  const std::pair<std::string, std::string> cases[] = {
      {"-1", "--point: '-1' is not an index"}, {"2", "--point 2: this sweep has points 0 to 1"}};
  for (const auto& [point, message] : cases) {
    const auto o = run("sweep configs/scenes/pingpong.toml --vary workload.bytes=8,16 --point " +
                       point + " -o /nonexistent/p.json 2>&1");
    EXPECT_EQ(o.exit_code, 2) << o.out;
    EXPECT_NE(o.out.find(message), std::string::npos) << o.out;
  }
}

TEST(SweepShare, ATimeoutThatIsNotSecondsIsAnError) {
  for (const std::string value : {"nan", "-3", "inf"}) {
    const auto o = run("sweep configs/scenes/pingpong.toml --vary workload.bytes=8,16 --timeout " +
                       value + " -o /nonexistent/p.json 2>&1");
    EXPECT_EQ(o.exit_code, 2) << value << "\n" << o.out;
    EXPECT_NE(o.out.find("--timeout: '" + value + "' is not a number of seconds"),
              std::string::npos)
        << o.out;
  }
}

}  // namespace
