// How many processes and channels one simulation holds: stated limits, so a program past them is an
// error naming the limit instead of SystemC's "(E518) stack setup failed" or an exhausted host.
// docs/reliability.md gives the measurements behind each figure and the command that repeats them.
#pragma once

#include <cstdint>

namespace network {

// Processes alive at once, each a SystemC thread with its own stack. The host maps each stack with
// a guard page and Linux allows a process 65,530 maps by default (vm.max_map_count): on this kind
// of host SystemC failed to set up a stack (E518) in some probes from 33,200 threads up, while
// 30,000 ran in every probe (bench/limits_bench, docs/reliability.md). The margin is for the
// simulator's own threads (routers, booted processors' link ports) and the libraries' maps.
inline constexpr std::int64_t kMaxProcesses = 30000;

// Channels declared by one program: each costs about 500 bytes of host memory with its name, and
// routing visits each once; a million were declared, realised and run in 3 s and 0.5 GB
// (bench/limits_bench, docs/reliability.md).
inline constexpr std::int64_t kMaxChannels = 1000000;

// Intervals a trace holds by default (--trace-limit changes it). A trace is kept in memory until
// the run ends and then formatted whole: a 10,027,665-interval trace (a trajectory of 3,500 steps,
// with --trace-csv and --trace-json) peaked at 6.3 GB of host memory and wrote 631 MB of CSV and
// 897 MB of JSON; 1,604,565 intervals peaked at 1.0 GB (docs/reliability.md).
inline constexpr std::int64_t kMaxTraceIntervals = 2000000;

}  // namespace network
