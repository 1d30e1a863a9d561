#include "workloads/dynamics/subtask.hpp"

#include <fmt/format.h>

#include "workloads/dynamics/robot_model.hpp"

namespace dynamics {

Subtask Subtask::inertia(int i, int j) {
  return {TermKind::inertia, i, j, 0, fmt::format("D{}{}", i + 1, j + 1)};
}

Subtask Subtask::coriolis(int i, int j, int k) {
  return {TermKind::coriolis, i, j, k, fmt::format("C{}_{}{}", i + 1, j + 1, k + 1)};
}

Subtask Subtask::gravity(int i) {
  return {TermKind::gravity, i, 0, 0, fmt::format("h{}", i + 1)};
}

bool operator==(const Subtask& a, const Subtask& b) {
  return a.kind == b.kind && a.i == b.i && a.j == b.j && a.k == b.k;
}

const char* to_string(TermKind kind) {
  switch (kind) {
    case TermKind::inertia:
      return "D";
    case TermKind::coriolis:
      return "C";
    case TermKind::gravity:
      return "h";
  }
  return "?";
}

std::vector<Subtask> all_terms() {
  std::vector<Subtask> terms;
  for (int i = 0; i < kJoints; ++i) {
    for (int j = i; j < kJoints; ++j) terms.push_back(Subtask::inertia(i, j));
  }
  for (int i = 0; i < kJoints; ++i) {
    for (int j = 0; j < kJoints; ++j) {
      for (int k = j; k < kJoints; ++k) terms.push_back(Subtask::coriolis(i, j, k));
    }
  }
  for (int i = 0; i < kJoints; ++i) terms.push_back(Subtask::gravity(i));
  return terms;
}

}  // namespace dynamics
