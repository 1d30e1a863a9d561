// The link protocol's timing for one link configuration, from timing_table.hpp: what the byte-level
// Link module uses, and the closed form of one uncontended message (exact while its direction is
// uncontended).
#pragma once

#include <cstdint>

#include "t800/processor_config.hpp"

namespace t800 {

struct LinkTiming {
  explicit LinkTiming(const LinkConfig& config);

  double bit_ns;
  double data_packet_ns;  // 11 bits
  double ack_packet_ns;   // 2 bits
  double
      ack_detect_ns;  // first (T800) or last (T414) bit of a data packet -> the acknowledge starts
  double ack_process_ns;  // end of an acknowledge -> the sender may start its next data packet
  double byte_period_ns;  // one direction streaming, uncontended

  // First data bit -> the last byte has arrived at the receiver.
  double arrival_ns(std::int64_t bytes) const;
  // First data bit -> the sender's last acknowledge has arrived (the sending process may go on).
  double acknowledged_ns(std::int64_t bytes) const;
};

}  // namespace t800
