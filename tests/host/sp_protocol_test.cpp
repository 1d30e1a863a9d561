// SP protocol fields, reply padding, framing and the reassembly of a host-link byte stream into
// request bodies (t800/host/sp_protocol.hpp). Expected bytes are written out from the layout:
// a 2-byte little-endian length, then the body; replies even and at least 6 bytes long.
#include "t800/host/sp_protocol.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace t800::host {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(SpFields, LittleEndian) {
  const Bytes bytes = {0x34, 0x12, 0x78, 0x56};
  EXPECT_EQ(load_le16(bytes.data()), 0x1234);
  EXPECT_EQ(load_le32(bytes.data()), 0x56781234u);
  Bytes out;
  append_le16(out, 0xbeef);
  append_le32(out, 0xc0ffee11u);
  EXPECT_EQ(out, (Bytes{0xef, 0xbe, 0x11, 0xee, 0xff, 0xc0}));
}

TEST(SpFields, ReaderReadsFieldsInOrder) {
  // BYTE 7, INT16 #0102, INT32 -2, slice "ab"
  const Bytes fields = {7, 0x02, 0x01, 0xfe, 0xff, 0xff, 0xff, 2, 0, 'a', 'b'};
  SpRequestReader reader(fields.data(), fields.size());
  std::uint8_t byte = 0;
  std::uint16_t half = 0;
  std::int32_t word = 0;
  std::string slice;
  ASSERT_TRUE(reader.read_u8(byte));
  ASSERT_TRUE(reader.read_u16(half));
  ASSERT_TRUE(reader.read_i32(word));
  ASSERT_TRUE(reader.read_slice(slice));
  EXPECT_EQ(byte, 7);
  EXPECT_EQ(half, 0x0102);
  EXPECT_EQ(word, -2);
  EXPECT_EQ(slice, "ab");
  EXPECT_EQ(reader.remaining(), 0u);
  EXPECT_FALSE(reader.read_u8(byte));
}

TEST(SpFields, ReaderRefusesWhatIsNotThere) {
  const Bytes three = {1, 2, 3};
  SpRequestReader reader(three.data(), three.size());
  std::int32_t word = 0;
  EXPECT_FALSE(reader.read_i32(word));
  EXPECT_EQ(reader.remaining(), 3u);

  // A slice whose count runs one byte past the body is refused and consumes nothing.
  const Bytes slice = {3, 0, 'a', 'b'};
  SpRequestReader slices(slice.data(), slice.size());
  std::string text;
  EXPECT_FALSE(slices.read_slice(text));
  EXPECT_EQ(slices.remaining(), 4u);
  std::uint16_t count = 0;
  EXPECT_TRUE(slices.read_u16(count));
  EXPECT_EQ(count, 3);

  const Bytes one = {1};
  SpRequestReader tiny(one.data(), one.size());
  EXPECT_FALSE(tiny.read_slice(text));
  std::uint16_t half = 0;
  EXPECT_FALSE(tiny.read_u16(half));

  SpRequestReader empty(nullptr, 0);
  std::uint8_t byte = 0;
  EXPECT_FALSE(empty.read_u8(byte));
}

TEST(SpFields, ReplyPaddedToEvenAndMinimum) {
  EXPECT_EQ(SpReplyWriter(SpResult::kError).finish(), (Bytes{129, 0, 0, 0, 0, 0}));
  SpReplyWriter seven(SpResult::kOk);
  seven.put_u32(0x04030201u);
  seven.put_u16(0x0605);
  EXPECT_EQ(std::move(seven).finish(), (Bytes{0, 1, 2, 3, 4, 5, 6, 0}));
  SpReplyWriter slice(SpResult::kOk);
  slice.put_slice("abcde");
  EXPECT_EQ(std::move(slice).finish(), (Bytes{0, 5, 0, 'a', 'b', 'c', 'd', 'e'}));
}

TEST(SpFields, ResultAndTagValues) {
  // hostio.inc and iserver sp.h.
  EXPECT_EQ(static_cast<int>(SpResult::kOk), 0);
  EXPECT_EQ(static_cast<int>(SpResult::kNotImplemented), 1);
  EXPECT_EQ(static_cast<int>(SpResult::kOperationFailed), 128);
  EXPECT_EQ(static_cast<int>(SpResult::kError), 129);
  EXPECT_EQ(static_cast<int>(SpTag::kOpen), 10);
  EXPECT_EQ(static_cast<int>(SpTag::kRename), 22);
  EXPECT_EQ(static_cast<int>(SpTag::kGetKey), 30);
  EXPECT_EQ(static_cast<int>(SpTag::kExit), 35);
  EXPECT_EQ(static_cast<int>(SpTag::kCommandLine), 40);
  EXPECT_EQ(static_cast<int>(SpTag::kVersion), 42);
  EXPECT_EQ(kSpMaxBodySize, 510u);
  EXPECT_EQ(kSpMinBodySize, 6u);
  EXPECT_EQ(kSpMaxReplyData, 507u);
}

TEST(SpExitStatus, MapsAsTheIserver) {
  EXPECT_EQ(iserver_exit_code(999999999), 0);
  EXPECT_EQ(iserver_exit_code(-999999999), 255);
  EXPECT_EQ(iserver_exit_code(0), 0);
  EXPECT_EQ(iserver_exit_code(1), 1);
  EXPECT_EQ(iserver_exit_code(42), 42);
  EXPECT_EQ(iserver_exit_code(255), 255);
  // What does not fit a process's 8-bit exit code is a failure, never its low bits (0 for 256).
  EXPECT_EQ(iserver_exit_code(-1), 255);
  EXPECT_EQ(iserver_exit_code(256), 255);
  EXPECT_EQ(iserver_exit_code(512), 255);
  EXPECT_EQ(iserver_exit_code(257), 255);
  EXPECT_EQ(iserver_exit_code(999999998), 255);
}

TEST(SpFraming, LengthRules) {
  EXPECT_NE(sp_length_problem(0), "");
  EXPECT_NE(sp_length_problem(4), "");
  EXPECT_NE(sp_length_problem(5), "");
  EXPECT_EQ(sp_length_problem(6), "");
  EXPECT_NE(sp_length_problem(7), "");
  EXPECT_EQ(sp_length_problem(8), "");
  EXPECT_EQ(sp_length_problem(510), "");
  EXPECT_NE(sp_length_problem(511), "");
  EXPECT_NE(sp_length_problem(512), "");
  EXPECT_NE(sp_length_problem(65535), "");
  EXPECT_NE(sp_length_problem(7).find("odd"), std::string::npos);
}

TEST(SpFraming, FramePrefixesTheLength) {
  EXPECT_EQ(sp_frame(Bytes{0, 0, 0, 0, 0, 0}), (Bytes{6, 0, 0, 0, 0, 0, 0, 0}));
  const Bytes body(300, 0xaa);
  const Bytes packet = sp_frame(body);
  ASSERT_EQ(packet.size(), 302u);
  EXPECT_EQ(packet[0], 300 & 0xff);
  EXPECT_EQ(packet[1], 300 >> 8);
  EXPECT_EQ(packet[301], 0xaa);
}

// Three requests as the hostio library sends them: padded to even lengths of 6 or more.
Bytes three_packets() {
  const Bytes exit_request = {6, 0, 35, 0xff, 0xc9, 0x9a, 0x3b, 0};           // SP.EXIT sps.success
  const Bytes write_request = {10, 0, 13, 1, 0, 0, 0, 3, 0, 'h', 'i', '\n'};  // SP.WRITE stdout
  Bytes long_request = {0xf8, 0x01};                                          // 504 bytes
  long_request.push_back(13);
  long_request.resize(2 + 504, 'x');
  Bytes stream = write_request;
  stream.insert(stream.end(), long_request.begin(), long_request.end());
  stream.insert(stream.end(), exit_request.begin(), exit_request.end());
  return stream;
}

std::vector<Bytes> expected_bodies() {
  Bytes long_body(504, 'x');
  long_body[0] = 13;
  return {Bytes{13, 1, 0, 0, 0, 3, 0, 'h', 'i', '\n'}, long_body,
          Bytes{35, 0xff, 0xc9, 0x9a, 0x3b, 0}};
}

std::vector<Bytes> drain(SpPacketReassembler& reassembler) {
  std::vector<Bytes> bodies;
  while (auto body = reassembler.next_packet()) bodies.push_back(std::move(*body));
  return bodies;
}

TEST(SpReassembler, EverySplitIntoTwoPieces) {
  const Bytes stream = three_packets();
  for (std::size_t cut = 0; cut <= stream.size(); ++cut) {
    SpPacketReassembler reassembler;
    reassembler.feed(stream.data(), cut);
    reassembler.feed(stream.data() + cut, stream.size() - cut);
    EXPECT_EQ(drain(reassembler), expected_bodies()) << "cut at " << cut;
    EXPECT_FALSE(reassembler.failed());
    EXPECT_EQ(reassembler.pending_bytes(), 0u);
  }
}

TEST(SpReassembler, ByteByByteDeliversEachPacketWhenItsLastByteArrives) {
  const Bytes stream = three_packets();
  SpPacketReassembler reassembler;
  std::vector<std::size_t> completed_at;
  std::vector<Bytes> bodies;
  for (std::size_t i = 0; i < stream.size(); ++i) {
    reassembler.feed(&stream[i], 1);
    while (auto body = reassembler.next_packet()) {
      completed_at.push_back(i + 1);
      bodies.push_back(std::move(*body));
    }
  }
  EXPECT_EQ(bodies, expected_bodies());
  EXPECT_EQ(completed_at, (std::vector<std::size_t>{12, 12 + 506, 12 + 506 + 8}));
}

TEST(SpReassembler, RandomPieces) {
  const Bytes one = three_packets();
  Bytes stream;
  std::vector<Bytes> expected;
  for (int copy = 0; copy < 20; ++copy) {
    stream.insert(stream.end(), one.begin(), one.end());
    for (const Bytes& body : expected_bodies()) expected.push_back(body);
  }
  std::mt19937 random(1234);
  for (int trial = 0; trial < 50; ++trial) {
    SpPacketReassembler reassembler;
    std::vector<Bytes> bodies;
    std::size_t at = 0;
    while (at < stream.size()) {
      const std::size_t piece = std::min<std::size_t>(
          stream.size() - at, std::uniform_int_distribution<>(0, 700)(random));
      reassembler.feed(stream.data() + at, piece);
      at += piece;
      for (Bytes& body : drain(reassembler)) bodies.push_back(std::move(body));
    }
    ASSERT_EQ(bodies, expected) << "trial " << trial;
  }
}

TEST(SpReassembler, PartialPacketIsPending) {
  SpPacketReassembler reassembler;
  reassembler.feed(Bytes{6, 0, 42, 0});
  EXPECT_FALSE(reassembler.next_packet().has_value());
  EXPECT_EQ(reassembler.pending_bytes(), 4u);
  reassembler.feed(Bytes{0, 0, 0, 0, 8});  // completes the packet, starts the next length
  EXPECT_EQ(reassembler.next_packet(), (Bytes{42, 0, 0, 0, 0, 0}));
  EXPECT_EQ(reassembler.pending_bytes(), 1u);
  EXPECT_FALSE(reassembler.failed());
}

TEST(SpReassembler, BadLengthsStopTheStream) {
  for (const int length : {0, 2, 4, 5, 7, 9, 509, 511, 512, 1000, 65535}) {
    SpPacketReassembler reassembler;
    Bytes stream = {6, 0, 42, 0, 0, 0, 0, 0};  // a good packet first: still delivered
    stream.push_back(static_cast<std::uint8_t>(length & 0xff));
    stream.push_back(static_cast<std::uint8_t>(length >> 8));
    stream.resize(stream.size() + 520, 0);  // whatever follows is not served
    reassembler.feed(stream);
    EXPECT_TRUE(reassembler.failed()) << length;
    EXPECT_NE(reassembler.error().find(std::to_string(length)), std::string::npos);
    EXPECT_EQ(reassembler.next_packet(), (Bytes{42, 0, 0, 0, 0, 0}));
    EXPECT_FALSE(reassembler.next_packet().has_value());
    reassembler.feed(Bytes{6, 0, 42, 0, 0, 0, 0, 0});
    EXPECT_FALSE(reassembler.next_packet().has_value());
    EXPECT_EQ(reassembler.pending_bytes(), 2u + 520u + 8u);
  }
}

TEST(SpReassembler, LengthSplitAcrossFeedsIsJudgedWhenWhole) {
  SpPacketReassembler reassembler;
  reassembler.feed(Bytes{7});
  EXPECT_FALSE(reassembler.failed());  // 7 alone could be the low byte of 0x0107 = 263: odd too
  reassembler.feed(Bytes{1});
  EXPECT_TRUE(reassembler.failed());

  SpPacketReassembler fine;
  fine.feed(Bytes{8});
  fine.feed(Bytes{0, 0, 1, 2, 3, 4, 5, 6, 7});
  EXPECT_FALSE(fine.failed());
  EXPECT_EQ(fine.next_packet(), (Bytes{0, 1, 2, 3, 4, 5, 6, 7}));
}

}  // namespace
}  // namespace t800::host
