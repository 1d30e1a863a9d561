// What a channel carries: occam's protocols, as C++ types, and the bytes each value takes on the
// wire by occam's rules (the occam 2 reference manual: a protocol's items are sent one after the
// other; a counted array sends its count, then that many elements; a variant protocol sends its
// tag, a BYTE, then the case's items).
//
//   occam                              t800sim                                  value in C++
//   CHAN OF REAL32 c:                  Chan<REAL32>                              float
//   CHAN OF [6]REAL32 c:               Chan<Array<REAL32, 6>>                    std::array<float,
//   6> CHAN OF INT::[]REAL32 c:           Chan<Counted<INT, REAL32>> std::vector<float> PROTOCOL P
//   IS INT; REAL64:         Chan<Sequential<INT, REAL64>>             std::tuple<int32_t, double>
//   PROTOCOL Q CASE data; REAL32       Chan<Variant<Case<REAL32>, Case<>>>
//   std::variant<Case<REAL32>,
//                   stop Case<>>
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

namespace t800sim {

// occam's primitive types.
using BOOL = bool;
using BYTE = std::uint8_t;
using INT16 = std::int16_t;
using INT = std::int32_t;  // a T800's word
using INT32 = std::int32_t;
using INT64 = std::int64_t;
using REAL32 = float;
using REAL64 = double;

template <class T, std::size_t N>
struct Array {};  // [N]T
template <class Count, class T>
struct Counted {};  // Count::[]T
template <class... Items>
struct Sequential {};  // Items; ...
// One case of a variant protocol: its items (none for a bare tag).
template <class... Items>
struct Case {
  std::tuple<Items...> items;
};
template <class... Cases>
struct Variant {};  // CASE ...

template <class P, class Enable = void>
struct protocol;  // how a protocol's values are held and how many bytes they take on the wire

namespace detail {
template <class T>
constexpr bool is_primitive = std::is_arithmetic_v<T>;
}

template <class T>
struct protocol<T, std::enable_if_t<detail::is_primitive<T>>> {
  using value_type = T;
  static std::int64_t bytes(const value_type&) {
    return std::is_same_v<T, bool> ? 1 : std::int64_t(sizeof(T));
  }
};

template <class T, std::size_t N>
struct protocol<Array<T, N>> {
  using value_type = std::array<typename protocol<T>::value_type, N>;
  static std::int64_t bytes(const value_type& v) {
    std::int64_t n = 0;
    for (const auto& x : v) n += protocol<T>::bytes(x);
    return n;
  }
};

template <class Count, class T>
struct protocol<Counted<Count, T>> {
  static_assert(std::is_integral_v<Count>, "a counted array's count is an integer type");
  using value_type = std::vector<typename protocol<T>::value_type>;
  static std::int64_t bytes(const value_type& v) {
    std::int64_t n = protocol<Count>::bytes(Count(0));
    for (const auto& x : v) n += protocol<T>::bytes(x);
    return n;
  }
};

template <class... Items>
struct protocol<Sequential<Items...>> {
  using value_type = std::tuple<typename protocol<Items>::value_type...>;
  static std::int64_t bytes(const value_type& v) {
    return std::apply(
        [](const auto&... x) { return (std::int64_t(0) + ... + protocol<Items>::bytes(x)); }, v);
  }
};

template <class... Items>
struct protocol<Case<Items...>> {
  using value_type = Case<Items...>;
  static std::int64_t bytes(const value_type& c) {
    return std::apply(
        [](const auto&... x) { return (std::int64_t(0) + ... + protocol<Items>::bytes(x)); },
        c.items);
  }
};

template <class... Cases>
struct protocol<Variant<Cases...>> {
  static_assert(sizeof...(Cases) <= 256, "a variant protocol's tag is a BYTE");
  using value_type = std::variant<Cases...>;
  static std::int64_t bytes(const value_type& v) {
    return 1 + std::visit(
                   [](const auto& c) { return protocol<std::decay_t<decltype(c)>>::bytes(c); }, v);
  }
};

template <class P>
using value_of = typename protocol<P>::value_type;

// The bytes value `v` takes on a channel of protocol P.
template <class P>
std::int64_t wire_bytes(const value_of<P>& v) {
  return protocol<P>::bytes(v);
}

}  // namespace t800sim
