// The smallest plugin, built in the test tree as a user builds one (t800sim::plugin: headers only),
// for the plugin tests (tests/sdk/plugin_test.cpp). Built four ways: as is; claiming another SDK
// version (T800SIM_TEST_OTHER_VERSION, as a plugin built against another release would); without
// T800SIM_PLUGIN() (T800SIM_TEST_NOT_A_PLUGIN: a shared library that is not a plugin); and
// registering its kind under a built-in kind's name (T800SIM_TEST_KIND="pingpong").
#include "t800sim/workload.hpp"

namespace {

using namespace t800sim;

// One process that computes `cycles` cycles and reports when it ended.
class Busy : public Program {
 public:
  explicit Busy(std::int64_t cycles) : cycles_(cycles) {}
  void build(Builder& b) override {
    b.process("busy", [this](Process& p) {
      p.compute(cycles_, "busy");
      end_us_ = p.now_us();
    });
  }
  void results(Results& r) const override { r.set("end_us", end_us_); }

 private:
  std::int64_t cycles_;
  double end_us_ = 0;
};

}  // namespace

#ifndef T800SIM_TEST_KIND
#define T800SIM_TEST_KIND "tiny_busy"
#endif

T800SIM_WORKLOAD(tiny_busy) {
  return {
      T800SIM_TEST_KIND,
      "a plugin's process that computes for a while",
      {integer_param("cycles", 1000, "cycles to compute", 1, 1e9)},
      [](const Params& p, const Network&) { return std::make_unique<Busy>(p.integer("cycles")); }};
}

#ifndef T800SIM_TEST_NOT_A_PLUGIN
#ifdef T800SIM_TEST_OTHER_VERSION
#undef T800SIM_VERSION
#define T800SIM_VERSION T800SIM_TEST_OTHER_VERSION
#endif
T800SIM_PLUGIN();
#endif
