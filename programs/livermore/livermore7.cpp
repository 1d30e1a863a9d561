// Livermore loop 7 on one processor, `repeat` times: its rate in MFLOPS against INMOS's published
// figures (TN06: 1.5 on a T800-20, 2.25 on a T800-30; docs/t800-timing.md). The kernel is timed
// from the T800 code it compiles to (or its operation mix, compute_cost = "mix").
#include "programs/livermore/loop7.hpp"
#include "t800sim/workload.hpp"

namespace programs {

namespace {

using namespace t800sim;

template <class S>
Kernel record_loop7(std::size_t n) {
  return record_kernel<S>("LOOP7", [n] {
    livermore::Loop7Data<S> data(n);
    // The arrays are the PROC's parameters (in vector space); r, t, q its workspace variables.
    declare(data.x, "x");
    declare(data.y, "y");
    declare(data.z, "z");
    declare(data.u, "u");
    declare_variable(data.r, "r");
    declare_variable(data.t, "t");
    declare_variable(data.q, "q");
    livermore::loop7(data.x, data.y, data.z, data.u, data.r, data.t, data.q);
    note_loads<S>(9 * long(n));  // the nine array elements each element reads
    note_stores<S>(long(n));
  });
}

class Livermore7 : public Program {
 public:
  Livermore7(const Params& p, const Network& n)
      : n_(std::size_t(p.integer("elements"))),
        repeat_(p.integer("repeat")),
        real64_(p.text("precision") == "real64"),
        processor_(p.text("processor").empty() ? n.processor_name(0) : p.text("processor")),
        kernel_(real64_ ? record_loop7<Real64>(n_) : record_loop7<Real32>(n_)) {}

  void build(Builder& b) override {
    b.code("loop7", kernel_);
    b.process("loop7", [this](Process& p) {
       start_us_ = p.now_us();
       for (std::int64_t i = 0; i < repeat_; ++i) p.compute(kernel_);
       end_us_ = p.now_us();
     }).placed_on(processor_);
  }

  void results(Results& r) const override {
    const double us = end_us_ - start_us_;
    const double flops = double(livermore::kLoop7FlopsPerElement) * double(n_) * double(repeat_);
    const double cycles = us * 1000.0 / r.cycle_ns(processor_);
    r.set("elements", std::int64_t(n_));
    r.set("repeat", repeat_);
    r.set("precision", real64_ ? "real64" : "real32");
    r.set("processor", r.processor_type(processor_));
    r.set("time_us", us);
    r.set("cycles_per_element", cycles / (double(n_) * double(repeat_)));
    r.set("mflops", us > 0 ? flops / us : 0.0);
  }

 private:
  std::size_t n_;
  std::int64_t repeat_;
  bool real64_;
  std::string processor_;
  Kernel kernel_;
  double start_us_ = 0, end_us_ = 0;
};

}  // namespace

T800SIM_WORKLOAD(livermore7) {
  return {
      "livermore7",
      "Livermore loop 7 (equation of state fragment, 16 flops per element) on one processor: its "
      "rate "
      "against INMOS's published MFLOPS",
      {integer_param("elements", 101, "loop length n (u has n + 6 elements)", 1, 1e6),
       integer_param("repeat", 1, "times the loop runs", 1, 1e6),
       precision_param("precision", "real32", "occam REAL32 or REAL64 arithmetic"),
       processor_param("processor", "the processor that runs it (default: the first)")},
      [](const Params& p, const Network& n) { return std::make_unique<Livermore7>(p, n); }};
}

}  // namespace programs
