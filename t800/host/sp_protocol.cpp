// SP protocol fields and framing (sp_protocol.hpp has the sources).
#include "t800/host/sp_protocol.hpp"

#include <cassert>
#include <utility>

namespace t800::host {

int iserver_exit_code(std::int32_t status) {
  // iserver 1.50 hostc.c SpExit: only the two toolset values are translated.
  if (status == kSpsSuccess) return kIserverSuccessExit;
  if (status == kSpsFailure) return kIserverFailureExit;
  // A process's exit code is 8 bits: a status that does not fit must not become 0 (256) or
  // another program's code (257 -> 1); the report keeps the status itself.
  if (status < 0 || status > 255) return kIserverFailureExit;
  return status;
}

std::uint16_t load_le16(const std::uint8_t* bytes) {
  return static_cast<std::uint16_t>(bytes[0] | (bytes[1] << 8));
}

std::uint32_t load_le32(const std::uint8_t* bytes) {
  return static_cast<std::uint32_t>(bytes[0]) | (static_cast<std::uint32_t>(bytes[1]) << 8) |
         (static_cast<std::uint32_t>(bytes[2]) << 16) |
         (static_cast<std::uint32_t>(bytes[3]) << 24);
}

void append_le16(std::vector<std::uint8_t>& out, std::uint16_t value) {
  out.push_back(static_cast<std::uint8_t>(value & 0xff));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
}

void append_le32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) {
    out.push_back(static_cast<std::uint8_t>((value >> shift) & 0xff));
  }
}

bool SpRequestReader::read_u8(std::uint8_t& value) {
  if (remaining() < 1) return false;
  value = data_[position_++];
  return true;
}

bool SpRequestReader::read_u16(std::uint16_t& value) {
  if (remaining() < 2) return false;
  value = load_le16(data_ + position_);
  position_ += 2;
  return true;
}

bool SpRequestReader::read_i32(std::int32_t& value) {
  if (remaining() < 4) return false;
  value = static_cast<std::int32_t>(load_le32(data_ + position_));
  position_ += 4;
  return true;
}

bool SpRequestReader::read_slice(std::string& value) {
  std::uint16_t count = 0;
  if (remaining() < 2) return false;
  count = load_le16(data_ + position_);
  // The count must fit in what the body still holds; the position moves only on success.
  if (remaining() - 2 < count) return false;
  position_ += 2;
  value.assign(reinterpret_cast<const char*>(data_ + position_), count);
  position_ += count;
  return true;
}

void SpReplyWriter::put_slice(std::string_view data) {
  assert(data.size() <= kSpMaxReplyData);
  append_le16(body_, static_cast<std::uint16_t>(data.size()));
  body_.insert(body_.end(), data.begin(), data.end());
}

std::vector<std::uint8_t> SpReplyWriter::finish() && {
  if (body_.size() % 2 != 0) body_.push_back(0);
  if (body_.size() < kSpMinBodySize) body_.resize(kSpMinBodySize, 0);
  assert(body_.size() <= kSpMaxBodySize);
  return std::move(body_);
}

std::string sp_length_problem(std::uint16_t length) {
  if (length < kSpMinBodySize) {
    return "SP packet length " + std::to_string(length) + " is shorter than the minimum " +
           std::to_string(kSpMinBodySize);
  }
  if (length > kSpMaxBodySize) {
    return "SP packet length " + std::to_string(length) + " is longer than the maximum " +
           std::to_string(kSpMaxBodySize);
  }
  if (length % 2 != 0) return "SP packet length " + std::to_string(length) + " is odd";
  return {};
}

std::vector<std::uint8_t> sp_frame(const std::vector<std::uint8_t>& body) {
  std::vector<std::uint8_t> packet;
  packet.reserve(body.size() + 2);
  append_le16(packet, static_cast<std::uint16_t>(body.size()));
  packet.insert(packet.end(), body.begin(), body.end());
  return packet;
}

void SpPacketReassembler::feed(const std::uint8_t* bytes, std::size_t size) {
  partial_.insert(partial_.end(), bytes, bytes + size);
  if (failed()) return;
  // Cut every complete packet off the front; what is left is the start of the next one.
  std::size_t start = 0;
  while (partial_.size() - start >= 2) {
    const std::uint16_t length = load_le16(partial_.data() + start);
    std::string problem = sp_length_problem(length);
    if (!problem.empty()) {
      error_ = std::move(problem);
      break;
    }
    if (partial_.size() - start - 2 < length) break;
    const auto body = partial_.begin() + static_cast<std::ptrdiff_t>(start + 2);
    ready_.emplace_back(body, body + length);
    start += 2 + length;
  }
  partial_.erase(partial_.begin(), partial_.begin() + static_cast<std::ptrdiff_t>(start));
}

std::optional<std::vector<std::uint8_t>> SpPacketReassembler::next_packet() {
  if (ready_.empty()) return std::nullopt;
  std::vector<std::uint8_t> body = std::move(ready_.front());
  ready_.pop_front();
  return body;
}

}  // namespace t800::host
