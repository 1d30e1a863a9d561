// SP packets built byte by byte for the server's tests, from iserver 1.50's layouts: little-endian
// INT32s, slices (an INT16 count, then the bytes), and the reply codes of hostc.c.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace t800::host::sp_bytes {

using Bytes = std::vector<std::uint8_t>;

inline Bytes cat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const Bytes& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}
inline Bytes text(const std::string& s) {
  return Bytes(s.begin(), s.end());
}
// A slice: INT16 count, then the bytes.
inline Bytes slice(const std::string& s) {
  return cat(
      {Bytes{static_cast<std::uint8_t>(s.size() & 0xff), static_cast<std::uint8_t>(s.size() >> 8)},
       text(s)});
}
inline Bytes le32(std::uint32_t v) {
  return Bytes{static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8),
               static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 24)};
}
// The hostio library pads every request to an even length (the server must not care).
inline Bytes padded_even(Bytes body) {
  if (body.size() % 2 != 0) body.push_back(0);
  return body;
}
// A reply: padded with zeros to an even length of at least 6 (serverc.c).
inline Bytes padded_to_six(Bytes body) {
  body = padded_even(std::move(body));
  if (body.size() < 6) body.resize(6, 0);
  return body;
}

inline const Bytes kOk = {0, 0, 0, 0, 0, 0};
inline const Bytes kNotImplemented = {1, 0, 0, 0, 0, 0};
inline const Bytes kError = {129, 0, 0, 0, 0, 0};
inline const Bytes kNoPrivilege = {131, 0, 0, 0, 0, 0};
inline const Bytes kNoResource = {132, 0, 0, 0, 0, 0};
inline const Bytes kNoFile = {133, 0, 0, 0, 0, 0};
inline const Bytes kBadId = {135, 0, 0, 0, 0, 0};
inline const Bytes kNoPosition = {136, 0, 0, 0, 0, 0};
inline const Bytes kBadParameters = {141, 0, 0, 0, 0, 0};

}  // namespace t800::host::sp_bytes
