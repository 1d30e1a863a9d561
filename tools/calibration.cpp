#include "tools/calibration.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "tools/child_run.hpp"

namespace tools {

std::vector<std::string> calibration_overrides(double code_efficiency, const std::string& fitted) {
  return {fmt::format("calibration.code_efficiency={:.17g}", code_efficiency),
          "calibration.fitted=\"" + fitted + "\""};
}

namespace {

double simulated_tp_ms(const std::string& scene, std::vector<std::string> overrides, int workers,
                       double efficiency) {
  overrides.push_back("network.workers=" + std::to_string(workers));
  for (const std::string& o : calibration_overrides(efficiency, "trial value of the calibration search"))
    overrides.push_back(o);
  return run_scene_child(scene, overrides)["workload"]["tp_ms"].get<double>();
}

}  // namespace

CalibrationFit fit_code_efficiency(const std::string& scene, const std::vector<std::string>& overrides,
                                   int workers, double target_ms) {
  CalibrationFit fit;
  double e0 = 1.0, t0 = simulated_tp_ms(scene, overrides, workers, e0);
  double e1 = e0 * target_ms / t0, t1 = simulated_tp_ms(scene, overrides, workers, e1);
  fit.runs = 2;
  while (std::abs(t1 - target_ms) > 1e-4 * target_ms && fit.runs < 10 && t1 != t0) {
    const double e2 = e1 + (target_ms - t1) * (e1 - e0) / (t1 - t0);
    e0 = e1;
    t0 = t1;
    e1 = e2;
    if (!(e1 > 0.1 && e1 < 100))
      throw std::runtime_error(fmt::format(
          "no code efficiency in 0.1 .. 100 gives Tp = {} ms with {} workers (last try {:.4g})", target_ms,
          workers, e1));
    t1 = simulated_tp_ms(scene, overrides, workers, e1);
    ++fit.runs;
  }
  fit.code_efficiency = std::round(e1 * 1e4) / 1e4;
  fit.tp_ms = simulated_tp_ms(scene, overrides, workers, fit.code_efficiency);
  ++fit.runs;
  return fit;
}

}  // namespace tools
