// The sequential solver: right answers, interchanges, failures that are reported, and op counts.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/elimination/elimination_fixtures.hpp"
#include "workloads/elimination/gauss.hpp"

namespace {

using namespace elimination_test;
using elimination::Pivoting;
using elimination::Status;
using C = dynamics::Counted<double>;

TEST(Gauss, ReferenceStateGivesThePublishedAcceleration) {
  const auto s = reference_system();
  const auto x = elimination::solve(s.a, s.b, rule(Pivoting::simple));
  ASSERT_EQ(x.status, Status::ok);
  // the reference state's q̈, six significant figures
  const double expected[] = {0.070682, -0.318066, -9.72784, 5.13206, 0.548757, -4.902692};
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(x.x[std::size_t(i)], expected[i], 1e-5 * std::fabs(expected[i]) + 1e-6);
  EXPECT_EQ(x.interchanges, 0);  // D is positive definite: no pivot is ever zero
}

// Within rounding of Eigen's LU: |x - x_eigen| <= 4 n growth kappa_inf u |x| (the textbook
// forward-error bound of elimination, Higham ch. 9, with a factor 4 for Eigen's own error).
TEST(Gauss, AgreesWithEigenPartialPivLuWithinRounding) {
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const auto s = elimination::random_system(6, seed);
    const Eigen::MatrixXd a = to_eigen(s);
    const Eigen::VectorXd expected = a.partialPivLu().solve(rhs(s));
    const double kappa =
        a.lpNorm<Eigen::Infinity>() * a.inverse().cwiseAbs().rowwise().sum().maxCoeff();
    for (Pivoting p : {Pivoting::simple, Pivoting::partial}) {
      const auto x = elimination::solve(s.a, s.b, rule(p));
      ASSERT_EQ(x.status, Status::ok) << "seed " << seed;
      const double bound =
          4 * 6 * double(x.growth) * kappa * 0x1p-53 * expected.lpNorm<Eigen::Infinity>();
      for (int i = 0; i < 6; ++i)
        EXPECT_LE(std::fabs(x.x[std::size_t(i)] - expected(i)), bound)
            << "seed " << seed << " " << to_string(p);
    }
  }
}

TEST(Gauss, ZeroPivotIsInterchangedWithTheFirstUsableRow) {
  const auto s = given({{0, 1, 2}, {0, 3, 1}, {2, 1, 1}}, {3, 4, 4});
  const auto x = elimination::solve(s.a, s.b, rule(Pivoting::simple));
  ASSERT_EQ(x.status, Status::ok);
  EXPECT_EQ(x.interchanges, 1);
  EXPECT_EQ(x.pivot_rows.front(), 2);  // rows 0 and 1 start with 0
  for (double v : x.x) EXPECT_NEAR(v, 1.0, 1e-15);
}

TEST(Gauss, SimpleInterchangeKeepsANonZeroPivotPartialTakesTheLargest) {
  const auto s = given({{1, 1}, {4, 1}}, {2, 5});
  EXPECT_EQ(elimination::solve(s.a, s.b, rule(Pivoting::simple)).interchanges, 0);
  const auto partial = elimination::solve(s.a, s.b, rule(Pivoting::partial));
  EXPECT_EQ(partial.interchanges, 1);
  EXPECT_EQ(partial.pivot_rows.front(), 1);
}

TEST(Gauss, SingularMatrixIsReportedNotSolved) {
  const auto s = given({{1, 2, 3}, {2, 4, 6}, {1, 1, 1}}, {1, 2, 3});
  for (Pivoting p : {Pivoting::simple, Pivoting::partial}) {
    const auto x = elimination::solve(s.a, s.b, rule(p));
    EXPECT_EQ(x.status, Status::no_pivot) << to_string(p);
    EXPECT_TRUE(x.x.empty());
    EXPECT_EQ(x.step, 2);  // rows 1 and 2 are dependent: the last step has nothing left
  }
}

TEST(Gauss, ZeroColumnWithNoRowToInterchangeFails) {
  const auto s = given({{0, 1}, {0, 2}}, {1, 2});
  const auto x = elimination::solve(s.a, s.b, rule(Pivoting::simple));
  EXPECT_EQ(x.status, Status::no_pivot);
  EXPECT_EQ(x.step, 0);
}

// The paper's rule accepts any non-zero pivot: a tiny one goes through and ruins the result
// (silently). The threshold option interchanges instead; the growth check reports it.
TEST(Gauss, TinyPivotThresholdAndGrowthCheck) {
  const auto s = given({{1e-14, 1, 1}, {1, 1, 0}, {1, 0, 2}}, {2, 2, 3});
  const auto paper = elimination::solve(s.a, s.b, rule(Pivoting::simple));
  ASSERT_EQ(paper.status, Status::ok);
  EXPECT_EQ(paper.interchanges, 0);
  EXPECT_GT(paper.growth, 1e13);

  const auto threshold = elimination::solve(s.a, s.b, rule(Pivoting::simple, 1e-10));
  ASSERT_EQ(threshold.status, Status::ok);
  EXPECT_EQ(threshold.pivot_rows.front(), 1);
  EXPECT_LT(threshold.growth, 10);

  const auto checked = elimination::solve(s.a, s.b, rule(Pivoting::simple, 0, 1e8));
  EXPECT_EQ(checked.status, Status::unstable);
  EXPECT_EQ(checked.step, 0);
  EXPECT_FALSE(checked.x.empty());  // flagged, not withheld
}

TEST(Gauss, ThresholdWithNoRowAboveItFails) {
  const auto s = given({{1e-14, 1}, {2e-14, 1}}, {1, 1});
  const auto x = elimination::solve(s.a, s.b, rule(Pivoting::simple, 1e-10));
  EXPECT_EQ(x.status, Status::no_pivot);
  EXPECT_EQ(x.step, 0);
}

TEST(Gauss, NonFiniteValuesAreReported) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(elimination::solve<double>({{1, nan}, {1, 1}}, {1, 1}, rule(Pivoting::simple)).status,
            Status::non_finite);
  EXPECT_EQ(elimination::solve<double>({{1, 1}, {1, 2}}, {inf, 1}, rule(Pivoting::simple)).status,
            Status::non_finite);
  EXPECT_EQ(elimination::solve<double>({{nan, 1}, {1, 1}}, {1, 1}, rule(Pivoting::partial)).status,
            Status::non_finite);
  // Overflow inside the elimination: 1e308 - (-1e308) = inf.
  const auto overflow =
      elimination::solve<double>({{1, 1e308}, {-1, 1e308}}, {1, 1}, rule(Pivoting::simple));
  EXPECT_EQ(overflow.status, Status::non_finite);
  EXPECT_EQ(overflow.step, 0);
}

TEST(Gauss, CountingScalarComputesTheSameBits) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto s = elimination::random_system(6, seed);
    for (Pivoting p : {Pivoting::simple, Pivoting::partial}) {
      const auto plain = elimination::solve(s.a, s.b, rule(p));
      const auto c = elimination::convert<C>(s);
      const auto counted = elimination::solve(c.a, c.b, rule(p));
      for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(counted.x[i].value(), plain.x[i]);
      const auto f = elimination::convert<float>(s);
      const auto cf = elimination::convert<dynamics::Counted<float>>(s);
      const auto pf = elimination::solve(f.a, f.b, rule(p));
      const auto cfs = elimination::solve(cf.a, cf.b, rule(p));
      for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(cfs.x[i].value(), pf.x[i]);
    }
  }
}

}  // namespace
