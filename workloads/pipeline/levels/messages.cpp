#include "workloads/pipeline/levels/messages.hpp"

#include "t800/payload_bytes.hpp"

namespace workloads::levels {

// Recovery's messages: the header word, the REALs (little-endian words, as the T800 stores them),
// the checksum. (Packets say their own, t800sim/protocol.hpp.)
template <class T>
void Messages<T>::register_faults() {
  using t800::flip_byte;
  constexpr std::int64_t size = sizeof(T);
  auto flip_reals = [](Row& values, std::int64_t byte, std::uint8_t mask) {
    const std::size_t i = std::size_t(byte / size);
    if (i >= values.size()) return false;
    values[i] = C(flip_byte(values[i].value(), byte % size, mask));
    return true;
  };
  t800::register_payload_bytes(
      typeid(CheckedRow), [=](std::any& a, std::int64_t b, std::uint8_t x) {
        auto& m = std::any_cast<CheckedRow&>(a);
        const std::int64_t end = kHeaderBytes + size * std::int64_t(m.values.size());
        if (b < kHeaderBytes) {
          const std::uint32_t header = flip_byte(m.header(), b, x);
          m.step = int(header / 256);
          m.index = header % 256;
        } else if (b < end) {
          flip_reals(m.values, b - kHeaderBytes, x);
        } else {
          m.checksum = flip_byte(m.checksum, b - end, x);
        }
        return true;
      });
  t800::register_payload_bytes(
      typeid(CheckedPivot), [=](std::any& a, std::int64_t b, std::uint8_t x) {
        auto& m = std::any_cast<CheckedPivot&>(a);
        const std::int64_t reals_end = kHeaderBytes + size * std::int64_t(m.row.size());
        if (b < kHeaderBytes) {
          m.step = int(flip_byte(m.header(), b, x));
        } else if (b < reals_end) {
          flip_reals(m.row, b - kHeaderBytes, x);
        } else if (m.step == 0 && b < reals_end + size) {
          m.scale = C(flip_byte(m.scale.value(), b - reals_end, x));
        } else {
          const std::int64_t at = b - reals_end - (m.step == 0 ? size : 0);
          if (at < 0 || at >= 4) return false;
          m.checksum = flip_byte(m.checksum, at, x);
        }
        return true;
      });
}

template struct Messages<float>;
template struct Messages<double>;

}  // namespace workloads::levels
