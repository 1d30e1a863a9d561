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

bool flip_payload_byte(std::any& payload, std::int64_t byte, std::uint8_t mask) {
  if (!payload.has_value()) return false;
  auto found = registry().find(std::type_index(payload.type()));
  return found != registry().end() && found->second(payload, byte, mask);
}

}  // namespace t800
