// A transputer's memory as its programs see it: the on-chip RAM from MostNeg, external memory above
// it up to the installed size, byte addressed, little endian (CWG, "memory"). An address beyond the
// installed memory either wraps modulo the installed size, as a board whose address decoding
// ignores the high bits does (Transputer Minix sizes memory by that wrap), or, `strict`, is a fault
// the processor halts on. Word accesses ignore the address's two low bits, as the chip does.
//
// Decoded instructions are cached by the processor (decoder.hpp); a write to a 16-byte line that
// holds cached code calls the invalidation hook, since bootstraps load later stages over
// themselves.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "t800/iss/machine_words.hpp"

namespace t800::iss {

enum class AddressPolicy { wrap, strict };

// An access outside the installed memory under AddressPolicy::strict.
struct MemoryFault : std::runtime_error {
  MemoryFault(Word address, const std::string& what) : std::runtime_error(what), address(address) {}
  Word address;
};

class Memory {
 public:
  static constexpr int kLineShift = 4;  // 16-byte code lines

  // `installed_bytes` counts from MostNeg and includes the on-chip RAM.
  Memory(std::int64_t on_chip_bytes, std::int64_t installed_bytes, AddressPolicy policy);

  Word word(Word address) const {
    Word w;
    std::memcpy(&w, &bytes_[offset(address & ~3u)], 4);
    return w;
  }
  // Stores past store_limit_ take the slow way: outside the installed memory, or any while the undo
  // log is on (which sets the limit to 0), so that the log costs the common store nothing.
  void set_word(Word address, Word value) {
    const std::uint32_t o = (address & ~3u) - kMostNeg;
    if (o >= store_limit_) [[unlikely]] {
      set_word_slowly(address, value);
      return;
    }
    std::memcpy(&bytes_[o], &value, 4);
    if (code_lines_[o >> kLineShift]) written_code(o);
  }
  // The same, saying whether the word is in external memory (external(address)): the commonest
  // instructions want both, and one look at the address serves.
  Word word(Word address, bool& is_external) const {
    const std::uint32_t o = address - kMostNeg;
    if (o >= size_) [[unlikely]] {
      is_external = external(address);
      return word(address);
    }
    is_external = o >= on_chip_;
    Word w;
    std::memcpy(&w, &bytes_[o & ~3u], 4);
    return w;
  }
  void set_word(Word address, Word value, bool& is_external) {
    const std::uint32_t o = address - kMostNeg;
    if (o >= store_limit_) [[unlikely]] {
      is_external = external(address);
      set_word_slowly(address, value);
      return;
    }
    is_external = o >= on_chip_;
    std::memcpy(&bytes_[o & ~3u], &value, 4);
    if (code_lines_[o >> kLineShift]) written_code(o & ~3u);
  }
  std::uint8_t byte(Word address) const { return bytes_[offset(address)]; }
  void set_byte(Word address, std::uint8_t value) {
    std::uint32_t o = address - kMostNeg;
    if (o >= store_limit_) [[unlikely]] {
      o = offset(address);
      if (logging()) log(o);
    }
    bytes_[o] = value;
    if (code_lines_[o >> kLineShift]) written_code(o);
  }
  // Copies `count` bytes within the machine, byte by byte in address order (as `move` does: an
  // overlapping move is the chip's, not memmove's).
  void copy(Word to, Word from, Word count);
  void read(Word address, std::uint8_t* out, std::size_t count) const;
  void write(Word address, const std::uint8_t* in, std::size_t count);

  // Where an address lives (after wrapping): external memory costs more (sequence_timing.hpp).
  bool external(Word address) const { return offset(address) >= on_chip_; }
  // The address's place in the installed memory; throws MemoryFault under `strict`.
  std::uint32_t offset(Word address) const {
    const std::uint32_t o = address - kMostNeg;
    if (o < size_) return o;
    return wrap(address);
  }
  std::int64_t installed_bytes() const { return size_; }
  std::int64_t on_chip_bytes() const { return on_chip_; }
  AddressPolicy policy() const { return policy_; }

  // A run that may have to be undone (Core::checkpoint): from start_undo_log on, every write keeps
  // the word it overwrites; undo() puts them back, newest first, and stops the log, as does
  // drop_undo_log() (the run stands).
  void start_undo_log() {
    undo_.clear();
    store_limit_ = 0;
  }
  void undo();
  void drop_undo_log() {
    undo_.clear();
    store_limit_ = size_;
  }

  // The decoder marks the lines it has cached code from, and is told when one is written.
  void mark_code(std::uint32_t offset) { code_lines_[offset >> kLineShift] = 1; }
  void on_code_written(std::function<void(std::uint32_t line_offset)> hook) {
    code_written_ = std::move(hook);
  }

 private:
  std::uint32_t wrap(Word address) const;
  void written_code(std::uint32_t offset);
  void set_word_slowly(Word address, Word value) {
    const std::uint32_t o = offset(address & ~3u);
    if (logging()) log(o);
    std::memcpy(&bytes_[o], &value, 4);
    if (code_lines_[o >> kLineShift]) written_code(o);
  }
  // The word holding `offset` before it is written.
  void log(std::uint32_t offset) {
    const std::uint32_t o = offset & ~3u;
    Word old;
    std::memcpy(&old, &bytes_[o], 4);
    undo_.push_back({o, old});
  }

  std::uint32_t size_, on_chip_;
  std::uint32_t store_limit_;  // size_, or 0 while the undo log is on (size_ is never 0)
  bool logging() const { return store_limit_ == 0; }
  AddressPolicy policy_;
  bool power_of_two_;
  std::vector<std::uint8_t> bytes_;
  std::vector<std::uint8_t> code_lines_;
  std::function<void(std::uint32_t)> code_written_;
  struct Overwritten {
    std::uint32_t offset;
    Word old;
  };
  std::vector<Overwritten> undo_;
};

}  // namespace t800::iss
