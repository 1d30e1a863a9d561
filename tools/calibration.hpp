// Fitting the one calibration constant the paper allows: the occam code-efficiency factor, on the 1-worker
// dynamics time of Table 4 alone (issue 3). Every other row is a prediction.
#pragma once

#include <string>
#include <vector>

namespace tools {

struct CalibrationFit {
  double code_efficiency = 1;  // rounded to 4 decimals, the value to record
  double tp_ms = 0;            // Tp simulated with that value
  int runs = 0;
};

// Finds code_efficiency such that the scene's Tp (workload.tp_ms) with network.workers = `workers` equals
// target_ms, by the secant method over child simulations (Tp is close to affine in the factor).
CalibrationFit fit_code_efficiency(const std::string& scene, const std::vector<std::string>& overrides,
                                   int workers, double target_ms);

// The --set lines that put a calibration into a run.
std::vector<std::string> calibration_overrides(double code_efficiency, const std::string& fitted);

}  // namespace tools
