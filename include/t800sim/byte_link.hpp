// A link of raw bytes between a process of a program and a booted neighbour: a transputer that runs
// real machine code (docs/iss.md, "Mixed networks"). What the process sends is what the booted
// processor's link engine receives, byte for byte -- first its boot file, as a host or a loader
// sends one, then whatever its program reads -- and what the booted program outputs is what the
// process takes in. Values go on the wire as the T800 holds them in memory (bytes_of, value_from).
//
//   b.booted("P1");
//   auto wire = b.byte_link("feed", "feeder", "P1");
//   b.process("feeder", [wire](Process& p) {
//     p.out(wire, boot_file);                  // the booted processor starts running it
//     p.out(wire, t800sim::bytes_of<INT>(3));
//     INT got = t800sim::value_from<INT>(p.in(wire, 4));
//   });
#pragma once

#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace t800 {
class Link;
}

namespace t800sim {

using Bytes = std::vector<std::uint8_t>;

namespace detail {
// What the simulator joins a byte link to (sdk/booted.cpp), and the block a booted sender's output
// is being taken from, piece by piece.
struct ByteLinkSlot {
  std::string name, process, processor;
  t800::Link* link = nullptr;
  int end = 0;  // the process's end of the link
  std::shared_ptr<Bytes> incoming;
  std::size_t taken = 0;
};

// The unsigned integer of T's size, whose bits are T's.
template <class T>
using UnsignedOf = std::conditional_t<
    sizeof(T) == 8, std::uint64_t,
    std::conditional_t<sizeof(T) == 4, std::uint32_t,
                       std::conditional_t<sizeof(T) == 2, std::uint16_t, std::uint8_t>>>;
}  // namespace detail

class ByteLink {
 public:
  explicit ByteLink(std::shared_ptr<detail::ByteLinkSlot> slot) : slot_(std::move(slot)) {}
  const std::string& name() const { return slot_->name; }
  detail::ByteLinkSlot* slot() const { return slot_.get(); }

 private:
  std::shared_ptr<detail::ByteLinkSlot> slot_;
};

// A value as a T800 holds it: little-endian, two's complement integers, IEEE 754 REAL32 and
// REAL64, a BOOL as one byte (whatever the host's own order).
template <class T>
Bytes bytes_of(T value) {
  static_assert(std::is_arithmetic_v<T>, "bytes_of: an integer, a bool or a floating-point value");
  if constexpr (std::is_same_v<T, bool>) {
    return Bytes{std::uint8_t(value ? 1 : 0)};
  } else {
    using U = detail::UnsignedOf<T>;
    U bits;
    std::memcpy(&bits, &value, sizeof bits);
    Bytes out(sizeof bits);
    for (std::size_t k = 0; k < sizeof bits; ++k) out[k] = std::uint8_t(bits >> (8 * k));
    return out;
  }
}

// The value of type T whose bytes start at `at` (as bytes_of writes them). Throws
// std::out_of_range when fewer bytes follow.
template <class T>
T value_from(const Bytes& bytes, std::size_t at = 0) {
  static_assert(std::is_arithmetic_v<T>,
                "value_from: an integer, a bool or a floating-point value");
  const std::size_t size = std::is_same_v<T, bool> ? 1 : sizeof(T);
  if (at > bytes.size() || bytes.size() - at < size)
    throw std::out_of_range("value_from: " + std::to_string(size) + " bytes wanted at " +
                            std::to_string(at) + " of " + std::to_string(bytes.size()));
  if constexpr (std::is_same_v<T, bool>) {
    return bytes[at] != 0;
  } else {
    using U = detail::UnsignedOf<T>;
    U bits = 0;
    for (std::size_t k = 0; k < sizeof bits; ++k) bits |= U(U(bytes[at + k]) << (8 * k));
    T value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
}

}  // namespace t800sim
