// Level 1 (L1): takes the system from the client, augments D with the right-hand side, and for
// each step chooses the pivot (simple interchange or partial pivoting), normalises the pivot row
// and hands it and the other rows to level 2 (round-robin, schedule.hpp); then takes the reduced
// matrix back from L3 for the next step. With overlap a receiver in PAR stores the rows L3 streams
// back while the steps go on; with recovery every message carries a checksum, L1's outputs give up
// at a deadline, and L1 resends what L3 asks for through the level-2 processors it still uses.
// A process of the SDK (t800sim::Process): the system comes as Messages::System, the rows go as
// packets; the steps and the receiver share the matrices through a t800sim::Shared.
#pragma once

#include <vector>

#include "workloads/pipeline/levels/context.hpp"

namespace workloads::levels {

template <class T>
class Level1 {
 public:
  explicit Level1(const Context<T>& context)
      : c_(context), unused_(std::size_t(context.shape.m), false) {}
  // One system; false when the pipeline stops (finish, or a failure every level is told of).
  bool round(Process& p);
  // Its channels, given when its process starts.
  void attach(Ends ends) { ends_ = std::move(ends); }

 private:
  using M = Messages<T>;
  using C = typename M::C;
  using Rows = elimination::Rows<C>;

  bool steps(Process& p, Rows first, C scale, C limit);
  bool stop(Process& p, int k);
  bool next_matrix(Process& p, int k, C limit);
  bool usable(const C& lead, const C& limit) const;
  void receive_streamed(Process& p);
  void await_row(Process& p, int k, std::size_t i);
  bool receive_reduced(Process& p, std::size_t rows, Rows& m);
  bool send_stop(Process& p, int k, bool finish);
  void hand_out(Process& p, int k, const typename M::Pivot& pivot, const Rows& m);
  // recovery
  void hand_out_checked(Process& p, int k, std::vector<std::size_t> rows,
                        const std::vector<int>& avoid);
  bool next_matrix_checked(Process& p, int k);
  void stop_level2(Process& p);
  // L1's outputs wait for a level-2 processor that may itself be waiting, up to the timeout, for
  // level 3 to take its output; twice the timeout, and L1 gives it up.
  double deadline(const Process& p) const { return p.now_us() + 2 * c_.settings.timeout_us; }

  Context<T> c_;
  Ends ends_;  // from the client; to level 2 (or the fan-out X); back from L3
  // The matrices, one per step (overlap: filled as rows stream back), and what has arrived.
  std::vector<Rows> matrices_;
  std::vector<int> arrived_;
  int handed_ = 0;        // steps handed out
  bool stopped_ = false;  // gave up before handing out step handed_
  Shared shared_;         // overlap: between the steps and the receiver
  // recovery
  typename M::CheckedPivot pivot_;  // the pivot row of the step L1 is in
  std::vector<bool> unused_;  // level-2 processors L1 no longer gives rows (failed, or lost by L3)
};

extern template class Level1<float>;
extern template class Level1<double>;

}  // namespace workloads::levels
