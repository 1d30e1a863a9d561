// The messages of a processor farm (t800sim/farm.hpp) and the bytes each takes on the wire. Every
// message is one communication, as a farm written in occam sends it (a CHAN OF ANY whose message
// lengths both ends agree on): an order of a round's shared input, or of a single INT (a task to
// run, the end of a round, the end of the farm); a reply of a round's results, or of a task's INT
// index and its result.
//
//   order, a round:      the shared input's bytes (its protocol's); a recovery's order also lists
//   its
//                        tasks, an INT each and their count
//   order, a control:    one INT (task index, end of round, finish)
//   reply, a round:      the results' bytes, in the order of the round's tasks
//   reply, one task:     an INT (the task) and the result's bytes
//
// With recovery on (FarmOptions::recovery), every order and reply also carries an INT checksum of
// its values, so a byte a link corrupted is caught by the end that receives it.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "t800sim/protocol.hpp"

namespace t800sim {

template <class SharedValue>
struct FarmOrder {
  enum class Kind { round, task, end_of_round, finish };
  Kind kind = Kind::finish;
  SharedValue shared{};
  // A round's tasks, in the order their results go back. Unlisted, they are the allocation compiled
  // into the worker's program and cost no bytes; listed (a recovery's reassignment), they are sent.
  std::vector<INT> tasks;
  bool listed = false;
  INT task = 0;  // Kind::task
  bool checksummed = false;
  std::uint32_t checksum = 0;
};

template <class ResultValue>
struct FarmReply {
  INT task = -1;  // on demand: the task the one result is for; -1: a round's results
  std::vector<ResultValue> results;
  bool checksummed = false;
  std::uint32_t checksum = 0;
};

// The protocols, by what they carry: the shared input's protocol, the result's.
template <class Shared>
struct FarmOrders {};
template <class Result>
struct FarmReplies {};

namespace detail {

constexpr std::int64_t kFarmIntBytes = 4;  // an occam INT on a T800

// FNV-1a over the values' bytes: what a checksum word in a farm's message covers.
class FarmChecksum {
 public:
  template <class T>
  FarmChecksum& add(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "a checksum covers plain values");
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (unsigned char b : bytes) hash_ = (hash_ ^ b) * 16777619u;
    return *this;
  }
  template <class T>
  FarmChecksum& add(const std::vector<T>& values) {
    for (const T& v : values) add(v);
    return *this;
  }
  template <class T, std::size_t N>
  FarmChecksum& add(const std::array<T, N>& values) {
    for (const T& v : values) add(v);
    return *this;
  }
  std::uint32_t value() const { return hash_; }

 private:
  std::uint32_t hash_ = 2166136261u;
};

template <class SharedValue>
std::uint32_t checksum_of(const FarmOrder<SharedValue>& o) {
  FarmChecksum c;
  c.add(int(o.kind)).add(o.task).add(o.tasks);
  if (o.kind == FarmOrder<SharedValue>::Kind::round) c.add(o.shared);
  return c.value();
}

template <class ResultValue>
std::uint32_t checksum_of(const FarmReply<ResultValue>& r) {
  return FarmChecksum().add(r.task).add(r.results).value();
}

// Whether a message arrived as it was sent: no checksum, or one that still matches.
template <class Message>
bool intact(const Message& m) {
  return !m.checksummed || checksum_of(m) == m.checksum;
}

template <class Message>
Message sealed(Message m, bool checksum) {
  m.checksummed = checksum;
  if (checksum) m.checksum = checksum_of(m);
  return m;
}

}  // namespace detail

template <class Shared>
struct protocol<FarmOrders<Shared>> {
  static_assert(protocol<Shared>::single, "a farm's shared input is one communication");
  using value_type = FarmOrder<value_of<Shared>>;
  static constexpr bool single = true;
  static std::int64_t bytes(const value_type& o) {
    const std::int64_t check = o.checksummed ? detail::kFarmIntBytes : 0;
    if (o.kind != value_type::Kind::round) return detail::kFarmIntBytes + check;
    const std::int64_t list =
        o.listed ? detail::kFarmIntBytes * (std::int64_t(o.tasks.size()) + 1) : 0;
    return protocol<Shared>::bytes(o.shared) + list + check;
  }
  static std::string name() { return "FARM.ORDER(" + protocol<Shared>::name() + ")"; }
  static void send(detail::Wire& w, value_type v) { detail::send_one(w, bytes(v), std::move(v)); }
  static value_type receive(detail::Wire& w) { return detail::take<value_type>(w); }
};

template <class Result>
struct protocol<FarmReplies<Result>> {
  static_assert(protocol<Result>::single, "a farm's result is one communication");
  using value_type = FarmReply<value_of<Result>>;
  static constexpr bool single = true;
  static std::int64_t bytes(const value_type& r) {
    std::int64_t n = r.checksummed ? detail::kFarmIntBytes : 0;
    if (r.task >= 0) n += detail::kFarmIntBytes;
    for (const auto& v : r.results) n += protocol<Result>::bytes(v);
    return n;
  }
  static std::string name() { return "FARM.REPLY(" + protocol<Result>::name() + ")"; }
  static void send(detail::Wire& w, value_type v) { detail::send_one(w, bytes(v), std::move(v)); }
  static value_type receive(detail::Wire& w) { return detail::take<value_type>(w); }
};

}  // namespace t800sim
