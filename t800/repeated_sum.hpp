// The sum a loop of floating-point additions reaches, without the loop. A link records its busy
// time as a running double, one addition per packet; a closed-form message (t800/link.hpp) adds all
// of its packets at once and must land on the very same double, bit for bit, or the reports of the
// fidelity levels would differ in their last digits.
#pragma once

#include <cstdint>

namespace t800 {

// `sum` after `times` executions of `sum += term` (IEEE double, round to nearest even), in a few
// operations per binade the sum crosses instead of one per addition. term >= 0 and sum >= 0.
double add_repeatedly(double sum, double term, std::int64_t times);

}  // namespace t800
