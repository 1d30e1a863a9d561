// A stand-alone executable: its own program (a pipeline of stages that each double a number) and
// t800sim's simulator, run through the SDK (t800sim/run.hpp) without t800sim's command line.
//   build/run_scene run_scene/pipeline.toml [KEY=VALUE ...]
#include <t800sim/run.hpp>
#include <t800sim/workload.hpp>

#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace t800sim;

// x + x compiles to ldl x; ldl x; add.
Mix doubling_code() {
  Mix m;
  m.word_loads = 2;
  m.int_simple = 1;
  return m;
}

// source -> stage[0] -> ... -> stage[n-1] -> sink, on a chain of processors: the sink adds up what
// arrives, each value doubled n times.
class Doubling : public Program {
 public:
  Doubling(std::int64_t stages, std::int64_t values) : stages_(int(stages)), values_(values) {}

  void build(Builder& b) override {
    std::vector<Chan<INT>> c;  // c[i] into stage i; c[stages] into the sink
    for (int i = 0; i <= stages_; ++i)
      c.push_back(b.channel<INT>("c" + std::to_string(i), i == 0 ? "source" : stage(i - 1),
                                 i == stages_ ? "sink" : stage(i)));
    const std::int64_t values = values_;
    b.process("source", [c, values](Process& p) {
      for (std::int64_t v = 1; v <= values; ++v) p.out(c.front(), INT(v));
    });
    b.processes("stage", stages_, [c, values](Process& p, int i) {
      for (std::int64_t v = 0; v < values; ++v) {
        const INT x = p.in(c[std::size_t(i)]);
        p.compute(doubling_code(), "x + x");
        p.out(c[std::size_t(i) + 1], x + x);
      }
    });
    b.process("sink", [this, c, values](Process& p) {
      for (std::int64_t v = 0; v < values; ++v) sum_ += p.in(c.back());
      end_us_ = p.now_us();
    });
  }

  void results(Results& r) const override {
    r.set("stages", std::int64_t(stages_));
    r.set("values", values_);
    r.set("sum", sum_);  // (1 + ... + values) * 2^stages
    r.set("us_per_value", end_us_ / double(values_));
  }

 private:
  static std::string stage(int i) { return "stage[" + std::to_string(i) + "]"; }

  int stages_;
  std::int64_t values_;
  std::int64_t sum_ = 0;
  double end_us_ = 0;
};

}  // namespace

T800SIM_WORKLOAD(doubling) {
  return {"doubling",
          "a source, a pipeline of stages that double each value, and a sink that adds them up",
          {integer_param("stages", 3, "doubling stages", 1, 64),
           integer_param("values", 100, "values the source sends (1, 2, ...)", 1, 1e6)},
          [](const Params& p, const Network&) {
            return std::make_unique<Doubling>(p.integer("stages"), p.integer("values"));
          }};
}

int sc_main(int argc, char* argv[]) {
  if (argc < 2) {
    std::cerr << "usage: run_scene SCENE [KEY=VALUE ...]\n";
    return 2;
  }
  const SceneRun r = run_scene(argv[1], std::vector<std::string>(argv + 2, argv + argc));
  if (!r.error.empty()) std::cerr << r.error << "\n";
  std::cout << r.report_json;
  return r.exit_code;
}
