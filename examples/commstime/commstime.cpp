// Commstime (P. H. Welch's benchmark of channel communication and context switching), as a t800sim
// plugin. Four processes in a ring: prefix emits 0, then copies its input to its output; delta
// copies each value to successor and to consume (its two outputs in PAR, or in SEQ); successor adds
// one; consume takes the values and times them. The occam it follows is pahihu/t4's
// examples/comstime/comstime.occ (which prints 15049 ns per loop for a T800-20, PAR delta).
//
// occam's processes run WHILE TRUE; here each runs `warmup + loops` times so that the run ends:
// prefix inputs the successor's last value too, so no one waits for ever.
#include <t800sim/workload.hpp>

namespace {

using namespace t800sim;

// The integer work occam compiles around the communications, priced by the operation-mix model:
// a WHILE TRUE loop closes with a jump (the mix prices it as a taken cj), consume's replicated SEQ
// with lend, successor's x + 1 is adc.
Mix loop_jump() {
  Mix m;
  m.branches = 1;
  return m;
}
Mix loop_end() {
  Mix m;
  m.loop_ends = 1;
  return m;
}
Mix add_one() {
  Mix m;
  m.int_simple = 1;
  return m;
}

class Commstime : public Program {
 public:
  Commstime(std::int64_t loops, std::int64_t warmup, bool par_delta)
      : loops_(loops), warmup_(warmup), par_delta_(par_delta) {}

  // comstime.occ's channels a, b, c, d and its four processes.
  void build(Builder& net) override {
    const auto a = net.channel<INT>("a", "prefix", "delta");
    const auto b = net.channel<INT>("b", "successor", "prefix");
    const auto c = net.channel<INT>("c", "delta", "successor");
    const auto d = net.channel<INT>("d", "delta", "consume");
    const std::int64_t n = warmup_ + loops_;
    net.process("prefix", [=](Process& p) {
      p.out(a, 0);
      for (std::int64_t i = 1; i < n; ++i) {
        p.out(a, p.in(b));
        p.compute(loop_jump(), "WHILE TRUE");
      }
      p.in(b);
    });
    net.process("delta", [=](Process& p) {
      for (std::int64_t i = 0; i < n; ++i) {
        const INT x = p.in(a);
        if (par_delta_)
          p.par({[=](Process& q) { q.out(c, x); }, [=](Process& q) { q.out(d, x); }});
        else {
          p.out(c, x);
          p.out(d, x);
        }
        p.compute(loop_jump(), "WHILE TRUE");
      }
    });
    net.process("successor", [=](Process& p) {
      for (std::int64_t i = 0; i < n; ++i) {
        const INT x = p.in(c);
        p.compute(add_one(), "x + 1");
        p.out(b, x + 1);
        p.compute(loop_jump(), "WHILE TRUE");
      }
    });
    net.process("consume", [=](Process& p) {
      for (std::int64_t i = 0; i < warmup_; ++i) {
        p.in(d);
        p.compute(loop_end(), "SEQ i = 0 FOR warm.up");
      }
      start_us_ = p.now_us();
      for (std::int64_t i = 0; i < loops_; ++i) {
        last_ = p.in(d);
        p.compute(loop_end(), "SEQ i = 0 FOR n.loops");
      }
      end_us_ = p.now_us();
    });
  }

  // Welch's accounting: a loop is four communications; its context switches are the four processes
  // descheduled on their inputs plus, with PAR delta, the start of its second branch (5 with PAR,
  // 4 with SEQ: comstime.occ's n.start.process).
  void results(Results& r) const override {
    const double loop_us = (end_us_ - start_us_) / double(loops_);
    r.set("loops", loops_);
    r.set("warmup", warmup_);
    r.set("delta", par_delta_ ? "par" : "seq");
    r.set("last_value", std::int64_t(last_));
    r.set("us_per_loop", loop_us);
    r.set("us_per_communication", loop_us / 4);
    r.set("us_per_context_switch", loop_us / (par_delta_ ? 5 : 4));
  }

 private:
  std::int64_t loops_, warmup_;
  bool par_delta_;
  double start_us_ = 0, end_us_ = 0;
  INT last_ = 0;
};

}  // namespace

T800SIM_WORKLOAD(commstime) {
  return {
      "commstime",
      "Welch's Commstime: prefix, delta, successor and consume in a ring; time per loop, per "
      "communication and per context switch",
      {integer_param("loops", 10000, "loops consume times", 1, 1e8),
       integer_param("warmup", 16, "loops before timing starts (comstime.occ's warm.up)", 0, 1e6),
       text_param("delta", "par", "delta's two outputs in PAR (comstime.occ) or in SEQ",
                  {"par", "seq"})},
      [](const Params& p, const Network&) {
        return std::make_unique<Commstime>(p.integer("loops"), p.integer("warmup"),
                                           p.text("delta") == "par");
      }};
}

T800SIM_PLUGIN();
