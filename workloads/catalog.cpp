// The one list of workload kinds and their parameters. Scene validation, `t800sim run --help` and the
// workloads themselves all read it.
#include "workloads/params.hpp"

namespace workloads {

const std::vector<WorkloadInfo>& workload_catalog() {
  using T = ParamType;
  static const std::vector<WorkloadInfo> catalog = {
      {"pingpong",
       "two neighbouring processors send a message back and forth",
       {
           {"bytes", T::integer, std::int64_t{64}, "message length in bytes", 1, 1e7, {}},
           {"iterations", T::integer, std::int64_t{100}, "round trips", 1, 1e7, {}},
           {"from", T::text, std::string{}, "first processor (default: the host's processor)", {}, {}, {}},
           {"to", T::text, std::string{}, "second processor (default: a neighbour of `from`)", {}, {}, {}},
       }},
      {"link-stream",
       "one processor streams messages to a neighbour, in one or both directions",
       {
           {"bytes", T::integer, std::int64_t{4096}, "message length in bytes", 1, 1e7, {}},
           {"messages", T::integer, std::int64_t{64}, "messages per direction", 1, 1e7, {}},
           {"direction", T::text, std::string{"one"}, "\"one\" or \"both\"", {}, {}, {"one", "both"}},
           {"from", T::text, std::string{}, "sending processor (default: the host's processor)", {}, {}, {}},
           {"to", T::text, std::string{}, "receiving processor (default: a neighbour of `from`)", {}, {}, {}},
       }},
      {"dynamics-farm",
       "one forward-dynamics evaluation (D, C, h of the robot) farmed from a master to workers",
       {
           {"robot", T::text, std::string{"../robots/stanford.toml"}, "robot model file, relative to the scene",
            {}, {}, {}},
           {"model", T::text, std::string{"paper"},
            "\"paper\" (64 subtasks, joint-6 Coriolis terms dropped) or \"full\" (every non-zero term)", {}, {},
            {"paper", "full"}},
           {"schedule", T::text, std::string{"static"},
            "\"static\" (pre-computed list schedule), \"on-demand\" (workers ask for work) or \"explicit\" "
            "(workload.allocation)",
            {}, {}, {"static", "on-demand", "explicit"}},
           {"allocation", T::text, std::string{}, "explicit allocation: \"P1: D11 D12 h2; P2: C1_23 ...\"", {},
            {}, {}},
           {"precision", T::text, std::string{"real32"}, "occam REAL32 or REAL64 arithmetic", {}, {},
            {"real32", "real64"}},
           {"tp_window", T::text, std::string{"farm"},
            "what Tp covers: \"farm\" (first input sent to last result received) or \"evaluation\" (state "
            "received to D, C, c, h assembled, with the master's sin/cos and assembly)",
            {}, {}, {"farm", "evaluation"}},
           {"buffer", T::integer, std::int64_t{2}, "on-demand: subtasks in flight per worker (1 = no buffering)",
            1, 8, {}},
           {"q", T::real_list, std::vector<double>{0.1, 0.2, 0.5, 0.3, 0.4, 0.5},
            "joint positions (rad, q3 in m); default: the reference state of stanford-arm.md", {}, {}, {}},
           {"qd", T::real_list, std::vector<double>{0.1, -0.2, 0.05, 0.3, -0.1, 0.2}, "joint rates", {}, {}, {}},
       }},
  };
  return catalog;
}

}  // namespace workloads
