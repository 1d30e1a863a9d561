// Which level-2 processor eliminates which row. Level 1 hands the rows of a step out round-robin,
// E1, E2, ..., Em, E1, ...; a row beyond the first m waits in level 1's memory until its processor
// has taken the previous one (the paper's "stored in the local memory ... and sent to any free
// processor"). Every row takes the same time to eliminate, so the processor that becomes free
// first is always the next one in the round, and the static order equals the dynamic one.
#pragma once

#include <cstddef>
#include <vector>

namespace workloads {

struct PipelineShape {
  int n = 6;  // unknowns
  int m = 1;  // level-2 processors

  // Rows 1 .. n-1-k of the reduced system at step k (row 0 is the pivot row) that processor e
  // (0-based) eliminates, in the order it receives them.
  std::vector<std::size_t> rows_for(int k, int e) const {
    std::vector<std::size_t> rows;
    for (int i = 1; i <= n - 1 - k; ++i)
      if (owner(static_cast<std::size_t>(i)) == e) rows.push_back(static_cast<std::size_t>(i));
    return rows;
  }
  // The processor (0-based) that eliminates row i of a reduced system.
  int owner(std::size_t i) const { return static_cast<int>((i - 1) % static_cast<std::size_t>(m)); }

  // Processor e takes part in step k when it has a row, and E1 always: it forwards the pivot row
  // to level 3 (which keeps the rows of U for level 4).
  bool participates(int k, int e) const { return e == 0 || !rows_for(k, e).empty(); }

  // Of the processors `served` (by one channel), those that take part in step k, and the rows of
  // step k they eliminate, in the order the channel carries them.
  std::vector<int> takers(const std::vector<int>& served, int k) const {
    std::vector<int> out;
    for (int e : served)
      if (participates(k, e)) out.push_back(e);
    return out;
  }
  std::vector<std::size_t> rows_of(const std::vector<int>& served, int k) const {
    std::vector<std::size_t> rows;
    for (int i = 1; i <= n - 1 - k; ++i)
      for (int e : served)
        if (owner(static_cast<std::size_t>(i)) == e) rows.push_back(static_cast<std::size_t>(i));
    return rows;
  }
};

}  // namespace workloads
