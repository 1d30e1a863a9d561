#include "workloads/elimination/gauss.hpp"

#include <fmt/format.h>

namespace elimination {

const char* to_string(Pivoting pivoting) {
  return pivoting == Pivoting::partial ? "partial" : "simple";
}

std::optional<Pivoting> parse_pivoting(std::string_view text) {
  if (text == "simple") return Pivoting::simple;
  if (text == "partial") return Pivoting::partial;
  return std::nullopt;
}

const char* to_string(Status status) {
  switch (status) {
    case Status::ok:
      return "ok";
    case Status::unstable:
      return "unstable";
    case Status::no_pivot:
      return "no_pivot";
    case Status::non_finite:
      return "non_finite";
    case Status::lost:
      return "lost";
  }
  return "?";
}

std::string to_string(const Work& work) {
  const IntegerWork& i = work.integer;
  return fmt::format("{} | loops={} iterations={} indexed={} tests={} moves={} abs={}",
                     dynamics::to_string(work.fp), i.loops, i.iterations, i.indexed, i.tests,
                     i.moves, i.abs);
}

}  // namespace elimination
