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
#include "tests/test_paths.hpp"
#include "workloads/dynamics/evaluate.hpp"
#include "workloads/dynamics/replay.hpp"
#include "workloads/dynamics/subtask_set.hpp"

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

// All the terms replayed together (sharing what their kernels compute alike), and one alone.
template <class T>
void expect_kernel_bits(const RobotModel& model, const std::string& name) {
  const std::vector<std::vector<T>> inputs = messages<T>(model);
  const std::vector<Subtask> tasks = all_terms();
  const SubtaskReplay<T> together(model, tasks);
  for (const std::vector<T>& message : inputs) {
    const std::vector<T>& replayed = together(message);
    ASSERT_EQ(replayed.size(), tasks.size());
    for (std::size_t t = 0; t < tasks.size(); ++t) {
      const T kernel = evaluate_subtask(model, tasks[t], input_of(model, message));
      EXPECT_TRUE(same_value(kernel, replayed[t]))
          << name << " " << tasks[t].name << ": " << kernel << " vs " << replayed[t];
    }
  }
  const Subtask& last = tasks.back();
  const SubtaskReplay<T> alone(model, {last});
  for (const std::vector<T>& message : inputs) {
    const T kernel = evaluate_subtask(model, last, input_of(model, message));
    EXPECT_TRUE(same_value(kernel, alone(message).front())) << name << " " << last.name;
  }
}

TEST(SubtaskReplay, EveryTermOfEveryRobotIsTheKernelsValueToTheBit) {
  int robots = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(test_paths::source_dir() + "/configs/robots")) {
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
  const WorkerInput<float> input = make_worker_input<float>(model, mid_configuration(model));
  for (const Subtask& task : all_terms()) {
    if (!evaluate_term(model, task, input).is_zero()) continue;
    const SubtaskReplay<float> replay(model, {task});
    EXPECT_EQ(replay.operations(), 0u) << task.name;
    EXPECT_TRUE(same_value(replay(message_of(model, input)).front(), 0.0f)) << task.name;
  }
}

// The values are kept for one message only: another message, even one differing from it only in a
// zero's sign, is replayed.
TEST(SubtaskReplay, AnotherMessageIsReplayedAgain) {
  const RobotModel& model = testing::stanford();
  const std::vector<Subtask> tasks = derive_subtasks(model, ModelVariant::full);
  const SubtaskReplay<float> replay(model, tasks);
  std::vector<float> first = messages<float>(model).front(), second = first, third = first;
  first[1] = 0.0f;
  second[1] = -0.0f;
  third[1] = 0.5f;
  for (const std::vector<float>* message : {&first, &third, &first, &second, &third, &second}) {
    const std::vector<float> values = replay(*message);
    for (std::size_t t = 0; t < tasks.size(); ++t) {
      const float kernel = evaluate_subtask(model, tasks[t], input_of(model, *message));
      EXPECT_TRUE(same_value(kernel, values[t])) << tasks[t].name;
    }
  }
}

}  // namespace
}  // namespace dynamics
