// Compute costed from the kernel itself: write the kernel once, templated on its scalar; run with
// Real32 or Real64 it computes exactly what float or double would and records its dataflow, which
// every processor compiles to its own T800 code and times instruction by instruction
// (docs/compute-model.md).
//
//   template <class S> void saxpy(std::vector<S>& y, const std::vector<S>& x, S a) {
//     for (std::size_t i : t800sim::seq<S>(y.size())) y[i] = y[i] + a * x[i];  // SEQ i = 0 FOR n
//   }
//   t800sim::Kernel k = t800sim::record_kernel<t800sim::Real32>("SAXPY", [&] {
//     std::vector<t800sim::Real32> y(n), x(n);
//     t800sim::declare(y, "y");          // arrays the PROC is given (loads and stores)
//     t800sim::declare(x, "x");
//     t800sim::Real32 a = 2.0f;
//     t800sim::declare_variable(a, "a");  // a workspace variable
//     saxpy(y, x, a);
//   });
//   p.compute(k);
#pragma once

#include <exception>
#include <memory>
#include <string>

#include "t800/codegen/recording.hpp"
#include "t800/compute_work.hpp"
#include "workloads/dynamics/counted.hpp"
#include "workloads/occam/structure.hpp"
#include "workloads/occam/subscript.hpp"

namespace t800sim {

using Real32 = dynamics::Counted<float>;   // occam REAL32
using Real64 = dynamics::Counted<double>;  // occam REAL64
// occam INT (32 bits on the T800): its arithmetic, comparisons, shifts and bitwise operations are
// recorded and compiled as REAL32's and REAL64's are; arrays of Int are declared the same way.
using Int = dynamics::CountedInt;
// REALn ROUND n, INT ROUND x, INT TRUNC x:
//   Real64 x = t800sim::to_real<Real64>(n);  Int k = t800sim::int_round(x);
using dynamics::int_round;
using dynamics::int_trunc;
using dynamics::to_real;

// x[k] for an INT k the kernel computes (k + 2 * h * b, perm[i]): t800sim::at(x, k), read or
// assigned; the code computes the subscript as written (workloads/occam/subscript.hpp).
using occam::at;
using occam::declare;
using occam::declare_each;
using occam::declare_variable;
using occam::seq;
// Integer statements occam compiles around the REAL arithmetic, where the kernel has them:
// integer<S>(IntegerStatement::test) for an IF on an integer (a hit's index, a flag),
// integer<S>(IntegerStatement::move) for an integer assignment (hit := k).
using IntegerStatement = t800::codegen::IntegerStatement;
using occam::integer;
// For the operation-mix level only (compute_cost = "mix"): REAL loads and stores the counting
// scalar does not see, declared by the kernel (the code generator sees them in the recording).
using dynamics::note_loads;
using dynamics::note_stores;

// A recorded kernel: its code (compiled per processor when it runs) and its operation mix (for
// fidelity.compute_cost = "mix").
class Kernel {
 public:
  Kernel(std::shared_ptr<const t800::codegen::Recording> code, const dynamics::OpCounts& counts,
         long loop_iterations);
  // A kernel recorded and costed elsewhere (the simulator's own workloads record theirs piece by
  // piece).
  explicit Kernel(t800::ComputeWork work) : work_(std::move(work)) {}
  const std::string& name() const;
  const t800::ComputeWork& work() const { return work_; }

 private:
  t800::ComputeWork work_;
};

// Runs `body` once, recording the kernel it computes with scalar S (Real32 or Real64).
template <class S, class Body>
Kernel record_kernel(const std::string& name, Body&& body) {
  static_assert(dynamics::is_counted_v<S>, "record_kernel<Real32> or record_kernel<Real64>");
  auto recording = std::make_shared<t800::codegen::Recording>(
      name, sizeof(typename S::value_type) == sizeof(double));
  dynamics::OpTally tally;
  occam::LoopTally loops;
  try {
    const t800::codegen::RecordingScope scope(*recording);
    body();
  } catch (const t800::codegen::KernelError&) {
    throw;  // names the kernel already
  } catch (const std::exception& e) {
    throw t800::codegen::KernelError("kernel \"" + name +
                                     "\" failed while it was recorded: " + e.what());
  }
  return Kernel(std::move(recording), tally.counts(), loops.iterations());
}

}  // namespace t800sim
