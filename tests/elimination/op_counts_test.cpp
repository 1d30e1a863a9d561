// What each piece costs, and where the cost depends on the data (row interchanges, and how far
// simple interchange has to search) and where it does not (everything else).
#include <gtest/gtest.h>

#include "tests/elimination/elimination_fixtures.hpp"
#include "workloads/elimination/gauss.hpp"

namespace {

using namespace elimination_test;
using elimination::Pivoting;
using elimination::Work;
using C = dynamics::Counted<double>;

template <class F>
Work work_of(F&& f) {
  elimination::WorkTally tally;
  f();
  return tally.work();
}

Work solve_work(const elimination::LinearSystem<double>& s, const elimination::PivotRule& r) {
  const auto c = elimination::convert<C>(s);
  return work_of([&] { elimination::solve(c.a, c.b, r); });
}

// n = 6: sum_k (n-k) divisions; sum_k (n-1-k)(n-k) multiply-subtracts, plus n(n-1)/2 in back
// substitution.
TEST(EliminationOpCounts, ArithmeticOfTheSixBySixSystem) {
  const Work w = solve_work(reference_system(), rule(Pivoting::simple));
  EXPECT_EQ(w.fp.fdiv, 21);
  EXPECT_EQ(w.fp.fmul, 70 + 15);
  EXPECT_EQ(w.fp.fadd, 70 + 15);
  EXPECT_EQ(w.fp.fsqrt, 0);
  EXPECT_EQ(w.integer.moves, 0);  // no interchange
}

// Without interchanges the whole solve costs the same for every system, for both strategies.
TEST(EliminationOpCounts, DoNotDependOnTheDataWithoutInterchanges) {
  const auto r_simple = rule(Pivoting::simple, 0, 1e8);  // growth check on: its scan too
  const Work first = solve_work(reference_system(), r_simple);
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    auto s = elimination::random_system(6, seed);
    // Diagonally dominant: no pivot is ever zero or smaller than another in its column.
    for (std::size_t i = 0; i < 6; ++i) s.a[i][i] += 10;
    EXPECT_EQ(solve_work(s, r_simple), first) << "seed " << seed;
  }
}

// Level 2's elimination of a row and level 4's back substitution are data-independent.
TEST(EliminationOpCounts, EliminateAndBackSubstituteAreDataIndependent) {
  const std::vector<C> pivot{C(0.5), C(-2), C(3), C(1e-300)};
  const Work a = work_of([&] { elimination::eliminate<C>({C(1), C(2), C(3), C(4), C(5)}, pivot); });
  const Work b = work_of([&] {
    elimination::eliminate<C>({C(0), C(-7), C(1e9), C(0), C(2)}, pivot);
  });
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.fp.fmul, 4);
  EXPECT_EQ(a.fp.fadd, 4);
  EXPECT_EQ(a.integer.iterations, 4);
  const elimination::Rows<C> u1{{C(1), C(2), C(3)}, {C(4), C(5)}, {C(6)}};
  const elimination::Rows<C> u2{{C(-1), C(0), C(9)}, {C(0), C(0)}, {C(1e10)}};
  EXPECT_EQ(work_of([&] { elimination::back_substitute(u1); }),
            work_of([&] { elimination::back_substitute(u2); }));
}

// Where the data does matter: an interchange costs three integer moves, and simple interchange
// tests rows until it finds a usable one (partial pivoting always tests them all).
TEST(EliminationOpCounts, InterchangesAndTheSimpleSearchDependOnTheData) {
  const auto in_place = given({{2, 1, 1}, {1, 3, 1}, {1, 1, 4}}, {1, 1, 1});
  const auto zero_first = given({{0, 1, 1}, {0, 3, 1}, {1, 1, 4}}, {1, 1, 1});
  const Work a = solve_work(in_place, rule(Pivoting::simple));
  const Work b = solve_work(zero_first, rule(Pivoting::simple));
  EXPECT_EQ(b.integer.moves - a.integer.moves, 3);  // one interchange
  EXPECT_EQ(b.fp.fcompare - a.fp.fcompare, 2);      // two more rows tested at step 0
  const Work pa = solve_work(in_place, rule(Pivoting::partial));
  const auto largest_first = given({{4, 1, 1}, {1, 3, 1}, {1, 1, 2}}, {1, 1, 1});
  EXPECT_EQ(solve_work(largest_first, rule(Pivoting::partial)), pa);  // same comparisons, no swap
}

}  // namespace
