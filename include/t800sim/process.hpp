// A process of a program, as its body sees it: ordinary sequential C++ that computes, talks over
// typed channels, runs parallel branches and reads its TIMER -- occam's primitives, on the
// simulated transputer it is placed on. No SystemC here: the simulator's process is behind it.
//
//   void prefix(t800sim::Process& p, In<INT> in, Out<INT> out) {
//     p.out(out, 0);
//     for (;;) p.out(out, p.in(in));
//   }
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "t800sim/byte_link.hpp"
#include "t800sim/channel.hpp"
#include "t800sim/protocol.hpp"

namespace network {
class Process;
}
namespace t800 {
struct OperationMix;
namespace isa {
struct Instruction;
}
}  // namespace t800

namespace t800sim {

class Kernel;
using Mix = t800::OperationMix;
// T800 instructions written out (t800/isa/instruction.hpp), for code no kernel records (an integer
// loop over a row's words).
using Instructions = std::vector<t800::isa::Instruction>;

class Process {
 public:
  using Body = std::function<void(Process&)>;
  using IndexedBody = std::function<void(Process&, int)>;

  explicit Process(network::Process& impl) : impl_(impl) {}

  const std::string& name() const;
  std::string processor() const;  // the processor's name ("host" for the host PC)
  double now_us() const;          // simulated time

  // An instant of simulated time, exact (in the simulator's time resolution): an interval
  // measured between two instants is the same wherever it lies in time, where a difference of
  // now_us() readings is rounded at the two absolute times (a program timing its steps, whose
  // reports must not drift as the run goes on).
  struct Instant {
    std::uint64_t ticks = 0;
  };
  Instant instant() const;
  static double us_between(Instant from, Instant to);

  // Computation on this process's CPU: a cycle count, an operation mix, or a recorded kernel
  // (t800sim/kernel.hpp), timed from its T800 code.
  void compute(std::int64_t cycles, const std::string& label = {});
  void compute(const Mix& mix, const std::string& label = {});
  void compute(const Kernel& kernel, const std::string& label = {});
  // What a kernel costs on this process's processor, in its cycles: what compute(kernel) takes
  // when nothing interrupts it (a program reports or schedules by it).
  std::int64_t cycles(const Kernel& kernel) const;
  // What a sequence of instructions costs on this processor, in its cycles (its memory's wait
  // states included): compute(cycles(code)) runs it.
  std::int64_t cycles(const Instructions& code) const;

  // c ! v: returns when the value has been taken (a protocol's items one communication each).
  // Traces and fault reports name the message by its channel, or by `label` when one is given
  // (nothing but those reads it). The value travels to the receiver as it is: pass it with
  // std::move, or as a temporary, and its storage goes along instead of a copy.
  template <class P>
  void out(const Out<P>& c, value_of<P> v, const std::string& label = {}) {
    auto wire = open(c.slot(), true, -1, label);
    protocol<P>::send(wire, std::move(v));
  }
  template <class P>
  void out(const Chan<P>& c, value_of<P> v) {
    out(c.out(), std::move(v));
  }
  // c ? v
  template <class P>
  value_of<P> in(const In<P>& c) {
    auto wire = open(c.slot(), false);
    return protocol<P>::receive(wire);
  }
  template <class P>
  value_of<P> in(const Chan<P>& c) {
    return in(c.in());
  }

  // Bytes down a byte link to a booted processor (t800sim/byte_link.hpp): returns when its link
  // engine has taken the last; and the next `count` bytes the booted program outputs, however it
  // split them.
  void out(const ByteLink& link, Bytes bytes);
  Bytes in(const ByteLink& link, std::size_t count);

  // occam's OutputOrFail.t / InputOrFail.t (INMOS's reliable-link library): the communication
  // gives up at `deadline_us` (simulated time, in us) and resets the link channel, so the process
  // goes on and the program can recover from a dead link or a halted partner. Costed with the
  // library's instructions (the timer read for the deadline, resetch when it gives up). On an
  // internal channel they communicate as out / in (both ends on one processor cannot fail); on a
  // routed channel the output fails only if the first hop does not take it. A protocol's items
  // each have the same deadline; after one fails the rest are not sent.
  template <class P>
  bool out_or_fail(const Out<P>& c, value_of<P> v, double deadline_us,
                   const std::string& label = {}) {
    auto wire = open(c.slot(), true, deadline_us, label);
    protocol<P>::send(wire, std::move(v));
    return !wire.failed();
  }
  template <class P>
  std::optional<value_of<P>> in_or_fail(const In<P>& c, double deadline_us) {
    auto wire = open(c.slot(), false, deadline_us);
    value_of<P> v = protocol<P>::receive(wire);
    if (wire.failed()) return std::nullopt;
    return v;
  }

  // PAR: the branches run as processes on this processor; returns when all have ended.
  void par(const std::vector<Body>& branches);
  // PAR i = 0 FOR n
  void par_for(int n, const IndexedBody& body);
  // PRI PAR: `high` at high priority, the others at low.
  void pri_par(const Body& high, const std::vector<Body>& low);

  // TIMER ? t: 1 us ticks at high priority, 64 us at low (the T800's two clocks).
  std::int64_t timer() const;
  // The same clock without the instructions timer() charges (ldtimer; stl): for a model whose
  // timer reads are costed elsewhere or not at all (the elimination pipeline's level 3 starts its
  // ALT's timeout from it).
  std::int64_t clock() const;
  double tick_us() const;
  // TIMER ? AFTER t: waits until the clock reads later than t.
  void wait_after(std::int64_t t);

  // occam's STOP, as a run-time error (a subscript out of range) ends a process: it stops for ever,
  // taking no processor time, and the run's deadlock report names it with `why` (and whoever then
  // waits for it).
  [[noreturn]] void stop(const std::string& why);

  // A fault-tolerant program's word to the run's fault report (a scene's [[fault]], --fault):
  // something sent along `path` -- processor names, in the order the message went -- did not
  // arrive, or arrived wrong, and `by` says who noticed and how. Each fault that has taken effect
  // on the path (on a link between two processors next to each other in it, or a halted processor
  // in it) and is not yet recovered counts; the first detection of a fault is the one reported.
  // Returns how many faults it counted. Throws std::invalid_argument for a name the network lacks.
  int fault_detected(const std::vector<std::string>& path, const std::string& by);
  // The program has worked round what it detected on `path` (`how`): those faults are recovered,
  // the first recovery of each counting (a fault that keeps acting is recovered once).
  void fault_recovered(const std::vector<std::string>& path, const std::string& how);

  // The simulator's process, for the SDK's own code (t800sim/alt.hpp).
  network::Process& impl() { return impl_; }
  // Throws std::logic_error, naming both, unless this process is placed where the channel's
  // writing (or reading) end is.
  void check_end(const detail::ChannelSlot* slot, bool writing) const;

 private:
  // One end of a channel as a protocol's communications see it.
  class Wire final : public detail::Wire {
   public:
    // deadline_us < 0: no deadline (out / in).
    Wire(network::Process& process, network::Channel& channel, double deadline_us,
         const std::string& label)
        : process_(process), channel_(channel), deadline_us_(deadline_us), label_(label) {}
    void send(std::int64_t bytes, std::any value) override;
    std::any receive() override;
    bool failed() const override { return failed_; }

   private:
    network::Process& process_;
    network::Channel& channel_;
    double deadline_us_;
    std::string label_;  // empty: the channel's name
    bool failed_ = false;
  };
  Wire open(const detail::ChannelSlot* slot, bool writing, double deadline_us = -1,
            const std::string& label = {});
  // A path of processor names as the simulator numbers them.
  std::vector<int> nodes(const std::vector<std::string>& path) const;

  network::Process& impl_;
};

}  // namespace t800sim
