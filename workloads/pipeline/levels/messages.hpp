// What the pipeline's levels send each other: one struct per message, and its protocol -- the bytes
// it takes on the wire follow from the value, as occam's counted protocols' do: one INT32 header
// word (a row's number, a step, a status flag) and the REALs (REAL32 for float, REAL64 for double),
// with recovery's messages a checksum word after them (checksum.hpp). message() makes the
// simulator's message with those bytes, so no call site writes a byte count.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "t800/message.hpp"
#include "workloads/dynamics/counted.hpp"
#include "workloads/elimination/gauss.hpp"
#include "workloads/elimination/system.hpp"
#include "workloads/pipeline/checksum.hpp"

namespace workloads::levels {

// One INT32 word in front of every row or matrix: the row's number (or the step) and a status flag.
constexpr std::int64_t kHeaderBytes = 4;
constexpr std::int64_t kChecksumBytes = 4;

template <class T>
struct Messages {
  using C = dynamics::Counted<T>;
  using Row = elimination::Row<C>;
  static constexpr std::int64_t kReal = sizeof(T);  // REAL32 or REAL64

  static std::int64_t reals(std::size_t count) {
    return kHeaderBytes + kReal * static_cast<std::int64_t>(count);
  }

  // The client's system (its REALs, no header), or nullopt: finish (a header word).
  using Input = std::optional<elimination::LinearSystem<C>>;
  static std::int64_t bytes(const Input& input) {
    if (!input) return kHeaderBytes;
    const auto n = static_cast<std::int64_t>(input->size());
    return kReal * n * (n + 1);
  }

  // A step's pivot row, L1 -> level 2 -> L3 -> L4; a stop (ok = false) is a header word.
  struct Pivot {
    bool ok = true;
    bool finish = false;    // with ok = false: the client called finish(), not a failure
    bool unstable = false;  // set by L3 on its way to L4
    Row row;
    C scale = C(0);           // step 0 only: level 3's growth check needs it
    bool with_scale = false;  // the scale travels (L1 -> L3 at step 0 with the growth check)

    static Pivot stop(bool finish) {
      Pivot m;
      m.ok = false;
      m.finish = finish;
      return m;
    }
    std::int64_t bytes() const {
      return ok ? reals(row.size() + (with_scale ? 1 : 0)) : kHeaderBytes;
    }
  };
  // A row to eliminate (L1 -> level 2) or eliminated (level 2 -> L3).
  struct RowMessage {
    std::size_t index = 0;  // position in the reduced system
    Row values;
    std::int64_t bytes() const { return reals(values.size()); }
  };
  // The reduced matrix goes back to L1 one row per message, like every other row transfer; a
  // failed step sends one header instead.
  struct ReturnedRow {
    bool ok = true;
    Row values;
    // Position in the next step's system (with overlap the rows come back as they are ready).
    std::size_t index = 0;
    std::int64_t bytes() const { return ok ? reals(values.size()) : kHeaderBytes; }
  };
  // q̈ back to the client (an empty one is a failure's header word).
  static std::int64_t bytes(const std::vector<double>& qdd) { return reals(qdd.size()); }

  // Recovery's messages (PipelineSettings::recovery): each carries the step it belongs to and a
  // checksum of its header word and REALs.
  struct CheckedPivot {
    int step = 0;
    bool stop = false;     // the level-2 processor ends (a header word)
    bool forward = false;  // it passes the pivot row on to L3
    Row row;
    C scale = C(0);
    std::uint32_t checksum = 0;
    std::uint32_t header() const { return std::uint32_t(step); }
    // The scale travels at step 0 when the growth check needs it (read from the step, as the
    // receiver reads it).
    std::int64_t bytes(bool growth_check) const {
      if (stop) return kHeaderBytes;
      const std::size_t extra = step == 0 && growth_check ? 1 : 0;
      return reals(row.size() + extra) + kChecksumBytes;
    }
    std::uint32_t sum() const {
      std::uint32_t s = workloads::checksum(header(), row);
      add_words(s, scale.value());
      return s;
    }
  };
  struct CheckedRow {
    int step = 0;
    std::size_t index = 0;  // 1-based, in the step's reduced system
    bool bad = false;       // its level-2 processor found its input damaged
    Row values;
    std::uint32_t checksum = 0;
    std::uint32_t header() const { return std::uint32_t(step * 256 + int(index)); }
    std::int64_t bytes() const { return reals(values.size()) + kChecksumBytes; }
    std::uint32_t sum() const {
      return workloads::checksum(header() + (bad ? 0x80000000u : 0u), values);
    }
  };
  // L3 to L1: resend these rows of the step (0: the pivot row) through other level-2 processors;
  // a word each, and a count.
  struct Resend {
    std::vector<std::size_t> rows;
    std::vector<int> lost;   // level-2 processors (0-based) L3 gave up on
    std::vector<int> avoid;  // and those whose rows arrived damaged
    std::int64_t bytes() const {
      return 4 * (std::int64_t(rows.size() + lost.size() + avoid.size()) + 1);
    }
  };

  // How each message's value changes when a byte of it arrives changed (a corrupting link fault).
  static void register_faults();
};

// The simulator's message carrying `m`, its bytes from its protocol.
template <class M>
t800::Message message(M m, const std::string& label) {
  const std::int64_t bytes = m.bytes();
  return {bytes, std::move(m), label};
}
template <class M>
t800::Message message(M m, std::int64_t bytes, const std::string& label) {
  return {bytes, std::move(m), label};
}

extern template struct Messages<float>;
extern template struct Messages<double>;

}  // namespace workloads::levels
