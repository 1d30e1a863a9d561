#include "workloads/elimination/system.hpp"

#include <random>

namespace elimination {

LinearSystem<double> random_system(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  LinearSystem<double> s;
  for (int i = 0; i < n; ++i) {
    Row<double> row;
    for (int j = 0; j < n; ++j) row.push_back(u(rng));
    s.a.push_back(std::move(row));
    s.b.push_back(u(rng));
  }
  return s;
}

}  // namespace elimination
