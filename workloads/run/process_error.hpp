// An exception a process's body let out, said with the workload, the process's own name, its
// processor and the simulated time. SystemC catches whatever leaves one of its threads and makes
// sc_start throw a report of its own instead, which names its thread ("proc_0") rather than the
// process, and says only "UNKNOWN EXCEPTION" for what is not a std::exception. So the wrapper
// around each body (sdk/realise.cpp) records the error here before SystemC sees it, and run()
// throws the record in place of SystemC's report.
#pragma once

#include <stdexcept>
#include <string>

namespace workloads {

class ProcessError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Records `error` unless one is recorded already: the first to fail ends the simulation.
void record_process_error(const ProcessError& error);

// Throws the recorded error, if there is one, and forgets it; otherwise returns.
void throw_recorded_process_error();

}  // namespace workloads
