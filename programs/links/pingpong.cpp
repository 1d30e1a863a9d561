// Ping-pong: a block of bytes goes to a neighbour and comes back, `iterations` times; the one-way
// time of a message is half a round trip.
#include "programs/links/neighbours.hpp"
#include "t800sim/workload.hpp"

namespace programs {

namespace {

using namespace t800sim;

class PingPong : public Program {
 public:
  PingPong(const Params& p, const Network& n)
      : bytes_(p.integer("bytes")),
        iterations_(p.integer("iterations")),
        ends_(neighbour_pair(p, n)) {}

  void build(Builder& b) override {
    const auto there = b.channel<Block<BYTE>>("ping", "pinger", "ponger");
    const auto back = b.channel<Block<BYTE>>("pong", "ponger", "pinger");
    b.process("pinger", [this, there, back](Process& p) {
       const std::vector<BYTE> buffer(std::size_t(bytes_), 0);
       for (std::int64_t i = 0; i < iterations_; ++i) {
         p.out(there, buffer);
         p.in(back);
       }
       end_us_ = p.now_us();
     }).placed_on(ends_.first);
    b.process("ponger", [this, there, back](Process& p) {
       for (std::int64_t i = 0; i < iterations_; ++i) p.out(back, p.in(there));
     }).placed_on(ends_.second);
  }

  void results(Results& r) const override {
    r.set("from", ends_.first);
    r.set("to", ends_.second);
    r.set("bytes", bytes_);
    r.set("iterations", iterations_);
    r.set("one_way_us", end_us_ / (2.0 * double(iterations_)));
  }

 private:
  std::int64_t bytes_, iterations_;
  std::pair<std::string, std::string> ends_;
  double end_us_ = 0;
};

}  // namespace

T800SIM_WORKLOAD(pingpong) {
  return {"pingpong",
          "two neighbouring processors send a message back and forth",
          {integer_param("bytes", 64, "message length in bytes", 1, 1e7),
           integer_param("iterations", 100, "round trips", 1, 1e7),
           processor_param("from", "first processor (default: the host's processor)"),
           processor_param("to", "second processor (default: a neighbour of `from`)")},
          [](const Params& p, const Network& n) { return std::make_unique<PingPong>(p, n); }};
}

}  // namespace programs
