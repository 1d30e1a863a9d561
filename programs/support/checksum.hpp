// One number for a result that differs if any element does: FNV-1a (64 bit) over the elements'
// bytes as REAL32, least significant byte first, printed as 16 hex digits. Programs report it so a
// test can hold a distributed result against a sequential one without printing it whole.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace programs {

inline std::string fnv1a_hex(const std::vector<float>& values) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a's 64-bit offset basis
  for (float v : values) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    for (int b = 0; b < 4; ++b) h = (h ^ ((bits >> (8 * b)) & 0xffu)) * 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

}  // namespace programs
