// The paper's processor farm for one forward-dynamics evaluation (workload kind "dynamics-farm").
//
// The host sends the state (q, q̇) to the master P0 (the processor wired to the host). The master
// computes sin/cos of the joint angles once and sends them to every worker; workers evaluate their
// subtasks (D_ij, C_ijk, h_i) and return the values; the master assembles D, C, c and h. Workers
// that are not the master's neighbours are reached through software routers on the processors
// between (network/transport/store_and_forward.hpp). Tp runs from the master holding the state to
// D, C, h assembled.
#pragma once

#include <memory>

#include "workloads/run/workload.hpp"

namespace workloads {

std::unique_ptr<Workload> make_dynamics_farm(const WorkloadContext& context);

}  // namespace workloads
