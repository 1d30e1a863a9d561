#include "workloads/run/process_error.hpp"

#include <optional>

namespace workloads {

namespace {

// One simulation per OS process (SystemC cannot be restarted), so one record.
std::optional<ProcessError>& recorded() {
  static std::optional<ProcessError> error;
  return error;
}

}  // namespace

void record_process_error(const ProcessError& error) {
  if (!recorded()) recorded() = error;
}

void throw_recorded_process_error() {
  std::optional<ProcessError> error;
  error.swap(recorded());
  if (error) throw *error;
}

}  // namespace workloads
