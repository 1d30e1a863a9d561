// The levels' pieces of work (elimination/gauss.hpp) as the processors run them: each piece's
// counted work (for the op-count model) and its recorded code (for the instruction-level one).
//
// A piece runs once for its numbers under a WorkTally. Its code depends only on its shape and on
// the path its data took (how far the pivot search went, an interchange), which the counted work
// identifies, so the first piece of each kind and work is run again -- on copies of its inputs
// taken before, as the arrays of a recording -- and the recording is kept for every later one.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "network/process.hpp"
#include "t800/codegen/recording.hpp"
#include "t800/compute_work.hpp"
#include "workloads/elimination/gauss.hpp"
#include "workloads/occam/structure.hpp"
#include "workloads/pipeline/costs.hpp"

namespace workloads {

// An input of a piece and the name its array has in the code.
template <class T>
struct Named {
  const char* name;
  T& value;
};
template <class T>
Named<T> named(const char* name, T& value) {
  return {name, value};
}

namespace detail {
template <class S>
void declare_input(elimination::Rows<S>& rows, const char* name) {
  for (auto& row : rows) occam::declare(row, name);
}
template <class S>
void declare_input(std::vector<S>& row, const char* name) {
  occam::declare(row, name);
}
template <class T>
void declare_input(dynamics::Counted<T>& value, const char* name) {
  occam::declare_variable(value, name);
}
inline void declare_input(std::vector<int>&, const char*) {}  // bookkeeping, not REALs
}  // namespace detail

template <class T>
class PieceCode {
 public:
  using C = dynamics::Counted<T>;

  // Runs kernel(inputs...) and returns its result and its cost.
  template <class Kernel, class... Inputs>
  auto run(const char* label, Kernel kernel, Named<Inputs>... inputs) {
    std::tuple<std::decay_t<Inputs>...> copies(inputs.value...);
    elimination::Work work;
    auto result = [&] {
      elimination::WorkTally tally;
      auto r = kernel(inputs.value...);
      work = tally.work();
      return r;
    }();
    std::shared_ptr<const t800::codegen::Recording>& code = recording_of(label, work);
    if (!code) {
      auto recording = std::make_shared<t800::codegen::Recording>(label, sizeof(T) == 8);
      {
        const t800::codegen::RecordingScope scope(*recording);
        std::apply(
            [&](auto&... copy) {
              const char* names[] = {inputs.name...};
              std::size_t i = 0;
              (detail::declare_input(copy, names[i++]), ...);
              kernel(copy...);
            },
            copies);
      }
      code = std::move(recording);
    }
    return std::make_pair(std::move(result), t800::ComputeWork{to_operation_mix(work), code});
  }

 private:
  using Recorded =
      std::vector<std::pair<elimination::Work, std::shared_ptr<const t800::codegen::Recording>>>;

  // The recording kept for a kind of piece and its work (null until made). A piece kind meets a
  // handful of works (its pivot paths), so a list per kind is searched; no key is formatted.
  std::shared_ptr<const t800::codegen::Recording>& recording_of(const char* label,
                                                                const elimination::Work& work) {
    auto kind = recorded_.find(label);
    if (kind == recorded_.end()) kind = recorded_.emplace(label, Recorded{}).first;
    for (auto& [w, recording] : kind->second)
      if (w == work) return recording;
    return kind->second.emplace_back(work, nullptr).second;
  }

  std::map<std::string, Recorded, std::less<>> recorded_;
};

}  // namespace workloads
