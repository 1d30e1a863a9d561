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
  };
  return catalog;
}

}  // namespace workloads
