// The pipeline's packets (levels/messages.hpp): what a level holds survives the wire, and a byte a
// corrupting link fault changes lands where the struct messages' own byte view put it before the
// packets (header word: the row's number; then the REALs, little-endian), counted by hand.
#include <gtest/gtest.h>

#include <any>

#include "t800/payload_bytes.hpp"
#include "workloads/pipeline/levels/messages.hpp"

namespace {

using M = workloads::levels::Messages<float>;
using C = M::C;

// The bytes on the wire, by hand: one header word and four bytes per REAL32.
TEST(PipelinePacket, ARowIsItsHeaderWordAndItsReals) {
  const M::RowMessage row{3, {C(1.0f), C(2.0f)}};
  EXPECT_EQ(t800sim::wire_bytes<M::Packet>(M::to_packet(row)), 4 + 2 * 4);
  const M::RowMessage back = M::row_message_of(M::to_packet(row));
  EXPECT_EQ(back.index, 3u);
  ASSERT_EQ(back.values.size(), 2u);
  EXPECT_EQ(back.values[1].value(), 2.0f);
  // A stop is the header word alone, and says so in its flags.
  EXPECT_EQ(t800sim::wire_bytes<M::Packet>(M::to_packet(0, M::Pivot::stop(true))), 4);
  EXPECT_FALSE(M::pivot_of(M::to_packet(0, M::Pivot::stop(true))).ok);
  EXPECT_TRUE(M::pivot_of(M::to_packet(0, M::Pivot::stop(true))).finish);
}

// A pivot row with the scale (step 0, growth check): one more REAL, and it comes back apart.
TEST(PipelinePacket, APivotRowCarriesTheScaleAsItsLastReal) {
  M::Pivot pivot;
  pivot.row = {C(1.0f), C(0.5f)};
  pivot.scale = C(8.0f);
  pivot.with_scale = true;
  const M::PacketValue packet = M::to_packet(0, pivot);
  EXPECT_EQ(t800sim::wire_bytes<M::Packet>(packet), 4 + 3 * 4);
  const M::Pivot back = M::pivot_of(packet);
  EXPECT_TRUE(back.ok);
  EXPECT_EQ(back.row.size(), 2u);
  EXPECT_EQ(back.scale.value(), 8.0f);
}

TEST(PipelinePacket, ACorruptedByteLandsInTheRowNumberOrTheReal) {
  const M::RowMessage row{3, {C(1.0f), C(2.0f)}};
  const M::PacketValue sent = M::to_packet(row);
  // Sending registers the packet's byte view with the simulator's faults.
  struct Wire : t800sim::detail::Wire {
    void send(std::int64_t, std::any v) override { value = std::move(v); }
    std::any receive() override { return value; }
    std::any value;
  } wire;
  t800sim::protocol<M::Packet>::send(wire, sent);
  std::any header_hit = wire.value;
  ASSERT_TRUE(t800::flip_payload_byte(header_hit, 0, 0x01));  // byte 0: the row number, 3 ^ 1
  EXPECT_EQ(M::row_message_of(std::any_cast<M::PacketValue>(header_hit)).index, 2u);
  std::any real_hit = wire.value;
  // Byte 4 + 4 + 3: the top byte of 2.0f (0x40000000); XOR 0x80 flips its sign.
  ASSERT_TRUE(t800::flip_payload_byte(real_hit, 11, 0x80));
  EXPECT_EQ(M::row_message_of(std::any_cast<M::PacketValue>(real_hit)).values[1].value(), -2.0f);
}

}  // namespace
