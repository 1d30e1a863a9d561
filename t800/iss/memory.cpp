#include "t800/iss/memory.hpp"

#include <fmt/format.h>

namespace t800::iss {

Memory::Memory(std::int64_t on_chip_bytes, std::int64_t installed_bytes, AddressPolicy policy)
    : policy_(policy) {
  if (installed_bytes < on_chip_bytes || installed_bytes > (std::int64_t(1) << 31) ||
      on_chip_bytes <= 0)
    throw std::invalid_argument(fmt::format(
        "memory: {} bytes installed with {} on chip: the installed memory must hold the on-chip "
        "RAM and be at most 2 GiB (half the address space, from MostNeg)",
        installed_bytes, on_chip_bytes));
  size_ = std::uint32_t(installed_bytes);
  store_limit_ = size_;
  on_chip_ = std::uint32_t(on_chip_bytes);
  power_of_two_ = (size_ & (size_ - 1)) == 0;
  bytes_.assign(size_, 0);
  code_lines_.assign((size_ >> kLineShift) + 1, 0);
}

std::uint32_t Memory::wrap(Word address) const {
  if (policy_ == AddressPolicy::strict)
    throw MemoryFault(address, fmt::format("address #{:08X} is outside the installed memory "
                                           "(#{:08X} to #{:08X})",
                                           address, kMostNeg, kMostNeg + size_ - 1));
  const std::uint32_t o = address - kMostNeg;
  return power_of_two_ ? (o & (size_ - 1)) : (o % size_);
}

void Memory::written_code(std::uint32_t offset) {
  code_lines_[offset >> kLineShift] = 0;
  if (code_written_) code_written_(offset & ~((1u << kLineShift) - 1));
}

void Memory::copy(Word to, Word from, Word count) {
  const std::uint32_t source = from - kMostNeg, target = to - kMostNeg;
  // Within the installed memory, unwrapped, and not a forward copy over its own source (which
  // repeats a pattern, as the chip's byte order does): memmove gives the same bytes.
  const bool plain = source <= size_ && count <= size_ - source && target <= size_ &&
                     count <= size_ - target && (target <= source || target - source >= count);
  if (!plain) {
    for (Word k = 0; k < count; ++k) set_byte(to + k, byte(from + k));
    return;
  }
  if (count == 0) return;
  if (logging())
    for (std::uint32_t o = target & ~3u; o < target + count; o += 4) log(o);
  std::memmove(&bytes_[target], &bytes_[source], count);
  for (std::uint32_t line = target >> kLineShift; line <= (target + count - 1) >> kLineShift;
       ++line)
    if (code_lines_[line]) written_code(line << kLineShift);
}

void Memory::undo() {
  for (auto it = undo_.rbegin(); it != undo_.rend(); ++it) {
    std::memcpy(&bytes_[it->offset], &it->old, 4);
    if (code_lines_[it->offset >> kLineShift]) written_code(it->offset);
  }
  drop_undo_log();
}

void Memory::read(Word address, std::uint8_t* out, std::size_t count) const {
  for (std::size_t k = 0; k < count; ++k) out[k] = byte(address + Word(k));
}

void Memory::write(Word address, const std::uint8_t* in, std::size_t count) {
  for (std::size_t k = 0; k < count; ++k) set_byte(address + Word(k), in[k]);
}

}  // namespace t800::iss
