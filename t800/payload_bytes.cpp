#include "t800/payload_bytes.hpp"

#include <map>

namespace t800 {

namespace {
std::map<std::type_index, ByteFlip>& registry() {
  static std::map<std::type_index, ByteFlip> flips;
  return flips;
}
}  // namespace

void register_payload_bytes(std::type_index type, ByteFlip flip) {
  registry().emplace(type, std::move(flip));
}

bool flip_payload_byte(std::any& value, std::int64_t byte, std::uint8_t mask) {
  if (!value.has_value()) return false;
  auto found = registry().find(std::type_index(value.type()));
  return found != registry().end() && found->second(value, byte, mask);
}

bool flip_message_byte(Payload& payload, std::int64_t byte, std::uint8_t mask) {
  const std::int64_t header = payload.route.bytes;
  return byte >= header && flip_payload_byte(payload.value, byte - header, mask);
}

}  // namespace t800
