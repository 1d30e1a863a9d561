// What travels over a channel: a length in bytes (which sets the time) and, optionally, the values
// the real program would send (which the receiving workload reads).
#pragma once

#include <any>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>

namespace t800 {

// The header the software routers read to pass a routed message on
// (network/transport/store_and_forward.hpp): the channel it is for, and the deadline every router
// forwards it by. On the wire it is the message's first `bytes` bytes, ahead of the writer's data,
// and Message::bytes counts them. It is typed data beside the writer's value, not a payload
// wrapping the writer's message: a routed message is the writer's own with its header set, and its
// reader gets it back with the header taken off. A fault on a byte of the header changes nothing
// modelled (flip_message_byte, t800/payload_bytes.hpp).
struct RouteHeader {
  std::int64_t bytes = 0;   // 0: not routed
  int channel = -1;         // the routed channel's id
  double deadline_us = -1;  // OutputOrFail's, which every router forwards it by; -1: sent with out
};

struct Message {
  std::int64_t bytes = 0;  // on the wire: a routed message's header included
  std::any payload;        // the writer's value, of any type (the reader casts it back)
  std::string label;       // for traces: what the message carries
  RouteHeader route{};     // on a routed channel, the routers' header ahead of the value
};

}  // namespace t800
