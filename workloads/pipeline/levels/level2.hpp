// A level-2 processor E_i: takes each step's pivot row and the rows L1 deals it, eliminates their
// leading element and sends them on to L3; E1 also forwards the pivot row. Buffered
// (PipelineSettings::buffered), it runs an input process, the eliminator and an output process in
// PAR, joined by one-row buffers. With recovery it checks each message's checksum and sends every
// row on with its own. A process of the SDK (t800sim::Process, typed In/Out of Messages::Packet,
// with recovery Messages::Checked); the buffers are a t800sim::Shared.
#pragma once

#include <vector>

#include "workloads/pipeline/levels/context.hpp"

namespace workloads::levels {

template <class T>
class Level2 {
 public:
  Level2(const Context<T>& context, int e) : c_(context), e_(e) {}
  // One system; false when the pipeline stops. A process of the SDK: typed channels, packets.
  bool round(t800sim::Process& p);
  // Its channels, given when its process starts.
  void attach(Ends ends) { ends_ = std::move(ends); }
  // Recovery: every system until L1's stop.
  void checked(t800sim::Process& p);

 private:
  using M = Messages<T>;
  using PacketValue = typename M::PacketValue;
  void eliminate_buffered(t800sim::Process& p, const PacketValue& pivot_packet,
                          const std::vector<std::size_t>& rows);
  t800sim::In<typename M::Packet> input() const {
    return t800sim::In<typename M::Packet>(ends_.from[0]);
  }
  t800sim::Out<typename M::Packet> output() const {
    return t800sim::Out<typename M::Packet>(ends_.to[0]);
  }

  Context<T> c_;
  Ends ends_;      // from L1 (or the fan-out X), to L3 (or the fan-in Y)
  int e_;          // 0-based: E1 is 0
  Shared buffer_;  // buffered: the one-row buffers between input, eliminator and output
};

extern template class Level2<float>;
extern template class Level2<double>;

}  // namespace workloads::levels
