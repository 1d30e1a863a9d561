// Fidelity levels (t800/fidelity.hpp): `automatic` must give the packet level's results to the
// kernel's time tick, including when the other direction starts in the middle of a closed-form
// message (the hand-over); `message` must agree while a link is used one way at a time, and may
// differ when both directions overlap. Compute: `fine` and `automatic` agree; link DMA takes its
// memory cycles from a computing CPU.
//
// SystemC elaborates once per process, so every simulation here runs in a forked child.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core_fixtures.hpp"

namespace {

using t800::ComputeFidelity;
using t800::LinkFidelity;
using t800::LinkProtocol;

constexpr int kValues = 16;
using Values = std::array<double, kValues>;

Values in_child(const std::function<Values()>& simulate) {
  return core_test::in_child<kValues>(simulate);
}

struct Exchange {
  double mbps = 20;
  LinkProtocol protocol = LinkProtocol::overlapped;
  std::int64_t forward_bytes = 64, reverse_bytes = 24;
  int receiver_delay_cycles = 0;  // P1 arms its input this late
  int reverse_delay_cycles = -1;  // P1 starts sending back this late (-1: no reverse message)
  int forward_messages = 1;
};

// P0 sends to P1 while P1, after a delay, sends back: the times each side sees, and the accounting.
// `packet_runs` false: at `packet`, every packet is its own step (the reference for the runs).
Values exchange(const Exchange& e, LinkFidelity links,
                ComputeFidelity compute = ComputeFidelity::automatic, bool packet_runs = true) {
  network::MachineOptions o = core_test::options(e.mbps, e.protocol);
  o.fidelity.links = links;
  o.fidelity.compute = compute;
  network::Machine m(core_test::chain(1), o);
  for (const auto& l : m.links()) l.link->plan_packet_runs(packet_runs);
  Values v;
  v.fill(-1);
  auto& forward = m.channel("forward", 0, 1);
  auto& reverse = m.channel("reverse", 1, 0);
  m.spawn(0, "send", t800::Priority::low, [&](network::Process& p) {
    for (int i = 0; i < e.forward_messages; ++i) p.out(forward, {e.forward_bytes, {}, "f"});
    v[0] = p.now_us();
  });
  m.spawn(1, "receive", t800::Priority::low, [&](network::Process& p) {
    p.compute(e.receiver_delay_cycles);
    for (int i = 0; i < e.forward_messages; ++i) p.in(forward);
    v[1] = p.now_us();
  });
  if (e.reverse_delay_cycles >= 0) {
    m.spawn(1, "back", t800::Priority::high, [&](network::Process& p) {
      p.compute(e.reverse_delay_cycles);
      p.out(reverse, {e.reverse_bytes, {}, "r"});
      v[2] = p.now_us();
    });
    m.spawn(0, "take", t800::Priority::high, [&](network::Process& p) {
      p.in(reverse);
      v[3] = p.now_us();
    });
  }
  if (!m.run().empty()) return v;
  v[4] = m.simulated_us();
  for (int i = 0; i < 2; ++i) {
    v[5 + i] = m.transputer(i).activity().compute_us();
    v[7 + i] = m.transputer(i).activity().communicate_us();
  }
  const t800::Link& link = *m.links()[0].link;
  for (int d = 0; d < 2; ++d) {
    v[9 + d] = link.activity(d).busy_us();
    v[11 + d] = double(link.activity(d).bytes());
  }
  v[13] = double(link.closed_form_messages());
  v[14] = double(link.handovers());
  v[15] = double(m.transputer(1).cpu().statistics().stolen_cycles);
  return v;
}

constexpr int kCompared = 13;  // values 0..12 are results; the rest describe how the run went

void expect_same_results(const Values& a, const Values& b, const std::string& what) {
  for (int i = 0; i < kCompared; ++i) EXPECT_NEAR(a[i], b[i], 1e-9) << what << ", value " << i;
}

std::string describe(const Exchange& e) {
  return std::to_string(int(e.mbps)) + " Mbit/s " + std::string(t800::to_string(e.protocol)) +
         ", receiver delay " + std::to_string(e.receiver_delay_cycles) + ", reverse delay " +
         std::to_string(e.reverse_delay_cycles);
}

// The reverse direction starts at every 50 ns step across several byte periods of a closed-form
// message, so the hand-over meets every phase of the protocol (data on the wire, detect pending,
// acknowledge on the other wire, acknowledge being processed), with the receiver armed early and
// late.
//  * Without DMA cycle stealing (compute `block`) the two levels agree to the kernel's tick in
//  every case.
//  * With it (compute `fine` against `auto`) too: a byte landing at the very instant a compute
//    block starts is never charged to that block (t800/link.hpp, DmaCount), whatever order the
//    kernel runs that instant's processes in -- before that rule a few cases differed by a cycle.
//  * The packet level's runs (a message planned from one event, handed over to per-packet steps
//    when the reverse message starts) must give the per-packet steps' results too.
TEST(Fidelity, AutoEqualsPacketWhenTheOtherDirectionStartsMidMessage) {
  int handovers = 0, runs_handed_over = 0, cases = 0;
  for (double mbps : {20.0, 10.0})
    for (LinkProtocol protocol : {LinkProtocol::overlapped, LinkProtocol::t414})
      for (int receiver_delay : {0, 30})
        for (int reverse_delay = 0; reverse_delay <= 90; reverse_delay += 1) {
          const Exchange e{mbps, protocol, 16, 5, receiver_delay, reverse_delay, 1};
          auto run = [&](LinkFidelity links, ComputeFidelity compute, bool packet_runs = true) {
            return in_child([&] { return exchange(e, links, compute, packet_runs); });
          };
          const Values packet = run(LinkFidelity::packet, ComputeFidelity::block, false);
          const Values automatic = run(LinkFidelity::automatic, ComputeFidelity::block);
          const Values packet_runs = run(LinkFidelity::packet, ComputeFidelity::block);
          ASSERT_GE(packet[3], 0) << describe(e) << ": the packet level did not finish";
          expect_same_results(packet, automatic, describe(e));
          expect_same_results(packet, packet_runs, describe(e) + ", packet runs");
          handovers += int(automatic[14]);
          runs_handed_over += int(packet_runs[14]);
          ++cases;

          const Values packet_fine = run(LinkFidelity::packet, ComputeFidelity::fine, false);
          const Values auto_fine = run(LinkFidelity::automatic, ComputeFidelity::automatic);
          const Values runs_fine = run(LinkFidelity::packet, ComputeFidelity::fine);
          for (int i = 0; i < kCompared; ++i) {
            EXPECT_NEAR(packet_fine[i], auto_fine[i], 1e-9) << describe(e) << ", value " << i;
            EXPECT_NEAR(packet_fine[i], runs_fine[i], 1e-9)
                << describe(e) << ", packet runs, value " << i;
          }
        }
  // Most of these start the reverse message while the forward one is in closed form; the packet
  // level plans a run only where the input is armed before the message starts.
  EXPECT_GT(handovers, cases / 2);
  EXPECT_GT(runs_handed_over, 0) << "no run was planned: the comparison tested none";
}

TEST(Fidelity, MessageAndAutoEqualPacketOnAOneWayLink) {
  for (double mbps : {20.0, 10.0, 5.0})
    for (LinkProtocol protocol : {LinkProtocol::overlapped, LinkProtocol::t414})
      for (int receiver_delay : {0, 7, 200})
        for (std::int64_t bytes : {1, 2, 3, 100}) {
          Exchange e{mbps, protocol, bytes, 0, receiver_delay, -1, 3};
          const Values packet = in_child(
              [&] { return exchange(e, LinkFidelity::packet, ComputeFidelity::automatic, false); });
          ASSERT_GE(packet[1], 0) << describe(e);
          const Values runs = in_child([&] { return exchange(e, LinkFidelity::packet); });
          expect_same_results(packet, runs, describe(e) + " packet runs");
          EXPECT_EQ(runs[13], bytes >= 3 ? 3 : 0) << describe(e)
                                                  << ": every message of 3 bytes or "
                                                     "more should be one run";
          for (LinkFidelity f : {LinkFidelity::message, LinkFidelity::automatic}) {
            const Values other = in_child([&] { return exchange(e, f); });
            expect_same_results(packet, other, describe(e) + " " + std::string(t800::to_string(f)));
            EXPECT_EQ(other[13], 3) << "every message should run in closed form";
            EXPECT_EQ(other[14], 0);
          }
        }
}

// A closed form does not record its packets one by one (unless a trace needs their times): its
// busy time and DMA cycles are derived. They must equal the packet level's sums exactly -- the same
// doubles, the same cycles -- for messages of every size.
TEST(Fidelity, ClosedFormBusyTimeAndDmaCyclesEqualThePacketLevelsSums) {
  for (std::int64_t bytes : {1, 2, 64, 4096})
    for (int receiver_delay : {0, 200}) {
      Exchange e{20, LinkProtocol::overlapped, bytes, 0, receiver_delay, -1, 3};
      const Values packet = in_child([&] { return exchange(e, LinkFidelity::packet); });
      const Values closed = in_child([&] { return exchange(e, LinkFidelity::message); });
      ASSERT_EQ(closed[13], 3) << "every message should run in closed form";
      for (int d = 0; d < 2; ++d)
        EXPECT_EQ(closed[9 + d], packet[9 + d]) << bytes << " bytes: busy time of direction " << d;
      EXPECT_EQ(closed[15], packet[15]) << bytes << " bytes: DMA cycles stolen on P1";
    }
}

// Both directions streaming: the acknowledges wait behind the other direction's data, which the
// closed form does not see -- `message` is faster than the truth, `automatic` is the truth.
TEST(Fidelity, MessageLevelIgnoresContentionAutoDoesNot) {
  Exchange e{20, LinkProtocol::overlapped, 4096, 4096, 0, 0, 1};
  const Values packet = in_child([&] { return exchange(e, LinkFidelity::packet); });
  const Values automatic = in_child([&] { return exchange(e, LinkFidelity::automatic); });
  const Values message = in_child([&] { return exchange(e, LinkFidelity::message); });
  expect_same_results(packet, automatic, "both ways");
  EXPECT_LT(message[1], 0.9 * packet[1]) << "closed form should miss the contention";
}

TEST(Fidelity, FineAndAutoComputeAgreeAndDmaStealsCycles) {
  // P1 computes while its input DMA receives: the stolen cycles lengthen the work.
  auto computing_receiver = [](ComputeFidelity compute, LinkFidelity links) {
    return in_child([=] {
      network::MachineOptions o = core_test::options(20);
      o.fidelity.compute = compute;
      o.fidelity.links = links;
      network::Machine m(core_test::chain(1), o);
      Values v;
      v.fill(-1);
      auto& c = m.channel("c", 0, 1);
      m.spawn(0, "send", t800::Priority::low, [&](network::Process& p) {
        p.out(c, {2000, {}, "x"});
      });
      m.spawn(1, "receive", t800::Priority::high, [&](network::Process& p) { p.in(c); });
      m.spawn(1, "work", t800::Priority::low, [&](network::Process& p) {
        p.compute(100000);  // 5 ms, longer than the transfer and than a timeslice
        v[0] = p.now_us();
      });
      if (!m.run().empty()) return v;
      v[1] = double(m.transputer(1).cpu().statistics().stolen_cycles);
      return v;
    });
  };
  const Values block = computing_receiver(ComputeFidelity::block, LinkFidelity::packet);
  const Values fine = computing_receiver(ComputeFidelity::fine, LinkFidelity::packet);
  const Values automatic = computing_receiver(ComputeFidelity::automatic, LinkFidelity::packet);
  const Values auto_message = computing_receiver(ComputeFidelity::automatic, LinkFidelity::message);
  ASSERT_GE(block[0], 0);
  EXPECT_EQ(block[1], 0);
  // One cycle per byte received (t800/timing_table.hpp kLinkDmaCyclesPerByte): 2000 cycles = 100
  // us.
  EXPECT_EQ(fine[1], 2000 * t800::timing::kLinkDmaCyclesPerByte);
  EXPECT_NEAR(fine[0] - block[0], 2000 * t800::timing::kLinkDmaCyclesPerByte * 0.05, 1e-6);
  EXPECT_NEAR(fine[0], automatic[0], 1e-9);
  EXPECT_NEAR(fine[0], auto_message[0], 1e-9);
}

}  // namespace
