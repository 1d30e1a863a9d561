// The one list of workload kinds and their parameters. Scene validation, `t800sim run --help` and
// the workloads themselves all read it.
#include "workloads/params.hpp"

namespace workloads {

const std::vector<WorkloadInfo>& workload_catalog() {
  using T = ParamType;
  // A table read row by row: one parameter per line, as written (clang-format would put each field
  // on a line).
  // clang-format off
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
      {"livermore7",
       "Livermore loop 7 (equation of state fragment, 16 flops per element) on one processor: "
       "its rate against INMOS's published MFLOPS",
       {
           {"elements", T::integer, std::int64_t{101}, "loop length n (u has n + 6 elements)", 1, 1e6, {}},
           {"repeat", T::integer, std::int64_t{1}, "times the loop runs", 1, 1e6, {}},
           {"precision", T::text, std::string{"real32"}, "occam REAL32 or REAL64 arithmetic", {}, {},
            {"real32", "real64"}},
           {"processor", T::text, std::string{}, "the processor that runs it (default: the first)", {}, {}, {}},
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
            "joint positions (rad, q3 in m); default: the README's reference state", {}, {}, {}},
           {"qd", T::real_list, std::vector<double>{0.1, -0.2, 0.05, 0.3, -0.1, 0.2}, "joint rates", {}, {}, {}},
       }},
      {"elimination",
       "the paper's Gaussian-elimination pipeline (Fig. 7): L1 pivots and normalises, m level-2 "
       "processors eliminate, L3 collects, L4 back-substitutes (workloads/pipeline/pipeline.hpp)",
       {
           {"m", T::integer, std::int64_t{0},
            "level-2 processors E1..Em used; 0 = all of the topology's (elimination-m<m>.toml has m)", 0, 64,
            {}},
           {"precision", T::text, std::string{"real64"}, "occam REAL32 or REAL64 arithmetic", {}, {},
            {"real32", "real64"}},
           {"pivoting", T::text, std::string{"simple"},
            "\"simple\" (the paper: interchange only when the pivot is unusable) or \"partial\" (largest in "
            "the column)",
            {}, {}, {"simple", "partial"}},
           {"pivot_threshold", T::real, 0.0,
            "a pivot p is unusable when |p| <= pivot_threshold * max|a_ij|; 0 = only an exact zero (the paper)",
            0.0, 1.0, {}},
           {"growth_check", T::flag, true,
            "level 3 also checks the pivot growth (catches tiny non-zero pivots; costs a pass over each reduced "
            "matrix and one over A on level 1); false = the paper's checks only (every row arrived, finite)",
            {}, {}, {}},
           {"growth_limit", T::real, 0.0,
            "growth above which level 3 flags the result unstable; 0 = 1/sqrt(unit roundoff) of the precision "
            "(4096 for REAL32, 9.5e7 for REAL64)",
            0.0, 1e300, {}},
           {"overlap", T::flag, false,
            "pipelined steps: level 3 streams each row back to level 1 as it arrives, and level 1 starts the next "
            "step once it has the rows its pivot choice needs (simple interchange: the first); false = strict steps",
            {}, {}, {}},
           {"buffered", T::flag, false,
            "each level-2 processor runs input, elimination and output as three parallel processes joined by "
            "one-row buffers (docs/table6.md); false = one process that takes, eliminates and passes a row",
            {}, {}, {}},
           {"source", T::text, std::string{"arm"},
            "the system: \"arm\" (D q'' = tau - c - h of the robot at q, qd, tau), \"random\" (n x n from "
            "seed) or \"given\" (workload.a, workload.b)",
            {}, {}, {"arm", "random", "given"}},
           {"robot", T::text, std::string{"../robots/stanford.toml"}, "robot model file, relative to the scene",
            {}, {}, {}},
           {"model", T::text, std::string{"full"},
            "dynamics model for source = \"arm\": \"full\" or \"paper\" (64 subtasks)", {}, {},
            {"paper", "full"}},
           {"q", T::real_list, std::vector<double>{0.1, 0.2, 0.5, 0.3, 0.4, 0.5},
            "joint positions (rad, q3 in m); default: the README's reference state", {}, {}, {}},
           {"qd", T::real_list, std::vector<double>{0.1, -0.2, 0.05, 0.3, -0.1, 0.2}, "joint rates", {}, {}, {}},
           {"tau", T::real_list, std::vector<double>{0, 0, 0, 0, 0, 0}, "joint torques (N m; N for joint 3)", {},
            {}, {}},
           {"n", T::integer, std::int64_t{6}, "unknowns, for source = \"random\"", 1, 64, {}},
           {"seed", T::integer, std::int64_t{1}, "random generator seed, for source = \"random\"", 0, 9.0e15,
            {}},
           {"a", T::real_list, std::vector<double>{}, "source = \"given\": the n x n matrix, row by row", {}, {},
            {}},
           {"b", T::real_list, std::vector<double>{}, "source = \"given\": the right-hand side", {}, {}, {}},
       }},
      {"trajectory",
       "forward dynamics end to end: the dynamics farm, the elimination pipeline and an integrator on the farm's "
       "master, step by step (workloads/trajectory/trajectory.hpp)",
       {
           {"robot", T::text, std::string{"../robots/stanford.toml"}, "robot model file, relative to the scene",
            {}, {}, {}},
           {"model", T::text, std::string{"full"},
            "dynamics model: \"full\" (every non-zero term) or \"paper\" (64 subtasks, joint-6 Coriolis terms "
            "dropped)",
            {}, {}, {"paper", "full"}},
           {"precision", T::text, std::string{"real32"}, "occam REAL32 or REAL64 arithmetic", {}, {},
            {"real32", "real64"}},
           {"m", T::integer, std::int64_t{3}, "level-2 processors E1..Em of the pipeline", 1, 64, {}},
           {"pivoting", T::text, std::string{"simple"},
            "\"simple\" (the paper: interchange only when the pivot is unusable) or \"partial\"", {}, {},
            {"simple", "partial"}},
           {"pivot_threshold", T::real, 0.0,
            "a pivot p is unusable when |p| <= pivot_threshold * max|a_ij|; 0 = only an exact zero", 0.0, 1.0, {}},
           {"integrator", T::text, std::string{"rk4"},
            "\"rk4\" (4 evaluations per step) or \"semi-implicit-euler\" (1 evaluation per step)", {}, {},
            {"rk4", "semi-implicit-euler"}},
           {"steps", T::integer, std::int64_t{100}, "integrator steps", 1, 1e7, {}},
           {"dt", T::real, 1e-3, "step, s", 1e-9, 10.0, {}},
           {"torque", T::text, std::string{"zero"},
            "\"zero\" (passive), \"csv\" (workload.torque_csv) or \"pd\" (kp, kd to target)", {}, {},
            {"zero", "csv", "pd"}},
           {"torque_csv", T::text, std::string{},
            "torque table, relative to the scene: header t,tau1,...,tau6, then rows with t increasing", {}, {}, {}},
           {"interpolation", T::text, std::string{"linear"},
            "torque table between rows: \"linear\" or \"hold\" (zero-order hold); held beyond its ends", {}, {},
            {"linear", "hold"}},
           {"kp", T::real_list, std::vector<double>{100.0}, "PD proportional gains, one or six values", {}, {}, {}},
           {"kd", T::real_list, std::vector<double>{20.0}, "PD derivative gains, one or six values", {}, {}, {}},
           {"target", T::real_list, std::vector<double>{0.0, 0.0, 0.5, 0.0, 0.0, 0.0}, "PD target q", {}, {}, {}},
           {"q", T::real_list, std::vector<double>{0.1, 0.2, 0.5, 0.3, 0.4, 0.5}, "initial joint positions", {}, {},
            {}},
           {"qd", T::real_list, std::vector<double>{0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, "initial joint rates", {}, {}, {}},
           {"stop_at_limits", T::flag, false,
            "stop at the first step that leaves the joint limits (reported either way, never clamped)", {}, {}, {}},
           {"output_csv", T::text, std::string{},
            "trajectory CSV (t, q, qd, tau, step_us and its split), relative to the scene; empty = none", {}, {}, {}},
       }},
  };
  // clang-format on
  return catalog;
}

}  // namespace workloads
