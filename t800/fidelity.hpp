// How much detail a simulation models (issue 6). The levels trade run time for detail; `automatic`,
// the default, keeps the fine detail only where something is shared and so gives the finest level's
// results.
//
// Links:   message   -- one closed form per message (t800/link_timing.hpp); exact while a link is
// used in one
//                       direction at a time, approximate when both directions overlap.
//          packet    -- every data and acknowledge packet at its own time (t800/link.hpp).
//          automatic -- closed form while the link is used one way; packets from the moment the
//          other
//                       direction starts, handing the message in flight over mid-way.
// Compute: block     -- one wait per compute block: no timeslicing among low-priority processes and
// no
//                       memory cycles taken by link DMA (high-priority preemption is still
//                       modelled).
//          fine      -- the CPU wakes at every timeslice tick, and link DMA takes its memory
//          cycles. automatic -- as fine, but a lone process is not woken at ticks where nobody
//          could take the CPU.
#pragma once

#include <optional>
#include <string_view>

namespace t800 {

enum class LinkFidelity { automatic, message, packet };
enum class ComputeFidelity { automatic, block, fine };
// How a block of computation is costed: `instructions` -- recorded kernels compiled to T800 code
// and timed instruction by instruction (compute_model.hpp); `mix` -- the faster op-count model
// (cost_model.hpp).
enum class ComputeCost { instructions, mix };

std::string_view to_string(LinkFidelity fidelity);     // "auto", "message", "packet"
std::string_view to_string(ComputeFidelity fidelity);  // "auto", "block", "fine"
std::optional<LinkFidelity> parse_link_fidelity(std::string_view text);
std::optional<ComputeFidelity> parse_compute_fidelity(std::string_view text);
std::string_view to_string(ComputeCost cost);  // "instructions", "mix"
std::optional<ComputeCost> parse_compute_cost(std::string_view text);

}  // namespace t800
