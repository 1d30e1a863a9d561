// Turns an operation mix into T800 processor cycles, using only timing_table.hpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "t800/operation_mix.hpp"
#include "t800/processor_config.hpp"

namespace t800 {

enum class Precision { real32, real64 };
std::optional<Precision> parse_precision(std::string_view text);  // "real32" | "real64"
std::string_view to_string(Precision precision);

struct CycleBreakdown {
  double integer_unit =
      0;             // cycles the integer unit is busy (including FP issue and data movement)
  double fpu = 0;    // cycles the FPU executes
  double total = 0;  // with the overlap rule applied
};

class CostModel {
 public:
  // `code_efficiency` multiplies every count: cycles of compiled occam per ideal instruction
  // sequence (1 = hand-written code). It is the one calibration constant the paper's data may fit
  // (issue 3).
  CostModel(const ProcessorConfig& processor, Precision precision, double code_efficiency = 1.0);

  CycleBreakdown breakdown(const OperationMix& mix) const;
  std::int64_t cycles(const OperationMix& mix) const;
  double cycle_ns() const;

  Precision precision() const { return precision_; }
  const ProcessorConfig& processor() const { return processor_; }
  double code_efficiency() const { return code_efficiency_; }

 private:
  double memory_extra_per_access() const;
  ProcessorConfig processor_;
  Precision precision_;
  double code_efficiency_;
};

}  // namespace t800
