// What a channel carries: occam's protocols as C++ types, how a value of each travels, and the
// bytes it takes on the wire -- by occam's rules (occam 2 reference manual, "Protocols"): the
// items of a sequential protocol are communicated one after the other, each its own input and
// output; a counted array sends its count, then that many elements; a variant protocol sends its
// tag, a BYTE, then the case's items. A single item (a primitive, or an array of them) is one
// communication of all its bytes. A packed protocol is several items laid out in one buffer and
// sent as one communication, as occam programs send a header word and a row together (a buffer
// slice on a CHAN OF ANY, or an occam 2.1 RECORD); two kinds of message told apart by a flag in
// that header are the program's values, not a tag byte.
//
// clang-format off
//   occam                                 t800sim                                value in C++
//   CHAN OF REAL32 c:                     Chan<REAL32>                           float
//   CHAN OF [6]REAL32 c:                  Chan<Array<REAL32, 6>>                 std::array<float, 6>
//   CHAN OF INT::[]REAL32 c:              Chan<Counted<INT, REAL32>>             std::vector<float>
//   CHAN OF ANY c: c ! [b FROM 0 FOR n]   Chan<Block<BYTE>>                      std::vector<uint8_t>
//   PROTOCOL P IS INT; REAL64:            Chan<Sequential<INT, REAL64>>          std::tuple<int32_t, double>
//   CHAN OF ANY c: c ! [buf FROM 0 FOR n]
//     (an INT header, then n-1 REAL32s)   Chan<Packed<INT, Block<REAL32>>>       std::tuple<int32_t, std::vector<float>>
//   PROTOCOL Q CASE data; REAL32 | stop   Chan<Variant<Case<REAL32>, Case<>>>    std::variant<Case<REAL32>, Case<>>
//   CHAN OF ANY c: c ! finish (an INT)
//     or c ! [m FROM 0 FOR n] (REAL32s)   Chan<Untagged<INT, Block<REAL32>>>     std::variant<int32_t, std::vector<float>>
// clang-format on
#pragma once

#include <any>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <typeinfo>
#include <utility>
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
// A block of elements whose length both ends know (occam's `c ! [buffer FROM 0 FOR n]` on a
// CHAN OF ANY): one communication, no count sent.
template <class T>
struct Block {};
template <class... Items>
struct Sequential {};  // Items; ...
// Items laid out one after the other in one buffer: ONE communication of all their bytes.
template <class... Items>
struct Packed {};
// protocol<P>: value_type (what a program sends and receives), bytes(v) (the bytes on the wire),
// name() (as occam would write it), send/receive (the communications, in occam's order).
template <class P, class Enable = void>
struct protocol;

// One case of a variant protocol: the values of its items (none for a bare tag), as a sequential
// protocol of the same items holds them (a counted array's is a std::vector).
template <class... Items>
struct Case {
  std::tuple<typename protocol<Items>::value_type...> items;
  friend bool operator==(const Case& a, const Case& b) { return a.items == b.items; }
  friend bool operator!=(const Case& a, const Case& b) { return !(a == b); }
};
template <class... Cases>
struct Variant {};  // CASE ...

namespace detail {

// One end of a channel as a protocol sees it: a sequence of communications (occam's `!` and `?` of
// one item each). The simulator's channels implement it; values stay typed at both ends, the
// wire in between carries them opaquely.
class Wire {
 public:
  virtual ~Wire() = default;
  virtual void send(std::int64_t bytes, std::any value) = 0;
  virtual std::any receive() = 0;
  // A communication with a deadline gave up (Process::out_or_fail / in_or_fail): the wire's later
  // items are not communicated and receive() delivers nothing.
  virtual bool failed() const { return false; }
};

template <class T>
T take(Wire& w) {
  std::any value = w.receive();
  if (!value.has_value() && w.failed()) return T{};           // discarded by in_or_fail
  if (T* v = std::any_cast<T>(&value)) return std::move(*v);  // the wire's copy is ours
  throw std::logic_error("a channel delivered a value of another protocol");
}

// One communication of `bytes` carrying v, moved onto the wire. The byte count is taken first: the
// wire's argument may be built from v before another argument is evaluated.
template <class T>
void send_one(Wire& w, std::int64_t bytes, T&& v) {
  w.send(bytes, std::any(std::forward<T>(v)));
}

template <class T>
constexpr bool is_primitive = std::is_arithmetic_v<T>;

// Byte `byte` (0-based, little-endian as the T800 stores) of a plain value XORed with `mask`.
template <class T>
void flip_byte(T& value, std::int64_t byte, std::uint8_t mask) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  raw[byte] ^= mask;
  std::memcpy(&value, raw, sizeof(T));
}

// A link fault that changes a byte in flight changes the value the receiver reads: the simulator
// asks the value's type how (registered once per type; sdk/process.cpp).
using FlipValueByte = bool (*)(std::any& value, std::int64_t byte, std::uint8_t mask);
void register_value_bytes(const std::type_info& type, FlipValueByte flip);

template <class T>
const char* primitive_name() {
  if (std::is_same_v<T, bool>) return "BOOL";
  if (std::is_same_v<T, std::uint8_t>) return "BYTE";
  if (std::is_same_v<T, std::int16_t>) return "INT16";
  if (std::is_same_v<T, std::int32_t>) return "INT";
  if (std::is_same_v<T, std::int64_t>) return "INT64";
  if (std::is_same_v<T, float>) return "REAL32";
  if (std::is_same_v<T, double>) return "REAL64";
  return "?";
}

}  // namespace detail

template <class T>
struct protocol<T, std::enable_if_t<detail::is_primitive<T>>> {
  using value_type = T;
  static constexpr bool single = true;  // one communication
  static std::int64_t bytes(const value_type&) {
    return std::is_same_v<T, bool> ? 1 : std::int64_t(sizeof(T));
  }
  static std::string name() { return detail::primitive_name<T>(); }
  // A byte of the value on the wire changed (a link fault); false for a BOOL (not modelled).
  static bool flip(value_type& v, std::int64_t byte, std::uint8_t mask) {
    if (std::is_same_v<T, bool> || byte < 0 || byte >= std::int64_t(sizeof(T))) return false;
    detail::flip_byte(v, byte, mask);
    return true;
  }
  static void send(detail::Wire& w, value_type v) { detail::send_one(w, bytes(v), std::move(v)); }
  static value_type receive(detail::Wire& w) { return detail::take<value_type>(w); }
};

namespace detail {
// A byte of an array or block: it lands in the element at that offset.
template <class T, class Elements>
bool flip_element(Elements& v, std::int64_t byte, std::uint8_t mask) {
  for (auto& x : v) {
    const std::int64_t size = protocol<T>::bytes(x);
    if (byte < size) return protocol<T>::flip(x, byte, mask);
    byte -= size;
  }
  return false;
}
}  // namespace detail

template <class T, std::size_t N>
struct protocol<Array<T, N>> {
  static_assert(protocol<T>::single, "an array's elements are primitives or arrays of them");
  using value_type = std::array<typename protocol<T>::value_type, N>;
  static constexpr bool single = true;
  static std::int64_t bytes(const value_type& v) {
    std::int64_t n = 0;
    for (const auto& x : v) n += protocol<T>::bytes(x);
    return n;
  }
  static std::string name() { return "[" + std::to_string(N) + "]" + protocol<T>::name(); }
  static bool flip(value_type& v, std::int64_t byte, std::uint8_t mask) {
    return detail::flip_element<T>(v, byte, mask);
  }
  static void send(detail::Wire& w, value_type v) { detail::send_one(w, bytes(v), std::move(v)); }
  static value_type receive(detail::Wire& w) { return detail::take<value_type>(w); }
};

template <class T>
struct protocol<Block<T>> {
  static_assert(protocol<T>::single, "a block's elements are primitives or arrays of them");
  using value_type = std::vector<typename protocol<T>::value_type>;
  static constexpr bool single = true;
  static std::int64_t bytes(const value_type& v) {
    std::int64_t n = 0;
    for (const auto& x : v) n += protocol<T>::bytes(x);
    return n;
  }
  static std::string name() { return "ANY ([]" + protocol<T>::name() + ")"; }
  static bool flip(value_type& v, std::int64_t byte, std::uint8_t mask) {
    return detail::flip_element<T>(v, byte, mask);
  }
  static void send(detail::Wire& w, value_type v) { detail::send_one(w, bytes(v), std::move(v)); }
  static value_type receive(detail::Wire& w) { return detail::take<value_type>(w); }
};

// The count, then the elements (no second communication for an empty array).
template <class Count, class T>
struct protocol<Counted<Count, T>> {
  static_assert(std::is_integral_v<Count>, "a counted array's count is an integer type");
  static_assert(protocol<T>::single, "a counted array's elements are primitives or arrays of them");
  using value_type = std::vector<typename protocol<T>::value_type>;
  static constexpr bool single = false;
  static std::int64_t bytes(const value_type& v) {
    std::int64_t n = protocol<Count>::bytes(Count(0));
    for (const auto& x : v) n += protocol<T>::bytes(x);
    return n;
  }
  static std::string name() { return protocol<Count>::name() + "::[]" + protocol<T>::name(); }
  static void send(detail::Wire& w, value_type v) {
    protocol<Count>::send(w, Count(v.size()));
    if (!v.empty()) detail::send_one(w, bytes(v) - protocol<Count>::bytes(Count(0)), std::move(v));
  }
  static value_type receive(detail::Wire& w) {
    const auto count = protocol<Count>::receive(w);
    if (count <= 0) return {};
    auto v = detail::take<value_type>(w);
    if (v.size() != std::size_t(count))
      throw std::logic_error("a counted array's count and length differ");
    return v;
  }
};

template <class... Items>
struct protocol<Sequential<Items...>> {
  using value_type = std::tuple<typename protocol<Items>::value_type...>;
  static constexpr bool single = false;
  static std::int64_t bytes(const value_type& v) {
    return std::apply(
        [](const auto&... x) { return (std::int64_t(0) + ... + protocol<Items>::bytes(x)); }, v);
  }
  static std::string name() {
    std::string s;
    ((s += (s.empty() ? "" : "; ") + protocol<Items>::name()), ...);
    return s;
  }
  static void send(detail::Wire& w, value_type v) {
    std::apply([&w](auto&... x) { (protocol<Items>::send(w, std::move(x)), ...); }, v);
  }
  // Braced initialisation: the items are received in order.
  static value_type receive(detail::Wire& w) { return value_type{protocol<Items>::receive(w)...}; }
};

namespace detail {
// One communication of a whole value (a packed or untagged protocol's), the simulator told once per
// type how a link fault's changed byte lands in it (Protocol::flip).
template <class Protocol>
bool flip_whole(std::any& value, std::int64_t byte, std::uint8_t mask) {
  auto* v = std::any_cast<typename Protocol::value_type>(&value);
  return v && byte >= 0 && Protocol::flip(*v, byte, mask);
}
template <class Protocol>
void send_whole(Wire& w, typename Protocol::value_type v) {
  static const bool registered =
      (register_value_bytes(typeid(typename Protocol::value_type), &flip_whole<Protocol>), true);
  (void)registered;
  send_one(w, Protocol::bytes(v), std::move(v));
}
}  // namespace detail

// One communication of all the items' bytes, in order; a link fault's changed byte lands in the
// item (and element) at that offset.
template <class... Items>
struct protocol<Packed<Items...>> {
  static_assert(
      (protocol<Items>::single && ...),
      "a packed protocol's items are each one communication (primitives, arrays, blocks)");
  using value_type = std::tuple<typename protocol<Items>::value_type...>;
  static constexpr bool single = true;
  static std::int64_t bytes(const value_type& v) {
    return protocol<Sequential<Items...>>::bytes(v);
  }
  static std::string name() { return "ANY (" + protocol<Sequential<Items...>>::name() + ")"; }
  static bool flip(value_type& v, std::int64_t byte, std::uint8_t mask) {
    bool changed = false, done = false;
    std::apply(
        [&](auto&... x) {
          auto item = [&](auto& value, auto* item_protocol) {
            using Item = std::remove_pointer_t<decltype(item_protocol)>;
            if (done) return;
            const std::int64_t size = Item::bytes(value);
            if (byte < size) {
              changed = Item::flip(value, byte, mask);
              done = true;
            }
            byte -= size;
          };
          (item(x, static_cast<protocol<Items>*>(nullptr)), ...);
        },
        v);
    return changed;
  }
  static void send(detail::Wire& w, value_type v) { detail::send_whole<protocol>(w, std::move(v)); }
  static value_type receive(detail::Wire& w) { return detail::take<value_type>(w); }
};

template <class... Items>
struct protocol<Case<Items...>> {
  using value_type = Case<Items...>;
  static constexpr bool single = false;
  static std::int64_t bytes(const value_type& c) {
    return protocol<Sequential<Items...>>::bytes(c.items);
  }
  static std::string name() {
    const std::string items = protocol<Sequential<Items...>>::name();
    return items.empty() ? "tag" : items;
  }
  static void send(detail::Wire& w, value_type c) {
    protocol<Sequential<Items...>>::send(w, std::move(c.items));
  }
  static value_type receive(detail::Wire& w) {
    return {protocol<Sequential<Items...>>::receive(w)};
  }
};

template <class... Cases>
struct protocol<Variant<Cases...>> {
  static_assert(sizeof...(Cases) <= 256, "a variant protocol's tag is a BYTE");
  using value_type = std::variant<Cases...>;
  static constexpr bool single = false;
  static std::int64_t bytes(const value_type& v) {
    return 1 + std::visit(
                   [](const auto& c) { return protocol<std::decay_t<decltype(c)>>::bytes(c); }, v);
  }
  static std::string name() { return case_names(std::index_sequence_for<Cases...>{}); }
  static void send(detail::Wire& w, value_type v) {
    protocol<BYTE>::send(w, BYTE(v.index()));
    std::visit([&w](auto& c) { protocol<std::decay_t<decltype(c)>>::send(w, std::move(c)); }, v);
  }
  static value_type receive(detail::Wire& w) {
    const std::size_t tag = protocol<BYTE>::receive(w);
    return receive_case(w, tag, std::index_sequence_for<Cases...>{});
  }

 private:
  template <std::size_t... I>
  static std::string case_names(std::index_sequence<I...>) {
    std::string s = "CASE";
    ((s += (I ? " | " : " ") + std::to_string(I) + ": " + protocol<Cases>::name()), ...);
    return s;
  }
  template <std::size_t... I>
  static value_type receive_case(detail::Wire& w, std::size_t tag, std::index_sequence<I...>) {
    using Receive = value_type (*)(detail::Wire&);
    static constexpr Receive cases[] = {[](detail::Wire& wire) {
      return value_type(std::in_place_index<I>, protocol<Cases>::receive(wire));
    }...};
    if (tag >= sizeof...(Cases)) throw std::logic_error("a variant protocol's tag is out of range");
    return cases[tag](w);
  }
};

// One of several messages, each one communication, sent with no tag: its bytes are the chosen
// alternative's alone, where a Variant sends a tag BYTE first. For messages a receiver tells apart
// by what arrives -- a bare INT saying `finish` against a whole matrix of REALs, whose lengths
// differ -- without a header word in front of the long one. The simulator delivers which
// alternative was sent (the value's index); a program for real transputers needs the lengths to
// tell, or a Variant.
template <class... Alternatives>
struct Untagged {};

template <class... Alternatives>
struct protocol<Untagged<Alternatives...>> {
  static_assert((protocol<Alternatives>::single && ...),
                "an untagged protocol's alternatives are each one communication (primitives, "
                "arrays, blocks, packed)");
  using value_type = std::variant<typename protocol<Alternatives>::value_type...>;
  static constexpr bool single = true;
  static std::int64_t bytes(const value_type& v) {
    return bytes_of(v, std::index_sequence_for<Alternatives...>{});
  }
  static std::string name() {
    std::string s;
    ((s += (s.empty() ? "" : " | ") + protocol<Alternatives>::name()), ...);
    return "UNTAGGED (" + s + ")";
  }
  // A link fault's changed byte lands in the alternative sent.
  static bool flip(value_type& v, std::int64_t byte, std::uint8_t mask) {
    return flip_of(v, byte, mask, std::index_sequence_for<Alternatives...>{});
  }
  static void send(detail::Wire& w, value_type v) { detail::send_whole<protocol>(w, std::move(v)); }
  static value_type receive(detail::Wire& w) { return detail::take<value_type>(w); }

 private:
  // By the value's index, not its type: two alternatives may hold the same C++ type.
  template <std::size_t... I>
  static std::int64_t bytes_of(const value_type& v, std::index_sequence<I...>) {
    std::int64_t n = 0;
    ((v.index() == I ? void(n = protocol<Alternatives>::bytes(std::get<I>(v))) : void()), ...);
    return n;
  }
  template <std::size_t... I>
  static bool flip_of(value_type& v, std::int64_t byte, std::uint8_t mask,
                      std::index_sequence<I...>) {
    bool changed = false;
    ((v.index() == I ? void(changed = protocol<Alternatives>::flip(std::get<I>(v), byte, mask))
                     : void()),
     ...);
    return changed;
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
