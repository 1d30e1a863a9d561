// Level 3 (L3): collects each step's rows from level 2, checks that all arrived and are finite
// (and, with the growth check, how much the pivots have grown), returns the reduced matrix to L1
// row by row, and passes each pivot row (a row of U) on to L4. With overlap it streams each row
// back as it arrives; with recovery it waits for a step's rows in an ALT with a timer guard and
// asks L1 to resend what is missing or damaged, reporting what it detects and recovers from to the
// run's fault report. A process of the SDK (t800sim::Process).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "workloads/pipeline/levels/context.hpp"

namespace workloads::levels {

template <class T>
class Level3 {
 public:
  // longest_message_us: how long a message that has started may take to arrive (recovery).
  Level3(const Context<T>& context, double longest_message_us)
      : c_(context), longest_message_us_(longest_message_us) {}
  // One system; false when the pipeline stops.
  bool round(Process& p);
  // Its channels, given when its process starts.
  void attach(Ends ends) { ends_ = std::move(ends); }
  // Recovery: one system, checked.
  bool checked(Process& p);

 private:
  using M = Messages<T>;
  using C = typename M::C;
  using Rows = elimination::Rows<C>;
  using Pivot = typename M::Pivot;
  using CheckedPivot = typename M::CheckedPivot;

  bool return_reduced(Process& p, int k, Rows& rows, C bound, bool& unstable);
  void collect(Process& p, int k, Pivot& pivot, bool unstable, Rows& rows);
  // One branch per level-2 port with rows in step k: takes its rows, checks each row number, stores
  // the row and tells `arrived` its index (0-based).
  void take_rows(std::vector<Process::Body>& branches, int k, Rows& rows,
                 std::function<void(std::size_t)> arrived);
  void stream(Process& p, int k, Pivot& pivot, C bound, bool& unstable);
  void forward(Process& p, int k, elimination::Row<C>& row, std::size_t i, C bound, bool& unstable);
  bool collect_checked(Process& p, int k, CheckedPivot& pivot, Rows& rows);
  void receive_step(Process& p, int k, CheckedPivot& pivot, Rows& rows, std::vector<bool>& have,
                    std::vector<int>& damaged, double first_wait_us);
  // A step's check found the growth above the limit: the first time, it is reported.
  void unstable_at(int k, bool& unstable);
  std::vector<std::string> path_through(int e) const;
  void send_back(Process& p, const typename M::ReturnedRow& row, const char* label) const;
  // Step k's pivot row (a row of U), or a stop, to L4 over its typed channel.
  void to_l4(Process& p, int k, const Pivot& pivot, const char* label) const;

  Context<T> c_;
  Ends ends_;  // from level 2 (or the fan-in Y); to L4; back to L1
  double longest_message_us_;
  Shared shared_;           // overlap: the rows the receiving branches have stored
  std::vector<bool> lost_;  // recovery: level-2 processors L3 no longer listens to
};

extern template class Level3<float>;
extern template class Level3<double>;

}  // namespace workloads::levels
