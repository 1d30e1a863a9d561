// What the pipeline's levels send each other: one struct per message, and its protocol -- the bytes
// it takes on the wire follow from the value, as occam's counted protocols' do: one INT32 header
// word (a row's number, a step, status flags) and the REALs (REAL32 for float, REAL64 for double),
// with recovery's messages a checksum word after them (checksum.hpp). Strict and overlapped steps'
// messages travel as a Packet over the SDK's typed channels (Packed<INT, Block<REAL>>, its bytes
// from the protocol); recovery's and the client's system still as the simulator's messages, which
// message() makes with their bytes, so no call site writes a byte count.
#pragma once

#include <any>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "t800/message.hpp"
#include "t800sim/protocol.hpp"
#include "workloads/dynamics/counted.hpp"
#include "workloads/elimination/gauss.hpp"
#include "workloads/elimination/system.hpp"
#include "workloads/pipeline/checksum.hpp"

namespace workloads::levels {

// One INT32 word in front of every row or matrix: the row's number (or the step) and a status flag.
constexpr std::int64_t kHeaderBytes = 4;
constexpr std::int64_t kChecksumBytes = 4;

// The header word of a packet (Messages::Packet): a number (a row's, or a step) in the low bits,
// status flags in the high ones, as the occam program's header word has them. A stop ends the
// pipeline: a failure, or with kFinish the client's finish; kUnstable: the pivots have grown past
// the limit.
namespace header {
constexpr std::int32_t kStop = 1 << 30;
constexpr std::int32_t kFinish = 1 << 29;
constexpr std::int32_t kUnstable = 1 << 28;
constexpr std::int32_t kScale =
    1 << 27;  // a pivot row's last REAL is the scale (Pivot::with_scale)
constexpr std::int32_t kNumber = kScale - 1;
}  // namespace header

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

  // The messages of strict and overlapped steps, as the levels hold them; on the wire each is a
  // Packet (to_packet, and back).
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
  };
  // A row to eliminate (L1 -> level 2) or eliminated (level 2 -> L3).
  struct RowMessage {
    std::size_t index = 0;  // position in the reduced system
    Row values;
  };
  // The reduced matrix goes back to L1 one row per message, like every other row transfer; a
  // failed step sends one header instead.
  struct ReturnedRow {
    bool ok = true;
    Row values;
    // Position in the next step's system (with overlap the rows come back as they are ready).
    std::size_t index = 0;
  };
  // What the SDK's typed channels carry: the header word and a row in one communication (occam:
  // both in one buffer, sent as a slice on a CHAN OF ANY), the REALs as T.
  using Packet = t800sim::Packed<t800sim::INT, t800sim::Block<T>>;
  using PacketValue = t800sim::value_of<Packet>;
  static PacketValue packet(std::int32_t header, const Row& row) {
    std::vector<T> values;
    for (const C& v : row) values.push_back(v.value());
    return {header, std::move(values)};
  }
  static Row row_of(const PacketValue& packet) {
    const std::vector<T>& values = std::get<1>(packet);
    return Row(values.begin(), values.end());
  }
  // A pivot row (L1 -> level 2 -> L3; a row of U, L3 -> L4) with its step; a stop is its header
  // word alone.
  static PacketValue to_packet(int step, const Pivot& pivot) {
    if (!pivot.ok) return {header::kStop | (pivot.finish ? header::kFinish : 0), {}};
    Row values = pivot.row;
    if (pivot.with_scale) values.push_back(pivot.scale);
    return packet(
        step | (pivot.unstable ? header::kUnstable : 0) | (pivot.with_scale ? header::kScale : 0),
        values);
  }
  static Pivot pivot_of(const PacketValue& packet) {
    const std::int32_t flags = std::get<0>(packet);
    if (flags & header::kStop) return Pivot::stop(flags & header::kFinish);
    Pivot pivot;
    pivot.unstable = flags & header::kUnstable;
    pivot.with_scale = flags & header::kScale;
    pivot.row = row_of(packet);
    if (pivot.with_scale) {
      pivot.scale = pivot.row.back();
      pivot.row.pop_back();
    }
    return pivot;
  }
  static PacketValue to_packet(const RowMessage& row) {
    return packet(std::int32_t(row.index), row.values);
  }
  static RowMessage row_message_of(const PacketValue& packet) {
    return {std::size_t(std::get<0>(packet) & header::kNumber), row_of(packet)};
  }
  // A failed step's is its header word alone.
  static PacketValue to_packet(const ReturnedRow& row) {
    if (!row.ok) return {header::kStop, {}};
    return packet(std::int32_t(row.index), row.values);
  }
  static ReturnedRow returned_row_of(const PacketValue& packet) {
    const std::int32_t flags = std::get<0>(packet);
    if (flags & header::kStop) return {false, {}};
    return {true, row_of(packet), std::size_t(flags & header::kNumber)};
  }
  // q̈ back to the client (the REALs of its precision), or a failure: the header word alone.
  static PacketValue answer(bool ok, const std::vector<double>& qdd) {
    if (!ok) return {header::kStop, {}};
    return {0, std::vector<T>(qdd.begin(), qdd.end())};
  }

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
