// Processors of one machine share compiled code (t800/code_cache.hpp): a kernel is compiled once
// per target, and what a processor then times is what compiling it alone would give.
#include <gtest/gtest.h>

#include <memory>

#include "t800/codegen/recording.hpp"
#include "t800/isa/instruction.hpp"
#include "t800/compute_model.hpp"

namespace {

// x[1] = x[0] * x[1] + 3; x[2] = x[1] / x[0], on an array x of three REAL32s.
std::shared_ptr<const t800::codegen::Recording> kernel() {
  using t800::codegen::NodeKind;
  auto r = std::make_shared<t800::codegen::Recording>("K", false);
  const int x = r->declare_array("x", 3);
  const int x0 = r->load(r->access(x, 0)), x1 = r->load(r->access(x, 1));
  const int sum =
      r->operation(NodeKind::add, r->operation(NodeKind::mul, x0, x1), r->constant(3.0));
  r->store(r->access(x, 1), sum);
  r->store(r->access(x, 2), r->operation(NodeKind::div, sum, x0));
  return r;
}

t800::ProcessorConfig of_type(t800::ProcessorType type) {
  t800::ProcessorConfig config;
  config.type = type;
  return config;
}

// The instructions a unit executes, as assembly text.
std::vector<std::string> code_text(const t800::codegen::CodeUnit& unit) {
  std::vector<std::string> text;
  for (const auto& run : unit.runs)
    for (const auto& instruction : run.code) text.push_back(t800::isa::assembly(instruction));
  return text;
}

TEST(CodeCache, AKernelIsCompiledOncePerTargetAndTimedAsIfAlone) {
  const auto k = kernel();
  const auto shared = std::make_shared<t800::CodeCache>();
  const t800::ComputeSettings settings;
  const t800::ComputeModel t800_a(of_type(t800::ProcessorType::T800_20), settings, shared);
  const t800::ComputeModel t800_b(of_type(t800::ProcessorType::T800_20), settings, shared);
  const t800::ComputeModel t414(of_type(t800::ProcessorType::T414_20), settings, shared);
  EXPECT_EQ(&t800_a.code(k), &t800_b.code(k));  // one compilation for both
  EXPECT_NE(&t800_a.code(k), &t414.code(k));    // a T414 has no FPU: its own code
  for (t800::ProcessorType type : {t800::ProcessorType::T800_20, t800::ProcessorType::T414_20}) {
    const t800::ComputeModel with_cache(of_type(type), settings, shared);
    const t800::ComputeModel alone(of_type(type), settings);
    EXPECT_EQ(code_text(with_cache.code(k)),
              code_text(t800::codegen::generate(*k, with_cache.target())));
    EXPECT_EQ(with_cache.cycles({{}, k}), alone.cycles({{}, k}));
  }
}

}  // namespace
