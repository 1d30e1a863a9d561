// A subtask: one term of the dynamics that one worker computes on its own: D_ij (i <= j),
// C_ijk (j <= k) or h_i.
#pragma once

#include <string>
#include <vector>

namespace dynamics {

enum class TermKind { inertia, coriolis, gravity };  // D, C, h

struct Subtask {
  TermKind kind = TermKind::inertia;
  int i = 0;  // 0-based joint indices: D_ij uses i, j; C_ijk uses i, j, k; h_i uses i
  int j = 0;
  int k = 0;
  std::string name;  // 1-based, as the paper writes them: "D12", "C1_23", "h2"

  static Subtask inertia(int i, int j);
  static Subtask coriolis(int i, int j, int k);
  static Subtask gravity(int i);
};

bool operator==(const Subtask& a, const Subtask& b);

const char* to_string(TermKind kind);

// Every term a six-joint arm has, before any zero is removed: 21 D, 126 C, 6 h, in this order.
std::vector<Subtask> all_terms();

}  // namespace dynamics
