#include "t800/link_timing.hpp"

#include <algorithm>

#include "t800/timing_table.hpp"

namespace t800 {

LinkTiming::LinkTiming(const LinkConfig& config)
    : bit_ns(1000.0 / config.speed_mbps),
      data_packet_ns(bit_ns * timing::kDataPacketBits),
      ack_packet_ns(bit_ns * timing::kAckPacketBits),
      ack_detect_ns(timing::kAckDetectNs +
                    (config.protocol == LinkProtocol::t414 ? data_packet_ns : 0.0)),
      ack_process_ns(bit_ns * timing::kAckProcessBits + timing::kAckProcessNs),
      byte_period_ns(std::max(data_packet_ns, ack_detect_ns + ack_packet_ns + ack_process_ns)) {}

double LinkTiming::arrival_ns(std::int64_t bytes) const {
  return double(bytes - 1) * byte_period_ns + data_packet_ns;
}

double LinkTiming::acknowledged_ns(std::int64_t bytes) const {
  return double(bytes - 1) * byte_period_ns + ack_detect_ns + ack_packet_ns;
}

}  // namespace t800
