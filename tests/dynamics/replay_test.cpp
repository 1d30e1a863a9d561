// The traced replay of a subtask (the farm's host-side evaluation) against the worker's kernel
// (evaluate_subtask): the same bits (or both NaN) for every term of each robot in configs/robots,
// in float and double, at configurations inside the joint limits and at messages no configuration
// gives (a corrupted message: NaN, infinities, signed zeros, subnormals), and for a short message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>

#include "dynamics_fixtures.hpp"
#include "workloads/dynamics/evaluate.hpp"
#include "workloads/dynamics/replay.hpp"

namespace dynamics {
namespace {

// The same bits, or both NaN: a NaN's sign and payload depend on how the compiler ordered the
// kernel's commutative operands (the farm takes a NaN from the kernel itself, farm_program.cpp).
template <class T>
bool same_value(T a, T b) {
  return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
}

template <class T>
std::vector<T> message_of(const RobotModel& model, WorkerInput<T> input) {
  std::vector<T> message;
  for (T* field : message_fields(model, input)) message.push_back(*field);
  return message;
}

template <class T>
WorkerInput<T> input_of(const RobotModel& model, const std::vector<T>& message) {
  WorkerInput<T> input;
  const std::vector<T*> fields = message_fields(model, input);
  for (std::size_t i = 0; i < fields.size() && i < message.size(); ++i) *fields[i] = message[i];
  return input;
}

// Messages to replay: from configurations, then with one field replaced by an odd value.
template <class T>
std::vector<std::vector<T>> messages(const RobotModel& model) {
  std::mt19937_64 rng(7800);
  std::vector<std::vector<T>> all;
  for (int sample = 0; sample < 8; ++sample)
    all.push_back(message_of(model, make_worker_input<T>(model, random_configuration(model, rng))));
  using limits = std::numeric_limits<T>;
  const T odd[] = {limits::quiet_NaN(),
                   -limits::quiet_NaN(),
                   limits::infinity(),
                   -limits::infinity(),
                   T(0),
                   -T(0),
                   limits::denorm_min(),
                   limits::max()};
  const std::vector<T> base = all.front();
  for (std::size_t field = 0; field < base.size(); ++field) {
    for (T value : odd) {
      all.push_back(base);
      all.back()[field] = value;
    }
  }
  all.push_back(std::vector<T>(base.begin(), base.begin() + 3));  // the rest: defaults
  return all;
}

template <class T>
void expect_kernel_bits(const RobotModel& model, const std::string& name) {
  const std::vector<std::vector<T>> inputs = messages<T>(model);
  for (const Subtask& task : all_terms()) {
    const SubtaskReplay<T> replay(model, task);
    for (const std::vector<T>& message : inputs) {
      const T kernel = evaluate_subtask(model, task, input_of(model, message));
      const T replayed = replay(message);
      EXPECT_TRUE(same_value(kernel, replayed))
          << name << " " << task.name << ": " << kernel << " vs " << replayed;
    }
  }
}

TEST(SubtaskReplay, EveryTermOfEveryRobotIsTheKernelsValueToTheBit) {
  int robots = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(T800SIM_SOURCE_DIR) + "/configs/robots")) {
    if (entry.path().extension() != ".toml") continue;
    const RobotModel model = tools::load_robot(entry.path().string());
    expect_kernel_bits<float>(model, entry.path().filename());
    expect_kernel_bits<double>(model, entry.path().filename());
    ++robots;
  }
  EXPECT_GE(robots, 2);
}

// A prismatic joint, zero offsets and a zero inertia component exercise the structural zeros; a
// twist that is no multiple of 90 degrees and a prismatic joint with a theta offset give operations
// on two constants (folded while tracing).
TEST(SubtaskReplay, ModifiedArmsAgree) {
  RobotModel model = testing::stanford();
  model.joints[kJoints - 1].link.inertia.z() = 0;
  model.joints[1].dh.a = 0;
  expect_kernel_bits<float>(model, "modified stanford");
  model.joints[2].dh.theta = 0.3;
  model.joints[3].dh.alpha = 0.7;
  model.joints[4].dh.a = 0.05;
  expect_kernel_bits<float>(model, "skewed stanford");
  expect_kernel_bits<double>(model, "skewed stanford");
}

// A term the model's constants make zero is a constant: nothing is replayed.
TEST(SubtaskReplay, StructuralZeroTermsAreConstants) {
  const RobotModel& model = testing::stanford();
  for (const Subtask& task : all_terms()) {
    const SubtaskReplay<float> replay(model, task);
    const WorkerInput<float> input = make_worker_input<float>(model, mid_configuration(model));
    if (evaluate_term(model, task, input).is_zero()) {
      EXPECT_EQ(replay.operations(), 0u) << task.name;
    }
  }
}

}  // namespace
}  // namespace dynamics
