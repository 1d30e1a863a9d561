// What the pipeline's levels send each other: one struct per message, and its protocol -- the bytes
// it takes on the wire follow from the value, as occam's counted protocols' do: one INT32 header
// word (a row's number, a step, status flags) and the REALs (REAL32 for float, REAL64 for double),
// with recovery's messages a checksum word after them (checksum.hpp). Strict and overlapped steps'
// messages travel as a Packet over the SDK's typed channels (Packed<INT, Block<REAL>>), recovery's
// as a Checked packet (Packed<INT, Block<REAL>, Block<INT>>), the client's system as a System
// (Untagged<INT, Block<REAL>>): their bytes from the protocol.
#pragma once

#include <any>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "t800sim/protocol.hpp"
#include "workloads/dynamics/counted.hpp"
#include "workloads/elimination/gauss.hpp"
#include "workloads/elimination/system.hpp"
#include "workloads/pipeline/checksum.hpp"

namespace workloads::levels {

// The trace label of a stop message (a bare header word); control flow reads the value, not this.
constexpr const char* kFailLabel = "fail";

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

// The header word of a recovery message (Messages::Checked). A row: step * 256 + its number, and
// kDamaged when its level-2 processor found its input damaged. A pivot row: kPivotRow | the step,
// kForward for the level-2 processor that passes it on to L3. A stop: header::kStop. L3's resend
// request: kResend and the lengths of its three lists, a byte each.
namespace checked_header {
constexpr std::uint32_t kForward = 1u << 26;
constexpr std::uint32_t kPivotRow = 1u << 27;
constexpr std::uint32_t kResend = 1u << 28;
constexpr std::uint32_t kDamaged = 1u << 31;
constexpr std::uint32_t kNumber = kForward - 1;
}  // namespace checked_header

template <class T>
struct Messages {
  using C = dynamics::Counted<T>;
  using Row = elimination::Row<C>;

  // The client's system -- its n(n+1) REALs, row by row each followed by its right-hand side, no
  // header word -- or finish, a bare INT. Untagged: the lengths tell the two apart, and a header
  // word in front of the system would lengthen its input.
  using System = t800sim::Untagged<t800sim::INT, t800sim::Block<T>>;
  using SystemValue = t800sim::value_of<System>;
  static SystemValue system(const elimination::LinearSystem<T>& s) {
    std::vector<T> values;
    for (std::size_t i = 0; i < s.size(); ++i) {
      values.insert(values.end(), s.a[i].begin(), s.a[i].end());
      values.push_back(s.b[i]);
    }
    return SystemValue(std::in_place_index<1>, std::move(values));
  }
  static SystemValue finish() {
    return SystemValue(std::in_place_index<0>, header::kStop | header::kFinish);
  }
  // The system as L1 computes with it, or nullopt: finish.
  static std::optional<elimination::LinearSystem<C>> system_of(const SystemValue& v);

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
    values.reserve(row.size());
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
    const std::int32_t word = step | (pivot.unstable ? header::kUnstable : 0);
    if (!pivot.with_scale) return packet(word, pivot.row);
    Row values;
    values.reserve(pivot.row.size() + 1);
    values.insert(values.end(), pivot.row.begin(), pivot.row.end());
    values.push_back(pivot.scale);
    return packet(word | header::kScale, values);
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
  // checksum of its header word and REALs. On the wire every one is a Checked packet: the header
  // word (checked_header), the REALs, and INT words -- the checksum, or a resend's lists, their
  // lengths in the header word; a stop is the header word alone.
  using Checked = t800sim::Packed<t800sim::INT, t800sim::Block<T>, t800sim::Block<t800sim::INT>>;
  using CheckedValue = t800sim::value_of<Checked>;

  struct CheckedPivot {
    int step = 0;
    bool stop = false;     // the level-2 processor ends
    bool forward = false;  // it passes the pivot row on to L3
    Row row;
    C scale = C(0);  // travels at step 0 when the growth check needs it; zero otherwise
    std::uint32_t checksum = 0;
    std::uint32_t sum() const {
      std::uint32_t s = workloads::checksum(std::uint32_t(step), row);
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
    std::uint32_t header() const {
      return std::uint32_t(step * 256 + int(index)) | (bad ? checked_header::kDamaged : 0u);
    }
    std::uint32_t sum() const { return workloads::checksum(header(), values); }
  };
  // L3 to L1: resend these rows of the step (0: the pivot row) through other level-2 processors;
  // a word each.
  struct Resend {
    std::vector<std::size_t> rows;
    std::vector<int> lost;   // level-2 processors (0-based) L3 gave up on
    std::vector<int> avoid;  // and those whose rows arrived damaged
  };

  // L1 -> level 2 -> L3. The scale is the pivot row's last REAL when it travels (step 0 with the
  // growth check: the receiver reads it from the step).
  static CheckedValue to_checked(const CheckedPivot& pivot, bool growth_check);
  static CheckedValue to_checked(const CheckedRow& row);
  // L3 -> L1: a returned row (its packet's header and REALs), or a resend request.
  static CheckedValue to_checked(const ReturnedRow& row);
  static CheckedValue to_checked(const Resend& request);
  // What a checked packet holds, by its header word.
  static bool is_pivot(const CheckedValue& v);
  static bool is_resend(const CheckedValue& v);
  static CheckedPivot checked_pivot_of(const CheckedValue& v, bool growth_check);
  static CheckedRow checked_row_of(const CheckedValue& v);
  static ReturnedRow returned_row_of(const CheckedValue& v);
  static Resend resend_of(const CheckedValue& v);
};

extern template struct Messages<float>;
extern template struct Messages<double>;

}  // namespace workloads::levels
