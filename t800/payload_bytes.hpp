// A message's payload seen as the bytes on the wire, for a link fault that changes a byte in flight
// (network/faults.hpp): the program that sends a payload type says how its value changes when byte
// k of the message arrives XORed with a mask, so a corrupted byte changes what the receiver reads.
#pragma once

#include <any>
#include <cstdint>
#include <cstring>
#include <functional>
#include <typeindex>

#include "t800/message.hpp"

namespace t800 {

// Changes a writer's value (Message::payload) as if byte `byte` of it (0 = the first on the wire)
// arrived XORed with `mask`; false when that byte has no modelled value.
using ByteFlip = std::function<bool(std::any& value, std::int64_t byte, std::uint8_t mask)>;

// Registering a type twice keeps the first.
void register_payload_bytes(std::type_index type, ByteFlip flip);
// false when the value's type was never registered, or the byte has no modelled value.
bool flip_payload_byte(std::any& value, std::int64_t byte, std::uint8_t mask);
// As if byte `byte` of the message carrying `payload` arrived changed: a byte of a routed message's
// header (RouteHeader) has no modelled value, the bytes after it are the writer's value's.
bool flip_message_byte(std::any& payload, const RouteHeader& route, std::int64_t byte,
                       std::uint8_t mask);

// Flips byte `byte` (0-based, little-endian as the T800 stores) of a plain value.
template <class T>
T flip_byte(T value, std::int64_t byte, std::uint8_t mask) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  raw[byte] ^= mask;
  std::memcpy(&value, raw, sizeof(T));
  return value;
}

}  // namespace t800
