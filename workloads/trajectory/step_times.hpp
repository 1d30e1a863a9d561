// The simulated time of one integrator step and its split (workloads/trajectory/trajectory.hpp says
// what each part covers).
#pragma once

namespace workloads {

struct StepTimes {
  double step_us = 0, dynamics_us = 0, solve_us = 0, integration_us = 0, communication_us = 0;
};

}  // namespace workloads
