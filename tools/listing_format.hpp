// A generated PROC as an engineer would hold it against a compiler listing: every instruction with
// its address, bytes, the cycle it starts, when the integer unit and the FPU are free again, what
// it waited for, and the memory its data access touches.
#pragma once

#include <string>

#include "t800/codegen/code_unit.hpp"
#include "t800/compute_model.hpp"

namespace tools {

std::string format_listing(const t800::codegen::CodeUnit& unit, const t800::ComputeModel& model);

}  // namespace tools
