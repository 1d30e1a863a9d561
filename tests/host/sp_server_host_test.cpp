// The SP server's host and server requests (GETKEY .. EXIT, COMMANDLINE, CORE, VERSION), unknown
// tags, malformed requests, and a whole session through the reassembler. Layouts from iserver
// 1.50's hostc.c and serverc.c; replies padded with zeros to an even length of at least 6.
#include "t800/host/sp_server.hpp"
#include "tests/host/sp_bytes.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <initializer_list>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace t800::host {
namespace {

namespace fs = std::filesystem;
using namespace sp_bytes;

// A server on a temporary root with every host hook replaced.
class SpServerHost : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "sp_server_host_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    root_ = pattern;
    options_.root = root_;
    host_.in = &in_;
    host_.out = &out_;
    host_.err = &err_;
    host_.clock = [] { return HostTime{1000003600, 1000000000}; };
    host_.getenv = [this](const std::string& name) -> std::optional<std::string> {
      asked_.push_back(name);
      if (name == "ISEARCH") return std::string("/libs/");
      if (name == "HOME") return std::string("/home/someone");
      if (name == "LONG") return std::string(600, 'v');
      return std::nullopt;
    };
    host_.system = [this](const std::string& command) {
      commands_.push_back(command);
      return system_status_;
    };
  }
  void TearDown() override { fs::remove_all(root_); }

  SpServer& server() {
    if (!server_) server_ = std::make_unique<SpServer>(options_, host_);
    return *server_;
  }
  Bytes handle(const Bytes& request) { return server().handle(request); }

  fs::path root_;
  SpServerOptions options_;
  SpHost host_;
  std::istringstream in_;
  std::ostringstream out_, err_;
  std::vector<std::string> asked_;
  std::vector<std::string> commands_;
  int system_status_ = 0;
  std::unique_ptr<SpServer> server_;
};

TEST_F(SpServerHost, GetKeyAndPollKey) {
  in_.str("ab\n");
  // GETKEY (30) -> OK, BYTE key.
  EXPECT_EQ(handle(Bytes{30, 0, 0, 0, 0, 0}), (Bytes{0, 'a', 0, 0, 0, 0}));
  // POLLKEY (31) -> OK, BYTE key while one is waiting.
  EXPECT_EQ(handle(Bytes{31, 0, 0, 0, 0, 0}), (Bytes{0, 'b', 0, 0, 0, 0}));
  EXPECT_EQ(handle(Bytes{31, 0, 0, 0, 0, 0}), (Bytes{0, '\n', 0, 0, 0, 0}));
  // No key: POLLKEY answers the error result (hostc.c SpPollkey), GETKEY at end of input too.
  EXPECT_EQ(handle(Bytes{31, 0, 0, 0, 0, 0}), kError);
  EXPECT_EQ(handle(Bytes{30, 0, 0, 0, 0, 0}), kError);
}

TEST_F(SpServerHost, ANewlineIsTheReturnKeyWhenAsked) {
  options_.newline_is_return = true;
  in_.str("7\n");
  EXPECT_EQ(handle(Bytes{30, 0, 0, 0, 0, 0}), (Bytes{0, '7', 0, 0, 0, 0}));
  EXPECT_EQ(handle(Bytes{30, 0, 0, 0, 0, 0}), (Bytes{0, '\r', 0, 0, 0, 0}));
}

TEST_F(SpServerHost, GetEnvListedVariablesOnly) {
  options_.environment.fixed = {{"IBOARDSIZE", "#200000"}};
  // GETENV (32), slice name -> OK, slice value.
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{32}, slice("IBOARDSIZE")}))),
            (Bytes{0, 7, 0, '#', '2', '0', '0', '0', '0', '0'}));
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{32}, slice("ISEARCH")}))),
            (Bytes{0, 6, 0, '/', 'l', 'i', 'b', 's', '/', 0}));
  // HOME is in the host environment but not listed: not revealed, not even looked up.
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{32}, slice("HOME")}))), kError);
  EXPECT_EQ(asked_, (std::vector<std::string>{"ISEARCH"}));
  // A listed variable the host does not have, and an empty name: the error result.
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{32}, slice("ITERM")}))), kError);
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{32}, slice("")}))), kError);
}

TEST_F(SpServerHost, GetEnvAllAndNone) {
  options_.environment.mode = SpEnvironmentPolicy::Mode::kAll;
  options_.environment.fixed = {{"HOME", "/fixed"}};
  {
    SpServer all(options_, host_);
    EXPECT_EQ(all.handle(padded_to_six(cat({Bytes{32}, slice("HOME")}))),
              padded_to_six(cat({Bytes{0}, slice("/fixed")})));  // fixed first
    EXPECT_EQ(all.handle(padded_to_six(cat({Bytes{32}, slice("ISEARCH")}))),
              padded_to_six(cat({Bytes{0}, slice("/libs/")})));
    // Too long for one reply: clipped to 507 and answered with the error result, as hostc.c.
    const Bytes reply = all.handle(padded_to_six(cat({Bytes{32}, slice("LONG")})));
    EXPECT_EQ(reply, cat({Bytes{129, 0xfb, 0x01}, Bytes(507, 'v')}));
  }
  options_.environment.mode = SpEnvironmentPolicy::Mode::kNone;
  SpServer none(options_, host_);
  asked_.clear();
  EXPECT_EQ(none.handle(padded_to_six(cat({Bytes{32}, slice("ISEARCH")}))), kError);
  EXPECT_EQ(none.handle(padded_to_six(cat({Bytes{32}, slice("HOME")}))),
            padded_to_six(cat({Bytes{0}, slice("/fixed")})));
  EXPECT_TRUE(asked_.empty());
}

TEST_F(SpServerHost, TimeFromTheInjectedClock) {
  // TIME (33) -> OK, INT32 local, INT32 UTC. 1000003600 = #3B9AD810, 1000000000 = #3B9ACA00.
  EXPECT_EQ(handle(Bytes{33, 0, 0, 0, 0, 0}),
            (Bytes{0, 0x10, 0xd8, 0x9a, 0x3b, 0x00, 0xca, 0x9a, 0x3b, 0}));
  // Times past 2038 go out as their low 32 bits.
  host_.clock = [] { return HostTime{0x100000005LL, 0x100000007LL}; };
  SpServer later(options_, host_);
  EXPECT_EQ(later.handle(Bytes{33, 0, 0, 0, 0, 0}), (Bytes{0, 5, 0, 0, 0, 7, 0, 0, 0, 0}));
}

TEST(SpServerClock, HostClockIsNearNow) {
  const HostTime now = host_clock_now();
  const std::int64_t utc = static_cast<std::int64_t>(std::time(nullptr));
  EXPECT_LE(std::abs(now.utc_seconds - utc), 2);
  EXPECT_LE(std::abs(now.local_seconds - now.utc_seconds), 14 * 3600 + 1);
}

TEST_F(SpServerHost, SystemRefusedUnlessAllowed) {
  // SYSTEM (34), slice command -> refused: ER_NOPRIV, and nothing runs.
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{34}, slice("rm -rf x")}))), kNoPrivilege);
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{34}, slice("")}))), kNoPrivilege);
  EXPECT_TRUE(commands_.empty());
}

TEST_F(SpServerHost, SystemWhenAllowed) {
  options_.allow_system = true;
  system_status_ = 256;  // "exit 1" as system() reports it
  // -> OK, INT32 the raw status.
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{34}, slice("exit 1")}))), (Bytes{0, 0, 1, 0, 0, 0}));
  EXPECT_EQ(commands_, (std::vector<std::string>{"exit 1"}));
  // The empty command asks for a shell: OK when it runs, the error result when it does not.
  system_status_ = 0;
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{34}, slice("")}))), kOk);
  system_status_ = 127;
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{34}, slice("")}))), (Bytes{129, 127, 0, 0, 0, 0}));
  EXPECT_EQ(handle(padded_to_six(cat({Bytes{34}, slice(std::string("a\0b", 3))}))), kError);
  EXPECT_EQ(commands_.size(), 3u);
}

TEST_F(SpServerHost, ExitStatusMapping) {
  EXPECT_FALSE(server().exited());
  EXPECT_EQ(server().exit_code(), 0);
  // EXIT (35), INT32 status -> OK. sps.success 999999999 = #3B9AC9FF -> exit code 0.
  EXPECT_EQ(handle(Bytes{35, 0xff, 0xc9, 0x9a, 0x3b, 0}), kOk);
  EXPECT_TRUE(server().exited());
  EXPECT_EQ(server().exit_status(), 999999999);
  EXPECT_EQ(server().exit_code(), 0);

  struct Case {
    std::uint32_t status;
    int code;
  };
  for (const Case c : {Case{static_cast<std::uint32_t>(-999999999), 255}, Case{0, 0}, Case{1, 1},
                       Case{42, 42}, Case{0xffffffffu, 255}, Case{256, 255}}) {
    SpServer fresh(options_, host_);
    EXPECT_EQ(fresh.handle(padded_to_six(cat({Bytes{35}, le32(c.status)}))), kOk);
    EXPECT_TRUE(fresh.exited());
    EXPECT_EQ(fresh.exit_code(), c.code) << c.status;
  }
}

TEST_F(SpServerHost, CommandLine) {
  options_.program_name = "prog.btl";
  options_.program_args = {"-x", "two words", "tab\there"};
  // COMMANDLINE (40), BYTE all: 0 the program's arguments, 1 the whole line.
  EXPECT_EQ(handle(Bytes{40, 0, 0, 0, 0, 0}),
            padded_to_six(cat({Bytes{0}, slice("-x \"two words\" \"tab\there\"")})));
  EXPECT_EQ(handle(Bytes{40, 1, 0, 0, 0, 0}),
            padded_to_six(cat({Bytes{0}, slice("prog.btl -x \"two words\" \"tab\there\"")})));
  // Any non-zero byte asks for the whole line (serverc.c: get_8() ? true : false).
  EXPECT_EQ(handle(Bytes{40, 7, 0, 0, 0, 0}), handle(Bytes{40, 1, 0, 0, 0, 0}));
}

TEST_F(SpServerHost, CommandLineEmptyAndTooLong) {
  EXPECT_EQ(handle(Bytes{40, 0, 0, 0, 0, 0}), kOk);  // OK, slice of 0 bytes
  EXPECT_EQ(handle(Bytes{40, 1, 0, 0, 0, 0}), kOk);
  options_.program_args = {std::string(300, 'a'), std::string(300, 'b')};
  SpServer long_line(options_, host_);
  const Bytes reply = long_line.handle(Bytes{40, 0, 0, 0, 0, 0});
  ASSERT_EQ(reply.size(), 510u);
  EXPECT_EQ(reply[0], 134);  // ER_TRUNCATED
  EXPECT_EQ(reply[1] | (reply[2] << 8), 507);
}

TEST_F(SpServerHost, CoreNotAvailableWithoutAnImage) {
  // CORE (41), INT32 offset, INT16 length -> the error result: nothing was peeked.
  EXPECT_EQ(handle(Bytes{41, 0, 0, 0, 0, 4, 0, 0}), kError);
}

TEST_F(SpServerHost, CoreFromTheImage) {
  Bytes image(2000);
  for (std::size_t i = 0; i < image.size(); ++i) image[i] = static_cast<std::uint8_t>(i);
  options_.core = image;
  EXPECT_EQ(handle(Bytes{41, 4, 0, 0, 0, 4, 0, 0}), (Bytes{0, 4, 0, 4, 5, 6, 7, 0}));
  // The length is clipped to the image: offset 1998 asking for 10 gets 2.
  EXPECT_EQ(handle(Bytes{41, 0xce, 0x07, 0, 0, 10, 0, 0}), (Bytes{0, 2, 0, 0xce, 0xcf, 0}));
  // ...and to the packet: 1000 asked, 507 sent.
  const Bytes big = handle(Bytes{41, 0, 0, 0, 0, 0xe8, 0x03, 0});
  ASSERT_EQ(big.size(), 510u);
  EXPECT_EQ(big[1] | (big[2] << 8), 507);
  EXPECT_EQ(big[3 + 506], 506 & 0xff);
  // Offsets outside the image: the error result.
  EXPECT_EQ(handle(Bytes{41, 0xd0, 0x07, 0, 0, 1, 0, 0}), kError);        // 2000
  EXPECT_EQ(handle(Bytes{41, 0xff, 0xff, 0xff, 0xff, 1, 0, 0}), kError);  // -1
}

TEST_F(SpServerHost, Version) {
  // VERSION (42) -> OK, BYTE version (1.50 -> 15), host (unknown), OS (SunOS 4), board (unknown).
  EXPECT_EQ(handle(Bytes{42, 0, 0, 0, 0, 0}), (Bytes{0, 15, 0, 4, 0, 0}));
  options_.identity = SpIdentity{10, 7, 4, 2};  // what t4 reports on a little-endian host
  SpServer t4_like(options_, host_);
  EXPECT_EQ(t4_like.handle(Bytes{42, 0, 0, 0, 0, 0}), (Bytes{0, 10, 7, 4, 2, 0}));
}

TEST_F(SpServerHost, OtherTagsAreNotImplemented) {
  // DOS, HELIOS, VMS, SUNOS, TDS, OTHER, and tags with no meaning here (0, 23 GETBLOCK, 43
  // GETINFO, 80 FILEEXISTS, 255).
  for (const int tag : {50, 51, 52, 53, 65, 128, 0, 1, 9, 23, 24, 29, 36, 39, 43, 80, 83, 255}) {
    EXPECT_EQ(handle(Bytes{static_cast<std::uint8_t>(tag), 0, 0, 0, 0, 0}), kNotImplemented) << tag;
  }
}

TEST_F(SpServerHost, MalformedRequestsGetAnErrorReply) {
  EXPECT_EQ(handle(Bytes{}), kBadParameters);
  // Each tag with fewer bytes than its fields.
  const std::vector<Bytes> short_requests = {
      {10},                             // OPEN: no slice
      {10, 5, 0, 'a', 'b'},             // OPEN: slice runs past the body
      {10, 1, 0, 'a', 1},               // OPEN: no mode byte
      {11, 3, 0, 0},                    // CLOSE: INT32 cut short
      {12, 1, 0, 0, 0, 5},              // READ: INT16 cut short
      {13, 1, 0, 0, 0, 9, 0, 'a'},      // WRITE: slice of 9 with 1 byte
      {14, 0, 0, 0, 0},                 // GETS: no limit
      {15, 1, 0, 0, 0, 2},              // PUTS: slice count cut short
      {16},                             // FLUSH
      {17, 3, 0, 0, 0, 0, 0, 0, 0, 1},  // SEEK: origin cut short
      {18, 0},                          // TELL
      {19},                             // EOF
      {20, 0, 0},                       // FERROR
      {21, 4, 0, 'a'},                  // REMOVE
      {22, 1, 0, 'a', 1, 0},            // RENAME: second slice runs past the body
      {22, 1, 0, 'a'},                  // RENAME: no second slice
      {32, 3},                          // GETENV
      {34, 2, 0, 'l'},                  // SYSTEM
      {35, 1, 0, 0},                    // EXIT
      {40},                             // COMMANDLINE
  };
  for (const Bytes& request : short_requests) {
    EXPECT_EQ(handle(request), kBadParameters) << int(request[0]) << " size " << request.size();
  }
  EXPECT_FALSE(server().exited());
  options_.core = Bytes(16, 0);
  SpServer with_core(options_, host_);
  EXPECT_EQ(with_core.handle(Bytes{41, 0, 0, 0, 0, 4}), kBadParameters);
}

TEST_F(SpServerHost, AnyBytesGiveAWellFormedReply) {
  // Random request bodies for every tag: each reply is even, 6..510 bytes, with a known result.
  std::mt19937 random(99);
  for (int tag = 0; tag < 256; ++tag) {
    if (tag == static_cast<int>(SpTag::kOpen) || tag == static_cast<int>(SpTag::kRemove) ||
        tag == static_cast<int>(SpTag::kRename)) {
      continue;  // random names would be created (harmless in the root, but noisy)
    }
    for (int trial = 0; trial < 40; ++trial) {
      Bytes request(1 + std::uniform_int_distribution<>(0, 20)(random));
      request[0] = static_cast<std::uint8_t>(tag);
      for (std::size_t i = 1; i < request.size(); ++i) {
        request[i] = static_cast<std::uint8_t>(std::uniform_int_distribution<>(0, 255)(random));
      }
      const Bytes reply = handle(request);
      ASSERT_GE(reply.size(), 6u);
      ASSERT_LE(reply.size(), 510u);
      ASSERT_EQ(reply.size() % 2, 0u);
      const int result = reply[0];
      EXPECT_TRUE(result == 0 || result == 1 || result >= 128) << tag;
    }
  }
}

TEST_F(SpServerHost, SessionThroughTheReassembler) {
  // What a program's link output looks like: framed requests, split anywhere.
  std::vector<Bytes> requests = {
      padded_to_six(cat({Bytes{13}, le32(1), slice("Hello, world\n")})),
      Bytes{42, 0, 0, 0, 0, 0},
      Bytes{35, 0xff, 0xc9, 0x9a, 0x3b, 0},
  };
  Bytes link;
  for (const Bytes& request : requests) {
    const Bytes packet = sp_frame(request);
    link.insert(link.end(), packet.begin(), packet.end());
  }
  SpPacketReassembler reassembler;
  Bytes replies;
  for (std::size_t at = 0; at < link.size(); at += 5) {
    reassembler.feed(link.data() + at, std::min<std::size_t>(5, link.size() - at));
    while (auto body = reassembler.next_packet()) {
      const Bytes packet = sp_frame(handle(*body));
      replies.insert(replies.end(), packet.begin(), packet.end());
    }
  }
  EXPECT_FALSE(reassembler.failed());
  EXPECT_EQ(out_.str(), "Hello, world\n");
  EXPECT_EQ(replies, (Bytes{6, 0, 0, 13, 0, 0, 0, 0,     // WRITE: 13 bytes written
                            6, 0, 0, 15, 0, 4, 0, 0,     // VERSION
                            6, 0, 0, 0,  0, 0, 0, 0}));  // EXIT
  EXPECT_TRUE(server().exited());
  EXPECT_EQ(server().exit_code(), 0);
}

}  // namespace
}  // namespace t800::host
