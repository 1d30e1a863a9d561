// How a run report is shown: aligned text for people, one JSON object for programs.
#pragma once

#include <string>

#include "workloads/run/run.hpp"

namespace tools {

std::string format_text(const workloads::RunReport& report, const std::string& fidelity_note = {});
std::string format_json(const workloads::RunReport& report);

}  // namespace tools
