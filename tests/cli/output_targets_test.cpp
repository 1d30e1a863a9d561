// The one output writer (workloads::OutputFile) on every kind of target, each made privately in a
// test directory (never /dev itself: the tests run as root): a regular file is replaced whole, a
// symbolic link is followed and stays a link, a FIFO, a socket and a device are written through,
// a directory and a read-only directory are errors before anything is written, and temporary files
// go away on errors, on SIGTERM and SIGINT, and (left by SIGKILL) at the next write.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <thread>

#include "cli_fixtures.hpp"
#include "tests/test_paths.hpp"
#include "workloads/run/output_file.hpp"

namespace {

namespace fs = std::filesystem;
using workloads::check_output_path;
using workloads::OutputFile;
using workloads::write_output_file;

using cli_test::fresh_dir;
using cli_test::read_file;

// The names in `dir`, hidden ones included.
std::vector<std::string> names_in(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Reads a FIFO to its end in a thread (opening it blocks until a writer opens it).
class FifoReader {
 public:
  explicit FifoReader(const std::string& fifo)
      : thread_([this, fifo] { text_ = read_file(fifo); }) {}
  std::string text() {
    thread_.join();
    return text_;
  }

 private:
  std::string text_;
  std::thread thread_;
};

bool is_fifo(const std::string& path) {
  struct stat st {};
  return lstat(path.c_str(), &st) == 0 && S_ISFIFO(st.st_mode);
}

// The error a call throws ("" for none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(OutputTargets, ARegularFileIsReplacedWholeKeepingItsPermissions) {
  const std::string dir = fresh_dir(), file = dir + "/out.csv";
  std::ofstream(file) << "old\n";
  chmod(file.c_str(), 0640);
  write_output_file(file, "new\n", "--x");
  EXPECT_EQ(read_file(file), "new\n");
  struct stat st {};
  ASSERT_EQ(stat(file.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"out.csv"});
}

TEST(OutputTargets, ALinkStaysALinkAndItsTargetIsReplaced) {
  const std::string dir = fresh_dir();
  fs::create_directories(dir + "/real");
  std::ofstream(dir + "/real/target.csv") << "old\n";
  fs::create_symlink("real/target.csv", dir + "/link.csv");   // relative, as ln -s makes it
  fs::create_symlink(dir + "/link.csv", dir + "/link2.csv");  // a chain of links
  write_output_file(dir + "/link2.csv", "new\n", "--x");
  EXPECT_TRUE(fs::is_symlink(dir + "/link.csv"));
  EXPECT_TRUE(fs::is_symlink(dir + "/link2.csv"));
  EXPECT_EQ(read_file(dir + "/real/target.csv"), "new\n");
  EXPECT_EQ(names_in(dir + "/real"), std::vector<std::string>{"target.csv"});
}

TEST(OutputTargets, ADanglingLinksTargetIsCreated) {
  const std::string dir = fresh_dir();
  fs::create_symlink("made.csv", dir + "/link.csv");
  write_output_file(dir + "/link.csv", "text\n", "--x");
  EXPECT_TRUE(fs::is_symlink(dir + "/link.csv"));
  EXPECT_EQ(read_file(dir + "/made.csv"), "text\n");
}

TEST(OutputTargets, AFifoIsWrittenThroughToItsReader) {
  const std::string dir = fresh_dir(), fifo = dir + "/fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  check_output_path(fifo, "--x");  // does not open it: that would wait for a reader
  FifoReader reader(fifo);
  write_output_file(fifo, "through\n", "--x");
  EXPECT_EQ(reader.text(), "through\n");
  EXPECT_TRUE(is_fifo(fifo));
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"fifo"});
}

TEST(OutputTargets, ALinkToAFifoIsWrittenThroughTheLink) {
  const std::string dir = fresh_dir(), fifo = dir + "/fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink("fifo", dir + "/stdout");  // as /dev/stdout links to a pipe
  FifoReader reader(fifo);
  write_output_file(dir + "/stdout", "via the link\n", "--x");
  EXPECT_EQ(reader.text(), "via the link\n");
  EXPECT_TRUE(fs::is_symlink(dir + "/stdout"));
  EXPECT_TRUE(is_fifo(fifo));
}

TEST(OutputTargets, ASocketIsWrittenThroughToItsListener) {
  const std::string dir = fresh_dir(), path = dir + "/sock";
  const int listener = socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(path.size(), sizeof(address.sun_path));
  std::strcpy(address.sun_path, path.c_str());
  ASSERT_EQ(bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  ASSERT_EQ(listen(listener, 1), 0);
  std::string got;
  std::thread server([&] {
    const int c = accept(listener, nullptr, nullptr);
    char buffer[256];
    for (ssize_t n; (n = ::read(c, buffer, sizeof buffer)) > 0;) got.append(buffer, std::size_t(n));
    close(c);
  });
  write_output_file(path, "to the socket\n", "--x");
  server.join();
  close(listener);
  EXPECT_EQ(got, "to the socket\n");
  struct stat st {};
  ASSERT_EQ(lstat(path.c_str(), &st), 0);
  EXPECT_TRUE(S_ISSOCK(st.st_mode));
}

// A private null device (char 1:3) in the test directory, where the container allows one.
TEST(OutputTargets, ADeviceIsWrittenThroughAndStaysADevice) {
  const std::string dir = fresh_dir(), node = dir + "/null";
  if (mknod(node.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
    GTEST_SKIP() << "cannot make a device node here: " << std::strerror(errno);
  const int fd = open(node.c_str(), O_WRONLY);
  if (fd < 0) GTEST_SKIP() << "device nodes do not open here (nodev): " << std::strerror(errno);
  close(fd);
  write_output_file(node, "gone\n", "--emit-jobs");
  struct stat st {};
  ASSERT_EQ(lstat(node.c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"null"});
}

TEST(OutputTargets, ADirectoryIsAnErrorNamingTheFlag) {
  const std::string dir = fresh_dir();
  fs::create_symlink(dir, dir + "/to-dir");
  const std::string e = error_of([&] { check_output_path(dir, "--trace-csv"); });
  EXPECT_EQ(e, "--trace-csv " + dir + ": cannot write it (it is a directory; give a file's path)");
  const std::string linked = error_of([&] { check_output_path(dir + "/to-dir", "-o"); });
  EXPECT_NE(linked.find("-o " + dir + "/to-dir: cannot write it (it links to the directory"),
            std::string::npos)
      << linked;
  EXPECT_NE(error_of([&] { write_output_file(dir, "x", "--x"); }), "");
}

// Root writes into a read-only directory anyway; the check runs as nobody when the test is root.
TEST(OutputTargets, AReadOnlyDirectoryIsAnErrorBeforeWriting) {
  const std::string dir = fresh_dir(), locked = dir + "/locked";
  fs::create_directories(locked);
  chmod(locked.c_str(), 0555);
  int pipe_fds[2];
  ASSERT_EQ(pipe(pipe_fds), 0);
  const pid_t child = fork();
  if (child == 0) {
    if (geteuid() == 0 && (setgid(65534) != 0 || setuid(65534) != 0)) _exit(3);
    const std::string e = error_of([&] { check_output_path(locked + "/t.csv", "--trace-csv"); });
    if (::write(pipe_fds[1], e.data(), e.size()) < 0) _exit(4);
    _exit(e.empty() ? 1 : 0);
  }
  close(pipe_fds[1]);
  std::string e;
  char buffer[512];
  for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0;)
    e.append(buffer, std::size_t(n));
  close(pipe_fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  chmod(locked.c_str(), 0755);
  ASSERT_TRUE(WIFEXITED(status)) << status;
  ASSERT_EQ(WEXITSTATUS(status), 0) << "no error: " << e;
  EXPECT_EQ(e, "--trace-csv " + locked + "/t.csv: cannot write it (Permission denied)");
  EXPECT_TRUE(fs::is_empty(locked));
}

TEST(OutputTargets, AnUncommittedFileLeavesTheTargetAndNoTemporary) {
  const std::string dir = fresh_dir(), file = dir + "/out.csv";
  std::ofstream(file) << "old\n";
  {
    OutputFile f(file, "--x");
    f.out() << "half";
  }
  EXPECT_EQ(read_file(file), "old\n");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"out.csv"});
}

// A child holds a temporary file open, then is sent the signal: the handler removes the file and
// the child dies by that signal.
void expect_signal_removes_temporary(int signal) {
  const std::string dir = fresh_dir(), file = dir + "/out.csv";
  std::ofstream(file) << "old\n";
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  if (child == 0) {
    OutputFile f(file, "--x");
    f.out() << "half";
    if (::write(ready[1], "r", 1) != 1) _exit(3);
    for (;;) pause();
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  EXPECT_EQ(names_in(dir).size(), 2u);  // the target and the temporary
  kill(child, signal);
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << status;
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"out.csv"});
  EXPECT_EQ(read_file(file), "old\n");
}

TEST(OutputTargets, SigtermRemovesTheTemporaryFile) {
  expect_signal_removes_temporary(SIGTERM);
}
TEST(OutputTargets, SigintRemovesTheTemporaryFile) {
  expect_signal_removes_temporary(SIGINT);
}

// SIGKILL cannot be caught: its temporary file stays until the next write to the same target,
// which removes those of processes that are gone and keeps those of live ones.
TEST(OutputTargets, AStaleTemporaryOfAKilledRunIsRemovedByTheNextWrite) {
  const std::string dir = fresh_dir(), file = dir + "/out.csv";
  const pid_t gone = fork();
  if (gone == 0) _exit(0);
  waitpid(gone, nullptr, 0);
  const std::string stale = ".out.csv." + std::to_string(gone) + "-0.tmp";
  const std::string live = ".out.csv." + std::to_string(getppid()) + "-3.tmp";
  const std::string other = ".other.csv." + std::to_string(gone) + "-0.tmp";
  for (const std::string& name : {stale, live, other}) std::ofstream(dir + "/" + name) << "x";
  write_output_file(file, "new\n", "--x");
  std::vector<std::string> expected{other, live, "out.csv"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names_in(dir), expected);
}

// ---- through the command line ----

TEST(OutputTargets, RunTracesFollowLinksAndWriteThroughFifos) {
  const std::string dir = fresh_dir();
  fs::create_symlink("real.csv", dir + "/trace.csv");  // dangling until the run writes it
  ASSERT_EQ(mkfifo((dir + "/trace.json").c_str(), 0600), 0);
  FifoReader reader(dir + "/trace.json");
  const auto o = cli_test::run("run configs/scenes/pingpong.toml --trace-csv " + dir +
                               "/trace.csv --trace-json " + dir + "/trace.json 2>&1");
  const std::string json = reader.text();
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(fs::is_symlink(dir + "/trace.csv"));
  EXPECT_EQ(read_file(dir + "/real.csv").rfind("kind,name,state,start_us,end_us,label\n", 0), 0u);
  EXPECT_EQ(json.rfind("{\"displayTimeUnit\"", 0), 0u) << json.substr(0, 80);
  EXPECT_TRUE(is_fifo(dir + "/trace.json"));
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"real.csv", "trace.csv", "trace.json"}));
}

TEST(OutputTargets, ATraceThatIsADirectoryIsFoundBeforeTheRunNamingItsFlag) {
  const std::string dir = fresh_dir();
  for (const std::string flag : {"--trace-csv", "--trace-json", "--trace-vcd"}) {
    const auto o = cli_test::run("run configs/scenes/pingpong.toml " + flag + " " + dir + " 2>&1");
    EXPECT_EQ(o.exit_code, 2) << o.out;
    EXPECT_NE(o.out.find("error: " + flag + " " + dir + ": cannot write it (it is a directory"),
              std::string::npos)
        << o.out;
    EXPECT_EQ(o.out.find("simulated time"), std::string::npos) << o.out;
  }
}

TEST(OutputTargets, AWorkloadCsvOnALinkReplacesTheLinksTarget) {
  const std::string dir = fresh_dir();
  std::ofstream(dir + "/real.csv") << "old\n";
  fs::create_symlink("real.csv", dir + "/q.csv");
  const auto o = cli_test::run(
      "run configs/scenes/trajectory.toml --set workload.steps=2 --set workload.output_csv=" + dir +
      "/q.csv 2>&1");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(fs::is_symlink(dir + "/q.csv"));
  EXPECT_NE(read_file(dir + "/real.csv"), "old\n");
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"q.csv", "real.csv"}));
}

// The defect of issue 27: --emit-jobs renamed a file over the device it named.
TEST(OutputTargets, EmittedJobsAreWrittenThroughAFifoAndALink) {
  const std::string dir = fresh_dir();
  ASSERT_EQ(mkfifo((dir + "/jobs").c_str(), 0600), 0);
  FifoReader reader(dir + "/jobs");
  const auto o = cli_test::run(
      "sweep configs/scenes/pingpong.toml --vary workload.bytes=0,8 "
      "--emit-jobs " +
      dir + "/jobs --jobs-dir " + dir + "/results 2>&1");
  const std::string jobs = reader.text();
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(is_fifo(dir + "/jobs"));
  EXPECT_NE(jobs.find("--point 1 -o"), std::string::npos) << jobs;

  fs::create_symlink("real-jobs.txt", dir + "/jobs.txt");
  const auto linked = cli_test::run(
      "sweep configs/scenes/pingpong.toml --vary workload.bytes=0,8 "
      "--emit-jobs " +
      dir + "/jobs.txt --jobs-dir " + dir + "/results 2>&1");
  ASSERT_EQ(linked.exit_code, 0) << linked.out;
  EXPECT_TRUE(fs::is_symlink(dir + "/jobs.txt"));
  EXPECT_NE(read_file(dir + "/real-jobs.txt").find("--point 1 -o"), std::string::npos);
}

TEST(OutputTargets, SweepOutputsThatCannotBeWrittenAreFoundBeforeAnyPoint) {
  const std::string dir = fresh_dir();
  const auto jobs = cli_test::run(
      "sweep configs/scenes/pingpong.toml --vary workload.bytes=0,8 "
      "--emit-jobs " +
      dir + " 2>&1");
  EXPECT_EQ(jobs.exit_code, 2) << jobs.out;
  EXPECT_NE(jobs.out.find("--emit-jobs " + dir + ": cannot write it (it is a directory"),
            std::string::npos)
      << jobs.out;
  const auto table = cli_test::run(
      "sweep configs/scenes/pingpong.toml --vary workload.bytes=0,8 "
      "-o " +
      dir + "/no/such/dir/r.csv 2>&1");
  EXPECT_EQ(table.exit_code, 2) << table.out;
  EXPECT_NE(table.out.find("-o " + dir + "/no/such/dir/r.csv: cannot write it"), std::string::npos)
      << table.out;
  EXPECT_EQ(table.out.find("ok"), std::string::npos) << table.out;  // no point ran
}

TEST(OutputTargets, AMergeOutputFollowsALinkAndInputsMustBeRegularFiles) {
  const std::string dir = fresh_dir();
  ASSERT_EQ(mkfifo((dir + "/fifo.json").c_str(), 0600), 0);
  const auto o = cli_test::run("merge " + dir + "/fifo.json -o " + dir + "/r.csv 2>&1");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find(dir + "/fifo.json: not a regular file (a FIFO), so it is not read"),
            std::string::npos)
      << o.out;
}

}  // namespace
