// The "trajectory" workload: forward dynamics end to end on one network (configs/scenes/
// trajectory.toml). The farm's master P0 integrates q̈ = D⁻¹(τ − c − h) for workload.steps steps of
// workload.dt; every evaluation of an integrator step is
//   1. τ at the stage's time and state (zero, a CSV table, or a PD controller), on P0;
//   2. D, c, h by the dynamics farm (FarmProgram: P0 and its workers, the paper's tree);
//   3. τ − c − h on P0, the system [D | τ − c − h] sent to the pipeline's L1;
//   4. q̈ by the Gaussian-elimination pipeline (PipelineProgram, m level-2 processors), back from
//   L4;
// and the integrator's own arithmetic runs on P0 after the step's last evaluation. Every piece of
// P0's arithmetic is charged by its counted operations (dynamics::Counted -> to_operation_mix).
//
// Per step it reports the simulated T800 time, split into
//   dynamics       farm rounds (P0's sin/cos and assembly, and the farm's messages);
//   solve          the pipeline's Tp (L1 has the system -> L4 has q̈);
//   integration    P0's controller, right-hand side and integrator arithmetic;
//   communication  the rest of the step: the system going P0 -> L1 and q̈ coming L4 -> P0 (routed
//                  through the workers' routers, configs/topologies/trajectory-9-m3.toml);
// and the real-time factor, step time / dt (< 1: faster than real time).
//
// The numbers are those of integration::step with elimination::dynamics_system and
// elimination::solve at the same precision, model and pivoting (tests/trajectory check it bit for
// bit). Joint limits are checked after every step; an exit is reported (joint, step, value), the
// state is never clamped.
#pragma once

#include <memory>

#include "workloads/run/workload.hpp"

namespace workloads {

std::unique_ptr<Workload> make_trajectory(const WorkloadContext& context);

}  // namespace workloads
