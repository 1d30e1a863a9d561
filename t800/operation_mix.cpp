#include "t800/operation_mix.hpp"

#include <tuple>

namespace t800 {

namespace {
auto fields(const OperationMix& m) {
  return std::tie(m.int_simple, m.word_loads, m.word_stores, m.int_mul, m.int_div, m.branches,
                  m.loop_ends, m.calls, m.prefixes, m.fp_add, m.fp_mul, m.fp_div, m.fp_sqrt,
                  m.fp_compare, m.fp_loads, m.fp_stores, m.sincos);
}
auto fields(OperationMix& m) {
  return std::tie(m.int_simple, m.word_loads, m.word_stores, m.int_mul, m.int_div, m.branches,
                  m.loop_ends, m.calls, m.prefixes, m.fp_add, m.fp_mul, m.fp_div, m.fp_sqrt,
                  m.fp_compare, m.fp_loads, m.fp_stores, m.sincos);
}
}  // namespace

OperationMix& OperationMix::operator+=(const OperationMix& o) {
  std::apply([&](auto&... a) { std::apply([&](const auto&... b) { ((a += b), ...); }, fields(o)); },
             fields(*this));
  return *this;
}

OperationMix OperationMix::operator*(std::int64_t n) const {
  OperationMix r = *this;
  std::apply([&](auto&... a) { ((a *= n), ...); }, fields(r));
  return r;
}

bool OperationMix::operator==(const OperationMix& o) const {
  return fields(*this) == fields(o);
}

}  // namespace t800
