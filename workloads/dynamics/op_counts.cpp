#include "workloads/dynamics/op_counts.hpp"

#include <fmt/format.h>

namespace dynamics {

std::string to_string(const OpCounts& counts) {
  const std::pair<const char*, long> fields[] = {
      {"fadd", counts.fadd},       {"fmul", counts.fmul},       {"fdiv", counts.fdiv},
      {"fsqrt", counts.fsqrt},     {"fsincos", counts.fsincos}, {"fcompare", counts.fcompare},
      {"fload", counts.fload},     {"fstore", counts.fstore},   {"int_ops", counts.int_ops},
      {"int_mul", counts.int_mul}, {"int_div", counts.int_div}};
  std::string text;
  for (const auto& [name, value] : fields) {
    if (value == 0) continue;
    if (!text.empty()) text += ' ';
    text += fmt::format("{}={}", name, value);
  }
  return text.empty() ? "none" : text;
}

}  // namespace dynamics
