// Benchmarks run t800sim as child processes (SystemC runs one simulation per process); this finds
// it.
#pragma once

#include <string>

namespace benchmarks {

// The t800sim to run: `given` (a --t800sim flag), or the one in the build directory this program
// was built in (BUILD/bench/NAME -> BUILD/t800sim). Throws std::invalid_argument saying where it
// looked.
std::string find_t800sim(const std::string& given);

}  // namespace benchmarks
