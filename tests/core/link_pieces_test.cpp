// Inputs that take part of a message (t800/link.hpp, Link::receive's `at_most`): flow control is
// byte by byte, so the sender is held after the bytes an input takes until the next input is armed,
// as on the chip. Expected times come from the protocol's rules worked by hand: byte k's data
// packet starts at s_k and is acknowledged at a_k, with
//   s_1 = 0, a_1 = max(detect, armed), s_2 = max(a_1 + ack + process, data),
//   s_k = s_2 + (k - 2) period (k >= 2), a_k = s_k + detect, period = max(data, detect + ack +
//   process),
// and an acknowledge owed to a byte that found no input armed starts when the next input is armed.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core_fixtures.hpp"
#include "t800/link_timing.hpp"
#include "t800/payload_bytes.hpp"

namespace {

using t800::LinkFidelity;
using t800::LinkProtocol;
using Bytes = std::vector<std::uint8_t>;
using SharedBytes = std::shared_ptr<Bytes>;

constexpr int kPieceValues = 8;
using PieceValues = std::array<double, kPieceValues>;

struct Split {
  LinkProtocol protocol = LinkProtocol::overlapped;
  LinkFidelity fidelity = LinkFidelity::packet;
  bool packet_runs = true;
  std::int64_t bytes = 40, first = 10;  // the first input takes `first` bytes, the second the rest
  double gap_us = 100;                  // the second input is armed this long after the start
};

std::string describe_split(const Split& s) {
  return std::string(t800::to_string(s.protocol)) + ", " +
         std::string(t800::to_string(s.fidelity)) + (s.packet_runs ? "" : " (no runs)") + ", " +
         std::to_string(s.bytes) + " bytes taken " + std::to_string(s.first) +
         " then the rest at " + std::to_string(s.gap_us) + " us";
}

// P0 sends one message; P1 takes `first` bytes of it at once and the rest at `gap_us`.
// PieceValues: sender done, first piece's time and bytes, second piece's time and bytes, whether
// the whether more of the message is pending after the second piece, and (7) a deadlock.
PieceValues split(const Split& s) {
  network::MachineOptions o = core_test::options(20, s.protocol);
  o.fidelity.links = s.fidelity;
  network::Machine m(core_test::chain(1), o);
  t800::Link& link = *m.links()[0].link;
  link.plan_packet_runs(s.packet_runs);
  PieceValues v;
  v.fill(-1);
  m.spawn(0, "send", t800::Priority::low, [&](network::Process& p) {
    link.transmit(0, {s.bytes, {}, "block"});
    v[0] = p.now_us();
  });
  m.spawn(1, "receive", t800::Priority::low, [&](network::Process& p) {
    const t800::Message first = link.receive(1, s.first);
    v[1] = p.now_us();
    v[2] = double(first.bytes);
    sc_core::wait(sc_core::sc_time(s.gap_us, sc_core::SC_US) - t800::sim_now());
    const t800::Message rest = link.receive(1);
    v[3] = p.now_us();
    v[4] = double(rest.bytes);
    v[5] = link.input_pending(1) ? 1 : 0;
  });
  v[7] = m.run().empty() ? 0 : 1;  // deadlocked
  return v;
}

struct Rules {
  double data, ack, detect, process, period;
  explicit Rules(LinkProtocol protocol) {
    network::MachineOptions o = core_test::options(20, protocol);
    const t800::LinkTiming t(o.link);
    data = t.data_packet_ns / 1e3;
    ack = t.ack_packet_ns / 1e3;
    detect = t.ack_detect_ns / 1e3;
    process = t.ack_process_ns / 1e3;
    period = std::max(data, detect + ack + process);
  }
  // Byte k's start when its message starts at `start` and the input is armed by then.
  double byte_start(double start, std::int64_t k) const {
    if (k == 1) return start;
    const double second = std::max(start + detect + ack + process, start + data);
    return second + double(k - 2) * period;
  }
};

TEST(LinkPieces, TheSenderWaitsAfterTheBytesAnInputTakesUntilTheNextInput) {
  for (LinkProtocol protocol : {LinkProtocol::overlapped, LinkProtocol::t414}) {
    const Rules r(protocol);
    for (auto [fidelity, runs] : {std::pair{LinkFidelity::packet, false},
                                  {LinkFidelity::packet, true},
                                  {LinkFidelity::message, true},
                                  {LinkFidelity::automatic, true}})
      for (std::int64_t first : {1, 2, 10, 38, 39}) {
        Split s{protocol, fidelity, runs, 40, first, 100};
        const PieceValues v = core_test::in_child<kPieceValues>([&] { return split(s); });
        ASSERT_EQ(v[7], 0) << describe_split(s) << ": deadlocked";
        ASSERT_GE(v[3], 0) << describe_split(s) << ": did not finish";
        EXPECT_EQ(v[2], double(first)) << describe_split(s);
        EXPECT_EQ(v[4], double(s.bytes - first)) << describe_split(s);
        EXPECT_EQ(v[5], 0) << describe_split(s) << ": the message should be all taken";
        // The first input has its bytes when its last has arrived.
        EXPECT_NEAR(v[1], r.byte_start(0, first) + r.data, 1e-6) << describe_split(s);
        // Byte first + 1 found no input and is acknowledged when the second is armed; from then
        // on the bytes stream as in any message whose input was armed late.
        const double resumed = s.gap_us + r.ack + r.process;  // byte first + 2 starts
        const std::int64_t after = s.bytes - first - 1;       // bytes from there on
        const double last_start =
            after == 0 ? r.byte_start(0, first + 1) : resumed + double(after - 1) * r.period;
        const double last_ack = after == 0 ? s.gap_us : last_start + r.detect;
        EXPECT_NEAR(v[0], last_ack + r.ack, 1e-6) << describe_split(s) << ": sender";
        EXPECT_NEAR(v[3], std::max(last_start + r.data, s.gap_us), 1e-6) << describe_split(s);
      }
  }
}

// An input that re-arms at once for each byte takes the message as fast as one input would: every
// re-arm comes at a byte's arrival, before the next byte's packet is detected.
TEST(LinkPieces, ByteByByteInputsTakeAMessageAsFastAsOneInput) {
  for (LinkProtocol protocol : {LinkProtocol::overlapped, LinkProtocol::t414}) {
    const Rules r(protocol);
    const std::int64_t bytes = 24;
    const PieceValues v = core_test::in_child<kPieceValues>([&] {
      network::Machine m(core_test::chain(1), core_test::options(20, protocol));
      t800::Link& link = *m.links()[0].link;
      PieceValues out;
      out.fill(-1);
      m.spawn(0, "send", t800::Priority::low, [&](network::Process& p) {
        link.transmit(0, {bytes, {}, "block"});
        out[0] = p.now_us();
      });
      m.spawn(1, "receive", t800::Priority::low, [&](network::Process& p) {
        std::int64_t got = 0, pieces = 0;
        while (got < bytes) {
          got += link.receive(1, 1).bytes;
          ++pieces;
        }
        out[1] = p.now_us();
        out[2] = double(pieces);
      });
      out[7] = m.run().empty() ? 0 : 1;
      return out;
    });
    const t800::LinkTiming t(core_test::options(20, protocol).link);
    EXPECT_NEAR(v[0], t.acknowledged_ns(bytes) / 1e3, 1e-6)
        << std::string(t800::to_string(protocol));
    EXPECT_NEAR(v[1], t.arrival_ns(bytes) / 1e3, 1e-6) << t800::to_string(protocol);
    EXPECT_NEAR(v[1], r.byte_start(0, bytes) + r.data, 1e-6) << t800::to_string(protocol);
    EXPECT_EQ(v[2], double(bytes));
    EXPECT_EQ(v[7], 0) << "deadlocked";
  }
}

// The first piece brings the payload; a fault on a byte not yet taken still reaches what the
// receiver reads, because the pieces share it.
TEST(LinkPieces, AFaultOnALaterPieceReachesTheSharedPayload) {
  t800::register_payload_bytes(typeid(SharedBytes),
                               [](std::any& a, std::int64_t k, std::uint8_t mask) {
                                 auto& bytes = *std::any_cast<SharedBytes&>(a);
                                 bytes[std::size_t(k)] ^= mask;
                                 return true;
                               });
  const Rules r(LinkProtocol::overlapped);
  const std::int64_t bytes = 40, first = 10, hit = 25;  // byte 25 (from 1) is in the second piece
  const double gap_us = 100;
  const PieceValues v = core_test::in_child<kPieceValues>([&] {
    network::Machine m(core_test::chain(1), core_test::options(20));
    t800::Link& link = *m.links()[0].link;
    // Byte `hit` is the first data packet starting after this.
    const double before_hit =
        gap_us + r.ack + r.process + double(hit - first - 2) * r.period - r.period / 2;
    link.corrupt_byte(0, sc_core::sc_time(before_hit, sc_core::SC_US), 0x5a, nullptr);
    PieceValues out;
    out.fill(-1);
    m.spawn(0, "send", t800::Priority::low, [&](network::Process&) {
      Bytes sent(bytes);
      for (std::int64_t k = 0; k < bytes; ++k) sent[std::size_t(k)] = std::uint8_t(k);
      link.transmit(0, {bytes, std::make_shared<Bytes>(sent), "block"});
    });
    m.spawn(1, "receive", t800::Priority::low, [&](network::Process&) {
      const t800::Message one = link.receive(1, first);
      const auto* shared = std::any_cast<SharedBytes>(&one.payload);
      out[0] = shared ? 1 : 0;
      out[1] = shared ? double((**shared)[hit - 1]) : -1;  // before the fault
      sc_core::wait(sc_core::sc_time(gap_us, sc_core::SC_US) - t800::sim_now());
      const t800::Message rest = link.receive(1);
      out[2] = rest.payload.has_value() ? 1 : 0;
      out[3] = shared ? double((**shared)[hit - 1]) : -1;  // after
      out[4] = shared ? double((**shared)[hit - 2]) : -1;  // its neighbour, untouched
    });
    out[7] = m.run().empty() ? 0 : 1;
    return out;
  });
  ASSERT_EQ(v[7], 0) << "deadlocked";
  EXPECT_EQ(v[0], 1) << "the first piece should carry the payload";
  EXPECT_EQ(v[1], double(hit - 1));
  EXPECT_EQ(v[2], 0) << "only the first piece carries the payload";
  EXPECT_EQ(v[3], double((hit - 1) ^ 0x5a));
  EXPECT_EQ(v[4], double(hit - 2));
}

}  // namespace
