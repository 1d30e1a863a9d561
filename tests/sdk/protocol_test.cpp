// occam's protocols as C++ types: how many communications a value takes and how many bytes each
// carries (the occam 2 reference manual's rules), checked against a wire that records them.
#include <gtest/gtest.h>

#include <vector>

#include "t800/payload_bytes.hpp"
#include "t800sim/protocol.hpp"

namespace {

using namespace t800sim;

// Records each communication's bytes and hands the values back in order.
class RecordingWire : public detail::Wire {
 public:
  void send(std::int64_t bytes, std::any value) override {
    sizes.push_back(bytes);
    values.push_back(std::move(value));
  }
  std::any receive() override { return values.at(next++); }
  std::vector<std::int64_t> sizes;
  std::vector<std::any> values;
  std::size_t next = 0;
};

template <class P>
std::pair<std::vector<std::int64_t>, value_of<P>> round_trip(const value_of<P>& v) {
  RecordingWire w;
  protocol<P>::send(w, v);
  return {w.sizes, protocol<P>::receive(w)};
}

TEST(Protocol, PrimitivesAreOneCommunicationOfTheirSize) {
  EXPECT_EQ(round_trip<INT>(-7), std::make_pair(std::vector<std::int64_t>{4}, INT(-7)));
  EXPECT_EQ(round_trip<REAL64>(2.5), std::make_pair(std::vector<std::int64_t>{8}, 2.5));
  EXPECT_EQ(round_trip<BYTE>(200), std::make_pair(std::vector<std::int64_t>{1}, BYTE(200)));
  EXPECT_EQ(round_trip<BOOL>(true).first, std::vector<std::int64_t>{1});
}

TEST(Protocol, AnArrayIsOneCommunication) {
  const value_of<Array<REAL32, 6>> v{1, 2, 3, 4, 5, 6};
  EXPECT_EQ((round_trip<Array<REAL32, 6>>(v)), std::make_pair(std::vector<std::int64_t>{24}, v));
  EXPECT_EQ((protocol<Array<REAL32, 6>>::name()), "[6]REAL32");
}

// INT::[]REAL32: the count (an INT) then the elements; nothing more for an empty array.
TEST(Protocol, ACountedArraySendsItsCountThenItsElements) {
  const std::vector<float> v{1.5f, 2.5f, 3.5f};
  EXPECT_EQ((round_trip<Counted<INT, REAL32>>(v)),
            std::make_pair(std::vector<std::int64_t>{4, 12}, v));
  EXPECT_EQ((round_trip<Counted<BYTE, REAL64>>({})),
            std::make_pair(std::vector<std::int64_t>{1}, std::vector<double>{}));
  EXPECT_EQ((protocol<Counted<INT, REAL32>>::name()), "INT::[]REAL32");
  EXPECT_EQ((wire_bytes<Counted<INT, REAL32>>(v)), 16);
}

// A sequential protocol's items are communicated one after the other, each its own communication.
TEST(Protocol, ASequentialProtocolSendsEachItemOnItsOwn) {
  using P = Sequential<INT, REAL64, Array<BYTE, 3>>;
  const value_of<P> v{9, -1.25, {1, 2, 3}};
  EXPECT_EQ(round_trip<P>(v), std::make_pair(std::vector<std::int64_t>{4, 8, 3}, v));
  EXPECT_EQ(protocol<P>::name(), "INT; REAL64; [3]BYTE");
}

// A variant: the tag (a BYTE), then the chosen case's items; a bare tag is one byte.
TEST(Protocol, AVariantSendsItsTagThenItsCase) {
  using P = Variant<Case<REAL32, INT>, Case<>>;
  const value_of<P> data{std::in_place_index<0>, Case<REAL32, INT>{{0.5f, 3}}};
  const auto [sizes, back] = round_trip<P>(data);
  EXPECT_EQ(sizes, (std::vector<std::int64_t>{1, 4, 4}));
  ASSERT_EQ(back.index(), 0u);
  EXPECT_EQ(std::get<0>(back).items, std::get<0>(data).items);
  const value_of<P> stop{std::in_place_index<1>};
  EXPECT_EQ(round_trip<P>(stop).first, std::vector<std::int64_t>{1});
  EXPECT_EQ(round_trip<P>(stop).second.index(), 1u);
  EXPECT_EQ(wire_bytes<P>(data), 9);
}

// A header word and a row in one buffer (occam's `c ! [buf FROM 0 FOR n]` on a CHAN OF ANY): one
// communication of 4 + 4 * 3 = 16 bytes (REAL32) or 4 + 8 * 2 = 20 (REAL64); a bare header, 4.
TEST(Protocol, APackedProtocolIsOneCommunicationOfAllItsBytes) {
  using P = Packed<INT, Block<REAL32>>;
  const value_of<P> row{7, {1.5f, -2.0f, 0.25f}};
  EXPECT_EQ(round_trip<P>(row), std::make_pair(std::vector<std::int64_t>{16}, row));
  EXPECT_EQ(wire_bytes<P>({-1, {}}), 4);
  EXPECT_EQ((wire_bytes<Packed<INT, Block<REAL64>>>({0, {1.0, 2.0}})), 20);
  // Header, row and a checksum word: 4 + 8 + 4.
  EXPECT_EQ((wire_bytes<Packed<INT, Block<REAL32>, INT>>({1, {1.0f, 2.0f}, 99})), 16);
  EXPECT_EQ(protocol<P>::name(), "ANY (INT; ANY ([]REAL32))");
}

// A link fault's changed byte lands where the value's bytes lie on the wire: bytes 0-3 are the
// header word (little-endian), then each REAL32 four bytes, then the trailing word.
TEST(Protocol, AChangedByteOfAPackedValueLandsInTheItemAtItsOffset) {
  using P = Packed<INT, Block<REAL32>, INT>;
  value_of<P> v{0x01020304, {1.0f, 2.0f}, 5};
  ASSERT_TRUE(protocol<P>::flip(v, 1, 0xff));  // the header's second-lowest byte
  EXPECT_EQ(std::get<0>(v), 0x0102fc04);
  // 2.0f is 0x40000000; byte 3 of it (the 4 + 4 + 3 = 11th byte) XOR 0x80 flips the sign.
  ASSERT_TRUE(protocol<P>::flip(v, 11, 0x80));
  EXPECT_EQ(std::get<1>(v), (std::vector<float>{1.0f, -2.0f}));
  ASSERT_TRUE(protocol<P>::flip(v, 12, 0x01));  // the trailing word's lowest byte: 5 ^ 1
  EXPECT_EQ(std::get<2>(v), 4);
  EXPECT_FALSE(protocol<P>::flip(v, 16, 0x01));  // past the end
}

// Sending a packed value tells the simulator's link faults how its bytes lie
// (t800/payload_bytes.hpp): a corrupted byte of the message lands in the value the receiver reads.
TEST(Protocol, ALinkFaultChangesTheValueOfAPackedMessageItCarries) {
  using P = Packed<INT, Block<REAL64>>;
  RecordingWire w;
  protocol<P>::send(w, {3, {1.0}});
  std::any carried = w.values.at(0);
  // 1.0 is 0x3ff0000000000000; its last byte (message byte 4 + 7) XOR 0x80: -1.0.
  ASSERT_TRUE(t800::flip_payload_byte(carried, 11, 0x80));
  EXPECT_EQ(std::any_cast<value_of<P>>(carried), (value_of<P>{3, {-1.0}}));
}

// An untagged protocol: one communication of the chosen alternative's bytes and nothing else (no
// tag byte, as a Variant sends): a bare INT is 4 bytes, six REAL32s 24, two REAL64s 16.
TEST(Protocol, AnUntaggedProtocolSendsTheAlternativeAloneAsOneCommunication) {
  using P = Untagged<INT, Block<REAL32>>;
  const value_of<P> finish(std::in_place_index<0>, 7);
  const value_of<P> matrix(std::in_place_index<1>, std::vector<float>{1, 2, 3, 4, 5, 6});
  EXPECT_EQ(round_trip<P>(finish), std::make_pair(std::vector<std::int64_t>{4}, finish));
  EXPECT_EQ(round_trip<P>(matrix), std::make_pair(std::vector<std::int64_t>{24}, matrix));
  EXPECT_EQ((wire_bytes<Untagged<INT, Block<REAL64>>>(
                value_of<Untagged<INT, Block<REAL64>>>(std::in_place_index<1>, {1.0, 2.0}))),
            16);
  EXPECT_EQ(protocol<P>::name(), "UNTAGGED (INT | ANY ([]REAL32))");
}

// Two alternatives of one C++ type stay apart: which was sent is the value's index, and the bytes
// are that alternative's (an INT16 is 2 bytes, an [2]INT16 4).
TEST(Protocol, AnUntaggedProtocolKeepsAlternativesOfOneTypeApart) {
  using P = Untagged<INT16, INT16, Array<INT16, 2>>;
  const value_of<P> second(std::in_place_index<1>, INT16(5));
  const auto [sizes, got] = round_trip<P>(second);
  EXPECT_EQ(sizes, std::vector<std::int64_t>{2});
  EXPECT_EQ(got.index(), 1u);
  EXPECT_EQ(std::get<1>(got), 5);
  EXPECT_EQ(wire_bytes<P>(value_of<P>(std::in_place_index<2>, std::array<INT16, 2>{1, 2})), 4);
}

// A link fault's changed byte lands in the alternative sent: 2.0f is 0x40000000, and its byte 3 of
// the second REAL32 (message byte 7) XOR 0x80 makes it -2.0f.
TEST(Protocol, ALinkFaultChangesTheAlternativeOfAnUntaggedMessage) {
  using P = Untagged<INT, Block<REAL32>>;
  RecordingWire w;
  protocol<P>::send(w, value_of<P>(std::in_place_index<1>, std::vector<float>{1.0f, 2.0f}));
  std::any carried = w.values.at(0);
  ASSERT_TRUE(t800::flip_payload_byte(carried, 7, 0x80));
  EXPECT_EQ(std::get<1>(std::any_cast<value_of<P>>(carried)), (std::vector<float>{1.0f, -2.0f}));
}

// A value of another protocol arriving is a program error, not a silent reinterpretation.
TEST(Protocol, AValueOfAnotherProtocolIsAnError) {
  RecordingWire w;
  protocol<REAL64>::send(w, 1.0);
  EXPECT_THROW(protocol<INT>::receive(w), std::logic_error);
}

// A value passed as a temporary or with std::move travels as it is: the receiver gets the sender's
// storage, not a copy, and the bytes on the wire are still the value's (counted before it moved).
class HandingWire : public RecordingWire {
 public:
  std::any receive() override { return std::move(values.at(next++)); }
};

TEST(Protocol, AMovedValueArrivesWithItsOwnStorageAndItsBytes) {
  std::vector<float> block{1, 2, 3, 4, 5};
  const float* storage = block.data();
  {
    HandingWire w;
    protocol<Block<REAL32>>::send(w, std::move(block));
    const std::vector<float> got = protocol<Block<REAL32>>::receive(w);
    EXPECT_EQ(w.sizes, std::vector<std::int64_t>{20});
    EXPECT_EQ(got.data(), storage);
    block = got;
    storage = block.data();
  }
  {
    using P = Packed<INT, Block<REAL32>>;
    HandingWire w;
    protocol<P>::send(w, value_of<P>{7, std::move(block)});
    const value_of<P> got = protocol<P>::receive(w);
    EXPECT_EQ(w.sizes, std::vector<std::int64_t>{24});
    EXPECT_EQ(std::get<1>(got).data(), storage);
    block = std::get<1>(got);
    storage = block.data();
  }
  {
    using P = Sequential<INT, Counted<INT, REAL32>>;
    HandingWire w;
    protocol<P>::send(w, value_of<P>{7, std::move(block)});
    const value_of<P> got = protocol<P>::receive(w);
    EXPECT_EQ(w.sizes, (std::vector<std::int64_t>{4, 4, 20}));
    EXPECT_EQ(std::get<1>(got).data(), storage);
  }
}

TEST(Protocol, AValueSentFromAVariableIsCopiedAndTheVariableKept) {
  const std::vector<float> kept{1, 2, 3};
  HandingWire w;
  protocol<Block<REAL32>>::send(w, kept);
  const std::vector<float> got = protocol<Block<REAL32>>::receive(w);
  EXPECT_EQ(got, kept);
  EXPECT_NE(got.data(), kept.data());
}

}  // namespace
