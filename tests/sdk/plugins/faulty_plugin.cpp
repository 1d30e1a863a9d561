// A plugin whose programs fail in each way a plugin can, for the tests of how t800sim reports
// them (tests/sdk/plugin_failure_test.cpp); a scene picks the failure by its kind. Built three
// ways: as is; with a static initialiser that throws a std::runtime_error
// (T800SIM_TEST_THROW_AT_LOAD=1); and one that throws an int, no std::exception
// (T800SIM_TEST_THROW_AT_LOAD=2). The messages thrown are the tests' (T800SIM_TEST_MESSAGE).
#include <functional>
#include <stdexcept>

#include "t800sim/workload.hpp"

namespace {

using namespace t800sim;

// A program made of a build function.
class Built : public Program {
 public:
  explicit Built(std::function<void(Builder&)> build) : build_(std::move(build)) {}
  void build(Builder& b) override { build_(b); }

 private:
  std::function<void(Builder&)> build_;
};

WorkloadSpec failing(const char* kind, const char* summary, std::function<void(Builder&)> build) {
  return {kind, summary, {}, [build](const Params&, const Network&) {
            return std::make_unique<Built>(build);
          }};
}

}  // namespace

T800SIM_WORKLOAD(faulty_build) {
  return failing("faulty_build", "a build() that throws",
                 [](Builder&) { throw std::runtime_error(T800SIM_TEST_MESSAGE); });
}

// Runs on the second processor (`pair` topology), throws after computing a while.
T800SIM_WORKLOAD(faulty_body) {
  return failing("faulty_body", "a process whose body throws", [](Builder& b) {
    b.process("thrower", [](Process& p) {
       p.compute(100, "before");
       throw std::runtime_error(T800SIM_TEST_MESSAGE);
     }).placed_on("P1");
  });
}

T800SIM_WORKLOAD(faulty_body_int) {
  return failing("faulty_body_int", "a process whose body throws an int", [](Builder& b) {
    b.process("int_thrower", [](Process&) { throw 7; }).placed_on("P1");
  });
}

// Runs, then throws an int when asked for its results.
class ThrowsResults : public Program {
 public:
  void build(Builder& b) override {
    b.process("quiet", [](Process& p) { p.compute(10, "quiet"); });
  }
  void results(Results&) const override { throw 7; }
};

T800SIM_WORKLOAD(faulty_results) {
  return {"faulty_results",
          "a program whose results() throws an int",
          {},
          [](const Params&, const Network&) { return std::make_unique<ThrowsResults>(); }};
}

T800SIM_WORKLOAD(faulty_two_writers) {
  return failing("faulty_two_writers", "two processes output to one channel", [](Builder& b) {
    const Out<INT> first = b.output<INT>("shared", "first");
    const Out<INT> second = b.output<INT>("shared", "second");
    const In<INT> in = b.input<INT>("shared", "reader");
    b.process("first", [first](Process& p) { p.out(first, 1); });
    b.process("second", [second](Process& p) { p.out(second, 2); });
    b.process("reader", [in](Process& p) {
      p.in(in);
      p.in(in);
    });
  });
}

T800SIM_WORKLOAD(faulty_missing_processor) {
  return failing("faulty_missing_processor", "a process placed on a processor not in the network",
                 [](Builder& b) { b.process("lost", [](Process&) {}).placed_on("P9"); });
}

#if T800SIM_TEST_THROW_AT_LOAD
// After the registrations above: the plugin is half initialised when it throws.
struct ThrowsWhenLoaded {
  ThrowsWhenLoaded() {
#if T800SIM_TEST_THROW_AT_LOAD == 1
    throw std::runtime_error(T800SIM_TEST_MESSAGE);
#else
    throw 7;
#endif
  }
} throws_when_loaded;
#endif

T800SIM_PLUGIN();
