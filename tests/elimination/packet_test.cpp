// The pipeline's packets (levels/messages.hpp): what a level holds survives the wire, and a byte a
// corrupting link fault changes lands where the struct messages' own byte view put it before the
// packets (header word: the row's number; then the REALs, little-endian), counted by hand.
#include <gtest/gtest.h>

#include <any>

#include "t800/payload_bytes.hpp"
#include "workloads/pipeline/levels/messages.hpp"

namespace {

using M = workloads::levels::Messages<float>;
using Real = M::C;

// The bytes on the wire, by hand: one header word and four bytes per REAL32.
TEST(PipelinePacket, ARowIsItsHeaderWordAndItsReals) {
  const M::RowMessage row{3, {Real(1.0f), Real(2.0f)}};
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

// The client's system, by hand: n(n + 1) REAL32s (n = 2: 6 of them, 24 bytes) and no header word;
// finish a bare INT (4 bytes). L1 gets back each row and its right-hand side.
TEST(PipelinePacket, TheSystemIsItsRealsAloneAndFinishAWord) {
  elimination::LinearSystem<float> s;
  s.a = {{1.0f, 2.0f}, {3.0f, 4.0f}};
  s.b = {5.0f, 6.0f};
  EXPECT_EQ(t800sim::wire_bytes<M::System>(M::system(s)), 6 * 4);
  EXPECT_EQ(t800sim::wire_bytes<M::System>(M::finish()), 4);
  EXPECT_FALSE(M::system_of(M::finish()).has_value());
  const auto back = M::system_of(M::system(s));
  ASSERT_TRUE(back.has_value());
  ASSERT_EQ(back->size(), 2u);
  EXPECT_EQ(back->a[1][0].value(), 3.0f);
  EXPECT_EQ(back->a[0][1].value(), 2.0f);
  EXPECT_EQ(back->b[0].value(), 5.0f);
  EXPECT_EQ(back->b[1].value(), 6.0f);
  // REAL64: 8 bytes each.
  elimination::LinearSystem<double> d;
  d.a = {{1.0}};
  d.b = {2.0};
  EXPECT_EQ(t800sim::wire_bytes<workloads::levels::Messages<double>::System>(
                workloads::levels::Messages<double>::system(d)),
            2 * 8);
}

// A pivot row with the scale (step 0, growth check): one more REAL, and it comes back apart.
TEST(PipelinePacket, APivotRowCarriesTheScaleAsItsLastReal) {
  M::Pivot pivot;
  pivot.row = {Real(1.0f), Real(0.5f)};
  pivot.scale = Real(8.0f);
  pivot.with_scale = true;
  const M::PacketValue packet = M::to_packet(0, pivot);
  EXPECT_EQ(t800sim::wire_bytes<M::Packet>(packet), 4 + 3 * 4);
  const M::Pivot back = M::pivot_of(packet);
  EXPECT_TRUE(back.ok);
  EXPECT_EQ(back.row.size(), 2u);
  EXPECT_EQ(back.scale.value(), 8.0f);
}

TEST(PipelinePacket, ACorruptedByteLandsInTheRowNumberOrTheReal) {
  const M::RowMessage row{3, {Real(1.0f), Real(2.0f)}};
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

// Recovery's messages, by hand: the header word, four bytes per REAL32, the checksum word; a stop
// the header word alone; a resend request a word per row or processor and the header word.
TEST(PipelineCheckedPacket, BytesByHand) {
  M::CheckedRow row{2, 3, false, {Real(1.0f), Real(2.0f), Real(3.0f)}, 0};
  row.checksum = row.sum();
  EXPECT_EQ(t800sim::wire_bytes<M::Checked>(M::to_checked(row)), 4 + 3 * 4 + 4);
  M::CheckedPivot pivot{0, false, true, {Real(1.0f), Real(0.5f)}, Real(8.0f), 0};
  // Step 0 with the growth check: the scale travels, one more REAL.
  EXPECT_EQ(t800sim::wire_bytes<M::Checked>(M::to_checked(pivot, true)), 4 + 3 * 4 + 4);
  EXPECT_EQ(t800sim::wire_bytes<M::Checked>(M::to_checked(pivot, false)), 4 + 2 * 4 + 4);
  M::CheckedPivot stop;
  stop.stop = true;
  EXPECT_EQ(t800sim::wire_bytes<M::Checked>(M::to_checked(stop, true)), 4);
  const M::Resend request{{0, 2, 4}, {1}, {2}};
  EXPECT_EQ(t800sim::wire_bytes<M::Checked>(M::to_checked(request)), 4 * (3 + 1 + 1 + 1));
}

TEST(PipelineCheckedPacket, WhatALevelHoldsSurvivesTheWire) {
  M::CheckedRow row{2, 3, true, {Real(1.0f)}, 0};
  row.checksum = row.sum();
  const M::CheckedValue sent = M::to_checked(row);
  EXPECT_FALSE(M::is_pivot(sent));
  const M::CheckedRow back = M::checked_row_of(sent);
  EXPECT_EQ(back.step, 2);
  EXPECT_EQ(back.index, 3u);
  EXPECT_TRUE(back.bad);
  EXPECT_EQ(back.checksum, row.checksum);
  M::CheckedPivot pivot{0, false, true, {Real(1.0f), Real(0.5f)}, Real(8.0f), 0};
  const M::CheckedPivot p = M::checked_pivot_of(M::to_checked(pivot, true), true);
  EXPECT_TRUE(M::is_pivot(M::to_checked(pivot, true)));
  EXPECT_TRUE(p.forward);
  EXPECT_FALSE(p.stop);
  EXPECT_EQ(p.row.size(), 2u);
  EXPECT_EQ(p.scale.value(), 8.0f);
  M::CheckedPivot stop;
  stop.stop = true;
  EXPECT_TRUE(M::checked_pivot_of(M::to_checked(stop, false), false).stop);
  const M::Resend request{{0, 2, 4}, {1}, {2}};
  const M::CheckedValue asked = M::to_checked(request);
  EXPECT_TRUE(M::is_resend(asked));
  const M::Resend r = M::resend_of(asked);
  EXPECT_EQ(r.rows, (std::vector<std::size_t>{0, 2, 4}));
  EXPECT_EQ(r.lost, std::vector<int>{1});
  EXPECT_EQ(r.avoid, std::vector<int>{2});
  // L3's reduced rows on the same channel are not requests.
  EXPECT_FALSE(M::is_resend(M::to_checked(M::ReturnedRow{true, {Real(1.0f)}, 1})));
}

// A changed byte: in the header word, the row's number (3 ^ 1); in the last word, the checksum,
// which then no longer matches.
TEST(PipelineCheckedPacket, ACorruptedByteLandsInTheNumberOrTheChecksum) {
  M::CheckedRow row{1, 3, false, {Real(1.0f), Real(2.0f)}, 0};
  row.checksum = row.sum();
  struct Wire : t800sim::detail::Wire {
    void send(std::int64_t, std::any v) override { value = std::move(v); }
    std::any receive() override { return value; }
    std::any value;
  } wire;
  t800sim::protocol<M::Checked>::send(wire, M::to_checked(row));
  std::any header_hit = wire.value;
  ASSERT_TRUE(t800::flip_payload_byte(header_hit, 0, 0x01));
  EXPECT_EQ(M::checked_row_of(std::any_cast<M::CheckedValue>(header_hit)).index, 2u);
  std::any checksum_hit = wire.value;
  ASSERT_TRUE(t800::flip_payload_byte(checksum_hit, 4 + 2 * 4, 0x01));
  const M::CheckedRow hit = M::checked_row_of(std::any_cast<M::CheckedValue>(checksum_hit));
  EXPECT_EQ(hit.checksum, row.checksum ^ 1u);
  EXPECT_NE(hit.sum(), hit.checksum);
}

}  // namespace
