// What travels over a channel: a length in bytes (which sets the time) and, optionally, the values
// the real program would send (which the receiving workload reads).
#pragma once

#include <any>
#include <cstdint>
#include <string>

namespace t800 {

struct Message {
  std::int64_t bytes = 0;
  std::any payload;
  std::string label;  // for traces: what the message carries
};

}  // namespace t800
