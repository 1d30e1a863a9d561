// The occam structure numerical kernels mark, so that the code generator can compile them as
// occam would: replicated SEQs and declared arrays. For plain float/double kernels these cost
// nothing; for the instrumented scalar (dynamics::Counted) they tally loops for the op-count
// model and mark the recording for the instruction-level one.
//
//   for (std::size_t j : occam::seq<S>(n)) out[j] = row[j + 1] - m * pivot[j];   // SEQ j = 0 FOR n
//   occam::declare(out, "out");  // out's elements are an array: assigning one is a store
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "t800/codegen/recording.hpp"
#include "workloads/dynamics/counted.hpp"

namespace occam {

// Loops and iterations of replicated SEQs run while it is alive (per thread; nests).
class LoopTally {
 public:
  LoopTally() : outer_(active()) { active() = this; }
  ~LoopTally() { active() = outer_; }
  LoopTally(const LoopTally&) = delete;
  LoopTally& operator=(const LoopTally&) = delete;

  long loops() const { return loops_; }
  long iterations() const { return iterations_; }
  static LoopTally* current() { return active(); }
  void loop() { ++loops_; }
  void iteration() { ++iterations_; }

 private:
  static LoopTally*& active() {
    thread_local LoopTally* tally = nullptr;
    return tally;
  }
  long loops_ = 0, iterations_ = 0;
  LoopTally* outer_;
};

// SEQ i = first FOR count, as a C++ range: each iteration begins when the loop variable is read.
// The variable is a std::size_t (for x[i]), or an INT (dynamics::CountedInt, t800sim::Int) that the
// recording holds as the loop's index, so that what is computed from it (at(x, 2 * i), a
// conversion to REAL) is the same code in every iteration:
//   for (std::size_t i : seq<S>(n)) ...       for (Int i : seq<S>(n)) at(re, i * s) = ...
// A first index or count given as an INT of the kernel's (a variable, an expression: SEQ j = k FOR
// n - k) is one the PROC computes when it runs, not one the compiler knows: the code sets the
// control block from it and tests the count, and subscripts by the index are range-checked
// (docs/kernels.md, "Loops").
template <class S>
class Seq {
  static constexpr bool kInstrumented = dynamics::is_counted_v<S>;

 public:
  Seq(std::size_t first, std::size_t count) : first_(first), count_(count) { begin({}); }
  Seq(const dynamics::CountedInt& first, const dynamics::CountedInt& count)
      : first_(checked_bound(first, "first index")), count_(checked_bound(count, "count")) {
    t800::codegen::LoopBounds bounds;
    if constexpr (kInstrumented) {
      if (auto* r = t800::codegen::Recording::current()) {
        bounds.first = unless_constant(*r, first);
        bounds.count = unless_constant(*r, count);
      }
    }
    begin(bounds);
  }
  ~Seq() {
    if constexpr (kInstrumented) {
      if (auto* r = t800::codegen::Recording::current()) r->loop_end();
    }
  }
  Seq(const Seq&) = delete;
  Seq& operator=(const Seq&) = delete;

  // One iteration's value of the loop's variable.
  class Index {
   public:
    Index(std::size_t i, int depth) : i_(i), depth_(depth) {}
    operator std::size_t() const { return i_; }  // NOLINT(google-explicit-constructor)
    operator dynamics::CountedInt() const {      // NOLINT(google-explicit-constructor)
      const auto i = std::int32_t(i_);
      if constexpr (kInstrumented) {
        auto* r = t800::codegen::Recording::current();
        if (r && depth_ >= 0 && depth_ < r->loop_depth())
          return dynamics::CountedInt::recorded(i, r->loop_index(depth_));
      }
      return dynamics::CountedInt(i);
    }

   private:
    std::size_t i_;
    int depth_;
  };

  class iterator {
   public:
    iterator(std::size_t i, int depth) : i_(i), depth_(depth) {}
    Index operator*() const {
      if constexpr (kInstrumented) {
        if (LoopTally* t = LoopTally::current()) t->iteration();
        if (auto* r = t800::codegen::Recording::current()) r->iteration(std::int64_t(i_));
      }
      return Index(i_, depth_);
    }
    iterator& operator++() {
      ++i_;
      return *this;
    }
    bool operator!=(const iterator& o) const { return i_ != o.i_; }

   private:
    std::size_t i_;
    int depth_;
  };
  iterator begin() const { return iterator(first_, depth_); }
  iterator end() const { return iterator(first_ + count_, depth_); }

 private:
  void begin(const t800::codegen::LoopBounds& bounds) {
    if constexpr (kInstrumented) {
      if (LoopTally* t = LoopTally::current()) t->loop();
      if (auto* r = t800::codegen::Recording::current()) {
        r->loop_begin(bounds);
        depth_ = r->loop_depth() - 1;
      }
    }
  }
  // occam stops a SEQ whose count is negative (the compiler's count check); a negative first
  // index has no std::size_t loop variable to be.
  static std::size_t checked_bound(const dynamics::CountedInt& v, const char* what) {
    if (v.value() < 0)
      throw std::out_of_range(std::string("SEQ with the negative ") + what + " " +
                              std::to_string(v.value()));
    return std::size_t(v.value());
  }
  static int unless_constant(t800::codegen::Recording& r, const dynamics::CountedInt& v) {
    const int node = dynamics::CountedInt::node_of(r, v);
    return r.nodes()[std::size_t(node)].kind == t800::codegen::NodeKind::constant ? -1 : node;
  }

  std::size_t first_, count_;
  int depth_ = -1;  // in the recording, when one is active
};

template <class S>
Seq<S> seq(std::size_t count) {
  return Seq<S>(0, count);
}
template <class S>
Seq<S> seq(std::size_t first, std::size_t count) {
  return Seq<S>(first, count);
}
template <class S>
Seq<S> seq(const dynamics::CountedInt& count) {
  return Seq<S>(dynamics::CountedInt(0), count);
}
template <class S>
Seq<S> seq(const dynamics::CountedInt& first, const dynamics::CountedInt& count) {
  return Seq<S>(first, count);
}

// What an array of S holds in the recording: INTs (t800sim::Int) or REALs.
template <class S>
constexpr t800::codegen::ElementType element_type() {
  return std::is_integral_v<typename S::value_type> ? t800::codegen::ElementType::int32
                                                    : t800::codegen::ElementType::real;
}

// Makes values an array of the active recording: reading an element is a load, assigning one a
// store. `in_workspace`: a small local array in the PROC's workspace rather than one reached
// through a pointer (a parameter or vector space).
template <class S>
void declare(S* values, std::size_t count, const char* name, bool in_workspace = false) {
  if constexpr (dynamics::is_counted_v<S>) {
    auto* r = t800::codegen::Recording::current();
    if (!r) return;
    const int array = r->declare_array(name, std::int64_t(count),
                                       in_workspace ? t800::codegen::ArrayStorage::workspace
                                                    : t800::codegen::ArrayStorage::pointer,
                                       element_type<S>());
    for (std::size_t i = 0; i < count; ++i) values[i].bind(r->access(array, std::int64_t(i)));
  }
}
template <class S>
void declare(std::vector<S>& values, const char* name, bool in_workspace = false) {
  declare(values.data(), values.size(), name, in_workspace);
}
template <class S, std::size_t N>
void declare(std::array<S, N>& values, const char* name, bool in_workspace = false) {
  declare(values.data(), N, name, in_workspace);
}
// Scattered values (the fields of a message struct) as one array, in the order given.
template <class S>
void declare_each(const std::vector<S*>& elements, const char* name) {
  if constexpr (dynamics::is_counted_v<S>) {
    auto* r = t800::codegen::Recording::current();
    if (!r) return;
    const int array = r->declare_array(name, std::int64_t(elements.size()),
                                       t800::codegen::ArrayStorage::pointer, element_type<S>());
    for (std::size_t i = 0; i < elements.size(); ++i)
      elements[i]->bind(r->access(array, std::int64_t(i)));
  }
}

// A scalar variable of the PROC's workspace.
template <class S>
void declare_variable(S& variable, const char* name) {
  declare(&variable, 1, name, true);
}

// A count the PROC holds in an INT variable rather than one the compiler knows: a row's length
// where one PROC serves rows of every length. seq<S>(n) of it is SEQ j = 0 FOR n with n a
// variable; for a scalar that records nothing, the number itself.
//   const occam::CountVariable<S> n(row.size(), "n");
//   for (std::size_t j : occam::seq<S>(n)) ...
template <class S>
class CountVariable {
 public:
  CountVariable(std::size_t n, const char* name) : n_(n), variable_(std::int32_t(n)) {
    if constexpr (dynamics::is_counted_v<S>) declare_variable(variable_, name);
  }
  CountVariable(const CountVariable&) = delete;  // declared where it lives
  std::size_t value() const { return n_; }
  const dynamics::CountedInt& variable() const { return variable_; }

 private:
  std::size_t n_;
  dynamics::CountedInt variable_;
};
template <class S>
Seq<S> seq(std::size_t first, const CountVariable<S>& count) {
  if constexpr (dynamics::is_counted_v<S>)
    return Seq<S>(dynamics::CountedInt(std::int32_t(first)), count.variable());
  else
    return Seq<S>(first, count.value());
}
template <class S>
Seq<S> seq(const CountVariable<S>& count) {
  return seq<S>(0, count);
}

// Integer statements occam would compile where the kernel says (tests on integers, assignments,
// the FPU error flag's test): recorded, never counted here (kernels count their integer work).
template <class S>
void integer(t800::codegen::IntegerStatement statement, long count = 1) {
  if constexpr (dynamics::is_counted_v<S>) {
    if (auto* r = t800::codegen::Recording::current()) r->integer(statement, count);
  }
}

}  // namespace occam
