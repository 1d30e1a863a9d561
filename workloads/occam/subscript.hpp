// Subscripts the kernel computes, recorded as it computes them: at(x, k) is occam's x[k] for an
// INT k (t800sim::Int), whether k is an expression of the kernel's (k + (2 * h) * b), a value read
// from an array (x[perm[i]]) or a variable. The code then computes the subscript, checks it
// against the array's bound and indexes the array with it (wsub, wsubdb), instead of the
// generator's reading the subscript off the addresses a run touched (subscripts.hpp). A subscript
// that is a constant (a literal, a value computed from constants only) is the element itself.
//
//   y[i] = y[i] + a * t800sim::at(x, perm[i]);        // y[i] := y[i] + (a * x[perm[i]])
//   t800sim::at(re, k + h) = t800sim::at(re, k) - t;  // re[k + h] := re[k] - t
//
// Out of the array's range, k is an error (std::out_of_range), as occam's range check stops the
// process. The array must be declared whole (occam::declare) in the recording that computes k.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "t800/codegen/recording.hpp"
#include "workloads/dynamics/counted.hpp"

namespace occam {

// x[k]: reading it is a load of x's element k at the computed subscript, assigning it a store.
template <class S>
class Element {
 public:
  // `access`: the subscripted access the element is read and written through, or -1 for the
  // element itself (a constant subscript, or no recording).
  Element(S& element, int access) : element_(element), subscripted_(access >= 0) {
    if constexpr (dynamics::is_counted_v<S>) {
      if (subscripted_) {
        view_ = S(element.value());
        view_.bind(access);
      }
    }
  }
  Element(const Element&) = delete;  // a copy of view_ would be a value, not the element

  operator S() const { return subscripted_ ? view_ : element_; }  // NOLINT: x[k] is a value
  Element& operator=(const S& value) {
    if constexpr (dynamics::is_counted_v<S>) {
      if (subscripted_) {
        view_ = value;  // the store, through the subscripted access
        element_.set_value_unrecorded(value.value());
        return *this;
      }
    }
    element_ = value;
    return *this;
  }
  Element& operator=(const Element& other) { return *this = S(other); }

 private:
  S& element_;
  bool subscripted_;
  S view_{};  // bound to the subscripted access (a copy would be a value: bind, never copy it)
};

namespace detail {

[[noreturn]] inline void out_of_range(std::int64_t k, std::size_t count, const std::string& name) {
  throw std::out_of_range("subscript " + std::to_string(k) + " of " +
                          (name.empty() ? std::string("an array") : name) +
                          " is out of its range 0.." + std::to_string(std::int64_t(count) - 1) +
                          " (occam's range check)");
}

template <class S>
Element<S> element_at(S* values, std::size_t count, const dynamics::CountedInt& k) {
  const std::int64_t index = k.value();
  using t800::codegen::KernelError;
  using t800::codegen::Recording;
  Recording* r = Recording::current();
  if constexpr (dynamics::is_counted_v<S>) {
    std::string name;
    const int home = count > 0 ? values[0].home() : -1;
    if (r && home >= 0 && values[0].belongs_to(*r))
      name = r->arrays()[std::size_t(r->accesses()[std::size_t(home)].array)].name;
    if (index < 0 || index >= std::int64_t(count)) out_of_range(index, count, name);
    S& element = values[std::size_t(index)];
    if (!r) return Element<S>(element, -1);
    const int subscript = dynamics::CountedInt::node_of(*r, k);
    if (r->nodes()[std::size_t(subscript)].kind == t800::codegen::NodeKind::constant)
      return Element<S>(element, -1);  // x[3]: the element itself
    if (name.empty() || !element.belongs_to(*r) ||
        r->accesses()[std::size_t(element.home())].index != index)
      throw KernelError("kernel \"" + r->name() +
                        "\": at(x, k) with a computed k needs x declared whole in this kernel "
                        "(occam::declare, t800sim::declare)");
    const int array = r->accesses()[std::size_t(element.home())].array;
    if (r->arrays()[std::size_t(array)].length != std::int64_t(count))
      throw KernelError("kernel \"" + r->name() + "\": at(" + name + ", k) is given " +
                        std::to_string(count) + " elements of " + name + "'s " +
                        std::to_string(r->arrays()[std::size_t(array)].length) +
                        ": subscript the array as it was declared");
    return Element<S>(element, r->subscripted(array, subscript, index));
  } else {
    if (index < 0 || index >= std::int64_t(count)) out_of_range(index, count, {});
    return Element<S>(values[std::size_t(index)], -1);
  }
}

}  // namespace detail

template <class S>
Element<S> at(std::vector<S>& values, const dynamics::CountedInt& k) {
  return detail::element_at(values.data(), values.size(), k);
}
template <class S, std::size_t N>
Element<S> at(std::array<S, N>& values, const dynamics::CountedInt& k) {
  return detail::element_at(values.data(), N, k);
}

}  // namespace occam
