// The zero analysis's shared-chain evaluation against the worker's kernel (evaluate_term), term by
// term: the same value to the bit and the same structure, for every term of each robot in
// configs/robots at configurations drawn inside its joint limits. Any difference could change
// which subtasks a farm runs.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <random>

#include "dynamics_fixtures.hpp"
#include "tests/test_paths.hpp"
#include "workloads/dynamics/evaluate.hpp"
#include "workloads/dynamics/term_sweep.hpp"

namespace dynamics {
namespace {

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expect_kernel_values(const RobotModel& model, const std::string& name) {
  std::mt19937_64 rng(2024);
  const std::vector<Subtask> terms = all_terms();
  for (int sample = 0; sample < 16; ++sample) {
    const auto input = make_worker_input<double>(model, random_configuration(model, rng));
    const std::vector<Folded<double>> swept = evaluate_terms(model, terms, input);
    ASSERT_EQ(swept.size(), terms.size());
    for (std::size_t t = 0; t < terms.size(); ++t) {
      const Folded<double> kernel = evaluate_term(model, terms[t], input);
      EXPECT_EQ(swept[t].kind(), kernel.kind()) << name << " " << terms[t].name;
      EXPECT_TRUE(same_bits(swept[t].value(), kernel.value()))
          << name << " " << terms[t].name << ": " << swept[t].value() << " vs " << kernel.value();
    }
  }
}

TEST(TermSweep, EveryTermOfEveryRobotIsTheKernelsValueToTheBit) {
  int robots = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(test_paths::source_dir() + "/configs/robots")) {
    if (entry.path().extension() != ".toml") continue;
    expect_kernel_values(tools::load_robot(entry.path().string()), entry.path().filename());
    ++robots;
  }
  EXPECT_GE(robots, 2);  // the Stanford arm and at least one other
}

// A prismatic joint, zero offsets and a zero inertia component exercise the structural zeros.
TEST(TermSweep, StructuralZerosOfAModifiedArmAgree) {
  RobotModel model = testing::stanford();
  model.joints[kJoints - 1].link.inertia.z() = 0;
  model.joints[1].dh.a = 0;
  expect_kernel_values(model, "modified stanford");
}

}  // namespace
}  // namespace dynamics
