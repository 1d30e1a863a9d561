// The SP server's file requests (OPEN .. RENAME) on a temporary root directory, the predefined
// streams, and every refusal of the sandbox. Requests and replies are written byte by byte from the
// layouts in iserver 1.50's filec.c: INT32 ids, INT16 counts, slices as INT16 count + bytes, all
// little-endian; replies padded with zeros to an even length of at least 6.
#include "t800/host/sp_server.hpp"
#include "tests/host/sp_bytes.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace t800::host {
namespace {

namespace fs = std::filesystem;
using namespace sp_bytes;

Bytes open_request(const std::string& name, std::uint8_t type, std::uint8_t mode) {
  return padded_even(cat({Bytes{10}, slice(name), Bytes{type, mode}}));
}
Bytes id_request(std::uint8_t tag, std::uint32_t id) {
  return padded_even(cat({Bytes{tag}, le32(id)}));
}
Bytes read_request(std::uint8_t tag, std::uint32_t id, std::uint16_t count) {
  return cat({Bytes{tag}, le32(id),
              Bytes{static_cast<std::uint8_t>(count), static_cast<std::uint8_t>(count >> 8)}});
}
Bytes write_request(std::uint8_t tag, std::uint32_t id, const std::string& data) {
  return padded_even(cat({Bytes{tag}, le32(id), slice(data)}));
}
Bytes seek_request(std::uint32_t id, std::int32_t offset, std::int32_t origin) {
  return cat({Bytes{17}, le32(id), le32(static_cast<std::uint32_t>(offset)),
              le32(static_cast<std::uint32_t>(origin))});
}

Bytes opened(std::uint8_t id) {
  return Bytes{0, id, 0, 0, 0, 0};
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream all;
  all << in.rdbuf();
  return all.str();
}

class SpServerFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "sp_server_test_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    base_ = pattern;
    root_ = base_ / "root";
    outside_ = base_ / "outside";
    fs::create_directories(root_ / "sub");
    fs::create_directories(outside_);
    std::ofstream(outside_ / "secret") << "outside";
  }
  void TearDown() override { fs::remove_all(base_); }

  SpServer& server() {
    if (!server_) {
      SpServerOptions options;
      options.root = root_;
      SpHost host;
      host.in = &in_;
      host.out = &out_;
      host.err = &err_;
      server_ = std::make_unique<SpServer>(options, host);
    }
    return *server_;
  }
  Bytes handle(const Bytes& request) { return server().handle(request); }

  fs::path base_, root_, outside_;
  std::istringstream in_;
  std::ostringstream out_, err_;
  std::unique_ptr<SpServer> server_;
};

TEST_F(SpServerFiles, RoundTrip) {
  // OPEN "data.bin" binary, output ("w") -> OK, id 3 (0..2 are the predefined streams).
  EXPECT_EQ(handle(Bytes{10, 8, 0, 'd', 'a', 't', 'a', '.', 'b', 'i', 'n', 1, 2, 0}), opened(3));
  // WRITE id 3 "hello\nworld\n" -> OK, INT16 12 written.
  EXPECT_EQ(handle(cat({Bytes{13, 3, 0, 0, 0, 12, 0}, text("hello\nworld\n")})),
            (Bytes{0, 12, 0, 0, 0, 0}));
  EXPECT_EQ(handle(Bytes{16, 3, 0, 0, 0, 0}), kOk);  // FLUSH
  EXPECT_EQ(handle(Bytes{11, 3, 0, 0, 0, 0}), kOk);  // CLOSE
  EXPECT_EQ(contents(root_ / "data.bin"), "hello\nworld\n");

  // OPEN again for input ("r"): the lowest free id, 3 again.
  EXPECT_EQ(handle(open_request("data.bin", 1, 1)), opened(3));
  // READ id 3, 5 bytes -> OK, slice "hello" (1 + 2 + 5 = 8 bytes, even: no padding).
  EXPECT_EQ(handle(Bytes{12, 3, 0, 0, 0, 5, 0}), (Bytes{0, 5, 0, 'h', 'e', 'l', 'l', 'o'}));
  // TELL -> OK, INT32 5.
  EXPECT_EQ(handle(Bytes{18, 3, 0, 0, 0, 0}), (Bytes{0, 5, 0, 0, 0, 0}));
  // GETS: the rest of the first line is empty; its newline is not returned.
  EXPECT_EQ(handle(Bytes{14, 3, 0, 0, 0, 100, 0}), (Bytes{0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(handle(Bytes{14, 3, 0, 0, 0, 100, 0}), (Bytes{0, 5, 0, 'w', 'o', 'r', 'l', 'd'}));
  // Not at end of file yet (nothing has tried to read past it): EOF answers the error result.
  EXPECT_EQ(handle(Bytes{19, 3, 0, 0, 0, 0}), kError);
  // GETS at the end: fgets returns NULL -> the error result; now EOF is OK.
  EXPECT_EQ(handle(Bytes{14, 3, 0, 0, 0, 100, 0}), kError);
  EXPECT_EQ(handle(Bytes{19, 3, 0, 0, 0, 0}), kOk);
  // READ at the end: OK with nothing.
  EXPECT_EQ(handle(Bytes{12, 3, 0, 0, 0, 5, 0}), (Bytes{0, 0, 0, 0, 0, 0}));

  // SEEK id 3 to offset 0 from the start (origin 1) -> OK, and the end-of-file indicator clears.
  EXPECT_EQ(handle(seek_request(3, 0, 1)), kOk);
  EXPECT_EQ(handle(Bytes{19, 3, 0, 0, 0, 0}), kError);
  // READ 100: all 12 bytes; 1 + 2 + 12 = 15, padded to 16.
  EXPECT_EQ(handle(Bytes{12, 3, 0, 0, 0, 100, 0}),
            cat({Bytes{0, 12, 0}, text("hello\nworld\n"), Bytes{0}}));
  // SEEK -6 from the end (origin 3), then from the current position (origin 2) +1.
  EXPECT_EQ(handle(seek_request(3, -6, 3)), kOk);
  EXPECT_EQ(handle(seek_request(3, 1, 2)), kOk);
  EXPECT_EQ(handle(Bytes{18, 3, 0, 0, 0, 0}), (Bytes{0, 7, 0, 0, 0, 0}));
  EXPECT_EQ(handle(Bytes{12, 3, 0, 0, 0, 4, 0}), (Bytes{0, 4, 0, 'o', 'r', 'l', 'd', 0}));
  // An origin other than 1, 2, 3 and a position before the start are errors.
  EXPECT_EQ(handle(seek_request(3, 0, 4)), kError);
  EXPECT_EQ(handle(seek_request(3, 0, 0)), kError);
  EXPECT_EQ(handle(seek_request(3, -100, 1)), kError);
  EXPECT_EQ(handle(Bytes{11, 3, 0, 0, 0, 0}), kOk);

  // PUTS appends a newline: OPEN "lines.txt" text, output; PUTS "one", PUTS "".
  EXPECT_EQ(handle(open_request("lines.txt", 2, 2)), opened(3));
  EXPECT_EQ(handle(Bytes{15, 3, 0, 0, 0, 3, 0, 'o', 'n', 'e', 0}), kOk);
  EXPECT_EQ(handle(Bytes{15, 3, 0, 0, 0, 0, 0}), kOk);
  EXPECT_EQ(handle(Bytes{11, 3, 0, 0, 0, 0}), kOk);
  EXPECT_EQ(contents(root_ / "lines.txt"), "one\n\n");

  // RENAME "data.bin" -> "sub/moved.bin"; the old name no longer opens.
  EXPECT_EQ(handle(padded_even(cat({Bytes{22}, slice("data.bin"), slice("sub/moved.bin")}))), kOk);
  EXPECT_EQ(handle(open_request("data.bin", 1, 1)), kError);
  EXPECT_EQ(contents(root_ / "sub" / "moved.bin"), "hello\nworld\n");
  // REMOVE it; a second REMOVE finds no file (ER_NOFILE).
  EXPECT_EQ(handle(padded_even(cat({Bytes{21}, slice("sub/moved.bin")}))), kOk);
  EXPECT_FALSE(fs::exists(root_ / "sub" / "moved.bin"));
  EXPECT_EQ(handle(padded_even(cat({Bytes{21}, slice("sub/moved.bin")}))), kNoFile);
  // RENAME of a file that is not there fails.
  EXPECT_EQ(handle(padded_even(cat({Bytes{22}, slice("nothing"), slice("else")}))), kError);
}

TEST_F(SpServerFiles, GetsLimitAndLongLines) {
  std::ofstream(root_ / "in.txt") << "abcdef\nxy";
  EXPECT_EQ(handle(open_request("in.txt", 2, 1)), opened(3));
  // Limit 3: "abc", the rest of the line stays.
  EXPECT_EQ(handle(read_request(14, 3, 3)), (Bytes{0, 3, 0, 'a', 'b', 'c'}));
  // Limit 4 takes "def\n": the newline counts against the limit, as fgets(buffer, limit + 1).
  EXPECT_EQ(handle(read_request(14, 3, 4)), (Bytes{0, 3, 0, 'd', 'e', 'f'}));
  // Limit 0 reads nothing and succeeds.
  EXPECT_EQ(handle(read_request(14, 3, 0)), (Bytes{0, 0, 0, 0, 0, 0}));
  // A last line without a newline.
  EXPECT_EQ(handle(read_request(14, 3, 50)), (Bytes{0, 2, 0, 'x', 'y', 0}));
  EXPECT_EQ(handle(read_request(14, 3, 50)), kError);
}

TEST_F(SpServerFiles, ReadAndGetsClippedToThePacket) {
  std::ofstream(root_ / "big.bin") << std::string(2000, 'z');
  EXPECT_EQ(handle(open_request("big.bin", 1, 1)), opened(3));
  // READ asking for 2000 bytes gets 507: 1 + 2 + 507 = 510 bytes, the largest body.
  const Bytes read = handle(read_request(12, 3, 2000));
  ASSERT_EQ(read.size(), 510u);
  EXPECT_EQ(read[0], 0);
  EXPECT_EQ(read[1] | (read[2] << 8), 507);
  EXPECT_EQ(handle(Bytes{18, 3, 0, 0, 0, 0}), (Bytes{0, 0xfb, 0x01, 0, 0, 0}));  // 507
  const Bytes line = handle(read_request(14, 3, 65535));
  ASSERT_EQ(line.size(), 510u);
  EXPECT_EQ(line[1] | (line[2] << 8), 507);
}

TEST_F(SpServerFiles, OpenModes) {
  std::ofstream(root_ / "f") << "abc";
  // Append ("a", 3) writes at the end.
  EXPECT_EQ(handle(open_request("f", 1, 3)), opened(3));
  EXPECT_EQ(handle(write_request(13, 3, "d")), (Bytes{0, 1, 0, 0, 0, 0}));
  EXPECT_EQ(handle(id_request(11, 3)), kOk);
  EXPECT_EQ(contents(root_ / "f"), "abcd");
  // Existing update ("r+", 4): from the start, overwriting.
  EXPECT_EQ(handle(open_request("f", 1, 4)), opened(3));
  EXPECT_EQ(handle(write_request(13, 3, "X")), (Bytes{0, 1, 0, 0, 0, 0}));
  EXPECT_EQ(handle(id_request(11, 3)), kOk);
  EXPECT_EQ(contents(root_ / "f"), "Xbcd");
  // Append update ("a+", 6): starts at the end (iserver seeks there), TELL says 4.
  EXPECT_EQ(handle(open_request("f", 2, 6)), opened(3));
  EXPECT_EQ(handle(id_request(18, 3)), (Bytes{0, 4, 0, 0, 0, 0}));
  EXPECT_EQ(handle(id_request(11, 3)), kOk);
  // New update ("w+", 5) truncates, then reads back what it wrote after a seek.
  EXPECT_EQ(handle(open_request("f", 1, 5)), opened(3));
  EXPECT_EQ(handle(write_request(13, 3, "new")), (Bytes{0, 3, 0, 0, 0, 0}));
  EXPECT_EQ(handle(seek_request(3, 0, 1)), kOk);
  EXPECT_EQ(handle(read_request(12, 3, 10)), (Bytes{0, 3, 0, 'n', 'e', 'w'}));
  EXPECT_EQ(handle(id_request(11, 3)), kOk);
  // "r+" of a file that is not there fails; "w" creates.
  EXPECT_EQ(handle(open_request("absent", 1, 4)), kError);
  EXPECT_EQ(handle(open_request("absent", 1, 1)), kError);
  EXPECT_EQ(handle(open_request("sub/created", 2, 2)), opened(3));
  EXPECT_TRUE(fs::exists(root_ / "sub" / "created"));
  // Types other than binary (1) and text (2), modes outside 1..6: the error result.
  EXPECT_EQ(handle(open_request("f", 0, 1)), kError);
  EXPECT_EQ(handle(open_request("f", 3, 1)), kError);
  EXPECT_EQ(handle(open_request("f", 1, 0)), kError);
  EXPECT_EQ(handle(open_request("f", 1, 7)), kError);
  // An empty name: the error result (filec.c SpOpen).
  EXPECT_EQ(handle(open_request("", 1, 1)), kError);
}

TEST_F(SpServerFiles, ReadAfterWriteNeedsASeek) {
  EXPECT_EQ(handle(open_request("u", 1, 5)), opened(3));
  EXPECT_EQ(handle(write_request(13, 3, "abc")), (Bytes{0, 3, 0, 0, 0, 0}));
  EXPECT_EQ(handle(read_request(12, 3, 3)), kNoPosition);
  EXPECT_EQ(handle(read_request(14, 3, 3)), kNoPosition);
  EXPECT_EQ(handle(seek_request(3, 0, 1)), kOk);
  EXPECT_EQ(handle(read_request(12, 3, 3)), (Bytes{0, 3, 0, 'a', 'b', 'c'}));
  EXPECT_EQ(handle(write_request(13, 3, "d")), kNoPosition);
  EXPECT_EQ(handle(write_request(15, 3, "d")), kNoPosition);
  EXPECT_EQ(handle(seek_request(3, 0, 2)), kOk);
  EXPECT_EQ(handle(write_request(15, 3, "d")), kOk);
  EXPECT_EQ(handle(id_request(11, 3)), kOk);
  EXPECT_EQ(contents(root_ / "u"), "abcd\n");
}

TEST_F(SpServerFiles, FerrorReportsTheFailure) {
  std::ofstream(root_ / "ro") << "x";
  EXPECT_EQ(handle(open_request("ro", 1, 1)), opened(3));
  // No error yet: FERROR answers the error result.
  EXPECT_EQ(handle(id_request(20, 3)), kError);
  // Writing to an input file writes nothing: OK, 0 written (as fwrite), and sets the error.
  EXPECT_EQ(handle(write_request(13, 3, "y")), (Bytes{0, 0, 0, 0, 0, 0}));
  const std::string message = std::strerror(EBADF);
  EXPECT_EQ(handle(id_request(20, 3)), padded_even(cat({Bytes{0}, le32(EBADF), slice(message)})));
  EXPECT_EQ(handle(id_request(11, 3)), kOk);
}

TEST_F(SpServerFiles, BadStreamIds) {
  for (const std::uint32_t id : {3u, 99u, 127u, 128u, 0xffffffffu, 0x80000000u}) {
    EXPECT_EQ(handle(id_request(11, id)), kBadId) << id;
    EXPECT_EQ(handle(read_request(12, id, 1)), kBadId) << id;
    EXPECT_EQ(handle(write_request(13, id, "x")), kBadId) << id;
    EXPECT_EQ(handle(read_request(14, id, 1)), kBadId) << id;
    EXPECT_EQ(handle(write_request(15, id, "x")), kBadId) << id;
    EXPECT_EQ(handle(id_request(16, id)), kBadId) << id;
    EXPECT_EQ(handle(seek_request(id, 0, 1)), kBadId) << id;
    EXPECT_EQ(handle(id_request(18, id)), kBadId) << id;
    EXPECT_EQ(handle(id_request(19, id)), kBadId) << id;
    EXPECT_EQ(handle(id_request(20, id)), kBadId) << id;
  }
}

TEST_F(SpServerFiles, StreamTableFills) {
  // iserver files.h MAX_FILES 128: ids 3..127 are free.
  for (int id = 3; id < 128; ++id) {
    ASSERT_EQ(handle(open_request("many", 1, 2)), opened(static_cast<std::uint8_t>(id)));
  }
  EXPECT_EQ(handle(open_request("many", 1, 2)), kNoResource);
  EXPECT_EQ(handle(id_request(11, 50)), kOk);
  EXPECT_EQ(handle(open_request("many", 1, 2)), opened(50));
}

TEST_F(SpServerFiles, PredefinedStreams) {
  in_.str("first line\nrest");
  // WRITE to stdout (1) and PUTS to stderr (2) reach the injected streams.
  EXPECT_EQ(handle(write_request(13, 1, "to stdout")), (Bytes{0, 9, 0, 0, 0, 0}));
  EXPECT_EQ(handle(write_request(15, 2, "to stderr")), kOk);
  EXPECT_EQ(out_.str(), "to stdout");
  EXPECT_EQ(err_.str(), "to stderr\n");
  // GETS and READ from stdin (0).
  EXPECT_EQ(handle(read_request(14, 0, 100)), cat({Bytes{0, 10, 0}, text("first line"), Bytes{0}}));
  EXPECT_EQ(handle(read_request(12, 0, 100)), (Bytes{0, 4, 0, 'r', 'e', 's', 't', 0}));
  EXPECT_EQ(handle(id_request(19, 0)), kOk);
  EXPECT_EQ(handle(id_request(19, 1)), kError);
  EXPECT_EQ(handle(id_request(16, 1)), kOk);
  // Not seekable, as a terminal or pipe is not.
  EXPECT_EQ(handle(seek_request(1, 0, 1)), kError);
  EXPECT_EQ(handle(id_request(18, 0)), kError);
  // After writing, a read needs a seek first, even on stdout.
  EXPECT_EQ(handle(read_request(12, 1, 5)), kNoPosition);
  // Closing stdout frees id 1 (the injected stream stays usable by its owner); OPEN reuses it.
  EXPECT_EQ(handle(id_request(11, 1)), kOk);
  EXPECT_EQ(handle(write_request(13, 1, "x")), kBadId);
  EXPECT_EQ(handle(open_request("reuse", 1, 2)), opened(1));
  EXPECT_EQ(out_.str(), "to stdout");
}

TEST_F(SpServerFiles, WrongDirectionOnPredefinedStreams) {
  // Writing stdin or reading stdout transfers nothing and sets the error indicator (as fwrite and
  // fread would); FERROR then reports EBADF.
  EXPECT_EQ(handle(write_request(13, 0, "x")), (Bytes{0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(handle(id_request(20, 0)),
            padded_even(cat({Bytes{0}, le32(EBADF), slice(std::strerror(EBADF))})));
  EXPECT_EQ(handle(read_request(12, 2, 5)), (Bytes{0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(handle(id_request(20, 2)),
            padded_even(cat({Bytes{0}, le32(EBADF), slice(std::strerror(EBADF))})));
  EXPECT_EQ(handle(id_request(20, 1)), kError);
  EXPECT_EQ(out_.str(), "");
}

TEST_F(SpServerFiles, RefusesNamesOutsideTheRoot) {
  const std::string outside_secret = (outside_ / "secret").string();
  for (const std::string& name :
       {outside_secret, std::string("/etc/passwd"), std::string("/"), std::string("../x"),
        std::string(".."), std::string("sub/../../outside/secret"), std::string("sub/.."),
        std::string("sub/../f"), std::string("./../x"), std::string("sub//../../x")}) {
    EXPECT_EQ(handle(open_request(name, 1, 1)), kNoPrivilege) << name;
    EXPECT_EQ(handle(open_request(name, 1, 2)), kNoPrivilege) << name;
    EXPECT_EQ(handle(padded_even(cat({Bytes{21}, slice(name)}))), kNoPrivilege) << name;
    EXPECT_EQ(handle(padded_even(cat({Bytes{22}, slice(name), slice("inside")}))), kNoPrivilege)
        << name;
    EXPECT_EQ(handle(padded_even(cat({Bytes{22}, slice("inside"), slice(name)}))), kNoPrivilege)
        << name;
  }
  EXPECT_EQ(contents(outside_ / "secret"), "outside");
  EXPECT_FALSE(fs::exists(base_ / "x"));
  // The root itself cannot be removed or renamed.
  EXPECT_EQ(handle(padded_even(cat({Bytes{21}, slice(".")}))), kNoPrivilege);
  EXPECT_EQ(handle(padded_even(cat({Bytes{22}, slice("./"), slice("y")}))), kNoPrivilege);
  EXPECT_TRUE(fs::is_directory(root_));
  // A NUL inside the name, or an empty name: the error result.
  EXPECT_EQ(handle(open_request(std::string("ok\0/../../x", 11), 1, 2)), kError);
  EXPECT_EQ(handle(padded_even(cat({Bytes{21}, slice("")}))), kError);
  EXPECT_EQ(handle(padded_even(cat({Bytes{22}, slice(""), slice("a")}))), kError);
}

TEST_F(SpServerFiles, RefusesSymbolicLinksThatLeadOut) {
  fs::create_directory_symlink(outside_, root_ / "out");         // a directory outside
  fs::create_symlink(outside_ / "secret", root_ / "escape");     // a file outside
  fs::create_symlink(outside_ / "created", root_ / "dangling");  // nothing, outside
  fs::create_symlink("loop", root_ / "loop");                    // itself
  fs::create_directory_symlink("../../outside", root_ / "sub" / "up");
  EXPECT_EQ(handle(open_request("out/secret", 1, 1)), kNoPrivilege);
  EXPECT_EQ(handle(open_request("out/new", 1, 2)), kNoPrivilege);
  EXPECT_EQ(handle(open_request("escape", 1, 1)), kNoPrivilege);
  EXPECT_EQ(handle(open_request("escape", 1, 4)), kNoPrivilege);
  EXPECT_EQ(handle(open_request("dangling", 1, 2)), kNoPrivilege);
  EXPECT_EQ(handle(open_request("loop", 1, 1)), kNoPrivilege);
  EXPECT_EQ(handle(open_request("sub/up/secret", 1, 1)), kNoPrivilege);
  EXPECT_EQ(handle(padded_even(cat({Bytes{21}, slice("out/secret")}))), kNoPrivilege);
  EXPECT_EQ(handle(padded_even(cat({Bytes{22}, slice("out/secret"), slice("mine")}))),
            kNoPrivilege);
  EXPECT_EQ(handle(padded_even(cat({Bytes{22}, slice("sub/f"), slice("out/f")}))), kNoPrivilege);
  EXPECT_FALSE(fs::exists(outside_ / "created"));
  EXPECT_FALSE(fs::exists(outside_ / "new"));
  EXPECT_EQ(contents(outside_ / "secret"), "outside");

  // REMOVE and RENAME act on a link itself (as C's remove and rename): it lies inside the root,
  // so removing it is allowed and leaves its target alone.
  EXPECT_EQ(handle(padded_even(cat({Bytes{21}, slice("escape")}))), kOk);
  EXPECT_FALSE(fs::is_symlink(fs::symlink_status(root_ / "escape")));
  EXPECT_EQ(contents(outside_ / "secret"), "outside");
  EXPECT_EQ(handle(padded_even(cat({Bytes{21}, slice("dangling")}))), kOk);
}

TEST_F(SpServerFiles, FollowsSymbolicLinksThatStayInside) {
  fs::create_directory_symlink("sub", root_ / "alias");
  fs::create_symlink("sub/target", root_ / "link");
  EXPECT_EQ(handle(open_request("alias/file", 1, 2)), opened(3));
  EXPECT_EQ(handle(write_request(13, 3, "via alias")), (Bytes{0, 9, 0, 0, 0, 0}));
  EXPECT_EQ(handle(id_request(11, 3)), kOk);
  EXPECT_EQ(contents(root_ / "sub" / "file"), "via alias");
  // A link to a file not yet there, inside the root: opening it for output creates the target.
  EXPECT_EQ(handle(open_request("link", 1, 2)), kNoPrivilege);  // dangling: refused even inside
  std::ofstream(root_ / "sub" / "target") << "t";
  EXPECT_EQ(handle(open_request("link", 1, 1)), opened(3));
  EXPECT_EQ(handle(read_request(12, 3, 5)), (Bytes{0, 1, 0, 't', 0, 0}));
  EXPECT_EQ(handle(id_request(11, 3)), kOk);
  // A link with an absolute target inside the root is followed too.
  fs::create_symlink(root_ / "sub" / "target", root_ / "absolute");
  EXPECT_EQ(handle(open_request("absolute", 1, 1)), opened(3));
}

// Another host process swapping a directory for a symbolic link that leads out, as fast as it can,
// while the program opens a file through it: the name is judged and then opened, and a swap between
// the two must not lead out (before the open was held beneath the root, 14 of 1,500 reads got the
// file outside). Each read gets the file inside or is refused; none gets the file outside.
TEST_F(SpServerFiles, ALinkSwappedInWhileANameIsOpenedCannotLeadOut) {
  fs::create_directories(root_ / "real");
  std::ofstream(root_ / "real" / "f") << "inside";
  std::ofstream(outside_ / "f") << "outside";
  fs::create_directory_symlink(outside_, root_ / "away");
  std::atomic<bool> done{false};
  std::thread swapper([&] {
    const fs::path d = root_ / "d";
    const fs::path real = root_ / "real";
    const fs::path away = root_ / "away";
    while (!done) {
      ::rename(real.c_str(), d.c_str());  // d is the directory inside
      std::this_thread::yield();
      ::rename(d.c_str(), real.c_str());
      ::rename(away.c_str(), d.c_str());  // d is the link that leads out
      ::rename(d.c_str(), away.c_str());
    }
  });
  int inside = 0;
  int outside = 0;
  // At least 3,000 opens, and on until some found d as the directory: on a loaded machine the
  // swapper may hold the opener off for many of them.
  for (int i = 0; (i < 3000 || inside < 20) && i < 1'000'000; ++i) {
    const Bytes reply = handle(open_request("d/f", 1, 1));
    if (reply != opened(3)) continue;  // refused, or d was not there
    const Bytes data = handle(read_request(12, 3, 16));
    const std::string got(data.begin() + 3, data.begin() + 3 + data[1]);
    (got == "outside" ? outside : inside) += 1;
    handle(id_request(11, 3));
  }
  done = true;
  swapper.join();
  EXPECT_EQ(outside, 0);
  EXPECT_GT(inside, 0);  // the race was run: some opens found d as the directory
}

// A file past 2 GiB (sparse): SP.TELL's position is an INT32, so a position it cannot hold is an
// error, not the position wrapped to a negative number or cut to its low bits.
TEST_F(SpServerFiles, TellPastTheRangeOfAnInt32IsAnError) {
  { std::ofstream(root_ / "big"); }
  fs::resize_file(root_ / "big", (std::uintmax_t{1} << 31) + 4);
  EXPECT_EQ(handle(open_request("big", 1, 1)), opened(3));
  EXPECT_EQ(handle(seek_request(3, 0x7ffffff0, 1)), kOk);  // from the start: still an INT32
  EXPECT_EQ(handle(id_request(18, 3)), (Bytes{0, 0xf0, 0xff, 0xff, 0x7f, 0}));
  EXPECT_EQ(handle(seek_request(3, 0, 3)), kOk);  // the end: 2^31 + 4
  EXPECT_EQ(handle(id_request(18, 3)), kError);
}

TEST(SpServerRoot, DefaultsToTheCurrentDirectoryAndMustExist) {
  std::istringstream in;
  std::ostringstream out;
  SpHost host;
  host.in = &in;
  host.out = &out;
  host.err = &out;
  SpServer server(SpServerOptions{}, host);
  EXPECT_EQ(server.root(), fs::canonical(fs::current_path()));
  SpServerOptions missing;
  missing.root = "/nonexistent/sp/server/root";
  EXPECT_THROW(SpServer(missing, host), std::invalid_argument);
}

}  // namespace
}  // namespace t800::host
