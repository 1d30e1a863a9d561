// A pipeline of fixed-cost stages on a ring of transputers, built with the SDK's pipeline
// skeleton (t800sim/pipeline.hpp): a feeder on the processor wired to the host sends `rounds`
// vectors of REAL32s through `stages` stages on the next processors of the ring, each of which
// scales and shifts every element and takes `stage_cycles` cycles of its CPU; a collector beside
// the feeder takes the results. With `buffered` every stage is an input, a worker and an output
// process in PAR, so a stage's links move items while its CPU works.
//
// Reports when each result arrived, so the pipeline's fill and period can be read off and compared
// with what the link protocol and the stage cost say they must be (docs/examples.md, "A pipeline of
// your own"; tests/examples/fixed_stages_test.cpp).
#include <string>
#include <vector>

#include "programs/pipeline/stage_function.hpp"
#include "programs/support/checksum.hpp"
#include "t800sim/pipeline.hpp"
#include "t800sim/workload.hpp"

namespace fixed_stages {

namespace {

using namespace t800sim;
using Item = Block<REAL32>;
using Values = value_of<Item>;

class FixedStages : public Program {
 public:
  FixedStages(const Params& p, const Network& n)
      : stages_(int(p.integer("stages"))),
        cycles_(p.integer("stage_cycles")),
        reals_(std::size_t(p.integer("item_reals"))),
        rounds_(int(p.integer("rounds"))),
        buffered_(p.flag("buffered")),
        arrived_us_(std::size_t(rounds_), 0),
        results_(std::size_t(rounds_)) {
    if (n.processors() < stages_ + 1)
      throw SettingError(
          {"workload.stages", kNetworkKey},
          std::to_string(stages_) + " stages and the client need " + std::to_string(stages_ + 1) +
              " processors; the network has " + std::to_string(n.processors()) +
              " (e.g. network.family = \"ring\" with network.workers = " + std::to_string(stages_) +
              ")");
    const int client = n.host_processor();
    client_ = n.processor_name(client);
    // The stages on the processors after the client's, in the network's order.
    for (int k = 0, s = 0; s < stages_; ++k)
      if (k != client) {
        processors_.push_back(n.processor_name(k));
        ++s;
      }
  }

  void build(Builder& b) override {
    auto decl = pipeline<Item>();
    for (int s = 0; s < stages_; ++s) {
      decl = std::move(decl).stage<Item>("stage" + std::to_string(s + 1),
                                         [s, cycles = cycles_](Process& p, const Values& x) {
                                           p.compute(cycles, "stage");
                                           return stage_function(s, x);
                                         });
      decl = std::move(decl).on(processors_[std::size_t(s)]);
      if (buffered_) decl = std::move(decl).buffered();
    }
    const auto pipe = decl.build(b, "feeder", "collector", rounds_);
    b.process("feeder", [this, pipe](Process& p) {
       start_us_ = p.now_us();
       for (int r = 0; r < rounds_; ++r) p.out(pipe.in(r), input(r, reals_));
     }).placed_on(client_);
    b.process("collector", [this, pipe](Process& p) {
       for (int r = 0; r < rounds_; ++r) {
         results_[std::size_t(r)] = p.in(pipe.out(r));
         arrived_us_[std::size_t(r)] = p.now_us();
       }
     }).placed_on(client_);
  }

  void results(Results& r) const override {
    r.set("stages", std::int64_t(stages_));
    r.set("stage_cycles", cycles_);
    r.set("item_reals", std::int64_t(reals_));
    r.set("item_bytes", std::int64_t(reals_ * sizeof(REAL32)));
    r.set("rounds", std::int64_t(rounds_));
    r.set("buffered", buffered_);
    r.set("precision", "real32");
    r.set("tp_us", rounds_ > 0 ? arrived_us_.back() - start_us_ : 0.0);
    ResultValue arrived = ResultValue::list();
    for (double t : arrived_us_) arrived.push(t - start_us_);
    r.set("arrived_us", arrived);
    // The period: the mean gap between results once the first is out (the pipeline is full).
    r.set("period_us",
          rounds_ > 1 ? (arrived_us_.back() - arrived_us_.front()) / double(rounds_ - 1) : 0.0);
    std::vector<REAL32> all;
    for (const Values& v : results_) all.insert(all.end(), v.begin(), v.end());
    r.set("results_checksum", programs::fnv1a_hex(all));
  }

 private:
  int stages_;
  std::int64_t cycles_;
  std::size_t reals_;
  int rounds_;
  bool buffered_;
  std::string client_;
  std::vector<std::string> processors_;
  double start_us_ = 0;
  std::vector<double> arrived_us_;
  std::vector<Values> results_;
};

}  // namespace

T800SIM_WORKLOAD(fixed_stages) {
  return {"fixed-stages",
          "a pipeline of fixed-cost stages on a ring (the SDK's pipeline skeleton): a feeder sends "
          "vectors of REAL32s through the stages, a collector takes the results",
          {integer_param("stages", 4, "stages, one per processor after the client's", 1, 64),
           integer_param("stage_cycles", 2000, "cycles each stage computes per item", 0, 1e9),
           integer_param("item_reals", 16, "REAL32s per item", 1, 65536),
           integer_param("rounds", 20, "items fed through the pipeline", 0, 1e6),
           flag_param("buffered", false,
                      "every stage an input, a worker and an output process in PAR (one-item "
                      "buffers)")},
          [](const Params& p, const Network& n) -> std::unique_ptr<Program> {
            return std::make_unique<FixedStages>(p, n);
          }};
}

}  // namespace fixed_stages
