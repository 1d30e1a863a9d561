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

bool flip_message_byte(std::any& payload, const RouteHeader& route, std::int64_t byte,
                       std::uint8_t mask) {
  return byte >= route.bytes && flip_payload_byte(payload, byte - route.bytes, mask);
}

}  // namespace t800
