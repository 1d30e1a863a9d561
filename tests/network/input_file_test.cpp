// What the program reads must be a regular file it can read whole: a FIFO would block for ever, a
// device such as /dev/zero would be read without end, an unreadable file in /proc would look
// empty. Each is refused before reading with a message saying which it is, by the reader every
// input goes through (network/input_file.hpp) and by the TOML readers built on it.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "network/input_file.hpp"
#include "network/topology_file.hpp"
#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
using nettest::fails_at;
using nettest::write_file;
using network::InputFileError;
using network::read_input_file;

// The message read_input_file throws, "" when it reads; `missing` says which kind it was.
std::string refusal(const std::string& path, std::size_t max_bytes, bool* missing = nullptr) {
  try {
    read_input_file(path, max_bytes);
  } catch (const InputFileError& e) {
    if (missing) *missing = e.missing;
    return e.what();
  }
  return "";
}

std::string private_fifo(const std::string& name) {
  const fs::path where = nettest::scratch_dir() / name;
  fs::create_directories(where.parent_path());
  const std::string path = where.string();
  fs::remove(path);
  EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0) << path;
  return path;
}

TEST(InputFile, ARegularFileIsReadWholeAndALinkIsFollowed) {
  const std::string text(200000, 'x');  // more than one read(2) buffer
  const std::string path = write_file("input_file/regular.txt", text);
  EXPECT_EQ(read_input_file(path, text.size()), text);
  const fs::path link = nettest::scratch_dir() / "input_file/link.txt";
  fs::remove(link);
  fs::create_symlink(path, link);
  EXPECT_EQ(read_input_file(link.string(), text.size()), text);
}

TEST(InputFile, OneByteOverTheBoundIsRefusedNotTruncated) {
  const std::string path = write_file("input_file/long.txt", std::string(101, 'y'));
  EXPECT_EQ(refusal(path, 101), "");
  EXPECT_EQ(refusal(path, 100), "it is 101 bytes; at most 100 are read");
}

TEST(InputFile, EachKindOfNonFileSaysWhatItIs) {
  bool missing = false;
  EXPECT_EQ(refusal((nettest::scratch_dir() / "input_file/absent").string(), 10, &missing),
            "no such file");
  EXPECT_TRUE(missing);
  fs::create_directories(nettest::scratch_dir() / "input_file/dir");
  EXPECT_EQ(refusal((nettest::scratch_dir() / "input_file/dir").string(), 10, &missing),
            "not a regular file (a directory), so it is not read");
  EXPECT_FALSE(missing);
  // Without the check this would block until someone writes to the FIFO.
  EXPECT_EQ(refusal(private_fifo("input_file/fifo"), 10),
            "not a regular file (a FIFO), so it is not read");
  // Reading a character device is harmless; without the check /dev/zero is read without end.
  EXPECT_EQ(refusal("/dev/zero", 10), "not a regular file (a device), so it is not read");
}

TEST(InputFile, AReadErrorIsReportedNotTakenForAnEmptyFile) {
  // /proc/self/mem is a regular file of size 0 whose first page is unmapped: read(2) fails (EIO).
  const std::string e = refusal("/proc/self/mem", 1000);
  EXPECT_EQ(e.rfind("it cannot be read: ", 0), 0u) << e;
}

TEST(InputFile, TheTomlReadersSayWhatTheyWanted) {
  const std::string fifo = private_fifo("input_file/topology.fifo");
  EXPECT_TRUE(fails_at([&] { network::load_topology(fifo); }, fifo, 0, 0,
                       {"not a regular file (a FIFO)", "give a topology file"}));
  EXPECT_TRUE(fails_at([&] { network::load_topology("/proc/self/mem"); }, "/proc/self/mem", 0, 0,
                       {"it cannot be read", "give a topology file"}));
}

}  // namespace
