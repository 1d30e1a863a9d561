#include "workloads/livermore/livermore_workload.hpp"

#include <stdexcept>

#include "t800/cost_model.hpp"
#include "workloads/livermore/loop7.hpp"
#include "workloads/run/operation_mix.hpp"

namespace workloads {

namespace {

// The loop as the processor's one process runs it, `repeat` times: the kernel's code compiled
// for the processor (or its operation mix, compute_cost = "mix"). Results: the rate in MFLOPS.
template <class T>
class Livermore7 : public Workload {
  using C = dynamics::Counted<T>;

 public:
  Livermore7(int processor, std::size_t n, int repeat)
      : processor_(processor), n_(n), repeat_(repeat) {}

  void build(network::Machine& m) override {
    work_ = record();
    m.declare_code(processor_, "loop7", work_.code);
    m.spawn(processor_, "loop7", t800::Priority::low, [this](network::Process& p) {
      start_us_ = p.now_us();
      for (int i = 0; i < repeat_; ++i) p.compute(work_, "LOOP7");
      end_us_ = p.now_us();
    });
  }

  ResultValue results(const network::Machine& m) const override {
    const double us = end_us_ - start_us_;
    const double flops = double(livermore::kLoop7FlopsPerElement) * double(n_) * repeat_;
    const double cycles = us * 1000.0 / m.compute_model(processor_).cycle_ns();
    ResultValue v;
    v.set("kind", std::string("livermore7"));
    v.set("elements", std::int64_t(n_));
    v.set("repeat", std::int64_t(repeat_));
    v.set("precision", std::string(sizeof(T) == 8 ? "real64" : "real32"));
    v.set("processor", std::string(m.compute_model(processor_).processor().name));
    v.set("time_us", us);
    v.set("cycles_per_element", cycles / double(n_ * std::size_t(repeat_)));
    v.set("mflops", us > 0 ? flops / us : 0.0);
    return v;
  }

 private:
  // The kernel's arrays are parameters (in vector space), r, t, q its workspace variables.
  t800::ComputeWork record() const {
    livermore::Loop7Data<C> data(n_);
    auto recording = std::make_shared<t800::codegen::Recording>("LOOP7", sizeof(T) == 8);
    dynamics::OpTally tally;
    {
      const t800::codegen::RecordingScope scope(*recording);
      occam::declare(data.x, "x");
      occam::declare(data.y, "y");
      occam::declare(data.z, "z");
      occam::declare(data.u, "u");
      occam::declare_variable(data.r, "r");
      occam::declare_variable(data.t, "t");
      occam::declare_variable(data.q, "q");
      livermore::loop7(data.x, data.y, data.z, data.u, data.r, data.t, data.q);
    }
    dynamics::OpCounts ops = tally.counts();
    ops.fload += 9 * long(n_);  // the nine array elements of each element, for the op-count model
    ops.fstore += long(n_);
    t800::OperationMix mix = to_operation_mix(ops);
    mix.loop_ends += std::int64_t(n_);
    return {mix, recording};
  }

  int processor_;
  std::size_t n_;
  int repeat_;
  t800::ComputeWork work_;
  double start_us_ = 0, end_us_ = 0;
};

}  // namespace

std::unique_ptr<Workload> make_livermore7(const WorkloadContext& c) {
  const int processor = processor_param(c.params, "processor", c.topology, 0);
  const auto n = std::size_t(c.params.integer("elements"));
  const int repeat = int(c.params.integer("repeat"));
  if (c.params.text("precision") == "real64")
    return std::make_unique<Livermore7<double>>(processor, n, repeat);
  return std::make_unique<Livermore7<float>>(processor, n, repeat);
}

}  // namespace workloads
